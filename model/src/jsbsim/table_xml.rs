//! Reading a `<table>` element: its `<independentVar>`s (`lookup="row"`, `"column"`, `"table"`)
//! and its `<tableData>` (one block, or one per `breakPoint` of the third variable), checking the
//! shape (every row as long as the header plus one, keys strictly increasing).

use super::error::JsbsimError;
use super::function::{property_ref, Symbols, Table};
use super::table::TableData;
use super::xml::{children, parse_number, Source};
use roxmltree::Node;

/// The `<table>` element `node`.
pub fn parse_table(src: Source, node: Node, symbols: &mut Symbols) -> Result<Table, JsbsimError> {
    let mut keys: [Option<_>; 3] = [None, None, None];
    for var in children(node, "independentVar") {
        let axis = match var.attribute("lookup").unwrap_or("row").trim() {
            "row" | "" | "axis1" => 0,
            "column" | "axis2" => 1,
            "table" | "axis3" => 2,
            other => {
                return Err(src.error(
                    var,
                    format!("lookup `{other}` not understood (expected row, column or table)"),
                ))
            }
        };
        if keys[axis].is_some() {
            return Err(src.error(var, "the same lookup axis is given twice"));
        }
        keys[axis] = Some(property_ref(src, var, symbols)?);
    }
    let blocks: Vec<Node> = children(node, "tableData").collect();
    let data = match blocks.as_slice() {
        [] => return Err(src.error(node, "no <tableData> (expected the table's data)")),
        [one] if one.attribute("breakPoint").is_none() => {
            let declared = keys.iter().filter(|k| k.is_some()).count();
            leaf(src, *one, declared == 1)?
        }
        many => three(src, many)?,
    };
    let n = data.dimension();
    let keys: Vec<_> = keys.iter().take(n).copied().collect::<Option<_>>().ok_or_else(|| {
        src.error(
            node,
            format!("a table of {n} independent variables needs {n} <independentVar>s (row, column, table)"),
        )
    })?;
    Ok(Table {
        keys,
        data,
        line: src.line(node),
    })
}

/// A three-variable table: one two-variable block per `breakPoint`.
fn three(src: Source, blocks: &[Node]) -> Result<TableData, JsbsimError> {
    let mut breakpoints = Vec::new();
    let mut tables = Vec::new();
    for block in blocks {
        let bp = block.attribute("breakPoint").ok_or_else(|| {
            src.error(
                *block,
                "several <tableData> blocks need a breakPoint attribute each",
            )
        })?;
        let bp = parse_number(bp.trim())
            .ok_or_else(|| src.error(*block, format!("breakPoint `{bp}` is not a number")))?;
        if breakpoints.last().is_some_and(|&last| bp <= last) {
            return Err(src.error(*block, "breakPoints must increase strictly"));
        }
        let table = leaf(src, *block, false)?;
        if table.dimension() != 2 {
            return Err(src.error(
                *block,
                "each breakPoint's data must be a table of two variables",
            ));
        }
        breakpoints.push(bp);
        tables.push(table);
    }
    Ok(TableData::Three {
        breakpoints,
        tables,
    })
}

/// The numbers of each non-empty line of `node`'s text (comments between the lines skipped).
fn lines(src: Source, node: Node) -> Result<Vec<Vec<f64>>, JsbsimError> {
    let mut rows = Vec::new();
    for text in node.children().filter(|c| c.is_text()) {
        let first = src.line(text);
        for (k, line) in text.text().unwrap_or("").lines().enumerate() {
            let mut row = Vec::new();
            for token in line.split_whitespace() {
                let v = parse_number(token).ok_or_else(|| {
                    JsbsimError::new(
                        src.file,
                        first + k as u32,
                        "tableData",
                        format!("`{token}` is not a number"),
                    )
                })?;
                row.push(v);
            }
            if !row.is_empty() {
                rows.push(row);
            }
        }
    }
    Ok(rows)
}

/// Whether `keys` increase strictly.
fn increasing(keys: &[f64]) -> bool {
    keys.windows(2).all(|w| w[0] < w[1])
}

/// One block of data: two numbers a line (one variable, always so when `one` says the table
/// declares one independent variable) or a header of column keys and rows one longer (two
/// variables).
fn leaf(src: Source, node: Node, one: bool) -> Result<TableData, JsbsimError> {
    let rows = lines(src, node)?;
    let bad = |msg: String| src.error(node, msg);
    if rows.is_empty() {
        return Err(bad("empty table data".into()));
    }
    if one {
        if let Some((k, r)) = rows.iter().enumerate().find(|(_, r)| r.len() != 2) {
            return Err(bad(format!(
                "data line {} has {} numbers (expected 2 in a table of one variable: key and value)",
                k + 1,
                r.len()
            )));
        }
    }
    let width = rows[0].len();
    let data = if width == 2 && rows.iter().all(|r| r.len() == 2) {
        TableData::One {
            keys: rows.iter().map(|r| r[0]).collect(),
            values: rows.iter().map(|r| r[1]).collect(),
        }
    } else {
        if rows.len() < 2 {
            return Err(bad(
                "a two-variable table needs a header line and at least one row".into(),
            ));
        }
        if let Some((k, r)) = rows
            .iter()
            .enumerate()
            .skip(1)
            .find(|(_, r)| r.len() != width + 1)
        {
            return Err(bad(format!(
                "data line {} has {} numbers (expected {}: the row key and one value per column)",
                k + 1,
                r.len(),
                width + 1
            )));
        }
        TableData::Two {
            rows: rows[1..].iter().map(|r| r[0]).collect(),
            cols: rows[0].clone(),
            values: rows[1..].iter().map(|r| r[1..].to_vec()).collect(),
        }
    };
    let ok = match &data {
        TableData::One { keys, .. } => increasing(keys),
        TableData::Two { rows, cols, .. } => increasing(rows) && increasing(cols),
        TableData::Three { .. } => true,
    };
    if !ok {
        return Err(bad("the table's keys must increase strictly".into()));
    }
    Ok(data)
}
