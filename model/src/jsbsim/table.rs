//! JSBSim's lookup tables (`<table>`) of one, two and three independent variables: linear
//! interpolation between breakpoints, clamped at the ends (no extrapolation), bilinear over rows
//! and columns, and linear between the two-variable tables at the `breakPoint`s of the third.

/// A table's data, by its number of independent variables.
#[derive(Clone, Debug, PartialEq)]
pub enum TableData {
    /// One independent variable.
    One {
        /// Breakpoints, increasing.
        keys: Vec<f64>,
        /// The value at each breakpoint.
        values: Vec<f64>,
    },
    /// Two independent variables.
    Two {
        /// Row keys, increasing.
        rows: Vec<f64>,
        /// Column keys, increasing.
        cols: Vec<f64>,
        /// The values, row by row.
        values: Vec<Vec<f64>>,
    },
    /// Three independent variables.
    Three {
        /// Breakpoints of the third variable, increasing.
        breakpoints: Vec<f64>,
        /// A two-variable table at each breakpoint.
        tables: Vec<TableData>,
    },
}

/// Where `key` falls among increasing `keys`: the lower index and the weight of the upper one,
/// clamped to the ends (a key outside the range takes the end value).
#[inline]
fn bracket(keys: &[f64], key: f64) -> (usize, f64) {
    let n = keys.len();
    if n == 1 || key <= keys[0] {
        return (0, 0.0);
    }
    if key >= keys[n - 1] {
        return (n - 2, 1.0);
    }
    // The breakpoints below the key, counted without branches: the catalogue's tables have a
    // few dozen at most, where this beats a binary search's mispredicted branches (the
    // simulation looks tables up at every step).
    let below: usize = keys.iter().map(|&k| usize::from(k < key)).sum();
    let i = below.max(1) - 1;
    (i, (key - keys[i]) / (keys[i + 1] - keys[i]))
}

/// Linear interpolation of `values` at `(i, t)` from [`bracket`].
fn interpolate(values: &[f64], (i, t): (usize, f64)) -> f64 {
    if values.len() == 1 {
        return values[0];
    }
    values[i] + t * (values[i + 1] - values[i])
}

impl TableData {
    /// The number of independent variables.
    pub fn dimension(&self) -> usize {
        match self {
            TableData::One { .. } => 1,
            TableData::Two { .. } => 2,
            TableData::Three { .. } => 3,
        }
    }

    /// The table's value at `keys` (row, column, table), clamped at the ends.
    pub fn lookup(&self, keys: &[f64]) -> f64 {
        match self {
            TableData::One { keys: k, values } => interpolate(values, bracket(k, keys[0])),
            TableData::Two { rows, cols, values } => {
                let (r, tr) = bracket(rows, keys[0]);
                let c = bracket(cols, keys[1]);
                let lo = interpolate(&values[r], c);
                if rows.len() == 1 {
                    return lo;
                }
                let hi = interpolate(&values[r + 1], c);
                lo + tr * (hi - lo)
            }
            TableData::Three {
                breakpoints,
                tables,
            } => {
                let (b, t) = bracket(breakpoints, keys[2]);
                let lo = tables[b].lookup(keys);
                if tables.len() == 1 {
                    return lo;
                }
                let hi = tables[b + 1].lookup(keys);
                lo + t * (hi - lo)
            }
        }
    }

    /// For each independent variable (row, column, table) whose key in `keys` lies outside the
    /// breakpoints that the lookup uses, those breakpoints' first and last: where [`lookup`]
    /// holds the end value. A three-variable table checks the row and column keys against the
    /// two-variable tables it interpolates between.
    ///
    /// [`lookup`]: TableData::lookup
    pub fn outside(&self, keys: &[f64]) -> [Option<(f64, f64)>; 3] {
        let beyond = |k: &[f64], key: f64| {
            let (lo, hi) = (k[0], k[k.len() - 1]);
            (key < lo || key > hi).then_some((lo, hi))
        };
        match self {
            TableData::One { keys: k, .. } => [beyond(k, keys[0]), None, None],
            TableData::Two { rows, cols, .. } => {
                [beyond(rows, keys[0]), beyond(cols, keys[1]), None]
            }
            TableData::Three {
                breakpoints,
                tables,
            } => {
                let (b, t) = bracket(breakpoints, keys[2]);
                let upper = (t > 0.0 && b + 1 < tables.len()).then(|| &tables[b + 1]);
                let mut out = [None, None, beyond(breakpoints, keys[2])];
                for inner in std::iter::once(&tables[b]).chain(upper) {
                    let [r, c, _] = inner.outside(keys);
                    out[0] = out[0].or(r);
                    out[1] = out[1].or(c);
                }
                out
            }
        }
    }

    /// The breakpoints of independent variable `axis` (0 row, 1 column, 2 table).
    pub fn breakpoints(&self, axis: usize) -> Vec<f64> {
        match (self, axis) {
            (TableData::One { keys, .. }, 0) => keys.clone(),
            (TableData::Two { rows, .. }, 0) => rows.clone(),
            (TableData::Two { cols, .. }, 1) => cols.clone(),
            (TableData::Three { breakpoints, .. }, 2) => breakpoints.clone(),
            (TableData::Three { tables, .. }, a) => {
                let mut all: Vec<f64> = tables.iter().flat_map(|t| t.breakpoints(a)).collect();
                all.sort_by(f64::total_cmp);
                all.dedup();
                all
            }
            _ => Vec::new(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_variable_interpolates_and_clamps() {
        let t = TableData::One {
            keys: vec![0.0, 1.0, 3.0],
            values: vec![1.0, 3.0, -1.0],
        };
        assert_eq!(t.lookup(&[0.5]), 2.0);
        assert_eq!(t.lookup(&[2.0]), 1.0);
        assert_eq!(t.lookup(&[-5.0]), 1.0);
        assert_eq!(t.lookup(&[9.0]), -1.0);
        assert_eq!(t.lookup(&[1.0]), 3.0);
    }

    #[test]
    fn two_variables_are_bilinear_and_clamped() {
        let t = TableData::Two {
            rows: vec![0.0, 1.0],
            cols: vec![0.0, 2.0],
            values: vec![vec![0.0, 2.0], vec![10.0, 12.0]],
        };
        assert_eq!(t.lookup(&[0.5, 1.0]), 6.0);
        assert_eq!(t.lookup(&[2.0, -1.0]), 10.0);
        assert_eq!(t.lookup(&[-1.0, 5.0]), 2.0);
    }

    #[test]
    fn keys_beyond_the_breakpoints_are_named_with_the_range() {
        let t = TableData::Two {
            rows: vec![0.0, 1.0],
            cols: vec![0.0, 2.0],
            values: vec![vec![0.0, 2.0], vec![10.0, 12.0]],
        };
        assert_eq!(t.outside(&[0.5, 1.0]), [None, None, None]);
        assert_eq!(t.outside(&[1.0, 0.0]), [None, None, None]);
        assert_eq!(
            t.outside(&[2.0, -1.0]),
            [Some((0.0, 1.0)), Some((0.0, 2.0)), None]
        );
        let three = TableData::Three {
            breakpoints: vec![0.0, 4.0],
            tables: vec![t.clone(), t],
        };
        assert_eq!(
            three.outside(&[0.5, 3.0, 5.0])[1..],
            [Some((0.0, 2.0)), Some((0.0, 4.0))]
        );
    }

    #[test]
    fn three_variables_interpolate_between_breakpoints() {
        let flat = |v: f64| TableData::Two {
            rows: vec![0.0, 1.0],
            cols: vec![0.0, 1.0],
            values: vec![vec![v, v], vec![v, v]],
        };
        let t = TableData::Three {
            breakpoints: vec![0.0, 4.0],
            tables: vec![flat(1.0), flat(5.0)],
        };
        assert_eq!(t.lookup(&[0.3, 0.3, 1.0]), 2.0);
        assert_eq!(t.lookup(&[0.3, 0.3, 8.0]), 5.0);
    }
}
