//! Nondimensional body-axis coefficients to the dimensional principal-axis derivatives of the
//! model (the formulas are in `docs/nondimensional.md`).
//!
//! Engineers hold coefficients per rad in body axes (DATCOM, wind tunnel, CFD), a product of
//! inertia `ixz`, a flight condition and a geometry; the PSS model of the paper wants dimensional
//! derivatives in principal axes. The conversion, with qbar = rho V^2 / 2 and rates made
//! nondimensional as p b/(2V), q c/(2V), r b/(2V):
//!
//! - z_alpha = -qbar S CL_alpha / (m V), y_beta = qbar S CY_beta / (m V);
//! - body moments L = qbar S b Cl (beta, controls), qbar S b (b/2V) Cl (p, r), the same for N
//!   with Cn, M_alpha = qbar S c Cm_alpha, M_q = qbar S c (c/2V) Cm_q, M_delta_e = qbar S c Cm_delta_e;
//! - principal axes: the eigenvectors of [[ix, -ixz], [-ixz, iz]] in the x-z plane, x_p the one
//!   nearest body x pointing forward, z_p pointing down, R = [x_p z_p]; the rate block
//!   [[L_p, L_r], [N_p, N_r]] becomes R^T [[..]] R, each (L, N) of beta, delta_a and delta_r
//!   becomes R^T (L, N); L is divided by the principal ix', N by iz', M by iy.
//!
//! Precision: every step is exact rational arithmetic on the literals of the file, except two
//! irrational quantities: the ISA density of `flight.altitude` (a power with a non-integer
//! exponent) and, when `ixz != 0`, the cosine and sine of the principal-axis tilt (a square root).
//! Those are computed in f64 and enter as the exact rationals of their shortest round-trip
//! decimals; the results are then rounded once each to the nearest f64 ([`Converted::rounded`]),
//! so they are within about 1e-16 relative of the exact conversion (the rotation is orthogonal to
//! within 1e-16, and the product of inertia left in the principal axes is of order 1e-16 (iz - ix)).
//! With `density` given and `ixz = 0` the conversion is exact.
//!
//! ```
//! use model::aircraft::convert::isa_density;
//!
//! // The ISA: 1.225 kg/m^3 at sea level, 0.3639 kg/m^3 at the tropopause (11 km).
//! assert!((isa_density(0.0) - 1.225).abs() < 1e-3);
//! assert!((isa_density(11_000.0) - 0.3639).abs() < 1e-4);
//! ```

use super::{f64_to_rational, rational_to_f64, Param};
use num_rational::BigRational;
use num_traits::{One, Zero};

mod dimensional_toml;
mod isa;
mod unreduced;

use unreduced::Unreduced;

pub use dimensional_toml::toml_number;
pub use isa::{isa_density, ISA_G0_M_S2, ISA_LAPSE_K_M, ISA_P0_PA, ISA_R_J_KG_K, ISA_T0_K};

/// A nondimensional coefficient of the `[coefficients]` table, per rad.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(missing_docs)]
pub enum Coefficient {
    CLAlpha,
    CYBeta,
    ClBeta,
    ClP,
    ClR,
    ClDeltaA,
    ClDeltaR,
    CmAlpha,
    CmQ,
    CmDeltaE,
    CnBeta,
    CnP,
    CnR,
    CnDeltaA,
    CnDeltaR,
}

impl Coefficient {
    /// All coefficients, in the order of [`BodyAxisInput::coefficients`].
    pub const ALL: [Coefficient; 15] = [
        Coefficient::CLAlpha,
        Coefficient::CYBeta,
        Coefficient::ClBeta,
        Coefficient::ClP,
        Coefficient::ClR,
        Coefficient::ClDeltaA,
        Coefficient::ClDeltaR,
        Coefficient::CmAlpha,
        Coefficient::CmQ,
        Coefficient::CmDeltaE,
        Coefficient::CnBeta,
        Coefficient::CnP,
        Coefficient::CnR,
        Coefficient::CnDeltaA,
        Coefficient::CnDeltaR,
    ];

    /// The derivative of the model this coefficient scales (the one it moves alone when
    /// `ixz = 0`; see [`convert`]).
    pub fn derivative(self) -> Param {
        match self {
            Coefficient::CLAlpha => Param::ZAlpha,
            Coefficient::CYBeta => Param::YBeta,
            Coefficient::ClBeta => Param::LBeta,
            Coefficient::ClP => Param::Lp,
            Coefficient::ClR => Param::Lr,
            Coefficient::ClDeltaA => Param::LDeltaA,
            Coefficient::ClDeltaR => Param::LDeltaR,
            Coefficient::CmAlpha => Param::MAlpha,
            Coefficient::CmQ => Param::Mq,
            Coefficient::CmDeltaE => Param::MDeltaE,
            Coefficient::CnBeta => Param::NBeta,
            Coefficient::CnP => Param::Np,
            Coefficient::CnR => Param::Nr,
            Coefficient::CnDeltaA => Param::NDeltaA,
            Coefficient::CnDeltaR => Param::NDeltaR,
        }
    }

    /// The TOML key.
    pub fn key(self) -> &'static str {
        match self {
            Coefficient::CLAlpha => "CL_alpha",
            Coefficient::CYBeta => "CY_beta",
            Coefficient::ClBeta => "Cl_beta",
            Coefficient::ClP => "Cl_p",
            Coefficient::ClR => "Cl_r",
            Coefficient::ClDeltaA => "Cl_delta_a",
            Coefficient::ClDeltaR => "Cl_delta_r",
            Coefficient::CmAlpha => "Cm_alpha",
            Coefficient::CmQ => "Cm_q",
            Coefficient::CmDeltaE => "Cm_delta_e",
            Coefficient::CnBeta => "Cn_beta",
            Coefficient::CnP => "Cn_p",
            Coefficient::CnR => "Cn_r",
            Coefficient::CnDeltaA => "Cn_delta_a",
            Coefficient::CnDeltaR => "Cn_delta_r",
        }
    }
}

/// Air density: given (exact) or from an ISA altitude.
#[derive(Clone, Debug, PartialEq)]
pub enum Density {
    /// `flight.density`, kg/m^3.
    Given(BigRational),
    /// `flight.altitude`, m (ISA troposphere, 0 to 11 km).
    Altitude(f64),
}

/// The data of a nondimensional body-axis file, checked by the loader (SI units, per rad).
#[derive(Clone, Debug, PartialEq)]
pub struct BodyAxisInput {
    /// Flight speed V, m/s.
    pub speed: BigRational,
    /// Air density.
    pub density: Density,
    /// Mass m, kg.
    pub mass: BigRational,
    /// Wing area S, m^2.
    pub wing_area: BigRational,
    /// Wing span b, m.
    pub span: BigRational,
    /// Mean aerodynamic chord c, m.
    pub chord: BigRational,
    /// Body-axis moment of inertia about x, kg m^2.
    pub ix: BigRational,
    /// Moment of inertia about y, kg m^2.
    pub iy: BigRational,
    /// Body-axis moment of inertia about z, kg m^2.
    pub iz: BigRational,
    /// Body-axis product of inertia (the integral of x z dm), kg m^2.
    pub ixz: BigRational,
    /// The coefficients in [`Coefficient::ALL`] order, per rad.
    pub coefficients: Vec<BigRational>,
    /// The body-axis angle of attack of the trim the coefficients were taken at, rad; `None`
    /// puts the principal axis on the flight path (the paper's convention).
    pub trim_alpha: Option<BigRational>,
    /// The load factor n of that trim (lift = n times weight); 0 for a zero-lift reference.
    pub load_factor: BigRational,
}

impl BodyAxisInput {
    /// One coefficient.
    pub fn coefficient(&self, c: Coefficient) -> &BigRational {
        &self.coefficients[c as usize]
    }
}

/// The dimensional principal-axis data equivalent to a [`BodyAxisInput`].
#[derive(Clone, Debug, PartialEq)]
pub struct Converted {
    /// Principal moments ix', iy, iz', kg m^2.
    pub principal: [BigRational; 3],
    /// The derivatives in [`Param::ALL`] order after C, D, E (z_alpha ... alpha_t).
    pub derivatives: Vec<BigRational>,
    /// Angle of the principal x axis below the body x axis, deg (positive: x_p points forward
    /// and down, as for the usual positive ixz with iz > ix).
    pub tilt_deg: f64,
    /// Whether the values went through f64 (ISA density or a rotation) and were rounded once each
    /// to the nearest f64; false when the conversion is exact.
    pub rounded: bool,
    /// The density used, kg/m^3 (for the output's comment).
    pub density: f64,
    /// Where the density came from, for the output's comment.
    pub density_source: String,
    /// Flight speed, m/s, exact.
    pub speed: BigRational,
}

impl Converted {
    /// The speed rounded to f64, m/s.
    pub fn speed_f64(&self) -> f64 {
        rational_to_f64(&self.speed)
    }

    /// The value of one derivative (z_alpha ... alpha_t).
    pub fn derivative(&self, p: Param) -> &BigRational {
        &self.derivatives[p.index() - 3]
    }
}

fn q(x: f64) -> BigRational {
    // Only finite values reach here: cos, sin and an ISA density of checked inputs.
    f64_to_rational(x).unwrap_or_else(BigRational::zero)
}

/// The principal-axis tilt, rad: tan 2 eps = 2 ixz / (iz - ix), |eps| <= 45 deg (x_p nearest body
/// x); 45 deg towards the sign of ixz when ix = iz.
fn tilt(ix: f64, iz: f64, ixz: f64) -> f64 {
    if ixz == 0.0 {
        0.0
    } else if iz == ix {
        std::f64::consts::FRAC_PI_4.copysign(ixz)
    } else {
        0.5 * (2.0 * ixz / (iz - ix)).atan()
    }
}

/// The trim's lift term `z_0 = -n g / V` (exact, with the standard gravity 9.80665 m/s^2) and
/// the angle of attack of the principal axis `alpha_t = alpha - eps` (the principal x axis lies
/// `eps` below the body x axis, so the flight path is `alpha - eps` below it); `alpha_t` is 0 when
/// the file gives no trim alpha.
fn trim_terms(input: &BodyAxisInput, eps: &f64) -> (Unreduced, Unreduced) {
    let g = Unreduced::from(&BigRational::new(980_665.into(), 100_000.into()));
    let z_0 = -&(&(&Unreduced::from(&input.load_factor) * &g) / &Unreduced::from(&input.speed));
    let alpha_t = match &input.trim_alpha {
        None => Unreduced::integer(0),
        Some(a) if *eps == 0.0 => a.into(),
        Some(a) => &Unreduced::from(a) - &Unreduced::from(&q(*eps)),
    };
    (z_0, alpha_t)
}

/// Converts body-axis coefficients to principal-axis derivatives (see the module docs).
pub fn convert(input: &BodyAxisInput) -> Converted {
    convert_rounding(input, true)
}

/// The exact change of each derivative per unit of coefficient `c` (the conversion is linear in
/// the coefficients: the derivatives of the input with every coefficient 0 but `c` = 1, with
/// the same density and principal axes as `input`'s conversion and nothing rounded); the
/// derivatives `c` does not move are left out.
pub fn slopes(input: &BodyAxisInput, c: Coefficient) -> Vec<(Param, BigRational)> {
    let mut unit = input.clone();
    unit.trim_alpha = None;
    unit.load_factor = BigRational::zero();
    for (i, x) in unit.coefficients.iter_mut().enumerate() {
        *x = if i == c as usize {
            BigRational::one()
        } else {
            BigRational::zero()
        };
    }
    let converted = convert_rounding(&unit, false);
    Param::ALL
        .iter()
        .skip(3)
        .map(|p| (*p, converted.derivative(*p).clone()))
        .filter(|(_, a)| !a.is_zero())
        .collect()
}

/// The air density, exact, with where it comes from and whether it went through f64 (the ISA
/// density of an altitude does).
fn air_density(density: &Density) -> (BigRational, String, bool) {
    match density {
        Density::Given(rho) => (rho.clone(), "given".to_string(), false),
        Density::Altitude(h) => (
            q(isa_density(*h)),
            format!("ISA troposphere at {h} m"),
            true,
        ),
    }
}

/// `x` rounded to the nearest f64 (`round`), or exact; a value beyond f64 stays exact, for the
/// loader to refuse with its name.
fn finished(x: &Unreduced, round: bool) -> BigRational {
    let v = x.to_f64();
    if round && v.is_finite() {
        q(v)
    } else {
        x.reduced()
    }
}

/// [`convert`], with the results rounded once each to f64 when an irrational step went
/// through f64 (`round`), or left exact. The arithmetic reduces only the results
/// ([`Unreduced`]).
fn convert_rounding(input: &BodyAxisInput, round: bool) -> Converted {
    let f = rational_to_f64;
    let (density, density_source, mut rounded) = air_density(&input.density);
    let u = |x: &BigRational| Unreduced::from(x);
    let v = &u(&input.speed);
    let two = &Unreduced::integer(2);
    let qbar = &(&(&(&u(&density) * v) * v) / two);
    let qs = &(qbar * &u(&input.wing_area));
    let (b, c, m, iy) = (
        &u(&input.span),
        &u(&input.chord),
        &u(&input.mass),
        &u(&input.iy),
    );
    let k = |x: Coefficient| u(input.coefficient(x));

    let z_alpha = -&(&(qs * &k(Coefficient::CLAlpha)) / &(m * v));
    let y_beta = &(qs * &k(Coefficient::CYBeta)) / &(m * v);
    let lat = &(qs * b);
    let lat_rate = &(&(lat * b) / &(two * v));
    let lon = &(qs * c);
    let lon_rate = &(&(lon * c) / &(two * v));
    let m_alpha = &(lon * &k(Coefficient::CmAlpha)) / iy;
    let m_q = &(lon_rate * &k(Coefficient::CmQ)) / iy;
    let m_delta_e = &(lon * &k(Coefficient::CmDeltaE)) / iy;

    let eps = tilt(f(&input.ix), f(&input.iz), f(&input.ixz));
    let (cs, sn) = if input.ixz.is_zero() {
        (Unreduced::integer(1), Unreduced::integer(0))
    } else {
        rounded = true;
        (u(&q(eps.cos())), u(&q(eps.sin())))
    };
    let (cs, sn) = (&cs, &sn);
    let (a, d, h) = (&u(&input.ix), &u(&input.iz), &u(&input.ixz));
    // R^T [[ix, -ixz], [-ixz, iz]] R with R = [[c, -s], [s, c]]
    let cc = &(cs * cs);
    let (ss, cs2) = (&(sn * sn), &(&(two * cs) * sn));
    let ix_p = &(&(cc * a) - &(cs2 * h)) + &(ss * d);
    let iz_p = &(&(ss * a) + &(cs2 * h)) + &(cc * d);

    // (L, N) -> R^T (L, N) = (c L + s N, -s L + c N)
    let rotate = |l: &Unreduced, n: &Unreduced| (&(cs * l) + &(sn * n), &(cs * n) - &(sn * l));
    let moments = |cl: Coefficient, cn: Coefficient| rotate(&(lat * &k(cl)), &(lat * &k(cn)));
    let (l_beta, n_beta) = moments(Coefficient::ClBeta, Coefficient::CnBeta);
    let (l_da, n_da) = moments(Coefficient::ClDeltaA, Coefficient::CnDeltaA);
    let (l_dr, n_dr) = moments(Coefficient::ClDeltaR, Coefficient::CnDeltaR);
    // Rate block: R^T A R, column by column: A R's columns are A (c, s) and A (-s, c).
    let (lp, lr) = (
        &(lat_rate * &k(Coefficient::ClP)),
        &(lat_rate * &k(Coefficient::ClR)),
    );
    let (np, nr) = (
        &(lat_rate * &k(Coefficient::CnP)),
        &(lat_rate * &k(Coefficient::CnR)),
    );
    let (l_p, n_p) = rotate(&(&(lp * cs) + &(lr * sn)), &(&(np * cs) + &(nr * sn)));
    let (l_r, n_r) = rotate(&(&(lr * cs) - &(lp * sn)), &(&(nr * cs) - &(np * sn)));

    let by = |x: &Unreduced, i: &Unreduced| {
        if i.is_zero() {
            Unreduced::integer(0)
        } else {
            x / i
        }
    };
    let (z_0, alpha_t) = trim_terms(input, &eps);
    let round = rounded && round;
    let mut derivatives = Vec::with_capacity(Param::COUNT - 3);
    for p in Param::ALL.iter().skip(3) {
        let x = match p {
            Param::ZAlpha => z_alpha.clone(),
            Param::YBeta => y_beta.clone(),
            Param::Lp => by(&l_p, &ix_p),
            Param::Lr => by(&l_r, &ix_p),
            Param::LBeta => by(&l_beta, &ix_p),
            Param::LDeltaA => by(&l_da, &ix_p),
            Param::LDeltaR => by(&l_dr, &ix_p),
            Param::Mq => m_q.clone(),
            Param::MAlpha => m_alpha.clone(),
            Param::MDeltaE => m_delta_e.clone(),
            Param::Np => by(&n_p, &iz_p),
            Param::Nr => by(&n_r, &iz_p),
            Param::NBeta => by(&n_beta, &iz_p),
            Param::NDeltaA => by(&n_da, &iz_p),
            Param::NDeltaR => by(&n_dr, &iz_p),
            Param::Z0 => z_0.clone(),
            Param::AlphaT => alpha_t.clone(),
            Param::C | Param::D | Param::E => continue,
        };
        derivatives.push(finished(&x, round));
    }
    let principal = [
        finished(&ix_p, round),
        finished(iy, round),
        finished(&iz_p, round),
    ];
    Converted {
        principal,
        derivatives,
        tilt_deg: eps.to_degrees(),
        rounded,
        density: f(&density),
        density_source,
        speed: input.speed.clone(),
    }
}

#[cfg(test)]
mod tests;
