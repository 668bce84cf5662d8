//! Spelling suggestions for unknown keys: the same key in another case, the table it belongs in,
//! or the closest valid key.

use super::tables_of_format;

/// Levenshtein distance over characters.
pub(super) fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut cur = Vec::with_capacity(b.len() + 1);
        cur.push(i + 1);
        for (j, cb) in b.iter().enumerate() {
            let substitute =
                prev.get(j).copied().unwrap_or(usize::MAX - 1) + usize::from(ca != *cb);
            let delete = prev.get(j + 1).copied().unwrap_or(usize::MAX - 1) + 1;
            let insert = cur.last().copied().unwrap_or(usize::MAX - 1) + 1;
            cur.push(substitute.min(delete).min(insert));
        }
        prev = cur;
    }
    prev.last().copied().unwrap_or(0)
}

/// A hint for an unknown key in `table`: the same key in another case, the table it belongs in,
/// or the closest valid key within edit distance 2.
pub(super) fn suggestion(table: &str, key: &str) -> Option<String> {
    let lower = key.to_lowercase();
    let all = tables_of_format();
    let own: &[&str] = all
        .iter()
        .find(|(t, _)| *t == table)
        .map_or(&[], |(_, keys)| keys.as_slice());
    if let Some(k) = own.iter().find(|k| k.to_lowercase() == lower) {
        return Some(format!("did you mean `{k}`?"));
    }
    for (other, keys) in &all {
        if *other == table {
            continue;
        }
        if let Some(k) = keys.iter().find(|k| k.to_lowercase() == lower) {
            return Some(if other.is_empty() {
                format!("`{k}` belongs at the top level, before any table")
            } else {
                format!("`{k}` belongs in the `[{other}]` table")
            });
        }
    }
    suggestion_among(own, key)
}

/// The closest of `own` to `key` within edit distance 2 (ignoring case), as a hint.
pub(super) fn suggestion_among(own: &[&str], key: &str) -> Option<String> {
    let lower = key.to_lowercase();
    own.iter()
        .map(|k| (edit_distance(&lower, &k.to_lowercase()), *k))
        .filter(|(d, _)| *d <= 2)
        .min_by_key(|(d, _)| *d)
        .map(|(_, k)| format!("did you mean `{k}`?"))
}
