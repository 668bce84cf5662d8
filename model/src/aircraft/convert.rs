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

use super::{f64_to_rational, rational_to_f64, Aircraft, Param};
use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use std::fmt::Write;

/// ISA sea-level temperature T0, K.
pub const ISA_T0_K: f64 = 288.15;
/// ISA sea-level pressure p0, Pa.
pub const ISA_P0_PA: f64 = 101_325.0;
/// ISA troposphere temperature lapse rate, K/m (T = T0 - 0.0065 h).
pub const ISA_LAPSE_K_M: f64 = 0.0065;
/// Specific gas constant of dry air R, J/(kg K) (ISA value).
pub const ISA_R_J_KG_K: f64 = 287.052_87;
/// Standard gravity g0, m/s^2.
pub const ISA_G0_M_S2: f64 = 9.806_65;

/// ISA troposphere density at geometric altitude `h` m (0 to 11 km): T = T0 - 0.0065 h,
/// p = p0 (T/T0)^(g0/(0.0065 R)), rho = p/(R T), kg/m^3.
pub fn isa_density(h: f64) -> f64 {
    let t = ISA_T0_K - ISA_LAPSE_K_M * h;
    let p = ISA_P0_PA * (t / ISA_T0_K).powf(ISA_G0_M_S2 / (ISA_LAPSE_K_M * ISA_R_J_KG_K));
    p / (ISA_R_J_KG_K * t)
}

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
    /// The derivatives in [`Param::ALL`] order after C, D, E (z_alpha ... l_delta_r).
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

    /// The value of one derivative (z_alpha ... l_delta_r).
    pub fn derivative(&self, p: Param) -> &BigRational {
        &self.derivatives[p.index() - 3]
    }

    /// The dimensional principal-axis TOML of this conversion, for `model convert`: principal
    /// moments in `[inertia]`, every derivative, the speed, and `aircraft`'s name, limits and
    /// validity. Values are exact: a terminating decimal is written out in full, any other
    /// rational as the string `"p/q"` with its approximate value in a comment, so that loading
    /// the output gives exactly the aircraft the body-axis file gives.
    pub fn to_toml(&self, aircraft: &Aircraft, file: &str) -> String {
        let mut out = String::new();
        // The path goes into a comment: no control character may end it.
        let file: String = file
            .chars()
            .map(|c| if c.is_control() { '?' } else { c })
            .collect();
        let precision = if self.rounded {
            "each value went through f64 (the ISA density and/or the cosine and sine of the\n\
             # tilt) and was rounded once to the nearest f64, so it is within about 1e-16\n\
             # relative of the exact conversion"
        } else {
            "exact (density given and ixz = 0: rational arithmetic throughout)"
        };
        let _ = writeln!(
            out,
            "# Converted by `model convert` from {file}: nondimensional body-axis coefficients\n\
             # to dimensional principal-axis derivatives (formulas in docs/nondimensional.md).\n\
             # Principal x axis tilt: {:.6} deg (positive: x_p below body x, forward and down).\n\
             # Flight: V = {} m/s, rho = {} kg/m^3 ({}).\n\
             # Precision: {precision}.\n",
            self.tilt_deg,
            self.speed_f64(),
            self.density,
            self.density_source,
        );
        let _ = writeln!(out, "name = {}\n", toml_string(&aircraft.name));
        let _ = writeln!(out, "[inertia]\n# Principal moments of inertia, kg m^2.");
        for (key, m) in ["ix", "iy", "iz"].iter().zip(&self.principal) {
            let _ = writeln!(out, "{key} = {}", toml_number(m));
        }
        let _ = writeln!(out, "\n[derivatives]\n# Principal axes, angles in rad.");
        for p in Param::ALL.iter().skip(3) {
            let _ = writeln!(
                out,
                "{} = {}   # {}",
                p.key(),
                toml_number(self.derivative(*p)),
                p.unit()
            );
        }
        let _ = writeln!(out, "\n[flight]\nspeed = {:?}   # m/s", aircraft.speed);
        let l = aircraft.limits;
        let limits: Vec<(&str, f64)> = [
            ("aileron", l.aileron_deg),
            ("elevator", l.elevator_deg),
            ("rudder", l.rudder_deg),
        ]
        .into_iter()
        .filter_map(|(k, v)| v.map(|v| (k, v)))
        .collect();
        if !limits.is_empty() {
            let _ = writeln!(out, "\n[limits]\n# Deflection limits, deg.");
            for (k, v) in limits {
                let _ = writeln!(out, "{k} = {v:?}");
            }
        }
        let v = aircraft.validity;
        let _ = writeln!(
            out,
            "\n[validity]\n# |alpha| and |beta| in which the linear aerodynamics are trusted, deg.\n\
             alpha_max = {:?}\nbeta_max = {:?}",
            v.alpha_max_deg, v.beta_max_deg
        );
        if !aircraft.uncertainty.is_empty() {
            let _ = writeln!(
                out,
                "\n[uncertainty]\n# Each coefficient's interval as its derivative's: the conversion of its ends."
            );
        }
        for u in &aircraft.uncertainty {
            let (lo, hi) = (toml_number(&u.lo), toml_number(&u.hi));
            match &u.coefficient {
                None => {
                    let _ = writeln!(out, "{} = [{lo}, {hi}]", u.param.key());
                }
                Some(c) => {
                    let moved: Vec<&str> = c.moves.iter().map(|(p, _)| p.key()).collect();
                    let _ = writeln!(
                        out,
                        "# {} = [{lo}, {hi}] moves {} together (ixz != 0), which a box per \
                         derivative cannot hold: `model clear` the nondimensional file for it.",
                        c.key,
                        moved.join(", ")
                    );
                }
            }
        }
        out
    }
}

/// A TOML basic string.
fn toml_string(s: &str) -> String {
    let mut out = String::from("\"");
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if c.is_control() => {
                let _ = write!(out, "\\u{:04X}", u32::from(c));
            }
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// An exact rational as TOML the loader reads back exactly: a terminating decimal in full (always
/// with a decimal point), otherwise the string `"p/q"` followed by a comment with its value.
pub fn toml_number(q: &BigRational) -> String {
    match terminating_decimal(q) {
        Some(d) => d,
        None => format!(
            "\"{}/{}\"   # ~ {:e}",
            q.numer(),
            q.denom(),
            rational_to_f64(q)
        ),
    }
}

/// The decimal expansion of `q` if its denominator has no prime factor but 2 and 5.
fn terminating_decimal(q: &BigRational) -> Option<String> {
    let mut d = q.denom().clone();
    let (two, five) = (BigInt::from(2), BigInt::from(5));
    let (mut a, mut b) = (0usize, 0usize);
    while d.is_even() {
        d /= &two;
        a += 1;
    }
    while (&d % &five).is_zero() {
        d /= &five;
        b += 1;
    }
    if !d.is_one() {
        return None;
    }
    let k = a.max(b);
    let scaled = q.numer().abs() * num_traits::pow(BigInt::from(10), k) / q.denom();
    let digits = scaled.to_string();
    let (int, frac) = if k == 0 {
        (digits, "0".to_string())
    } else {
        let padded = format!("{digits:0>width$}", width = k + 1);
        let (i, f) = padded.split_at(padded.len() - k);
        (i.to_string(), f.to_string())
    };
    let sign = if q.is_negative() { "-" } else { "" };
    Some(format!("{sign}{int}.{frac}"))
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

/// [`convert`], with the results rounded once each to f64 when an irrational step went
/// through f64 (`round`), or left exact.
fn convert_rounding(input: &BodyAxisInput, round: bool) -> Converted {
    let f = rational_to_f64;
    let (density, density_source, mut rounded) = match &input.density {
        Density::Given(rho) => (rho.clone(), "given".to_string(), false),
        Density::Altitude(h) => (
            q(isa_density(*h)),
            format!("ISA troposphere at {h} m"),
            true,
        ),
    };
    let v = &input.speed;
    let two = BigRational::from_integer(2.into());
    let qbar = &density * v * v / &two;
    let qs = &qbar * &input.wing_area;
    let (b, c, m) = (&input.span, &input.chord, &input.mass);
    let k = |x: Coefficient| input.coefficient(x).clone();

    let z_alpha = -(&qs * k(Coefficient::CLAlpha)) / (m * v);
    let y_beta = &qs * k(Coefficient::CYBeta) / (m * v);
    let lat = &qs * b;
    let lat_rate = &lat * b / (&two * v);
    let lon = &qs * c;
    let lon_rate = &lon * c / (&two * v);
    let m_alpha = &lon * k(Coefficient::CmAlpha) / &input.iy;
    let m_q = &lon_rate * k(Coefficient::CmQ) / &input.iy;
    let m_delta_e = &lon * k(Coefficient::CmDeltaE) / &input.iy;

    let eps = tilt(f(&input.ix), f(&input.iz), f(&input.ixz));
    let (cs, sn) = if input.ixz.is_zero() {
        (BigRational::one(), BigRational::zero())
    } else {
        rounded = true;
        (q(eps.cos()), q(eps.sin()))
    };
    let (a, d, h) = (&input.ix, &input.iz, &input.ixz);
    // R^T [[ix, -ixz], [-ixz, iz]] R with R = [[c, -s], [s, c]]
    let ix_p = &cs * &cs * a - &two * &cs * &sn * h + &sn * &sn * d;
    let iz_p = &sn * &sn * a + &two * &cs * &sn * h + &cs * &cs * d;

    // (L, N) -> R^T (L, N) = (c L + s N, -s L + c N)
    let rotate = |l: BigRational, n: BigRational| (&cs * &l + &sn * &n, -(&sn * &l) + &cs * &n);
    let moments = |cl: Coefficient, cn: Coefficient, scale: &BigRational| {
        rotate(scale * k(cl), scale * k(cn))
    };
    let (l_beta, n_beta) = moments(Coefficient::ClBeta, Coefficient::CnBeta, &lat);
    let (l_da, n_da) = moments(Coefficient::ClDeltaA, Coefficient::CnDeltaA, &lat);
    let (l_dr, n_dr) = moments(Coefficient::ClDeltaR, Coefficient::CnDeltaR, &lat);
    // Rate block: R^T A R, column by column: A R's columns are A (c, s) and A (-s, c).
    let (lp, lr) = (
        &lat_rate * k(Coefficient::ClP),
        &lat_rate * k(Coefficient::ClR),
    );
    let (np, nr) = (
        &lat_rate * k(Coefficient::CnP),
        &lat_rate * k(Coefficient::CnR),
    );
    let col1 = rotate(&lp * &cs + &lr * &sn, &np * &cs + &nr * &sn);
    let col2 = rotate(-(&lp * &sn) + &lr * &cs, -(&np * &sn) + &nr * &cs);
    let (l_p, n_p) = col1;
    let (l_r, n_r) = col2;

    let by = |x: BigRational, i: &BigRational| {
        if i.is_zero() {
            BigRational::zero()
        } else {
            x / i
        }
    };
    let mut derivatives = Vec::with_capacity(15);
    for p in Param::ALL.iter().skip(3) {
        derivatives.push(match p {
            Param::ZAlpha => z_alpha.clone(),
            Param::YBeta => y_beta.clone(),
            Param::Lp => by(l_p.clone(), &ix_p),
            Param::Lr => by(l_r.clone(), &ix_p),
            Param::LBeta => by(l_beta.clone(), &ix_p),
            Param::LDeltaA => by(l_da.clone(), &ix_p),
            Param::LDeltaR => by(l_dr.clone(), &ix_p),
            Param::Mq => m_q.clone(),
            Param::MAlpha => m_alpha.clone(),
            Param::MDeltaE => m_delta_e.clone(),
            Param::Np => by(n_p.clone(), &iz_p),
            Param::Nr => by(n_r.clone(), &iz_p),
            Param::NBeta => by(n_beta.clone(), &iz_p),
            Param::NDeltaA => by(n_da.clone(), &iz_p),
            Param::NDeltaR => by(n_dr.clone(), &iz_p),
            Param::C | Param::D | Param::E => continue,
        });
    }
    let mut principal = [ix_p, input.iy.clone(), iz_p];
    if rounded && round {
        // A value beyond f64 stays exact here, for the loader to refuse with its name.
        let round = |x: &BigRational| {
            let v = f(x);
            if v.is_finite() {
                q(v)
            } else {
                x.clone()
            }
        };
        derivatives = derivatives.iter().map(round).collect();
        principal = principal.map(|x| round(&x));
    }
    Converted {
        principal,
        derivatives,
        tilt_deg: eps.to_degrees(),
        rounded,
        density: f(&density),
        density_source,
        speed: v.clone(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::aircraft::{decimal_to_rational, parse, AircraftError, Limits};
    use nalgebra::{Matrix2, SymmetricEigen, Vector2};

    /// A made-up aircraft in the body-axis format; round numbers so that the conversion can be
    /// done by hand (see `conversion_by_hand_exact`).
    const BODY: &str = r#"name = "Made up"
[flight]
speed = 100
density = 1.2
[geometry]
mass = 10000
wing_area = 20
span = 10
chord = 2
[inertia]
ix = 10000
iy = 40000
iz = 50000
ixz = 0
[coefficients]
CL_alpha = 5
CY_beta = -1
Cl_beta = -0.1
Cl_p = -0.4
Cl_r = 0.1
Cl_delta_a = -0.2
Cl_delta_r = 0.01
Cm_alpha = -0.5
Cm_q = -10
Cm_delta_e = -1
Cn_beta = 0.1
Cn_p = -0.05
Cn_r = -0.3
Cn_delta_a = 0.01
Cn_delta_r = -0.05
"#;

    const FILE: &str = "body.toml";

    fn fighter_text() -> &'static str {
        include_str!(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../aircraft/fighter.toml"
        ))
    }

    fn body(from: &str, to: &str) -> String {
        assert!(BODY.contains(from), "{from}");
        BODY.replacen(from, to, 1)
    }

    fn err(text: &str, line: usize, needles: &[&str]) -> AircraftError {
        let e = match parse(text, FILE) {
            Ok(a) => panic!("expected an error, got {a:?}"),
            Err(e) => e,
        };
        let msg = e.to_string();
        assert!(
            msg.contains(&format!("{FILE}:{line}:")),
            "no line {line} in: {msg}"
        );
        for n in needles {
            assert!(msg.contains(n), "no `{n}` in: {msg}");
        }
        e
    }

    /// `model convert` on a text: written to a temporary file, converted by `convert_file`.
    fn convert_text(text: &str) -> String {
        use std::sync::atomic::{AtomicUsize, Ordering};
        static N: AtomicUsize = AtomicUsize::new(0);
        let n = N.fetch_add(1, Ordering::Relaxed);
        let path = std::env::temp_dir().join(format!("convert-{}-{n}.toml", std::process::id()));
        std::fs::write(&path, text).unwrap();
        let out = crate::aircraft::convert_file(&path);
        let _ = std::fs::remove_file(&path);
        out.unwrap_or_else(|e| panic!("{e}"))
    }

    #[test]
    fn conversion_by_hand_exact() {
        // qbar = 1.2 * 100^2 / 2 = 6000 Pa, qbar S = 120000 N; qbar S b = 1.2e6 N m,
        // qbar S b (b/2V) = 60000 N m s; qbar S c = 240000 N m, qbar S c (c/2V) = 2400 N m s.
        // ixz = 0: the body axes are principal.
        let a = parse(BODY, FILE).unwrap();
        let q = |s: &str| decimal_to_rational(s).unwrap();
        let want = [
            (Param::C, "1"),          // (50000 - 10000) / 40000
            (Param::D, "0.6"),        // (40000 - 10000) / 50000
            (Param::E, "1"),          // (50000 - 40000) / 10000
            (Param::ZAlpha, "-0.6"),  // -120000 * 5 / (10000 * 100)
            (Param::YBeta, "-0.12"),  // 120000 * -1 / (10000 * 100)
            (Param::Lp, "-2.4"),      // 60000 * -0.4 / 10000
            (Param::Lr, "0.6"),       // 60000 * 0.1 / 10000
            (Param::LBeta, "-12"),    // 1.2e6 * -0.1 / 10000
            (Param::LDeltaA, "-24"),  // 1.2e6 * -0.2 / 10000
            (Param::LDeltaR, "1.2"),  // 1.2e6 * 0.01 / 10000
            (Param::Mq, "-0.6"),      // 2400 * -10 / 40000
            (Param::MAlpha, "-3"),    // 240000 * -0.5 / 40000
            (Param::MDeltaE, "-6"),   // 240000 * -1 / 40000
            (Param::Np, "-0.06"),     // 60000 * -0.05 / 50000
            (Param::Nr, "-0.36"),     // 60000 * -0.3 / 50000
            (Param::NBeta, "2.4"),    // 1.2e6 * 0.1 / 50000
            (Param::NDeltaA, "0.24"), // 1.2e6 * 0.01 / 50000
            (Param::NDeltaR, "-1.2"), // 1.2e6 * -0.05 / 50000
        ];
        assert_eq!(want.len(), Param::ALL.len());
        for (p, v) in want {
            assert_eq!(*a.exact(p), q(v), "{p:?}");
        }
        assert_eq!(a.speed, 100.0);
        assert_eq!(a.name, "Made up");
    }

    /// The conversion by straightforward f64 code of its own: ISA by the formula with the
    /// constants typed here, principal axes by nalgebra's symmetric eigensolver.
    fn independent_f64(
        v: f64,
        rho: f64,
        geom: [f64; 4],
        inertia: [f64; 4],
        c: &[f64; 15],
    ) -> ([f64; 18], f64) {
        let [m, s, b, ch] = geom;
        let [ix, iy, iz, ixz] = inertia;
        let qbar = 0.5 * rho * v * v;
        let [cla, cyb, clb, clp, clr, clda, cldr, cma, cmq, cmde, cnb, cnp, cnr, cnda, cndr] = *c;
        let lat = qbar * s * b;
        let rate = lat * b / (2.0 * v);
        let eig = SymmetricEigen::new(Matrix2::new(ix, -ixz, -ixz, iz));
        let cols: Vec<Vector2<f64>> = (0..2).map(|i| eig.eigenvectors.column(i).into()).collect();
        let k = if cols[0].x.abs() >= cols[1].x.abs() {
            0
        } else {
            1
        };
        let mut xp = cols[k];
        if xp.x < 0.0 {
            xp = -xp;
        }
        let mut zp = cols[1 - k];
        if zp.y < 0.0 {
            zp = -zp;
        }
        let r = Matrix2::from_columns(&[xp, zp]);
        let ixp = (r.transpose() * Matrix2::new(ix, -ixz, -ixz, iz) * r)[(0, 0)];
        let izp = (r.transpose() * Matrix2::new(ix, -ixz, -ixz, iz) * r)[(1, 1)];
        let a = r.transpose() * Matrix2::new(rate * clp, rate * clr, rate * cnp, rate * cnr) * r;
        let vec = |l: f64, n: f64| r.transpose() * Vector2::new(lat * l, lat * n);
        let (beta, da, dr) = (vec(clb, cnb), vec(clda, cnda), vec(cldr, cndr));
        let lon = qbar * s * ch;
        let out = [
            (izp - ixp) / iy,
            (iy - ixp) / izp,
            (izp - iy) / ixp,
            -qbar * s * cla / (m * v),
            qbar * s * cyb / (m * v),
            a[(0, 0)] / ixp,
            a[(0, 1)] / ixp,
            beta.x / ixp,
            da.x / ixp,
            lon * ch / (2.0 * v) * cmq / iy,
            lon * cma / iy,
            lon * cmde / iy,
            a[(1, 0)] / izp,
            a[(1, 1)] / izp,
            beta.y / izp,
            da.y / izp,
            dr.y / izp,
            dr.x / ixp,
        ];
        (out, xp.y.atan2(xp.x).to_degrees())
    }

    #[test]
    fn conversion_with_tilt_and_isa_matches_an_independent_f64_computation() {
        // The numbers of aircraft/fighter.toml, typed again here.
        let h = 4000.0;
        let t = 288.15 - 0.0065 * h;
        let rho =
            101325.0 * (t / 288.15_f64).powf(9.80665 / (0.0065 * 287.05287)) / (287.05287 * t);
        // ISA table at 4000 m: T = 262.15 K, p = 61640 Pa, so rho = p / (R T) = 0.81913 kg/m^3
        assert!((rho - 0.81913).abs() < 1e-4, "{rho}");
        let coeffs = [
            4.6, -1.07, -0.092, -0.38, 0.10, -0.10, 0.021, -0.35, -5.0, -0.55, 0.12, -0.03, -0.35,
            0.008, -0.045,
        ];
        let (want, tilt) = independent_f64(
            180.0,
            rho,
            [9300.0, 27.87, 9.144, 3.45],
            [12875.0, 75674.0, 85552.0, 1331.0],
            &coeffs,
        );
        let a = parse(fighter_text(), "fighter.toml").unwrap();
        for p in Param::ALL {
            let (got, w) = (a.value(p), want[p.index()]);
            assert!(
                (got - w).abs() <= 1e-12 * w.abs().max(1e-3),
                "{p:?}: {got} vs {w}"
            );
        }
        assert!(tilt > 0.5 && tilt < 1.5, "{tilt}");
        let out = convert_text(fighter_text());
        let printed: f64 = out
            .lines()
            .find_map(|l| l.strip_prefix("# Principal x axis tilt: "))
            .and_then(|l| l.split(' ').next())
            .and_then(|t| t.parse().ok())
            .unwrap();
        assert!((printed - tilt).abs() < 1e-6, "{printed} vs {tilt}");
        assert!(out.contains("rounded once"), "{out}");
        // aileron yaw and roll due to rudder both present in principal axes
        assert!(a.value(Param::NDeltaA) != 0.0 && a.value(Param::LDeltaR) != 0.0);
        assert_eq!(a.limits.aileron_deg, Some(21.5));
        assert_eq!(a.validity.beta_max_deg, 20.0);
    }

    #[test]
    fn convert_output_loads_as_the_same_aircraft() {
        // ix = 7000 kg m^2: l_p = 60000 * -0.4 / 7000 = -24/7, not a terminating decimal
        let sevenths = body("ix = 10000", "ix = 7000").replacen("iz = 50000", "iz = 45000", 1);
        let limited = format!("{BODY}[limits]\naileron = 20\n[validity]\nalpha_max = 15\n");
        for text in [BODY, &sevenths, &limited, fighter_text()] {
            let a = parse(text, FILE).unwrap();
            let out = convert_text(text);
            let back = parse(&out, "out.toml").unwrap_or_else(|e| panic!("{e}\n{out}"));
            assert_eq!(back, a, "{out}");
            assert!(out.contains("# Principal x axis tilt: "), "{out}");
        }
        let out = convert_text(&sevenths);
        assert!(out.contains("l_p = \"-24/7\""), "{out}");
        let limited = parse(&limited, FILE).unwrap();
        assert_eq!(
            limited.limits,
            Limits {
                aileron_deg: Some(20.0),
                ..Limits::default()
            }
        );
        assert_eq!(limited.validity.alpha_max_deg, 15.0);
    }

    #[test]
    #[cfg(feature = "analysis")]
    fn analyze_agrees_on_body_axis_and_converted_files() {
        // The fighter as it is (aileron yaw, roll due to rudder from the tilt, ixz != 0), and
        // without aileron yaw and product of inertia.
        let plain = fighter_text().replacen("Cn_delta_a = 0.008", "Cn_delta_a = 0.0", 1);
        let plain = plain.replacen("ixz = 1331.0", "ixz = 0.0", 1);
        for text in [fighter_text().to_string(), plain] {
            let a = parse(&text, FILE).unwrap();
            let b = parse(&convert_text(&text), "out.toml").unwrap();
            let (ra, rb) = (
                crate::analysis::analyze(&a, 0.0349),
                crate::analysis::analyze(&b, 0.0349),
            );
            assert!(ra.as_ref().is_ok_and(|r| r.critical.is_some()), "{ra:?}");
            assert_eq!(ra, rb);
        }
    }

    #[test]
    fn terminating_decimals_are_written_in_full() {
        let q = |s: &str| decimal_to_rational(s).unwrap();
        assert_eq!(toml_number(&q("-12")), "-12.0");
        assert_eq!(toml_number(&q("0.0625")), "0.0625");
        assert_eq!(toml_number(&q("-0.003")), "-0.003");
        assert_eq!(toml_number(&q("123.45e10")), "1234500000000.0");
        let third = BigRational::new(1.into(), 3.into());
        assert!(toml_number(&third).starts_with("\"1/3\""));
        assert_eq!(toml_string("a\"b\\c\u{1}"), "\"a\\\"b\\\\c\\u0001\"");
    }

    #[test]
    fn bad_body_axis_files_name_file_line_and_key() {
        // missing tables
        for t in ["[geometry]\n", "[coefficients]\n"] {
            let other = if t.starts_with("[geometry]") {
                "coefficients"
            } else {
                "geometry"
            };
            let cut = BODY
                .split(t)
                .next()
                .map(|head| {
                    let tail = BODY.split(t).nth(1).unwrap_or("");
                    let rest = tail.find('[').map_or("", |i| &tail[i..]);
                    format!("{head}{rest}")
                })
                .unwrap();
            let name = t.trim().trim_matches(['[', ']']);
            let e = err(&cut, 1, &[&format!("missing table `[{name}]`")]);
            assert!(matches!(e, AircraftError::MissingTable { .. }), "{other}");
        }
        let no_flight = body("[flight]\nspeed = 100\ndensity = 1.2\n", "");
        err(
            &no_flight,
            1,
            &["missing table `[flight]`", "`speed`, `density`, `altitude`"],
        );
        // missing keys
        for (line, key, header) in [
            ("speed = 100\n", "flight.speed", 2),
            ("mass = 10000\n", "geometry.mass", 5),
            ("ixz = 0\n", "inertia.ixz", 10),
            ("Cn_delta_r = -0.05\n", "coefficients.Cn_delta_r", 15),
            ("iy = 40000\n", "inertia.iy", 10),
        ] {
            let e = err(
                &body(line, ""),
                header,
                &[&format!("missing required key `{key}`")],
            );
            assert!(matches!(e, AircraftError::MissingKey { .. }));
        }
        err(
            &body("density = 1.2\n", ""),
            2,
            &["flight.density", "or `altitude = <number>` in m"],
        );
        // non-positive values
        for (from, to, line, key) in [
            ("mass = 10000", "mass = 0", 6, "geometry.mass"),
            ("wing_area = 20", "wing_area = -20", 7, "geometry.wing_area"),
            ("span = 10", "span = 0.0", 8, "geometry.span"),
            ("chord = 2", "chord = -2", 9, "geometry.chord"),
            ("speed = 100", "speed = 0", 3, "flight.speed"),
            ("density = 1.2", "density = -1.2", 4, "flight.density"),
            ("ix = 10000", "ix = 0", 11, "inertia.ix"),
        ] {
            let e = err(&body(from, to), line, &[key, "> 0"]);
            assert!(matches!(e, AircraftError::InvalidValue { .. }), "{e}");
        }
        // altitude outside the ISA troposphere, and both density and altitude
        for h in ["-1", "11000.5", "2e4"] {
            err(
                &body("density = 1.2", &format!("altitude = {h}")),
                4,
                &["flight.altitude", "ISA troposphere, 0 to 11000", h],
            );
        }
        err(
            &body("density = 1.2", "density = 1.2\naltitude = 100"),
            5,
            &[
                "flight.altitude",
                "either `flight.density` or `flight.altitude`",
            ],
        );
        // unphysical inertias: the triangle inequality, a principal moment <= 0
        let e = err(
            &body("iz = 50000", "iz = 60000"),
            10,
            &["ix' + iy < iz'", "triangle inequalities"],
        );
        assert!(matches!(e, AircraftError::UnphysicalInertia { .. }));
        err(
            &body("ixz = 0", "ixz = 30000"),
            10,
            &["principal moment ix' <= 0"],
        );
        // mixing the formats
        let e = err(
            &body("ixz = 0\n", "ixz = 0\nC = 0.5\n"),
            15,
            &["`inertia.C`", "not a mix"],
        );
        assert!(matches!(e, AircraftError::MixedFormats { .. }));
        err(
            &format!("{BODY}[derivatives]\nl_p = 1\n"),
            31,
            &[
                "`[derivatives]` given together with `[geometry]`",
                "not a mix",
            ],
        );
        // no roll authority
        err(
            &body("Cl_delta_a = -0.2", "Cl_delta_a = 0"),
            21,
            &["coefficients.Cl_delta_a", "nonzero aileron derivative"],
        );
        // wrong types and unknown keys
        err(
            &body("Cm_q = -10", "Cm_q = \"x\""),
            24,
            &["coefficients.Cm_q", "a number"],
        );
        err(
            &body("Cm_q = -10", "cm_q = -10"),
            24,
            &["unknown key `coefficients.cm_q`", "did you mean `Cm_q`?"],
        );
    }

    #[test]
    fn conversions_beyond_f64_are_refused_and_nothing_panics() {
        err(
            &body("mass = 10000", "mass = 1e-310"), // z_alpha = -6000 / m = -6e313
            6,
            &["key `geometry.mass`", "rho V S / (2 m)", "overflows"],
        );
        // principal axes at 45 deg (ix = iz), and every prefix of two files: no panic
        let _ = parse(
            &body("iz = 50000", "iz = 10000").replacen("ixz = 0", "ixz = 5", 1),
            FILE,
        );
        for text in [BODY, fighter_text()] {
            for (i, _) in text.char_indices() {
                let _ = parse(&text[..i], FILE);
            }
        }
    }

    #[test]
    fn a_flight_condition_that_makes_the_derivatives_underflow_names_its_key() {
        // g/V = 9.8e320 leaves f64 before any derivative is computed
        let e = err(
            &body("speed = 100", "speed = 1e-320"),
            3,
            &["key `flight.speed`", "`1e-320`"],
        );
        assert!(!e.to_string().contains("Cl_delta_a"), "{e}");
        // rho V^2 / 2 = 6e-321: every static lateral derivative underflows
        err(
            &body("speed = 100", "speed = 1e-160"),
            3,
            &[
                "key `flight.speed`",
                "rho V^2 S b / (2 ix')",
                "underflows",
                "`1e-160`",
            ],
        );
        err(
            &body("density = 1.2", "density = 1e-320"),
            4,
            &["key `flight.density`", "rho V S / (2 m)", "underflows"],
        );
    }

    #[test]
    fn geometry_inertia_and_coefficients_that_take_a_derivative_beyond_f64_name_their_key() {
        // l_p per unit Cl_p = rho V S b^2 / (4 ix') = 1.2e601
        err(
            &body("span = 10", "span = 1e300"),
            8,
            &["key `geometry.span`", "rho V S b^2 / (4 ix')", "overflows"],
        );
        let tiny = body(
            "ix = 10000\niy = 40000\niz = 50000",
            "ix = 1e-316\niy = 4e-316\niz = 5e-316",
        );
        err(&tiny, 11, &["key `inertia.ix`", "overflows"]);
        // l_p = 6 Cl_p
        err(
            &body("Cl_p = -0.4", "Cl_p = 1e308"),
            19,
            &["key `coefficients.Cl_p`", "l_p", "range of f64"],
        );
    }

    #[test]
    fn convert_refuses_a_dimensional_file() {
        let path = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../aircraft/a.toml"));
        let e = crate::aircraft::convert_file(path).unwrap_err();
        assert!(matches!(e, AircraftError::AlreadyDimensional { .. }));
        assert!(e.to_string().contains("a.toml:1:1"), "{e}");
    }

    #[test]
    fn isa_density_at_the_ends_of_the_troposphere() {
        // ISA tables: 1.2250 kg/m^3 at sea level, 0.36392 kg/m^3 at 11 km.
        assert!((isa_density(0.0) - 1.2250).abs() < 1e-4);
        assert!((isa_density(11000.0) - 0.36392).abs() < 1e-4);
    }
}
