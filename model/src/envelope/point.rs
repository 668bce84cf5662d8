//! One point of an envelope: the n-g trim at its altitude and speed (alpha and elevator for lift
//! n times the weight and no pitching moment), the aircraft file the import writes there, and
//! the analysis `model analyze` makes of it (the certified route, the exact path where a
//! certificate fails) at the elevator increment from the trim.

use super::clearance::{clear_point, PointClearance};
use super::elevator::Elevator;
use super::uncertainty::Uncertainty;
use super::validation::Validation;
use crate::aircraft;
use crate::analysis::fast::analyze_first_departure;
use crate::analysis::{Analysis, FirstDeparture};
use crate::jsbsim::condition::{Condition, Speed};
use crate::jsbsim::import::{trimmed_file, Loaded};
use crate::jsbsim::trim::{trim, Trim};
use serde::Serialize;

/// The critical jump of a point, as `analyze` reports it.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct Critical {
    /// Trim roll rate at the jump, rad/s.
    pub p0: f64,
    /// Aileron deflection at the jump, deg.
    pub delta_a_deg: f64,
    /// Whether the aileron (and elevator) are within the aircraft's limits; `None` without.
    pub within_limits: Option<bool>,
}

/// Everything an envelope reports at one grid point.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct Point {
    /// Geometric altitude, m.
    pub altitude_m: f64,
    /// Mach number.
    pub mach: f64,
    /// True airspeed, m/s.
    pub speed_m_s: f64,
    /// The load factor of the trim (lift over weight).
    pub load_factor: f64,
    /// The trim's angle of attack, deg; `None` where there is no trim.
    pub alpha_deg: Option<f64>,
    /// The trim's elevator, deg (JSBSim's sign, positive trailing edge down; normalised travel
    /// for a model that gives the elevator only as travel); `None` where there is no trim.
    pub elevator_trim_deg: Option<f64>,
    /// The elevator increment from the trim analysed (the paper's `delta_e`), deg.
    pub delta_e_deg: Option<f64>,
    /// Whether the trim exists here.
    pub trimmed: bool,
    /// Why not, when not trimmed (the limit that makes it untrimmable).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reason: Option<String>,
    /// Why a trimmed point has no analysis (import or analysis refused).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error: Option<String>,
    /// The warnings of the point's aircraft, as `analyze` gives them (the tables its flight
    /// state reads beyond their breakpoints, for instance); absent from JSON when none.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub warnings: Vec<String>,
    /// The critical jump; `None` with `critical_note` when there is none.
    pub critical: Option<Critical>,
    /// Why there is no critical jump.
    pub critical_note: Option<String>,
    /// The first loss of stability on the primary branch, as `analyze` gives it.
    pub first_departure: Option<FirstDeparture>,
    /// The aircraft's aileron limit, deg; `None` without one.
    pub aileron_limit_deg: Option<f64>,
    /// The aileron limit minus |critical aileron|, deg: zero or positive where a full-stick roll
    /// reaches the jump (by this much), negative where the jump lies beyond the stick's travel;
    /// `None` without a limit or without a critical jump.
    pub margin_deg: Option<f64>,
    /// The aileron limit minus the |delta_a| of the first departure (a jump or a Hopf point),
    /// deg: as `margin_deg`, for the departure the branch meets first, which may be a Hopf
    /// point where there is no jump; `None` without a limit or without a jump or Hopf departure.
    pub departure_margin_deg: Option<f64>,
    /// `"certified"` or `"exact"` (the certified route did not answer, a case it does not
    /// cover or a failed certificate, and the exact path did).
    pub route: Option<&'static str>,
    /// The certified clearance over the box of `--uncertainty` (absent without it).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub clearance: Option<PointClearance>,
    /// Why a point analysed without fault has no clearance (its proof refused the box); the
    /// nominal analysis above stands.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub clearance_error: Option<String>,
    /// The native 6-DOF's verdict with `--validate` (absent at points not validated).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub validation: Option<Validation>,
    /// Why a point chosen for `--validate` has no verdict (the 6-DOF refused it).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub validation_error: Option<String>,
}

impl Point {
    /// A point at `altitude_m`, `mach` and `speed_m_s` with nothing found yet.
    fn empty(altitude_m: f64, mach: f64, speed_m_s: f64, elevator: Elevator) -> Point {
        Point {
            altitude_m,
            mach,
            speed_m_s,
            load_factor: elevator.load_factor,
            alpha_deg: None,
            elevator_trim_deg: None,
            delta_e_deg: Some(elevator.increment.to_degrees()),
            trimmed: false,
            reason: None,
            error: None,
            warnings: Vec::new(),
            critical: None,
            critical_note: None,
            first_departure: None,
            aileron_limit_deg: None,
            margin_deg: None,
            departure_margin_deg: None,
            route: None,
            clearance: None,
            clearance_error: None,
            validation: None,
            validation_error: None,
        }
    }

    /// The point of `loaded` (named `name`) at `altitude_m` and `mach`, analysed at `elevator`.
    pub fn at(
        loaded: &Loaded,
        name: &str,
        altitude_m: f64,
        mach: f64,
        elevator: Elevator,
    ) -> Point {
        Point::cleared_at(
            loaded,
            name,
            (altitude_m, Speed::Mach(mach)),
            elevator,
            None,
        )
    }

    /// The point at `altitude_m` and `speed` (Mach or true airspeed) as [`Point::at`], and with
    /// `uncertainty` the certified clearance of the point's box at the same elevator increment.
    pub fn cleared_at(
        loaded: &Loaded,
        name: &str,
        (altitude_m, speed): (f64, Speed),
        elevator: Elevator,
        uncertainty: Option<&Uncertainty>,
    ) -> Point {
        let condition = match Condition::new(altitude_m, speed) {
            Ok(c) => c,
            Err(reason) => {
                // Outside the atmosphere the other speed is unknown: zero, the point untrimmed.
                let (mach, speed_m_s) = match speed {
                    Speed::Mach(m) => (m, 0.0),
                    Speed::True(v) => (0.0, v),
                };
                let mut p = Point::empty(altitude_m, mach, speed_m_s, elevator);
                p.reason = Some(reason);
                return p;
            }
        };
        let mut p = Point::empty(altitude_m, condition.mach, condition.speed, elevator);
        let setup = loaded.setup(condition);
        let trimmed = match trim(&setup, elevator.load_factor) {
            Ok(t) => t,
            Err(reason) => {
                p.reason = Some(reason);
                return p;
            }
        };
        p.trimmed = true;
        p.alpha_deg = Some(trimmed.alpha.to_degrees());
        p.elevator_trim_deg = Some(if trimmed.per_unit_travel {
            trimmed.elevator
        } else {
            trimmed.elevator.to_degrees()
        });
        if let Err(e) = p.analyse(&setup, &trimmed, name, (elevator, uncertainty)) {
            p.error = Some(e);
        }
        p
    }

    /// Imports at the trim `trimmed` and analyses (and clears the box of `uncertainty`) at the
    /// elevator increment, filling in the results.
    fn analyse(
        &mut self,
        setup: &crate::jsbsim::coefficients::Setup,
        trimmed: &Trim,
        name: &str,
        (elevator, uncertainty): (Elevator, Option<&Uncertainty>),
    ) -> Result<(), String> {
        let text = trimmed_file(setup, trimmed)?;
        let ac = aircraft::parse(&text, name).map_err(|e| e.to_string())?;
        self.warnings.clone_from(&ac.warnings);
        self.aileron_limit_deg = ac.limits.aileron_deg;
        let delta_e = elevator.increment;
        let (a, route) = analyze_first_departure(&ac, delta_e).map_err(|e| e.to_string())?;
        self.route = Some(route.name());
        self.take(a);
        if let Some(u) = uncertainty {
            let boxed = u
                .aircraft(&text, name)
                .map_err(|e| format!("--uncertainty: {e}"))?;
            match clear_point(&boxed, delta_e) {
                Ok(c) => self.clearance = Some(c),
                Err(e) => self.clearance_error = Some(e.to_string()),
            }
        }
        Ok(())
    }

    /// The reported parts of `a`.
    fn take(&mut self, a: Analysis) {
        self.critical = a.critical.map(|c| Critical {
            p0: c.p0,
            delta_a_deg: c.delta_a_deg,
            within_limits: c.within_limits,
        });
        self.critical_note = a.critical_note;
        self.margin_deg = a.margin_deg;
        self.departure_margin_deg = match (&a.first_departure, self.aileron_limit_deg) {
            (Some(d), Some(limit)) if d.kind != "unstable_trim" => {
                Some(limit - d.delta_a_deg.abs())
            }
            _ => None,
        };
        self.first_departure = a.first_departure;
    }
}
