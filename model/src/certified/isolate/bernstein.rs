//! Bernstein subdivision on `[0, 1]`: the Bernstein coefficients enclosed as f64 midpoints with
//! radii bounding their rounding (in intervals above degree 56), bisected by de Casteljau's
//! algorithm, and Descartes' rule of signs for the Bernstein form deciding each node.

use super::local::{keeps_bits, split_point};
use super::*;

/// An exact integer as an interval (a point below 2^53, else the two nearest doubles).
pub(super) fn integer(v: u128) -> I {
    let x = v as f64;
    match (x as u128).cmp(&v) {
        std::cmp::Ordering::Equal => I::point(x),
        std::cmp::Ordering::Less => I::new(x, next_up(x)),
        std::cmp::Ordering::Greater => I::new(next_down(x), x),
    }
}

/// The rows of Pascal's triangle up to [`MAX_BERNSTEIN_DEGREE`], as intervals (exact below
/// 2^53; the entries are exact in u128), made once.
pub(super) fn pascal() -> &'static [Vec<I>] {
    static P: std::sync::OnceLock<Vec<Vec<I>>> = std::sync::OnceLock::new();
    P.get_or_init(|| {
        let mut row: Vec<u128> = vec![1];
        let mut rows = vec![vec![I::point(1.0)]];
        for j in 1..=MAX_BERNSTEIN_DEGREE {
            let mut next = vec![1u128; j + 1];
            for i in 1..j {
                next[i] = row[i - 1] + row[i];
            }
            rows.push(next.iter().map(|v| integer(*v)).collect());
            row = next;
        }
        rows
    })
}

/// The highest degree [`bernstein`] converts (binomials stay exact in u128).
pub(super) const MAX_BERNSTEIN_DEGREE: usize = 120;

/// The highest degree `Node::bernstein` converts in f64 (`C(56, 28) < 2^53`: every binomial of
/// these rows is an exact double).
pub(super) const MAX_F64_BERNSTEIN_DEGREE: usize = 56;

/// The Bernstein coefficients on `[0, 1]` of the polynomial with (ascending) coefficients `a`:
/// `b_j = sum_{i <= j} C(j, i) / C(n, i) a_i`.
pub(super) fn bernstein(a: &[I]) -> Option<Vec<I>> {
    let n = a.len() - 1;
    if n > MAX_BERNSTEIN_DEGREE {
        return None;
    }
    let rows = pascal();
    let scaled: Vec<I> = (0..=n)
        .map(|i| a[i].checked_div(rows[n][i]))
        .collect::<Option<_>>()?;
    Some(
        (0..=n)
            .map(|j| (0..=j).fold(I::point(0.0), |acc, i| acc + rows[j][i] * scaled[i]))
            .collect(),
    )
}

/// Sign changes of a sequence whose signs are all certain; `None` if some sign is not.
pub(super) fn variations(b: &[I]) -> Option<usize> {
    sign_changes(b.iter().map(|x| x.sign()))
}

/// Sign changes of a sequence of signs, all certain; `None` if some sign is not.
pub(super) fn sign_changes(signs: impl Iterator<Item = Option<f64>>) -> Option<usize> {
    let mut last = None;
    let mut v = 0;
    for s in signs {
        let s = s?;
        if last.is_some_and(|l| l != s) {
            v += 1;
        }
        last = Some(s);
    }
    Some(v)
}

/// Bernstein coefficients of a node of the bisection as f64 midpoints `m_j` and radii `r_j`:
/// the exact coefficient lies in `[m_j - r_j, m_j + r_j]`. De Casteljau's subdivision runs on
/// the midpoints in f64 and carries a bound on its rounding error in the radii, a few times
/// less work than the same subdivision in outward-rounded intervals.
///
/// The bisection keeps its nodes in one buffer ([`isolate_unit_ends`]): a `Node` borrows its
/// coefficients (`C = &[..]` or `&mut [..]`) or owns them (`Vec`, the root and the tests).
#[derive(Clone, Debug)]
pub(super) struct Node<C = Vec<(f64, f64)>> {
    /// `(m_j, r_j)`.
    pub(super) c: C,
}

/// A coefficient `(m, r)` as a node holds it: as computed when both are finite, else `(0, inf)`,
/// which no sign is claimed for. A sum that overflowed to an infinity says nothing about the
/// sign of the exact value (later terms of the other sign cannot bring it back), so every
/// computed coefficient passes through here.
pub(super) fn entry(m: f64, r: f64) -> (f64, f64) {
    if m.is_finite() && r.is_finite() {
        (m, r)
    } else {
        (0.0, f64::INFINITY)
    }
}

/// What each subdivision level adds to a radius for underflow, `2^-1072`: each of the five
/// products of a level (two for the midpoint, three for the radius) that underflows is off by
/// at most `2^-1075`, and sums of subnormals are exact, so a level loses at most `5 * 2^-1075`.
pub(super) const NODE_FLOOR: f64 = f64::from_bits(4);

impl Node {
    /// The node of the enclosed coefficients `b` (a radius is infinite, so no sign is certain,
    /// where an enclosure is not finite).
    pub(super) fn of(b: &[I]) -> Node {
        let c = b
            .iter()
            .map(|c| {
                let (m, r) = c.mid_rad();
                entry(m, r)
            })
            .collect();
        Node { c }
    }

    /// The node of the Bernstein coefficients on `[0, 1]` of the polynomial with enclosed
    /// ascending coefficients `a` (`None` beyond [`MAX_BERNSTEIN_DEGREE`]): [`bernstein`]'s
    /// `b_j = sum_(i <= j) C(j, i) s_i`, `s_i = a_i / C(n, i)`, computed in f64 on the
    /// midpoints up to degree [`MAX_F64_BERNSTEIN_DEGREE`] (every binomial exact), in intervals
    /// above.
    ///
    /// With midpoints `m_i`, radii `r_i` and `u = 2^-53`: `fl(m_i / C(n, i))` is off by at most
    /// `u |s_i|`, and the sum of `j + 1` exact-binomial products by at most
    /// `gamma_(j+1) sum C(j, i) |fl(s_i)|` (Higham, *Accuracy and Stability of Numerical
    /// Algorithms*, 2nd ed., eq. (3.5)), together at most `g = (n + 4) u` times that sum; the
    /// coefficients' radii add `sum C(j, i) r_i / C(n, i)`, and an underflowing quotient at
    /// most `2^-1075` per quotient or product. So `r_j = sum C(j, i) t_i` with
    /// `t_i = r_i / C(n, i) + g |fl(s_i)| + 2^-1073`, computed in f64 from nonnegative terms
    /// (at most `n + 7` roundings down) and multiplied by `1 + (2n + 16) u`, then rounded up.
    pub(super) fn bernstein(a: &[I]) -> Option<Node> {
        let n = a.len() - 1;
        if n > MAX_F64_BERNSTEIN_DEGREE {
            return bernstein(a).map(|b| Node::of(&b));
        }
        let rows = pascal();
        let u = f64::EPSILON / 2.0;
        let g = (n + 4) as f64 * u;
        // 2^-1073: the underflow of two quotients and a product.
        let tiny = f64::from_bits(2);
        let (s, t): (Vec<f64>, Vec<f64>) = Node::of(a)
            .c
            .iter()
            .zip(&rows[n])
            .map(|((m, r), c)| {
                // Binomials up to this degree are below 2^53: exact points.
                let s = m / c.lo;
                (s, r / c.lo + g * s.abs() + tiny)
            })
            .unzip();
        let grow = 1.0 + (2 * n + 16) as f64 * u;
        let c = (0..=n)
            .map(|j| {
                let row = &rows[j];
                let (mut m, mut r) = (0.0, 0.0);
                for i in 0..=j {
                    m += row[i].lo * s[i];
                    r += row[i].lo * t[i];
                }
                entry(m, next_up(r * grow))
            })
            .collect();
        Some(Node { c })
    }
}

impl<C: AsMut<[(f64, f64)]>> Node<C> {
    /// Coefficient `j` replaced by its enclosure's intersection with `e` (`None` when they
    /// are disjoint).
    pub(super) fn tighten(&mut self, j: usize, e: I) -> Option<()> {
        let c = self.c.as_mut();
        let (m, r) = c[j];
        let (cm, cr) = I::new(next_down(m - r), next_up(m + r))
            .intersect(e)?
            .mid_rad();
        c[j] = entry(cm, cr);
        Some(())
    }
}

impl<C: AsRef<[(f64, f64)]>> Node<C> {
    /// The coefficients.
    pub(super) fn coefs(&self) -> &[(f64, f64)] {
        self.c.as_ref()
    }

    /// The certain sign of coefficient `j` (`None` if its enclosure holds zero).
    pub(super) fn sign(&self, j: usize) -> Option<f64> {
        let (m, r) = self.coefs()[j];
        if !(m.is_finite() && r.is_finite()) {
            None
        } else if m > r {
            Some(1.0)
        } else if -m > r {
            Some(-1.0)
        } else {
            None
        }
    }

    /// A split weight in `(0, 1)` between the first two zero crossings of the control polygon
    /// (the points `(j / n, m_j)`), rounded to a multiple of 1/16, when there are two: the
    /// roots sit near the crossings, so splitting there tends to separate the first root
    /// from the others at once. A heuristic for speed only: any split is sound.
    pub(super) fn guide(&self) -> Option<f64> {
        let c = self.coefs();
        let n = (c.len() - 1) as f64;
        let mut crossings = c.windows(2).enumerate().filter_map(|(j, w)| {
            let (m0, m1) = (w[0].0, w[1].0);
            ((m0 < 0.0) != (m1 < 0.0) && m0 != m1).then(|| (j as f64 + m0 / (m0 - m1)) / n)
        });
        let (x1, x2) = (crossings.next()?, crossings.next()?);
        let t = (8.0 * (x1 + x2)).round() / 16.0;
        (t > 0.0 && t < 1.0).then_some(t)
    }

    /// Where in `[0, 1]` the control polygon (the points `(j / n, m_j)`) first crosses zero, a
    /// guess of the root of a node with one sign change (the crossing is within the square of
    /// the node's width of it as the node shrinks); NaN without a crossing. A heuristic only.
    pub(super) fn crossing(&self) -> f64 {
        let c = self.coefs();
        let n = (c.len() - 1) as f64;
        c.windows(2)
            .enumerate()
            .find_map(|(j, w)| {
                let (m0, m1) = (w[0].0, w[1].0);
                ((m0 < 0.0) != (m1 < 0.0) && m0 != m1).then(|| (j as f64 + m0 / (m0 - m1)) / n)
            })
            .unwrap_or(f64::NAN)
    }

    /// Sign changes of the coefficients, all of whose signs are certain; `None` if some sign
    /// is not.
    pub(super) fn variations(&self) -> Option<usize> {
        sign_changes((0..self.coefs().len()).map(|j| self.sign(j)))
    }

    /// De Casteljau's subdivision at `t` (a dyadic weight: `t` and `1 - t` exact): (left,
    /// right); `w` is working space.
    ///
    /// Each level replaces `w_j` by `(1 - t) w_j + t w_(j+1)`, a convex combination: the exact
    /// values stay within the same combination of the radii, and the computed midpoint is off
    /// from the combination of the midpoints by at most the rounding of two products and a
    /// sum, `u (|(1 - t) w_j| + |t w_(j+1)|) + u |sum| <= 2u (1 + u) max(|w_j|, |w_(j+1)|)`,
    /// plus underflow. So each level's radius is that combination of the radii plus
    /// `2.01 u max(|w_j|, |w_(j+1)|)` plus [`NODE_FLOOR`], all computed in f64 and then times
    /// `1 + 8u`, which covers the (at most five) roundings down of those nonnegative terms.
    #[cfg(test)]
    pub(super) fn split(&self, t: f64, w: &mut Vec<(f64, f64)>) -> (Node, Node) {
        let n = self.coefs().len();
        let (mut left, mut right) = (vec![(0.0, 0.0); n], vec![(0.0, 0.0); n]);
        self.split_into(t, w, &mut left, &mut right);
        (Node { c: left }, Node { c: right })
    }

    /// [`Node::split`] written into `left` and `right` (each as long as the node), without
    /// allocating: what the bisection runs.
    pub(super) fn split_into(
        &self,
        t: f64,
        w: &mut Vec<(f64, f64)>,
        left: &mut [(f64, f64)],
        right: &mut [(f64, f64)],
    ) {
        let n = self.coefs().len() - 1;
        w.clear();
        w.extend_from_slice(self.coefs());
        left[0] = w[0];
        right[n] = w[n];
        let (a, b) = (1.0 - t, t);
        let u = 2.01 * f64::EPSILON / 2.0;
        let grow = 1.0 + 8.0 * f64::EPSILON / 2.0;
        // The halves' coefficients pass through `entry` as they are written; the levels in
        // between need not: an infinity or NaN never turns finite again in these convex
        // combinations (positive weights, nonnegative radii), so it reaches the coefficient it
        // feeds, which `entry` then makes sign-free, as a level-by-level `entry` would.
        for level in 1..=n {
            for j in 0..=n - level {
                let ((m0, r0), (m1, r1)) = (w[j], w[j + 1]);
                let mu = m0.abs().max(m1.abs());
                w[j] = (
                    a * m0 + b * m1,
                    (a * r0 + b * r1 + u * mu + NODE_FLOOR) * grow,
                );
            }
            left[level] = entry(w[0].0, w[0].1);
            right[n - level] = entry(w[n - level].0, w[n - level].1);
        }
    }
}

/// The open sub-intervals `(tl, tr)` of `(0, 1)` holding exactly one root each, for a
/// polynomial (ascending coefficients `a`) with certain, nonzero values at 0 and 1.
pub(super) fn isolate_unit(a: &[I]) -> Result<Vec<Isolating>, Uncertified> {
    isolate_unit_within(a, MAX_NODES)
}

/// [`isolate_unit`] with a budget of `max_nodes` bisection nodes.
pub(super) fn isolate_unit_within(
    a: &[I],
    max_nodes: usize,
) -> Result<Vec<Isolating>, Uncertified> {
    isolate_unit_ends(a, max_nodes, (None, None))
}

/// [`isolate_unit_within`] with tighter enclosures of the values at 0 and 1 (`ends`), which
/// are the first and last Bernstein coefficients of every node that reaches that end.
pub(super) fn isolate_unit_ends(
    a: &[I],
    max_nodes: usize,
    ends: (Option<I>, Option<I>),
) -> Result<Vec<Isolating>, Uncertified> {
    let root = Node::bernstein(a).ok_or(Uncertified::Degenerate)?;
    let len = root.c.len();
    let n = len - 1;
    let tighten = |b: &mut Node<&mut [(f64, f64)]>, tl: f64, tr: f64| -> Result<(), Uncertified> {
        if let (0.0, Some(e)) = (tl, ends.0) {
            b.tighten(0, e).ok_or(Uncertified::Sign)?;
        }
        if let (1.0, Some(e)) = (tr, ends.1) {
            b.tighten(n, e).ok_or(Uncertified::Sign)?;
        }
        Ok(())
    };
    let mut out = Vec::new();
    // The nodes waiting, depth first: `stack[k]` holds the coefficients
    // `coefs[k * len..(k + 1) * len]` (every node has `len`), so a node is popped and its halves
    // pushed without allocating.
    let mut stack = vec![(0.0f64, 1.0f64, 0u32)];
    let mut coefs = root.c;
    tighten(&mut Node { c: &mut coefs[..] }, 0.0, 1.0)?;
    let mut nodes = 0usize;
    let (mut w, mut node) = (Vec::with_capacity(len), vec![(0.0, 0.0); len]);
    let (mut left, mut right) = (vec![(0.0, 0.0); len], vec![(0.0, 0.0); len]);
    while let Some((tl, tr, depth)) = stack.pop() {
        let top = coefs.len() - len;
        node.copy_from_slice(&coefs[top..]);
        coefs.truncate(top);
        tighten(&mut Node { c: &mut node[..] }, tl, tr)?;
        let b = Node { c: &node[..] };
        nodes += 1;
        if nodes > max_nodes || depth > MAX_DEPTH {
            return Err(Uncertified::Budget);
        }
        match b.variations() {
            Some(0) => continue,
            Some(1) => {
                out.push((tl, tr, tl + b.crossing() * (tr - tl)));
                continue;
            }
            _ => {}
        }
        // Split between the first two roots the control polygon suggests, else near the
        // middle; always where the value has a certain sign, so that no root sits on the split
        // point, and where the split point is exact.
        let at = |t: f64| split_point(tl, tr, t).map(|tm| (tm, t));
        let guided = b
            .guide()
            .and_then(at)
            .filter(|(tm, _)| keeps_bits(tl, *tm, tr));
        let mut split = None;
        for (tm, t) in guided.into_iter().chain(
            [0.5, 0.4375, 0.5625, 0.375, 0.625]
                .into_iter()
                .filter_map(at),
        ) {
            b.split_into(t, &mut w, &mut left, &mut right);
            if (Node { c: &left[..] }).sign(n).is_some() {
                split = Some(tm);
                break;
            }
        }
        let tm = split.ok_or(Uncertified::Sign)?;
        coefs.extend_from_slice(&right);
        stack.push((tm, tr, depth + 1));
        coefs.extend_from_slice(&left);
        stack.push((tl, tm, depth + 1));
    }
    out.sort_by(|x, y| x.0.total_cmp(&y.0));
    Ok(out)
}
