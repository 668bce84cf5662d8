//! Where the JSBSim models are and which of them this crate reads: the root directory
//! (`--jsbsim-root`, else `JSBSIM_ROOT`, else the installed `jsbsim` Python package's own
//! directory), a model by catalogue name (`aircraft/NAME/NAME.xml`) or path, and the catalogue
//! listing with the reason each model that cannot be read is refused.

use super::model::Model;
use std::path::{Path, PathBuf};

/// How to get the models, for the message when none are found.
pub const HOW_TO_GET: &str = "no JSBSim models found: give --jsbsim-root DIR (a directory with \
     aircraft/NAME/NAME.xml), set JSBSIM_ROOT, or install JSBSim's Python package \
     (`pip install jsbsim==1.3.3`), whose directory holds the models";

/// The root directory of the models: `explicit`, else `JSBSIM_ROOT`, else the Python package's
/// directory (asking `python3`). `None` when none of these is a directory with `aircraft/`.
pub fn root(explicit: Option<&Path>) -> Option<PathBuf> {
    if let Some(p) = explicit {
        return Some(p.to_path_buf());
    }
    if let Some(p) = std::env::var_os("JSBSIM_ROOT") {
        return Some(PathBuf::from(p));
    }
    let out = std::process::Command::new("python3")
        .args([
            "-c",
            "import jsbsim, os; print(os.path.dirname(jsbsim.__file__))",
        ])
        .stderr(std::process::Stdio::null())
        .output()
        .ok()?;
    let dir = PathBuf::from(String::from_utf8(out.stdout).ok()?.trim());
    (out.status.success() && dir.join("aircraft").is_dir()).then_some(dir)
}

/// `root` if it is a folder holding `aircraft/`, else why it is not JSBSim's root (a file, a
/// missing path, a folder without `aircraft/`).
pub fn checked_root(root: &Path) -> Result<&Path, String> {
    let expected =
        "expected the folder holding aircraft/NAME/NAME.xml (--jsbsim-root, else $JSBSIM_ROOT)";
    if root.is_file() {
        return Err(format!(
            "the JSBSim root {} is a file; {expected}",
            root.display()
        ));
    }
    if !root.is_dir() {
        return Err(format!(
            "the JSBSim root {} does not exist; {expected}",
            root.display()
        ));
    }
    if !root.join("aircraft").is_dir() {
        return Err(format!(
            "the JSBSim root {} has no aircraft/ folder; {expected}",
            root.display()
        ));
    }
    Ok(root)
}

/// The XML file of `model`: a path if it names an existing file, else the catalogue entry
/// `root/aircraft/NAME/NAME.xml` (the name matched without regard to case).
pub fn model_path(root: Option<&Path>, model: &str) -> Result<PathBuf, String> {
    let p = Path::new(model);
    if p.is_file() {
        return Ok(p.to_path_buf());
    }
    let root = checked_root(root.ok_or_else(|| HOW_TO_GET.to_string())?)?;
    let names = names(root);
    let name = names
        .iter()
        .find(|n| n.eq_ignore_ascii_case(model))
        .ok_or_else(|| {
            format!(
                "no model `{model}` in {} (expected one of: {})",
                root.join("aircraft").display(),
                names.join(", ")
            )
        })?;
    Ok(root.join("aircraft").join(name).join(format!("{name}.xml")))
}

/// The catalogue's model names (directories of `root/aircraft` holding `NAME/NAME.xml`), sorted.
pub fn names(root: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(root.join("aircraft"))
        .into_iter()
        .flatten()
        .flatten()
        .filter_map(|e| e.file_name().into_string().ok())
        .filter(|n| {
            root.join("aircraft")
                .join(n)
                .join(format!("{n}.xml"))
                .is_file()
        })
        .collect();
    names.sort_by_key(|n| n.to_lowercase());
    names
}

/// Each catalogue model with whether it reads, and if not, why.
pub fn listing(root: &Path) -> Vec<(String, Result<Model, String>)> {
    names(root)
        .into_iter()
        .map(|n| {
            let path = root.join("aircraft").join(&n).join(format!("{n}.xml"));
            let model = Model::load(&path).map_err(|e| e.to_string());
            (n, model)
        })
        .collect()
}
