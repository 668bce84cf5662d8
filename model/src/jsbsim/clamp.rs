//! Table lookups beyond a table's breakpoints. JSBSim does not extrapolate a table: a key
//! outside its breakpoints reads the end value (the F-104's Mach tables, which end at Mach 2,
//! give Mach 5 their Mach-2 values). An import at such a state is still JSBSim's model, but its
//! numbers there are the edge of the data, so each lookup beyond a range is recorded during the
//! evaluation and reported as a warning: one per independent variable, naming the functions
//! whose tables it leaves, each table's range, and the variable's value.

use super::digits::short;
use super::evaluate::Functions;
use super::function::Expr;

/// What the warnings of an import begin with (the catalogue tells them from the loader's own).
pub const WARNING_START: &str = "the imported flight state";

/// One table lookup beyond the table's breakpoints.
#[derive(Clone, Debug, PartialEq)]
pub struct Clamp {
    /// The function whose expression holds the table (`None`: the reference point's shift).
    pub function: Option<usize>,
    /// The line of the `<table>` element.
    pub line: u32,
    /// The independent variable (its symbol).
    pub symbol: usize,
    /// Whether the table reads it negated (`-aero/beta-rad`): then `value` and `range` are
    /// those of the negated variable.
    pub negated: bool,
    /// Its value at the lookup.
    pub value: f64,
    /// The first and last breakpoint of that variable in the table.
    pub range: (f64, f64),
}

impl Clamp {
    /// Whether `other` is the same table left in the same variable.
    fn same_place(&self, other: &Clamp) -> bool {
        (self.line, self.symbol, self.negated, self.function)
            == (other.line, other.symbol, other.negated, other.function)
    }
}

/// Adds `clamp` to `clamps` unless its table and variable are there already.
pub fn record(clamps: &mut Vec<Clamp>, clamp: Clamp) {
    if !clamps.iter().any(|c| c.same_place(&clamp)) {
        clamps.push(clamp);
    }
}

/// Marks in `seen` every function that `e` reads, directly or through others.
fn mark_read(functions: &Functions, e: &Expr, seen: &mut [bool]) {
    let symbol = |s: usize, seen: &mut [bool]| {
        if let Some(f) = functions.defined_by[s] {
            if !seen[f] {
                seen[f] = true;
                mark_read(functions, &functions.list[f].expr, seen);
            }
        }
    };
    match e {
        Expr::Value(_) => {}
        Expr::Property(r) => symbol(r.symbol, seen),
        Expr::Table(t) => t.keys.iter().for_each(|r| symbol(r.symbol, seen)),
        Expr::Apply(_, args) => args.iter().for_each(|a| mark_read(functions, a, seen)),
    }
}

/// For each function, whether one of `roots` (function indices) or `extra` (an expression)
/// reads it, directly or through others; a root reads itself.
pub fn read_by(functions: &Functions, roots: &[usize], extra: Option<&Expr>) -> Vec<bool> {
    let mut seen = vec![false; functions.list.len()];
    for &f in roots {
        if !seen[f] {
            seen[f] = true;
            mark_read(functions, &functions.list[f].expr, &mut seen);
        }
    }
    if let Some(e) = extra {
        mark_read(functions, e, &mut seen);
    }
    seen
}

/// The name of the function (or element) that holds a table.
fn holder(functions: &Functions, clamp: &Clamp) -> String {
    match clamp.function {
        Some(f) => functions.list[f].name.clone(),
        None => "aero_ref_pt_shift_x".into(),
    }
}

/// The warnings of `clamps` (recorded at the import's state `place`, in words: altitude, Mach,
/// alpha): one per independent variable, its tables grouped by range. In order of the
/// variables' names, so that the same state always gives the same text.
pub fn warnings(clamps: &[Clamp], functions: &Functions, place: &str) -> Vec<String> {
    let mut variables: Vec<(usize, bool)> = clamps.iter().map(|c| (c.symbol, c.negated)).collect();
    variables.sort_by_key(|&(s, negated)| (functions.symbols.name(s), negated));
    variables.dedup();
    variables
        .into_iter()
        .map(|(s, negated)| {
            let of_symbol: Vec<&Clamp> = clamps
                .iter()
                .filter(|c| (c.symbol, c.negated) == (s, negated))
                .collect();
            let mut ranges: Vec<(f64, f64)> = of_symbol.iter().map(|c| c.range).collect();
            ranges.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
            ranges.dedup();
            let groups: Vec<String> = ranges
                .iter()
                .map(|&(lo, hi)| {
                    let mut names: Vec<String> = of_symbol
                        .iter()
                        .filter(|c| c.range == (lo, hi))
                        .map(|c| holder(functions, c))
                        .collect();
                    names.dedup();
                    format!("{} to {} in {}", short(lo), short(hi), names.join(", "))
                })
                .collect();
            let tables = of_symbol.len();
            format!(
                "{WARNING_START} ({place}) reads `{}{}` = {} beyond the breakpoints of {tables} \
                 table{}, where JSBSim holds the end value (no extrapolation): {}",
                if negated { "-" } else { "" },
                functions.symbols.name(s),
                short(of_symbol[0].value),
                if tables == 1 { "" } else { "s" },
                groups.join("; ")
            )
        })
        .collect()
}
