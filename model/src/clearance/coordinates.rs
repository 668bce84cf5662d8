//! The box of uncertain data and its coordinates: how each coordinate moves the aircraft's
//! parameters, the aircraft at exact coordinates, f64 coordinates clamped into the box as exact
//! values, and uniform random aircraft of the box (seeded).

use crate::aircraft::{Aircraft, Param, Uncertain};
use crate::interval::I;
use num_rational::BigRational;

/// How one coordinate of a box enters the data, enclosed: what the branch and bound
/// ([`super::bound::BoxPolys`]) and the Monte Carlo ([`super::monte_carlo::run`]) both build on.
#[derive(Clone, Debug)]
pub(crate) enum Coordinate {
    /// The value of a parameter.
    Param(Param),
    /// A coefficient of a nondimensional file: each parameter `p` it moves is its fixed value
    /// plus `a_p (x - nominal)` (enclosures of the exact `a_p` and nominal).
    Coefficient { nominal: I, moves: Vec<(Param, I)> },
}

impl Coordinate {
    /// The coordinate of an uncertain entry.
    pub(crate) fn of(u: &Uncertain) -> Coordinate {
        match &u.coefficient {
            None => Coordinate::Param(u.param),
            Some(c) => Coordinate::Coefficient {
                nominal: I::from_q(&c.nominal),
                moves: c.moves.iter().map(|(p, a)| (*p, I::from_q(a))).collect(),
            },
        }
    }

    /// The parameters it moves.
    pub(crate) fn params(&self) -> Vec<Param> {
        match self {
            Coordinate::Param(p) => vec![*p],
            Coordinate::Coefficient { moves, .. } => moves.iter().map(|(p, _)| *p).collect(),
        }
    }
}

/// The box of an aircraft: its uncertain parameters of nonzero width with their exact ends, and
/// the aircraft with every zero-width parameter set to its value.
pub fn split_box(aircraft: &Aircraft) -> (Aircraft, Vec<Uncertain>) {
    let mut base = aircraft.clone();
    let mut wide = Vec::new();
    for u in &aircraft.uncertainty {
        if u.lo == u.hi {
            base = u.moved(base, &u.lo);
        } else {
            wide.push(u.clone());
        }
    }
    base.uncertainty = Vec::new();
    (base, wide)
}

/// The aircraft at exact coordinates `x` of the box.
pub fn at(base: &Aircraft, params: &[Uncertain], x: &[BigRational]) -> Aircraft {
    params
        .iter()
        .zip(x)
        .fold(base.clone(), |a, (u, v)| u.moved(a, v))
}

/// f64 coordinates of the box as exact values within the exact ends ([`clamp_exact`] each).
pub fn exact_coordinates(params: &[Uncertain], x: &[f64]) -> Vec<BigRational> {
    params
        .iter()
        .zip(x)
        .map(|(u, v)| clamp_exact(u, *v))
        .collect()
}

/// An f64 coordinate of the box as an exact value within the exact ends.
pub fn clamp_exact(u: &Uncertain, v: f64) -> BigRational {
    let q = BigRational::from_float(v).unwrap_or_else(|| u.lo.clone());
    if q < u.lo {
        u.lo.clone()
    } else if q > u.hi {
        u.hi.clone()
    } else {
        q
    }
}

/// The seeded generator of the samples and candidates.
pub use crate::random::Rng;

/// A uniform random aircraft of the box.
pub fn sample(base: &Aircraft, params: &[Uncertain], rng: &mut Rng) -> Aircraft {
    at(base, params, &sample_coordinates(params, rng))
}

/// Uniform random (exact) coordinates in the box.
pub fn sample_coordinates(params: &[Uncertain], rng: &mut Rng) -> Vec<BigRational> {
    params
        .iter()
        .map(|u| {
            let b = I::from_q_pair(&u.lo, &u.hi);
            clamp_exact(u, b.lo + rng.unit() * (b.hi - b.lo))
        })
        .collect()
}
