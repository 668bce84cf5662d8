//! The n-g trim of an import: the angle of attack and the elevator at which a wings-level
//! pull-up at load factor `n` is in equilibrium, found with the same native evaluation of the
//! model's coefficients that the import differentiates.
//!
//! Two equations in alpha and the elevator: the aerodynamic lift carries `n` times the weight,
//! `CL qbar S = n m g` (thrust left out: the clean power-off aerodynamics of the import, and
//! JSBSim's own load factor is the aerodynamic lift over the weight too), and the pitching moment
//! about the CG is zero, `Cm = 0`. The state is the instant of a steady pull-up through level
//! flight: flight path level, pitch rate `q = (n - 1) g / V` (the flight path turns at that rate
//! when the lift exceeds the weight by `(n - 1) m g`), so that `n = 1` is level flight and
//! `n = 0` the unloaded (zero-lift) push-over of a roll.
//!
//! The elevator is found at each alpha (the pitching moment's zero over the elevator), then alpha
//! where the lift is met, the first from below; the elevator must lie within its travel.

use super::coefficients::{Sequence, Setup, CL, CM};
use super::condition::State;
use super::digits::{every_digit, short};
use super::surfaces::Control;
use super::units::{KG_PER_SLUG, SLUG_PER_LB};

/// Standard gravity, m/s^2 (JSBSim's weight is the mass times it).
pub const G: f64 = 9.806_65;

/// The angles of attack searched, deg: the first lift solution from below.
const ALPHA_SEARCH_DEG: (f64, f64) = (-10.0, 30.0);

/// The alpha step of the search, deg.
const ALPHA_STEP_DEG: f64 = 0.5;

/// The elevator angles searched for a pitch balance, deg, wider than any travel, so that a
/// balance beyond the travel is found and named (the model's tables hold their last value
/// beyond their breakpoints, as JSBSim's do).
const ELEVATOR_SEARCH_DEG: f64 = 60.0;

/// A trim found.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Trim {
    /// Load factor: lift over weight.
    pub load_factor: f64,
    /// Angle of attack, rad.
    pub alpha: f64,
    /// Elevator, rad (JSBSim's sign, positive trailing edge down), or normalised travel when
    /// the model gives the elevator only as travel.
    pub elevator: f64,
    /// Whether [`Trim::elevator`] is normalised travel rather than an angle.
    pub per_unit_travel: bool,
    /// Pitch rate, rad/s.
    pub q: f64,
}

impl Trim {
    /// The flight state of the trim: wings level, no sideslip, the pull-up's pitch rate, the
    /// elevator at its trim position, aileron and rudder neutral.
    pub fn state(&self) -> State {
        State {
            alpha: self.alpha,
            beta: 0.0,
            rates: [0.0, self.q, 0.0],
            surfaces: [0.0, self.elevator, 0.0],
        }
    }

    /// The elevator as a person reads it: `"-8.83 deg"` or `"travel -0.25"`.
    pub fn elevator_text(&self) -> String {
        if self.per_unit_travel {
            format!("travel {:.4}", self.elevator)
        } else {
            format!("{:.4} deg", self.elevator.to_degrees())
        }
    }
}

/// The pull-up's pitch rate, rad/s, at load factor `n` and true airspeed `speed` (m/s).
pub fn pull_up_rate(n: f64, speed: f64) -> f64 {
    (n - 1.0) * G / speed
}

/// The elevator's travel and the interval searched for its pitch balance.
struct Travel {
    /// The limits, when known: (min, max, where read).
    limits: Option<(f64, f64, String)>,
    /// The search interval.
    search: (f64, f64),
    /// Whether the variable is normalised travel.
    per_unit_travel: bool,
}

impl Travel {
    fn of(setup: &Setup) -> Travel {
        let surface = setup
            .surfaces
            .iter()
            .find(|s| s.control == Control::Elevator);
        let wide = ELEVATOR_SEARCH_DEG.to_radians();
        match surface {
            Some(s) if s.per_unit_travel => Travel {
                limits: Some((-1.0, 1.0, "normalised travel".to_string())),
                search: (-1.0, 1.0),
                per_unit_travel: true,
            },
            Some(s) => {
                let limits = s.range.as_ref().map(|r| (r.min, r.max, r.source.clone()));
                let search = match &limits {
                    Some((lo, hi, _)) => (lo.min(-wide), hi.max(wide)),
                    None => (-wide, wide),
                };
                Travel {
                    limits,
                    search,
                    per_unit_travel: false,
                }
            }
            None => Travel {
                limits: None,
                search: (-wide, wide),
                per_unit_travel: false,
            },
        }
    }

    /// `x` as the message says it.
    fn show(&self, x: f64) -> String {
        if self.per_unit_travel {
            format!("travel {x:.3}")
        } else {
            format!("{:.2} deg", x.to_degrees())
        }
    }
}

/// `x` with four decimals, never `-0.0000`; from 1e9 on in exponent notation ([`short`]).
fn four(x: f64) -> String {
    if x.is_finite() && x.abs() >= 1e9 {
        return short(x);
    }
    let s = format!("{x:.4}");
    match s.strip_prefix('-') {
        Some(rest) if rest.chars().all(|c| c == '0' || c == '.') => rest.to_string(),
        _ => s,
    }
}

/// The zero of `f` between `a` and `b` (where `f` changes sign), by the Illinois variant of
/// regula falsi, to `tol` in the argument.
fn zero(
    f: &mut dyn FnMut(f64) -> Result<f64, String>,
    (mut a, mut fa): (f64, f64),
    (mut b, mut fb): (f64, f64),
    tol: f64,
) -> Result<f64, String> {
    let mut side = 0;
    for _ in 0..200 {
        if fa == 0.0 {
            return Ok(a);
        }
        if fb == 0.0 || (b - a).abs() <= tol {
            return Ok(if fa.abs() < fb.abs() { a } else { b });
        }
        let mut c = (a * fb - b * fa) / (fb - fa);
        if !(c > a.min(b) && c < a.max(b)) {
            c = 0.5 * (a + b);
        }
        let fc = f(c)?;
        if (fc > 0.0) == (fb > 0.0) {
            b = c;
            fb = fc;
            if side == -1 {
                fa /= 2.0;
            }
            side = -1;
        } else {
            a = c;
            fa = fc;
            if side == 1 {
                fb /= 2.0;
            }
            side = 1;
        }
    }
    Ok(0.5 * (a + b))
}

/// CL and Cm at `alpha`, elevator `de` and pitch rate `q`, refused when not finite.
fn cl_cm(setup: &mut Sequence, alpha: f64, de: f64, q: f64) -> Result<(f64, f64), String> {
    let state = State {
        alpha,
        beta: 0.0,
        rates: [0.0, q, 0.0],
        surfaces: [0.0, de, 0.0],
    };
    let values = setup.values(&state).map_err(|e| e.to_string())?;
    let (cl, cm) = (values[CL], values[CM]);
    if !(cl.is_finite() && cm.is_finite()) {
        return Err(format!(
            "the trim met CL = {cl}, Cm = {cm} at alpha {:.3} deg, elevator {:.3}: the model's \
             coefficients are not finite there",
            alpha.to_degrees(),
            de
        ));
    }
    Ok((cl, cm))
}

/// The elevator that zeroes the pitching moment at `alpha` within the search interval, with
/// the lift coefficient there; `None` when the moment keeps one sign over the interval. The
/// zero is one of the elevators evaluated on the way, whose lift is kept rather than evaluated
/// again.
fn pitch_balance(
    setup: &mut Sequence,
    travel: &Travel,
    alpha: f64,
    q: f64,
) -> Result<Option<(f64, f64)>, String> {
    let (lo, hi) = travel.search;
    let (cl_lo, m_lo) = cl_cm(setup, alpha, lo, q)?;
    let (cl_hi, m_hi) = cl_cm(setup, alpha, hi, q)?;
    if (m_lo > 0.0) == (m_hi > 0.0) && m_lo != 0.0 && m_hi != 0.0 {
        return Ok(None);
    }
    let mut lifts = vec![(lo, cl_lo), (hi, cl_hi)];
    let de = {
        let mut cm = |de: f64| {
            cl_cm(setup, alpha, de, q).map(|(cl, m)| {
                lifts.push((de, cl));
                m
            })
        };
        zero(&mut cm, (lo, m_lo), (hi, m_hi), 1e-13)?
    };
    let cl = match lifts
        .iter()
        .rev()
        .find(|(d, _)| d.to_bits() == de.to_bits())
    {
        Some(&(_, cl)) => cl,
        None => cl_cm(setup, alpha, de, q)?.0,
    };
    Ok(Some((de, cl)))
}

/// The pitch balances found at each angle of attack (rad) of one trim, so that none is sought
/// twice.
#[derive(Default)]
struct Balances(Vec<(f64, Option<(f64, f64)>)>);

impl Balances {
    /// [`pitch_balance`] at `alpha`, sought once.
    fn at(
        &mut self,
        setup: &mut Sequence,
        travel: &Travel,
        alpha: f64,
        q: f64,
    ) -> Result<Option<(f64, f64)>, String> {
        if let Some(&(_, b)) = self
            .0
            .iter()
            .rev()
            .find(|(a, _)| a.to_bits() == alpha.to_bits())
        {
            return Ok(b);
        }
        let b = pitch_balance(setup, travel, alpha, q)?;
        self.0.push((alpha, b));
        Ok(b)
    }
}

/// The trim of `setup` at load factor `n`, or why it is untrimmable (the message names the
/// limit: the elevator's travel, no pitch balance, or no lift solution below CLmax, and the
/// user's `--set` values, which may be what moved the model there).
pub fn trim(setup: &Setup, n: f64) -> Result<Trim, String> {
    trim_unnamed(setup, n).map_err(|e| with_settings(e, &setup.settings))
}

/// `message` followed by the `--set` values it arose under, if any.
pub fn with_settings(message: String, settings: &[(String, f64)]) -> String {
    if settings.is_empty() {
        return message;
    }
    let set: Vec<String> = settings
        .iter()
        .map(|(k, v)| format!("--set {k}={}", every_digit(*v)))
        .collect();
    format!("{message} (with {})", set.join(" "))
}

/// [`trim`] without naming the `--set` values.
fn trim_unnamed(setup: &Setup, n: f64) -> Result<Trim, String> {
    if !(n.is_finite() && n.abs() <= 20.0) {
        return Err(format!(
            "load factor {n}: expected a finite load factor of at most 20 g"
        ));
    }
    let weight = setup.model.totals().weight;
    let qs = setup.condition.qbar_psf() * setup.model.metrics.wing_area;
    let need = n * weight / qs;
    let q = pull_up_rate(n, setup.condition.speed);
    let travel = Travel::of(setup);
    let setup = &mut setup.sequence();
    let untrimmable = |why: String| format!("untrimmable at n = {n}: {why}");
    let (a0, a1) = ALPHA_SEARCH_DEG;
    let steps = ((a1 - a0) / ALPHA_STEP_DEG).round() as usize;
    let mut last: Option<(f64, f64)> = None;
    let mut best: Option<(f64, f64)> = None;
    let mut balanced_any = false;
    let mut gap_from: Option<f64> = None;
    let mut balances = Balances::default();
    for k in 0..=steps {
        let alpha = (a0 + k as f64 * ALPHA_STEP_DEG).to_radians();
        let Some((_, cl)) = balances.at(setup, &travel, alpha, q)? else {
            gap_from = gap_from.or(last.map(|(a, _)| a)).or(Some(alpha));
            continue;
        };
        balanced_any = true;
        let excess = cl - need;
        if best.is_none_or(|(_, c)| cl > c) {
            best = Some((alpha, cl));
        }
        if last.is_none() && excess > 0.0 {
            return Err(untrimmable(format!(
                "at alpha {:.1} deg the pitch-balanced lift coefficient {} already exceeds \
                 the {} that n x weight needs (fly slower or higher, or at a larger load \
                 factor)",
                alpha.to_degrees(),
                four(cl),
                four(need)
            )));
        }
        if let Some((a_prev, e_prev)) = last {
            if e_prev <= 0.0 && excess >= 0.0 {
                if let Some(from) = gap_from {
                    return Err(untrimmable(format!(
                        "the lift reaches n x weight between alpha {:.2} and {:.2} deg, where no \
                         elevator from {} to {} zeroes the pitching moment (beyond the model's \
                         elevator tables or the surface's authority)",
                        from.to_degrees(),
                        alpha.to_degrees(),
                        travel.show(travel.search.0),
                        travel.show(travel.search.1)
                    )));
                }
                return refine(
                    (setup, &mut balances),
                    &travel,
                    (n, need, q),
                    (a_prev, e_prev),
                    (alpha, excess),
                );
            }
        }
        gap_from = None;
        last = Some((alpha, excess));
    }
    if !balanced_any {
        return Err(untrimmable(format!(
            "no elevator from {} to {} zeroes the pitching moment at any alpha from {a0} to \
             {a1} deg",
            travel.show(travel.search.0),
            travel.show(travel.search.1)
        )));
    }
    let (alpha_best, cl_best) = best.expect("balanced somewhere");
    let end = if alpha_best >= a1.to_radians() - 1e-12 {
        format!("still rising at {a1} deg, the end of the search")
    } else {
        format!("CLmax, at alpha {:.1} deg", alpha_best.to_degrees())
    };
    Err(untrimmable(format!(
        "no lift solution from {a0} to {a1} deg alpha: the largest lift coefficient of the \
         pitch-balanced aircraft is {} ({end}), n x weight ({n} x {weight:.0} lbs, {:.0} kg) \
         needs CL = {} (fly faster or lower, or at a smaller load factor)",
        four(cl_best),
        weight * SLUG_PER_LB * KG_PER_SLUG,
        four(need)
    )))
}

/// The trim between two alphas of the search whose lift excess changes sign, then the travel
/// checked.
fn refine(
    (setup, balances): (&mut Sequence, &mut Balances),
    travel: &Travel,
    (n, need, q): (f64, f64, f64),
    lo: (f64, f64),
    hi: (f64, f64),
) -> Result<Trim, String> {
    let mut excess = |alpha: f64| -> Result<f64, String> {
        match balances.at(setup, travel, alpha, q)? {
            Some((_, cl)) => Ok(cl - need),
            None => Err(format!(
                "untrimmable at n = {n}: no elevator zeroes the pitching moment at alpha {:.3} \
                 deg, where the lift reaches n x weight",
                alpha.to_degrees()
            )),
        }
    };
    let alpha = zero(&mut excess, lo, hi, 1e-13)?;
    let (elevator, _) = balances
        .at(setup, travel, alpha, q)?
        .ok_or_else(|| format!("untrimmable at n = {n}: no pitch balance at the trim's alpha"))?;
    if let Some((min, max, source)) = &travel.limits {
        if elevator < *min || elevator > *max {
            return Err(format!(
                "untrimmable at n = {n}: the trim needs elevator {} (alpha {:.2} deg), beyond \
                 its travel of {} to {} ({source})",
                travel.show(elevator),
                alpha.to_degrees(),
                travel.show(*min),
                travel.show(*max)
            ));
        }
    }
    Ok(Trim {
        load_factor: n,
        alpha,
        elevator,
        per_unit_travel: travel.per_unit_travel,
        q,
    })
}

/// The lift of coefficient `lift_coefficient` at `setup`'s condition in weights: the load
/// factor that an angle of attack given by the user holds.
pub fn lift_in_weights(setup: &Setup, lift_coefficient: f64) -> f64 {
    lift_coefficient * setup.condition.qbar_psf() * setup.model.metrics.wing_area
        / setup.model.totals().weight
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::jsbsim::condition::{Condition, Speed};
    use crate::jsbsim::model::Model;
    use crate::jsbsim::surfaces::{Range, Surface};
    use crate::jsbsim::units::FT_PER_M;

    /// A model whose lift and pitching moment are linear, `CL = 0.2 + 4 alpha + 0.5 de` and
    /// `Cm = 0.05 - 0.8 alpha - 1.2 de - 10 q c / (2V)`, the CG at the reference point.
    const LINEAR: &str = r#"<?xml version="1.0"?>
<fdm_config name="Linear">
 <metrics>
   <wingarea unit="FT2">200</wingarea><wingspan unit="FT">30</wingspan><chord unit="FT">8</chord>
   <location name="AERORP" unit="IN"><x>100</x><y>0</y><z>0</z></location>
 </metrics>
 <mass_balance>
   <ixx unit="SLUG*FT2">3000</ixx><iyy unit="SLUG*FT2">20000</iyy><izz unit="SLUG*FT2">22000</izz>
   <emptywt unit="LBS">15000</emptywt>
   <location name="CG" unit="IN"><x>100</x><y>0</y><z>0</z></location>
 </mass_balance>
 <aerodynamics>
  <axis name="LIFT"><function name="aero/lift"><product>
    <property>aero/qbar-psf</property><property>metrics/Sw-sqft</property>
    <sum><value>0.2</value>
      <product><value>4</value><property>aero/alpha-rad</property></product>
      <product><value>0.5</value><property>fcs/elevator-pos-rad</property></product></sum>
  </product></function></axis>
  <axis name="PITCH"><function name="aero/pitch"><product>
    <property>aero/qbar-psf</property><property>metrics/Sw-sqft</property>
    <property>metrics/cbarw-ft</property>
    <sum><value>0.05</value>
      <product><value>-0.8</value><property>aero/alpha-rad</property></product>
      <product><value>-1.2</value><property>fcs/elevator-pos-rad</property></product>
      <product><value>-10</value><property>aero/ci2vel</property>
        <property>velocities/q-aero-rad_sec</property></product></sum>
  </product></function></axis>
 </aerodynamics>
</fdm_config>"#;

    fn with_linear<T>(body: impl FnOnce(&Setup) -> T) -> T {
        let model = Model::parse(LINEAR, "linear.xml").unwrap_or_else(|e| panic!("{e}"));
        let surface = |control, range| Surface {
            control,
            range,
            note: None,
            per_unit_travel: false,
        };
        let elevator = Range {
            min: -0.3,
            max: 0.25,
            at_plus: 0.25,
            at_minus: -0.3,
            source: "the test".to_string(),
        };
        let setup = Setup::new(
            &model,
            Condition::new(3000.0, Speed::Mach(0.5)).unwrap(),
            vec![
                surface(Control::Aileron, None),
                surface(Control::Elevator, Some(elevator)),
                surface(Control::Rudder, None),
            ],
            Vec::new(),
        );
        body(&setup)
    }

    /// The trim against the two linear equations solved by hand (Cramer's rule). To 2e-9 rad:
    /// the model's forces scale with the dynamic pressure it reads (aero/qbar-psf, from the
    /// density in slug/ft^3 and the speed in ft/s), whose unit factors differ from those of the
    /// condition's qbar used here by 3.5e-9 relative, about 1e-9 rad of alpha at these lifts.
    #[test]
    fn the_trim_of_a_linear_model_solves_lift_and_pitch_by_hand() {
        with_linear(|setup| {
            let qs = setup.condition.qbar_psf() * 200.0;
            let v_fps = setup.condition.speed * FT_PER_M;
            for n in [0.0, 1.0, 2.5, -0.5] {
                let q = (n - 1.0) * G / setup.condition.speed;
                let lift = n * 15000.0 / qs - 0.2;
                let pitch = -0.05 + 10.0 * q * 8.0 / (2.0 * v_fps);
                // 4 a + 0.5 de = lift; -0.8 a - 1.2 de = pitch.
                let det = 4.0 * -1.2 - 0.5 * -0.8;
                let alpha = (lift * -1.2 - 0.5 * pitch) / det;
                let de = (4.0 * pitch + 0.8 * lift) / det;
                let t = trim(setup, n).unwrap();
                assert!((t.alpha - alpha).abs() < 2e-9, "n {n}: {t:?} vs {alpha}");
                assert!((t.elevator - de).abs() < 2e-9, "n {n}: {t:?} vs {de}");
                assert_eq!(t.q, q);
                assert_eq!(t.state().rates, [0.0, q, 0.0]);
            }
        });
    }

    /// Beyond the elevator's travel, and beyond the lift of 30 deg alpha, the trim is refused
    /// naming the limit.
    #[test]
    fn an_untrimmable_load_factor_names_the_limit() {
        with_linear(|setup| {
            assert!(trim(setup, 6.0).is_ok());
            let e = trim(setup, 7.0).unwrap_err();
            assert!(
                e.starts_with("untrimmable at n = 7: the trim needs elevator")
                    && e.contains("beyond its travel of -17.19 deg to 14.32 deg (the test)"),
                "{e}"
            );
            let e = trim(setup, 15.0).unwrap_err();
            assert!(e.contains("no lift solution"), "{e}");
            assert_eq!(
                (four(-1e-7), four(-0.5), four(2.0)),
                ("0.0000".into(), "-0.5000".into(), "2.0000".into())
            );
            let e = trim(setup, f64::NAN).unwrap_err();
            assert!(e.contains("expected a finite load factor"), "{e}");
        });
    }
}
