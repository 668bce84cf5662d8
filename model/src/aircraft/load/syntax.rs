//! Text the TOML parser refuses: a control character TOML forbids, a syntax error, a number the
//! parser cannot hold, and a value cut off at the end of the file, each named by its line and key.

use super::{key_at, line_col, qualified, shorten, AircraftError, Cx, F64_RANGE, I64_RANGE};

impl Cx<'_> {
    /// The first control character TOML forbids (all of U+0000-U+001F but tab, LF and CR, and
    /// U+007F), reported with the key on its line; the parser itself says only "invalid basic
    /// string" or, through `toml`, nothing at all.
    pub(super) fn control_character(&self) -> Option<AircraftError> {
        let (offset, c) = self
            .text
            .char_indices()
            .find(|&(_, c)| (c < ' ' && !matches!(c, '\t' | '\n' | '\r')) || c == '\u{7f}')?;
        let mut patched = self.text.to_string();
        patched.replace_range(offset..offset + c.len_utf8(), " ");
        let place = match key_at(&patched, offset) {
            Some(key) => format!("key `{key}`"),
            None => format!("line {}", line_col(self.text, offset).0),
        };
        let name = match c {
            '\0' => " (NUL)",
            '\u{7f}' => " (DEL)",
            '\u{1b}' => " (ESC)",
            _ => "",
        };
        Some(AircraftError::ControlCharacter {
            at: self.at_offset(Some(offset)),
            place,
            found: format!("U+{:04X}{name}", u32::from(c)),
        })
    }

    /// A TOML syntax error; for a number the parser cannot hold (an integer past i64, `1e309`, a
    /// 400-digit literal) the error names the key and the range instead: the literal is replaced
    /// by `0` of the same length, the text parsed again, and the key found by its position.
    pub(super) fn syntax_error(&self, e: &toml_edit::TomlError) -> AircraftError {
        let message = one_line(e.message());
        let span = e.span();
        let number_message = [
            "number too large",
            "number too small",
            "invalid floating-point number",
        ]
        .iter()
        .any(|m| message.contains(m));
        if let (true, Some(span)) = (number_message, span.as_ref()) {
            let start = span.start.min(self.text.len());
            let rest = self.text.get(start..).unwrap_or("");
            let len = rest
                .find(|c: char| c.is_whitespace() || matches!(c, ',' | ']' | '}' | '#'))
                .unwrap_or(rest.len());
            if len > 0 {
                let literal = &rest[..len];
                let mut patched = self.text.to_string();
                patched.replace_range(start..start + len, &format!("0{}", " ".repeat(len - 1)));
                if let Some(key) = key_at(&patched, start) {
                    let integer = !literal.contains(['.', 'e', 'E']);
                    return AircraftError::InvalidValue {
                        at: self.at_offset(Some(start)),
                        key,
                        expected: if integer { I64_RANGE } else { F64_RANGE }.to_string(),
                        value: shorten(literal),
                    };
                }
            }
        }
        let message = if message.trim().is_empty() {
            self.cut_off(span.as_ref().map_or(self.text.len(), |s| s.start))
        } else {
            message
        };
        AircraftError::Syntax {
            at: self.at(span.as_ref()),
            message,
        }
    }

    /// What to say where the parser stops without a message (a value cut off at the end of
    /// the file): the key of that line, with its table, and what it expects.
    pub(super) fn cut_off(&self, offset: usize) -> String {
        let offset = offset.min(self.text.len());
        let line_start = self.text[..offset].rfind('\n').map_or(0, |i| i + 1);
        let line = self.text[line_start..].lines().next().unwrap_or("");
        let key = line
            .split_once('=')
            .map(|(k, _)| k.trim())
            .filter(|k| !k.is_empty() && !k.starts_with('#'));
        let table = self.text[..line_start]
            .lines()
            .rev()
            .find_map(|l| {
                let t = l.trim();
                t.strip_prefix('[')
                    .and_then(|t| t.strip_suffix(']'))
                    .map(|t| t.trim().to_string())
            })
            .unwrap_or_default();
        match key {
            Some(k) => format!(
                "key `{}`: the value is missing or cut off here: expected a number",
                qualified(&table, k)
            ),
            None => "the text is cut off here: expected a complete `key = value` line or a \
                     `[table]` header"
                .to_string(),
        }
    }
}

fn one_line(message: &str) -> String {
    message
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty())
        .collect::<Vec<_>>()
        .join("; ")
}
