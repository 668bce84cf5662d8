//! The TOML document as a small tree of keys and values with their byte spans, read through
//! `toml_edit`'s public API, and the positions in the text every error message names: the line
//! and column of an offset, and the key written there.

use std::ops::Range;

/// The qualified key (`derivatives.l_p`) of the entry at byte `offset` of a TOML text that
/// parses: the last key that starts at or before `offset` on the same line, or whose value
/// spans it. `None` when the text does not parse or nothing is there.
pub(super) fn key_at(text: &str, offset: usize) -> Option<String> {
    let doc = toml_edit::ImDocument::parse(text).ok()?;
    let line = |o: usize| line_col(text, o).0;
    let mut best: Option<(usize, String)> = None;
    let mut stack = vec![(String::new(), entries_of(doc.as_table()))];
    while let Some((prefix, entries)) = stack.pop() {
        for (key, node) in entries {
            let path = if prefix.is_empty() {
                key.name.clone()
            } else {
                format!("{prefix}.{}", key.name)
            };
            let start = key.start();
            // a standard table spans its whole body; only values (and inline tables) count
            let covers = !matches!(node.kind, Kind::Table(_) if node.span.as_ref().is_some_and(|s| text.get(s.start..s.start + 1) == Some("[")))
                && node
                    .span
                    .as_ref()
                    .is_some_and(|s| s.start <= offset && offset < s.end.max(s.start + 1));
            let same_line = start <= offset && line(start) == line(offset);
            if (covers || same_line) && best.as_ref().is_none_or(|(b, _)| start >= *b) {
                best = Some((start, path.clone()));
            }
            if let Kind::Table(inner) = node.kind {
                stack.push((path, inner));
            }
        }
    }
    best.map(|(_, k)| k)
}

/// 1-based line and column (in characters) of a byte offset; never panics.
pub(super) fn line_col(text: &str, offset: usize) -> (usize, usize) {
    let mut end = offset.min(text.len());
    while end > 0 && !text.is_char_boundary(end) {
        end -= 1;
    }
    let before = text.get(..end).unwrap_or("");
    let line = before.matches('\n').count() + 1;
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    let column = before.get(line_start..).unwrap_or("").chars().count() + 1;
    (line, column)
}

/// A key of a TOML table, with its span when the parser has one.
#[derive(Debug)]
pub(super) struct Key {
    pub(super) name: String,
    pub(super) span: Option<Range<usize>>,
}

impl Key {
    /// Byte offset of the key (0 without a span), for ordering keys by position.
    pub(super) fn start(&self) -> usize {
        self.span.as_ref().map_or(0, |s| s.start)
    }
}

/// A TOML value, with its span when the parser has one.
#[derive(Debug)]
pub(super) struct Node {
    pub(super) span: Option<Range<usize>>,
    pub(super) kind: Kind,
}

#[derive(Debug)]
pub(super) enum Kind {
    Integer(i64),
    Float(f64),
    String(String),
    Boolean(bool),
    /// An array, with its elements (empty for an array of tables).
    Array(Vec<Node>),
    Datetime,
    Table(Vec<(Key, Node)>),
}

impl Kind {
    pub(super) fn describe(&self) -> &'static str {
        match self {
            Kind::Integer(_) => "an integer",
            Kind::Float(_) => "a float",
            Kind::String(_) => "a string",
            Kind::Boolean(b) => {
                if *b {
                    "a boolean (`true`)"
                } else {
                    "a boolean (`false`)"
                }
            }
            Kind::Array(_) => "an array",
            Kind::Datetime => "a date-time",
            Kind::Table(_) => "a table",
        }
    }
}

/// The entries of a table (standard, implicit or dotted), in document order.
pub(super) fn entries_of(table: &toml_edit::Table) -> Vec<(Key, Node)> {
    table
        .iter()
        .filter_map(|(name, item)| {
            let node = item_node(item)?;
            let key = Key {
                name: name.to_string(),
                span: table.key(name).and_then(toml_edit::Key::span),
            };
            Some((key, node))
        })
        .collect()
}

pub(super) fn item_node(item: &toml_edit::Item) -> Option<Node> {
    use toml_edit::Item;
    match item {
        Item::None => None,
        Item::Value(v) => Some(value_node(v)),
        Item::Table(t) => Some(Node {
            span: t.span(),
            kind: Kind::Table(entries_of(t)),
        }),
        Item::ArrayOfTables(a) => Some(Node {
            span: a.span(),
            kind: Kind::Array(Vec::new()),
        }),
    }
}

pub(super) fn value_node(value: &toml_edit::Value) -> Node {
    use toml_edit::Value;
    let kind = match value {
        Value::String(s) => Kind::String(s.value().clone()),
        Value::Integer(i) => Kind::Integer(*i.value()),
        Value::Float(x) => Kind::Float(*x.value()),
        Value::Boolean(b) => Kind::Boolean(*b.value()),
        Value::Datetime(_) => Kind::Datetime,
        Value::Array(a) => Kind::Array(a.iter().map(value_node).collect()),
        Value::InlineTable(t) => Kind::Table(
            t.iter()
                .map(|(name, v)| {
                    let key = Key {
                        name: name.to_string(),
                        span: t.key(name).and_then(toml_edit::Key::span),
                    };
                    (key, value_node(v))
                })
                .collect(),
        ),
    };
    Node {
        span: value.span(),
        kind,
    }
}
