//! The files a JSBSim model's systems come from: the model itself and every file its
//! `<system>`, `<flight_control>` and `<autopilot>` elements reference, found where JSBSim looks
//! for them. A referenced file that is missing or unreadable is an error naming it: JSBSim
//! itself refuses to load such a model, and reading on without it would silently lose the
//! flight control system (no limits, and surfaces the aerodynamics read left at zero).

use std::path::{Path, PathBuf};

/// The elements whose `file` attribute names a system file.
const REFERENCING: [&str; 3] = ["system", "flight_control", "autopilot"];

/// A system file's text, with its path.
#[derive(Clone, Debug)]
pub struct SystemFile {
    /// Where it was found.
    pub path: PathBuf,
    /// Its XML text.
    pub text: String,
}

/// The model's own file and every system file it references, in the order JSBSim reads them;
/// an error names a referenced file that cannot be found, read or parsed.
pub fn system_files(model: &Path) -> Result<Vec<SystemFile>, String> {
    let text = std::fs::read_to_string(model)
        .map_err(|e| format!("{}: cannot read: {e}", model.display()))?;
    let references = references(&text, model)?;
    let mut files = vec![SystemFile {
        path: model.to_path_buf(),
        text,
    }];
    for (element, name) in references {
        let path = locate(model, &element, &name).ok_or_else(|| {
            format!(
                "{}: <{element} file=\"{name}\">: no such file in {} (JSBSim itself refuses to \
                 load the model without it: it may hold the flight control system, and the \
                 surfaces' limits and any system output the aerodynamics read would be lost)",
                model.display(),
                searched(model, &element).join(", ")
            )
        })?;
        let text = std::fs::read_to_string(&path).map_err(|e| {
            format!(
                "{}: <{element} file=\"{name}\">: cannot read {}: {e} (expected a UTF-8 XML \
                 file; JSBSim itself refuses to load the model without it)",
                model.display(),
                path.display()
            )
        })?;
        if let Err(e) = parse(&text) {
            return Err(format!(
                "{}: not well-formed XML: {e} (referenced by <{element} file=\"{name}\"> of {})",
                path.display(),
                model.display()
            ));
        }
        files.push(SystemFile { path, text });
    }
    Ok(files)
}

/// Parses a system file; a document type declaration is allowed, as JSBSim's own
/// `systems/` files have them.
pub fn parse(text: &str) -> Result<roxmltree::Document<'_>, roxmltree::Error> {
    let options = roxmltree::ParsingOptions {
        allow_dtd: true,
        ..Default::default()
    };
    roxmltree::Document::parse_with_options(text, options)
}

/// The `(element, file)` references of the model's text.
fn references(text: &str, model: &Path) -> Result<Vec<(String, String)>, String> {
    let doc = parse(text).map_err(|e| format!("{}: not well-formed XML: {e}", model.display()))?;
    Ok(doc
        .root_element()
        .children()
        .filter(|n| REFERENCING.contains(&n.tag_name().name()))
        .filter_map(|n| Some((n.tag_name().name().to_string(), n.attribute("file")?)))
        .map(|(element, file)| (element, file.to_string()))
        .collect())
}

/// The directories JSBSim searches for a file referenced by `element`: the aircraft's own
/// directory, then for a `<system>` its `Systems/` (or `systems/`) and the root's `systems/`.
fn directories(model: &Path, element: &str) -> Vec<PathBuf> {
    let aircraft = model.parent().unwrap_or(Path::new(".")).to_path_buf();
    let mut dirs = vec![aircraft.clone()];
    if element == "system" {
        dirs.push(aircraft.join("Systems"));
        dirs.push(aircraft.join("systems"));
        if let Some(root) = aircraft.parent().and_then(Path::parent) {
            dirs.push(root.join("systems"));
        }
    }
    dirs
}

/// The directories searched, for messages.
fn searched(model: &Path, element: &str) -> Vec<String> {
    directories(model, element)
        .iter()
        .map(|d| d.display().to_string())
        .collect()
}

/// Where JSBSim finds `name` (`.xml` appended when it has another extension or none).
fn locate(model: &Path, element: &str, name: &str) -> Option<PathBuf> {
    let file = if name.ends_with(".xml") {
        name.to_string()
    } else {
        format!("{name}.xml")
    };
    let given = Path::new(&file);
    if given.is_absolute() {
        return given.is_file().then(|| given.to_path_buf());
    }
    directories(model, element)
        .into_iter()
        .map(|d| d.join(&file))
        .find(|p| p.is_file())
}
