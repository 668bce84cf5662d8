//! The reader of one aircraft file: its text and name, from which every error takes its file,
//! line and column, and the checks every table shares (only valid keys, a key missing, a key of
//! the other format).

use super::suggest::suggestion;
use super::{
    keys_of, line_col, list, qualified, AircraftError, Key, Kind, Location, Node, TOP_KEYS,
};
use std::ops::Range;

/// The reader of one file: its text, which every span indexes, and its name, which every message
/// starts with.
pub(super) struct Cx<'a> {
    pub(super) text: &'a str,
    pub(super) file: &'a str,
}

/// A table of the file, checked to hold only valid keys.
pub(super) struct Table<'n> {
    pub(super) name: &'static str,
    /// The table's own span or, failing that, its key's.
    pub(super) span: Option<Range<usize>>,
    pub(super) entries: &'n [(Key, Node)],
}

impl Table<'_> {
    /// The entry of `key`, if the table has it.
    pub(super) fn get(&self, key: &str) -> Option<&(Key, Node)> {
        self.entries.iter().find(|(k, _)| k.name == key)
    }
}

/// At most 40 characters of a value as written, for messages (a 400-digit number stays legible).
pub(super) fn shorten(s: &str) -> String {
    let s = s.trim().replace('\n', " ");
    if s.chars().count() <= 40 {
        return s;
    }
    let head: String = s.chars().take(24).collect();
    format!("{head}... ({} characters)", s.chars().count())
}

impl Cx<'_> {
    pub(super) fn at(&self, span: Option<&Range<usize>>) -> Location {
        self.at_offset(span.map(|s| s.start))
    }

    pub(super) fn at_offset(&self, offset: Option<usize>) -> Location {
        let (line, column) = offset.map_or((1, 1), |o| line_col(self.text, o));
        Location {
            file: self.file.to_string(),
            line,
            column,
        }
    }

    pub(super) fn at_key(&self, key: &Key) -> Location {
        self.at(key.span.as_ref())
    }

    pub(super) fn at_value(&self, key: &Key, value: &Node) -> Location {
        self.at(value.span.as_ref().or(key.span.as_ref()))
    }

    pub(super) fn written(&self, value: &Node) -> String {
        value
            .span
            .as_ref()
            .and_then(|s| self.text.get(s.clone()))
            .map(|s| s.trim().to_string())
            .filter(|s| !s.is_empty())
            .unwrap_or_else(|| match &value.kind {
                Kind::Integer(i) => i.to_string(),
                Kind::Float(x) => x.to_string(),
                other => other.describe().to_string(),
            })
            .chars()
            .take(80)
            .collect::<String>()
            .replace('\n', " ")
    }

    pub(super) fn unknown(&self, table: &str, key: &Key) -> AircraftError {
        AircraftError::UnknownKey {
            at: self.at_key(key),
            key: qualified(table, &key.name),
            hint: suggestion(table, &key.name),
            expected: list(&keys_of(table)),
        }
    }

    /// Checks that `value` (under top-level `key`) is a table holding only `valid` keys.
    pub(super) fn table<'n>(
        &self,
        key: &Key,
        value: &'n Node,
        valid: &[&str],
    ) -> Result<Table<'n>, AircraftError> {
        let name = TOP_KEYS
            .iter()
            .copied()
            .find(|k| *k == key.name)
            .unwrap_or("");
        let Kind::Table(entries) = &value.kind else {
            return Err(AircraftError::NotATable {
                at: self.at_value(key, value),
                key: key.name.clone(),
                expected: list(valid),
                found: value.kind.describe(),
            });
        };
        // `[uncertainty]` takes the keys of the file's format, known only later: its loaders
        // check them (`uncertainty.rs`).
        if let Some((k, _)) = entries
            .iter()
            .find(|(k, _)| name != "uncertainty" && !valid.contains(&k.name.as_str()))
        {
            return Err(self.unknown(name, k));
        }
        Ok(Table {
            name,
            span: value.span.clone().or_else(|| key.span.clone()),
            entries,
        })
    }

    pub(super) fn missing_key(
        &self,
        table: &Table<'_>,
        key: &str,
        expected: String,
    ) -> AircraftError {
        AircraftError::MissingKey {
            at: self.at(table.span.as_ref()),
            table: table.name.to_string(),
            key: qualified(table.name, key),
            expected,
        }
    }

    pub(super) fn mixed(&self, key: &Key, problem: String) -> AircraftError {
        AircraftError::MixedFormats {
            at: self.at_key(key),
            problem,
        }
    }
}
