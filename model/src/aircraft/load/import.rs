//! The optional `[import]` table that `model import jsbsim` writes: `warnings`, an array of
//! sentences (the tables its flight state reads beyond their breakpoints, for instance). They
//! join the aircraft's own warnings, so that `analyze` and the envelope report them with the
//! answers they qualify.

use super::{AircraftError, Cx, Kind, Table};

impl Cx<'_> {
    /// `[import]`: its `warnings`, each a string without control characters (none without).
    pub(super) fn import_warnings(&self, table: &Table<'_>) -> Result<Vec<String>, AircraftError> {
        let Some((key, value)) = table.get("warnings") else {
            return Ok(Vec::new());
        };
        let expected = "an array of strings (the import's warnings)";
        let Kind::Array(items) = &value.kind else {
            return Err(AircraftError::WrongType {
                at: self.at_value(key, value),
                key: "import.warnings".to_string(),
                expected,
                found: value.kind.describe(),
            });
        };
        items
            .iter()
            .map(|item| match &item.kind {
                Kind::String(s) if !s.chars().any(char::is_control) => Ok(s.clone()),
                Kind::String(s) => Err(AircraftError::InvalidValue {
                    at: self.at_value(key, item),
                    key: "import.warnings".to_string(),
                    expected: "a warning without control characters (it is printed on \
                               terminals)"
                        .to_string(),
                    value: super::shorten(&crate::aircraft::shown(s)),
                }),
                other => Err(AircraftError::WrongType {
                    at: self.at_value(key, item),
                    key: "import.warnings".to_string(),
                    expected,
                    found: other.describe(),
                }),
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use crate::aircraft::parse;

    const A: &str = include_str!("../../../../aircraft/a.toml");

    #[test]
    fn import_warnings_join_the_aircraft_warnings() {
        let text = format!("{A}\n[import]\nwarnings = [\"one\", \"two\"]\n");
        assert_eq!(parse(&text, "a.toml").unwrap().warnings, ["one", "two"]);
        assert!(parse(A, "a.toml").unwrap().warnings.is_empty());
    }

    #[test]
    fn import_warnings_must_be_strings() {
        let text = format!("{A}\n[import]\nwarnings = [\"one\", 2]\n");
        let e = parse(&text, "a.toml").unwrap_err().to_string();
        assert!(
            e.contains("import.warnings") && e.contains("found an integer"),
            "{e}"
        );
        let text = format!("{A}\n[import]\nwarning = \"one\"\n");
        let e = parse(&text, "a.toml").unwrap_err().to_string();
        assert!(
            e.contains("import.warning") && e.contains("warnings"),
            "{e}"
        );
    }
}
