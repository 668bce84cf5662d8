//! The aircraft of an envelope: a `jsbsim:` source without a flight condition,
//! `"jsbsim:MODEL [--load-factor N] [--set PROPERTY=VALUE]... [--jsbsim-root DIR]"` (the words
//! `import jsbsim` takes for the model and its trim); the grid's `--altitude-m` and `--mach` (or
//! `--speed`) give every flight condition, and each point is trimmed at the load factor
//! (default 1 g).

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
    /// The load factor of the trim, if given.
    pub load_factor: Option<f64>,
}

/// What a source may not say: the grid and the trim give the flight condition.
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
        let usage = "expected \"jsbsim:MODEL [--load-factor N] [--set PROPERTY=VALUE]... \
                     [--jsbsim-root DIR]\"";
        let rest = spec
            .strip_prefix("jsbsim:")
            .ok_or_else(|| format!("{spec}: an envelope needs a jsbsim: source, {usage}"))?;
        let words: Vec<&str> = rest.split_whitespace().collect();
        let (mut model, mut root, mut settings) = (None, None, Vec::new());
        let mut load_factor = None;
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
                "--load-factor" => {
                    let text = next()?;
                    let n = text.parse::<f64>().ok().filter(|n| n.is_finite());
                    load_factor = Some(n.ok_or_else(|| {
                        format!("{spec}: --load-factor {text}: expected a finite number, {usage}")
                    })?);
                }
                _ if CONDITION.contains(&w) => {
                    return Err(format!(
                        "{spec}: {w} is the envelope's to give (its --altitude-m range and its \
                         --mach or --speed range, each point trimmed at the load factor), {usage}"
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
            load_factor,
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
        assert_eq!(s.load_factor, None);
        let s = Source::parse("jsbsim:f104 --load-factor 0").unwrap();
        assert_eq!(s.load_factor, Some(0.0));
        assert!(Source::parse("jsbsim:f104 --load-factor nan").is_err());
        let e = Source::parse("jsbsim:f104 --mach 0.5").unwrap_err();
        assert!(e.contains("--mach is the envelope's"), "{e}");
        assert!(Source::parse("f104").is_err());
        assert!(Source::parse("jsbsim:").is_err());
        assert!(Source::parse("jsbsim:f104 --set x=inf").is_err());
    }
}
