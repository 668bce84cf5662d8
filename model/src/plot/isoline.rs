//! The isoline of a field sampled on a rectangular grid, by marching squares: where a cell's
//! corners lie on both sides of the level, the line crosses the cell's edges at the points
//! found by linear interpolation along each edge, and the pieces are joined into polylines.
//! A cell with a corner missing (no value there) is skipped, so the line stops at the edge of
//! the data instead of guessing through a hole.
//!
//! Hand-written rather than taken from the `contour` crate: that crate (a port of d3-contour)
//! builds closed rings around the grid's border, has no notion of a missing value, and brings
//! `geo-types`; the envelope's maps need open lines that end where the data ends.
//!
//! ```
//! use model::plot::isoline::{isolines, Field};
//!
//! // z = x - 0.5 on a 2 x 2 grid: the level 0 crosses both horizontal edges at x = 0.5.
//! let field = Field {
//!     xs: vec![0.0, 1.0],
//!     ys: vec![0.0, 1.0],
//!     values: vec![Some(-0.5), Some(0.5), Some(-0.5), Some(0.5)],
//! };
//! assert_eq!(isolines(&field, 0.0), [vec![(0.5, 0.0), (0.5, 1.0)]]);
//! ```

use std::collections::BTreeMap;

/// A field on the grid `xs` by `ys` (each ascending): `values[j * xs.len() + i]` is the value
/// at `(xs[i], ys[j])`, `None` where there is none.
#[derive(Clone, Debug, PartialEq)]
pub struct Field {
    /// The grid's abscissae, ascending.
    pub xs: Vec<f64>,
    /// The grid's ordinates, ascending.
    pub ys: Vec<f64>,
    /// The values, row by row (`ys` outer, `xs` inner).
    pub values: Vec<Option<f64>>,
}

impl Field {
    /// The value at node `(i, j)`; `None` when missing, not finite or off the grid.
    fn at(&self, i: usize, j: usize) -> Option<f64> {
        if i >= self.xs.len() {
            return None;
        }
        let v = (*self.values.get(j * self.xs.len() + i)?)?;
        v.is_finite().then_some(v)
    }

    /// The node `(i, j)` in plot units.
    fn node(&self, (i, j): (usize, usize)) -> (f64, f64) {
        (self.xs[i], self.ys[j])
    }
}

/// A cell edge, named by its lower-left node and direction, so that the two cells sharing it
/// find the same crossing point.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Edge {
    /// From node `(i, j)` to `(i + 1, j)`.
    Across(usize, usize),
    /// From node `(i, j)` to `(i, j + 1)`.
    Up(usize, usize),
}

impl Edge {
    fn ends(self) -> ((usize, usize), (usize, usize)) {
        match self {
            Edge::Across(i, j) => ((i, j), (i + 1, j)),
            Edge::Up(i, j) => ((i, j), (i, j + 1)),
        }
    }
}

/// The polylines where the field equals `level`, in the grid's units. A line that closes on
/// itself repeats its first point at the end; a line that reaches the grid's border or a
/// missing value ends there. Nodes at or above the level count as above.
pub fn isolines(field: &Field, level: f64) -> Vec<Vec<(f64, f64)>> {
    let segments = segments(field, level);
    let mut at_edge: BTreeMap<Edge, Vec<usize>> = BTreeMap::new();
    for (k, (a, b)) in segments.iter().enumerate() {
        at_edge.entry(*a).or_default().push(k);
        at_edge.entry(*b).or_default().push(k);
    }
    let point = |e: Edge| crossing(field, e, level);
    let mut used = vec![false; segments.len()];
    let mut lines = Vec::new();
    // Open lines first, from an edge only one segment touches; then the closed ones.
    let ends: Vec<Edge> = at_edge
        .iter()
        .filter(|(_, ks)| ks.len() == 1)
        .map(|(e, _)| *e)
        .collect();
    let starts = ends.into_iter().chain(segments.iter().map(|s| s.0));
    for start in starts {
        let mut edges = vec![start];
        let mut here = start;
        while let Some(&k) = at_edge[&here].iter().find(|&&k| !used[k]) {
            used[k] = true;
            let (a, b) = segments[k];
            here = if a == here { b } else { a };
            edges.push(here);
        }
        if edges.len() > 1 {
            lines.push(edges.into_iter().map(point).collect());
        }
    }
    lines
}

/// The cells' pieces of the isoline, each as the two edges it joins.
fn segments(field: &Field, level: f64) -> Vec<(Edge, Edge)> {
    let (nx, ny) = (field.xs.len(), field.ys.len());
    let mut out = Vec::new();
    for j in 0..ny.saturating_sub(1) {
        for i in 0..nx.saturating_sub(1) {
            out.extend(cell(field, i, j, level));
        }
    }
    out
}

/// The pieces in cell `(i, j)` (nodes `(i, j)` to `(i + 1, j + 1)`): none when a corner is
/// missing or all corners lie on one side; two at a saddle, paired by the value at the centre
/// (the mean of the corners).
fn cell(field: &Field, i: usize, j: usize, level: f64) -> Vec<(Edge, Edge)> {
    let corners = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)];
    let Some(v) = corners
        .iter()
        .map(|&(a, b)| field.at(a, b))
        .collect::<Option<Vec<f64>>>()
    else {
        return Vec::new();
    };
    // Counter-clockwise from the bottom: edge k joins corners k and k + 1.
    let edges = [
        Edge::Across(i, j),
        Edge::Up(i + 1, j),
        Edge::Across(i, j + 1),
        Edge::Up(i, j),
    ];
    let above: Vec<bool> = v.iter().map(|&x| x >= level).collect();
    let crossed: Vec<Edge> = (0..4)
        .filter(|&k| above[k] != above[(k + 1) % 4])
        .map(|k| edges[k])
        .collect();
    match crossed.len() {
        2 => vec![(crossed[0], crossed[1])],
        4 => {
            // Corners 0 and 2 on one side, 1 and 3 on the other. If the centre sides with
            // corner 0, the region of corners 0 and 2 is joined through it and the line cuts
            // off corners 1 and 3; otherwise it cuts off corners 0 and 2.
            let centre_above = v.iter().sum::<f64>() / 4.0 >= level;
            if centre_above == above[0] {
                vec![(edges[0], edges[1]), (edges[2], edges[3])]
            } else {
                vec![(edges[3], edges[0]), (edges[1], edges[2])]
            }
        }
        _ => Vec::new(),
    }
}

/// Where the field crosses `level` on edge `e`, by linear interpolation between its ends.
fn crossing(field: &Field, e: Edge, level: f64) -> (f64, f64) {
    let (a, b) = e.ends();
    let (va, vb) = (field.at(a.0, a.1), field.at(b.0, b.1));
    let t = match (va, vb) {
        (Some(va), Some(vb)) if va != vb => ((level - va) / (vb - va)).clamp(0.0, 1.0),
        _ => 0.0,
    };
    let ((xa, ya), (xb, yb)) = (field.node(a), field.node(b));
    (xa + t * (xb - xa), ya + t * (yb - ya))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The field `f` sampled on `xs` by `ys`.
    fn sampled(xs: Vec<f64>, ys: Vec<f64>, f: impl Fn(f64, f64) -> Option<f64>) -> Field {
        let values = ys
            .iter()
            .flat_map(|&y| xs.iter().map(move |&x| (x, y)))
            .map(|(x, y)| f(x, y))
            .collect();
        Field { xs, ys, values }
    }

    fn steps(lo: f64, hi: f64, n: usize) -> Vec<f64> {
        (0..=n)
            .map(|k| lo + (hi - lo) * k as f64 / n as f64)
            .collect()
    }

    /// A plane is linear along every edge, so the interpolated line is exact: the level
    /// `x + 2 y = 3.05` on an uneven grid (through no node), every point on that line, one
    /// line from border to border with a point on each grid line it crosses.
    #[test]
    fn the_isoline_of_a_plane_is_the_exact_line() {
        let xs = vec![0.0, 0.3, 1.1, 1.5, 2.0, 2.9, 3.0];
        let ys = vec![0.0, 0.25, 0.5, 1.0, 1.2, 2.0];
        let field = sampled(xs.clone(), ys.clone(), |x, y| Some(x + 2.0 * y));
        let lines = isolines(&field, 3.05);
        assert_eq!(lines.len(), 1, "{lines:?}");
        let line = &lines[0];
        for &(x, y) in line {
            assert!((x + 2.0 * y - 3.05).abs() < 1e-12, "({x}, {y})");
        }
        // From the right border at y = 0.025 to the left border at y = 1.525.
        let near = |p: (f64, f64), q: (f64, f64)| (p.0 - q.0).abs() + (p.1 - q.1).abs() < 1e-12;
        let ends = [line[0], line[line.len() - 1]];
        assert!(ends.iter().any(|&p| near(p, (3.0, 0.025))), "{ends:?}");
        assert!(ends.iter().any(|&p| near(p, (0.0, 1.525))), "{ends:?}");
        // Between them, one point on each inner grid line crossed: x = 0.3, 1.1, 1.5, 2.0,
        // 2.9 and y = 0.25, 0.5, 1.0, 1.2.
        assert_eq!(line.len(), 5 + 4 + 2, "{line:?}");
    }

    /// A circle's isoline closes on itself and lies within the interpolation error of the
    /// circle.
    #[test]
    fn the_isoline_of_a_circle_is_one_closed_line_near_the_circle() {
        let (r, n) = (1.0, 40);
        let h = 3.0 / n as f64;
        let grid = steps(-1.5, 1.5, n);
        let field = sampled(grid.clone(), grid, |x, y| Some(x * x + y * y));
        let lines = isolines(&field, r * r);
        assert_eq!(lines.len(), 1);
        let line = &lines[0];
        assert_eq!(line[0], line[line.len() - 1], "closed");
        // Along an edge, x^2 + y^2 minus its linear interpolant is (s - a)(s - b) for the
        // edge's ends a and b, between -h^2 / 4 and 0: each point lies inside the circle, by at
        // most r - sqrt(r^2 - h^2 / 4).
        let bound = r - (r * r - h * h / 4.0).sqrt() + 1e-12;
        for &(x, y) in line {
            let miss = r - (x * x + y * y).sqrt();
            assert!(
                (-1e-12..=bound).contains(&miss),
                "({x}, {y}) misses by {miss}"
            );
        }
        // Every crossing is on a grid line.
        for &(x, y) in line {
            let on = field.xs.contains(&x) || field.ys.contains(&y);
            assert!(on, "({x}, {y}) is on no grid line");
        }
    }

    /// Cells with a missing corner are skipped: the plane's line through a hole of missing
    /// nodes breaks into two lines, none with a point inside a cell that touches the hole.
    #[test]
    fn a_missing_value_stops_the_line_at_the_cells_around_it() {
        let grid = steps(0.0, 4.0, 4);
        let hole = |x: f64, y: f64| x == 2.0 && y == 2.0;
        let field = sampled(grid.clone(), grid, |x, y| (!hole(x, y)).then_some(x - 2.3));
        let lines = isolines(&field, 0.0);
        assert_eq!(lines.len(), 2, "{lines:?}");
        for &(x, y) in lines.iter().flatten() {
            assert!((x - 2.3).abs() < 1e-12);
            assert!(
                y <= 1.0 || y >= 3.0,
                "({x}, {y}) in a cell touching the hole"
            );
        }
        // Not finite counts as missing.
        let mut nan = field.clone();
        nan.values[2 * 5 + 2] = Some(f64::NAN);
        assert_eq!(isolines(&nan, 0.0), lines);
    }

    /// The lines with their points in order and in the order of their first points, to compare
    /// lines whatever their direction.
    fn ordered(mut lines: Vec<Vec<(f64, f64)>>) -> Vec<Vec<(f64, f64)>> {
        for l in &mut lines {
            l.sort_by(|a, b| a.partial_cmp(b).unwrap());
        }
        lines.sort_by(|a, b| a[0].partial_cmp(&b[0]).unwrap());
        lines
    }

    /// A saddle cell is resolved by its centre: corners 0 and 2 high, 1 and 3 low.
    #[test]
    fn a_saddle_pairs_its_crossings_by_the_centre_value() {
        let field = |centre_high: bool| {
            let (hi, lo) = if centre_high {
                (3.0, -1.0)
            } else {
                (1.0, -3.0)
            };
            Field {
                xs: vec![0.0, 1.0],
                ys: vec![0.0, 1.0],
                values: vec![Some(hi), Some(lo), Some(lo), Some(hi)],
            }
        };
        // Values at nodes (0,0) and (1,1) are high. With a high centre they are joined and
        // the two lines cut off the low corners (1, 0) and (0, 1).
        assert_eq!(
            ordered(isolines(&field(true), 0.0)),
            [
                vec![(0.0, 0.75), (0.25, 1.0)],
                vec![(0.75, 0.0), (1.0, 0.25)]
            ]
        );
        assert_eq!(
            ordered(isolines(&field(false), 0.0)),
            [
                vec![(0.0, 0.25), (0.25, 0.0)],
                vec![(0.75, 1.0), (1.0, 0.75)]
            ]
        );
    }

    /// Nothing crosses the level, or a grid of one row has no cells: no line.
    #[test]
    fn no_line_where_nothing_crosses() {
        let grid = steps(0.0, 1.0, 3);
        let field = sampled(grid.clone(), grid.clone(), |x, y| Some(x + y));
        assert!(isolines(&field, 5.0).is_empty());
        let row = sampled(grid, vec![0.0], |x, _| Some(x - 0.5));
        assert!(isolines(&row, 0.0).is_empty());
    }
}
