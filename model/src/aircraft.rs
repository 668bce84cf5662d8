//! Aircraft data: the inertia coefficients and dimensional derivatives of Table A.1, exact.
//!
//! Every value is held as the exact rational its decimal literal denotes (`-13.52504` is
//! `-338126/25000`), so that the symbolic derivation specialised to an aircraft is exact and the
//! only rounding happens once, when a result is printed or emitted. Built-in aircraft A and B are
//! Table A.1 of the paper, read from `aircraft/a.toml` and `aircraft/b.toml` (compiled in, so the
//! table exists once); users bring their own as TOML, either dimensional or as nondimensional
//! body-axis coefficients (see [`load`] and [`convert`]).
//!
//! ```
//! use model::aircraft::{Aircraft, Param};
//!
//! let a = Aircraft::a();
//! assert_eq!(a.name, "Aircraft A");
//! // Table A.1's decimals enter exactly: l_p = -21.7529 = -217529/10000
//! assert_eq!(a.exact(Param::Lp).to_string(), "-217529/10000");
//! ```

use num_rational::BigRational;
use std::sync::OnceLock;

pub mod convert;
mod exact;
mod load;
mod param;
pub use exact::{decimal_to_rational, f64_to_rational, rational_to_f64};
pub use load::{convert_file, convert_text, load, parse, AircraftError, Location};
pub use param::Param;

/// Standard acceleration due to gravity, m/s^2: the g of the 7th-order model's g/V terms
/// (Appendix A.1), and the floor of a file's speed, at which g/V is still a finite double.
pub const G: f64 = 9.80665;

/// Speed used for the g/V terms of the 7th-order model when a file gives none.
///
/// The paper does not state a speed. 150 m/s (Mach 0.45 at sea level) is a typical speed for the
/// rapid-roll manoeuvres of fighter aircraft of this class; it only affects the slow gravity
/// terms (g/V = 0.065 1/s), not the PSS model or the criterion.
pub const DEFAULT_SPEED_M_S: f64 = 150.0;

/// Default of both `[validity]` limits, deg: beyond about 30 deg of alpha or beta linear
/// aerodynamics of a fighter-like aircraft are no longer trusted (stall, vortex breakdown).
pub const VALIDITY_DEFAULT_DEG: f64 = 30.0;

/// How far the primary branch is followed when the aircraft gives no aileron limit, rad: a
/// quarter turn of the aileron, where the small-angle model has long stopped meaning anything.
pub const DEFAULT_AILERON_RANGE: f64 = std::f64::consts::FRAC_PI_2;

/// Control-surface deflection limits from the optional `[limits]` table, degrees (None: no limit).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Limits {
    /// |delta_a| limit, deg.
    pub aileron_deg: Option<f64>,
    /// |delta_e| limit, deg.
    pub elevator_deg: Option<f64>,
    /// |delta_r| limit, deg.
    pub rudder_deg: Option<f64>,
}

/// Range in which the linear aerodynamics are trusted, from the optional `[validity]` table, degrees.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct Validity {
    /// |alpha| limit, deg (default 30).
    pub alpha_max_deg: f64,
    /// |beta| limit, deg (default 30).
    pub beta_max_deg: f64,
}

impl Default for Validity {
    fn default() -> Self {
        Validity {
            alpha_max_deg: VALIDITY_DEFAULT_DEG,
            beta_max_deg: VALIDITY_DEFAULT_DEG,
        }
    }
}

/// One aircraft: a name, the exact parameters, the speed for the 7th-order model, and the
/// control limits and validity range the reports are checked against.
#[derive(Clone, Debug, PartialEq)]
pub struct Aircraft {
    /// Display name, e.g. "Aircraft A".
    pub name: String,
    values: Vec<BigRational>,
    /// Flight speed in m/s (only used by the g/V terms of the 7th-order model, Appendix A.1).
    pub speed: f64,
    /// Control deflection limits (`[limits]`; none by default).
    pub limits: Limits,
    /// Range of alpha and beta in which the model is trusted (`[validity]`; 30 deg by default).
    pub validity: Validity,
    /// The uncertain parameters of the optional `[uncertainty]` table, each with its exact
    /// interval (empty without the table); see [`Uncertain`].
    pub uncertainty: Vec<Uncertain>,
    /// What the loader accepted with a warning (moments of inertia that break the triangle
    /// inequalities, for instance) and what the file's `[import]` warns of (tables read beyond
    /// their breakpoints): each a sentence, empty when none.
    pub warnings: Vec<String>,
    /// Whether the file gives the trim its derivatives were taken at (`z_0` or `alpha_t`, or
    /// a body-axis file's `flight.alpha` or `flight.load_factor`): then delta_e is the
    /// increment from that trim, 0 by default, instead of the deflection from zero lift of
    /// the paper's aircraft (2 deg by default, Figs 7-8).
    pub trimmed: bool,
}

/// The trim the derivatives of an aircraft were taken at (see [`Aircraft::trim_state`]).
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct TrimState {
    /// Load factor n, lift over weight: `-z_0 V / g`.
    pub load_factor: f64,
    /// Angle of attack of the principal x axis, deg.
    pub alpha_t_deg: f64,
    /// True airspeed, m/s.
    pub speed_m_s: f64,
}

/// One coordinate of the uncertainty box: the closed interval `[lo, hi]` (exact) of a parameter,
/// or of a nondimensional coefficient that moves several parameters at once (`coefficient`).
#[derive(Clone, Debug, PartialEq)]
pub struct Uncertain {
    /// The parameter (for a coefficient: the derivative it scales).
    pub param: Param,
    /// Lower end, exact.
    pub lo: BigRational,
    /// Upper end, exact (`lo <= hi`).
    pub hi: BigRational,
    /// `None`: the coordinate is the value of `param`. `Some`: it is a coefficient of a
    /// nondimensional file, `[lo, hi]` its interval, and it moves the parameters of its map.
    pub coefficient: Option<CoefficientMap>,
}

/// How a coefficient of a nondimensional file moves the model's parameters: the conversion is
/// linear in the coefficients, so at coefficient value x each parameter p of `moves` is its
/// nominal value plus `a_p (x - nominal)`, exactly (with `ixz != 0` the principal-axis rotation
/// makes a lateral coefficient move both an `l_x` and an `n_x`).
#[derive(Clone, Debug, PartialEq)]
pub struct CoefficientMap {
    /// The coefficient's TOML key, e.g. `Cl_p`.
    pub key: &'static str,
    /// Its nominal value (that of the file).
    pub nominal: BigRational,
    /// Each parameter it moves and the exact change of that parameter per unit coefficient.
    pub moves: Vec<(Param, BigRational)>,
}

impl Uncertain {
    /// The uncertain parameter `param` in `[lo, hi]`.
    pub fn param(param: Param, lo: BigRational, hi: BigRational) -> Uncertain {
        Uncertain {
            param,
            lo,
            hi,
            coefficient: None,
        }
    }

    /// The coordinate's name: the TOML key the file gives it by.
    pub fn key(&self) -> &'static str {
        match &self.coefficient {
            Some(c) => c.key,
            None => self.param.key(),
        }
    }

    /// `aircraft` moved to coordinate value `x` (exact): the parameter set to `x`, or each
    /// parameter of the coefficient's map moved by `a_p (x - nominal)`.
    pub fn moved(&self, aircraft: Aircraft, x: &BigRational) -> Aircraft {
        match &self.coefficient {
            None => aircraft.with(self.param, x.clone()),
            Some(c) => c.moves.iter().fold(aircraft, |a, (p, slope)| {
                let v = a.exact(*p) + slope * (x - &c.nominal);
                a.with(*p, v)
            }),
        }
    }
}

impl Aircraft {
    /// How far the primary branch is followed: the aileron limit of `[limits]`, at least
    /// [`DEFAULT_AILERON_RANGE`], rad.
    pub fn aileron_range(&self) -> f64 {
        self.limits.aileron_deg.map_or(DEFAULT_AILERON_RANGE, |l| {
            l.to_radians().max(DEFAULT_AILERON_RANGE)
        })
    }

    /// Whether control deflections (rad) are within the `[limits]`: the aileron and elevator
    /// always, the rudder when given. `None` when the file sets none of the limits that apply.
    pub fn within_limits(&self, delta_a: f64, delta_e: f64, delta_r: Option<f64>) -> Option<bool> {
        let within = |limit: Option<f64>, x: f64| limit.map(|l| x.to_degrees().abs() <= l);
        [
            within(self.limits.aileron_deg, delta_a),
            within(self.limits.elevator_deg, delta_e),
            delta_r.and_then(|dr| within(self.limits.rudder_deg, dr)),
        ]
        .into_iter()
        .flatten()
        .reduce(|a, b| a && b)
    }

    /// Whether a state is within the `[validity]` range of the linear aerodynamics (rad).
    pub fn valid(&self, alpha: f64, beta: f64) -> bool {
        alpha.to_degrees().abs() <= self.validity.alpha_max_deg
            && beta.to_degrees().abs() <= self.validity.beta_max_deg
    }

    /// Builds an aircraft from exact values in [`Param::ALL`] order, without limits and with the
    /// default validity range.
    pub fn new(name: impl Into<String>, values: Vec<BigRational>, speed: f64) -> Self {
        assert_eq!(values.len(), Param::ALL.len(), "one value per parameter");
        Aircraft {
            name: name.into(),
            values,
            speed,
            limits: Limits::default(),
            validity: Validity::default(),
            uncertainty: Vec::new(),
            warnings: Vec::new(),
            trimmed: false,
        }
    }

    /// The trim of an aircraft whose file gives it (else `None`): the flight state every
    /// increment of the analysis is measured from.
    pub fn trim_state(&self) -> Option<TrimState> {
        self.trimmed.then(|| TrimState {
            load_factor: -self.value(Param::Z0) * self.speed / G,
            alpha_t_deg: self.value(Param::AlphaT).to_degrees(),
            speed_m_s: self.speed,
        })
    }

    /// The default elevator of every command, rad: the trim itself (0) for an aircraft whose
    /// file gives its trim, else the paper's 2 deg from zero lift.
    pub fn default_delta_e_rad(&self) -> f64 {
        if self.trimmed {
            0.0
        } else {
            2f64.to_radians()
        }
    }

    /// Builds an aircraft from decimal literals in [`Param::ALL`] order (for built-ins and tests).
    pub fn from_decimals(name: &str, decimals: [&str; Param::COUNT], speed: f64) -> Self {
        let values = decimals
            .iter()
            .map(|s| decimal_to_rational(s).expect("built-in decimal literal"))
            .collect();
        Aircraft::new(name, values, speed)
    }

    /// The same aircraft with `p` set to the exact value `v` (for points of an uncertainty box).
    pub fn with(&self, p: Param, v: BigRational) -> Aircraft {
        let mut a = self.clone();
        a.values[p.index()] = v;
        a
    }

    /// The exact value of a parameter.
    pub fn exact(&self, p: Param) -> &BigRational {
        &self.values[p.index()]
    }

    /// The value of a parameter rounded once to f64.
    pub fn value(&self, p: Param) -> f64 {
        rational_to_f64(self.exact(p))
    }

    /// All values rounded to f64, in [`Param::ALL`] order.
    pub fn values_f64(&self) -> [f64; Param::COUNT] {
        let mut out = [0.0; Param::COUNT];
        for p in Param::ALL {
            out[p.index()] = self.value(p);
        }
        out
    }

    /// Aircraft A of Table A.1 (after ref. 9 of the paper), from `aircraft/a.toml`.
    pub fn a() -> Self {
        static A: OnceLock<Aircraft> = OnceLock::new();
        A.get_or_init(|| builtin_file(include_str!("../../aircraft/a.toml"), "aircraft/a.toml"))
            .clone()
    }

    /// Aircraft B of Table A.1 (after ref. 2 of the paper), from `aircraft/b.toml`.
    pub fn b() -> Self {
        static B: OnceLock<Aircraft> = OnceLock::new();
        B.get_or_init(|| builtin_file(include_str!("../../aircraft/b.toml"), "aircraft/b.toml"))
            .clone()
    }

    /// A built-in aircraft by its short name (`A` or `B`, case-insensitive).
    pub fn builtin(name: &str) -> Option<Self> {
        match name.to_ascii_uppercase().as_str() {
            "A" => Some(Aircraft::a()),
            "B" => Some(Aircraft::b()),
            _ => None,
        }
    }
}

/// A compiled-in aircraft file; `builtin_aircraft_are_table_a1` tests that both parse.
fn builtin_file(text: &str, file: &str) -> Aircraft {
    match parse(text, file) {
        Ok(a) => a,
        Err(e) => panic!("built-in aircraft file does not load: {e}"),
    }
}

/// `name` with control characters escaped (`\u{1b}`, `\n`, ...): an aircraft name as it may be
/// printed on a terminal or written into a report (a file may hold any string).
pub fn shown(name: &str) -> String {
    name.chars()
        .map(|c| {
            if c.is_control() {
                c.escape_default().to_string()
            } else {
                c.to_string()
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn builtin_aircraft_are_table_a1() {
        // Table A.1 of the paper, written out here independently of aircraft/a.toml and b.toml
        // (n_delta_r = -1 and the speed are the files' own choices; l_delta_r = 0 and the trim
        // terms z_0 = alpha_t = 0).
        let a = Aircraft::from_decimals(
            "Aircraft A",
            [
                "0.959",
                "0.786",
                "0.705",
                "-3.0076",
                "-0.0558",
                "-21.7529",
                "1.5207",
                "-110.45",
                "-327.28",
                "-1.815",
                "-13.52504",
                "-33.268",
                "0",
                "-0.2608",
                "3.716",
                "0",
                "-1",
                "0",
                "0",
                "0",
            ],
            150.0,
        );
        let b = Aircraft::from_decimals(
            "Aircraft B",
            [
                "0.949", "0.716", "0.727", "-1.329", "-0.196", "-3.933", "0.126", "-9.99",
                "-45.83", "-0.814", "-23.18", "-28.37", "0", "-0.235", "5.67", "0", "-1", "0", "0",
                "0",
            ],
            150.0,
        );
        assert_eq!(Aircraft::a(), a);
        assert_eq!(Aircraft::b(), b);
        assert_eq!(Aircraft::builtin("a"), Some(a));
        assert_eq!(Aircraft::builtin("B"), Some(b));
        assert_eq!(Aircraft::builtin("C"), None);
        assert_eq!(Aircraft::a().value(Param::MAlpha), -13.52504);
    }
}
