//! The aircraft of an envelope: a `jsbsim:` source without a flight condition,
//! `"jsbsim:MODEL [--set PROPERTY=VALUE]... [--jsbsim-root DIR]"` (the words `import jsbsim`
//! takes for the model); the grid's `--altitude-m` and `--mach` give every flight condition,
//! and each point is trimmed in level flight.

use crate::jsbsim::cli::setting;
use crate::jsbsim::import::Loaded;
use std::path::PathBuf;

/// The model and its settings, as named on the command line.
#[derive(Clone, Debug, PartialEq)]
pub struct Source {
    /// Catalogue name or path of the model XML.
    pub model: String,
    /// The models' root directory, if given.
    pub root: Option<PathBuf>,
    /// `--set` values.
    pub settings: Vec<(String, f64)>,
}

/// What a source may not say: the grid and the level-flight trim give the flight condition.
const CONDITION: [&str; 5] = [
    "--altitude-m",
    "--mach",
    "--speed",
    "--alpha-deg",
    "--level-flight",
];

impl Source {
    /// Parses `spec`, or says why it is not an envelope's source.
    pub fn parse(spec: &str) -> Result<Source, String> {
        let usage = "expected \"jsbsim:MODEL [--set PROPERTY=VALUE]... [--jsbsim-root DIR]\"";
        let rest = spec
            .strip_prefix("jsbsim:")
            .ok_or_else(|| format!("{spec}: an envelope needs a jsbsim: source, {usage}"))?;
        let words: Vec<&str> = rest.split_whitespace().collect();
        let (mut model, mut root, mut settings) = (None, None, Vec::new());
        let mut i = 0;
        while i < words.len() {
            let w = words[i];
            let mut next = || {
                i += 1;
                words
                    .get(i)
                    .copied()
                    .ok_or_else(|| format!("{spec}: {w} needs a value, {usage}"))
            };
            match w {
                "--set" => settings.push(setting(next()?)?),
                "--jsbsim-root" => root = Some(PathBuf::from(next()?)),
                _ if CONDITION.contains(&w) => {
                    return Err(format!(
                        "{spec}: {w} is the envelope's to give (its --altitude-m and --mach \
                         ranges, each point trimmed in level flight), {usage}"
                    ))
                }
                _ if w.starts_with("--") || model.is_some() => {
                    return Err(format!("{spec}: unexpected {w}, {usage}"))
                }
                _ => model = Some(w.to_string()),
            }
            i += 1;
        }
        let model = model.ok_or_else(|| format!("{spec}: no model named, {usage}"))?;
        Ok(Source {
            model,
            root,
            settings,
        })
    }

    /// The model, read once.
    pub fn load(&self) -> Result<Loaded, String> {
        Loaded::new(&self.model, self.root.as_deref(), &self.settings)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_source_names_the_model_and_its_settings_but_no_condition() {
        let s = Source::parse("jsbsim:f104 --set fcs/flap-pos-norm=0.5").unwrap();
        assert_eq!(s.model, "f104");
        assert_eq!(s.settings, [("fcs/flap-pos-norm".to_string(), 0.5)]);
        let e = Source::parse("jsbsim:f104 --mach 0.5").unwrap_err();
        assert!(e.contains("--mach is the envelope's"), "{e}");
        assert!(Source::parse("f104").is_err());
        assert!(Source::parse("jsbsim:").is_err());
        assert!(Source::parse("jsbsim:f104 --set x=inf").is_err());
    }
}
