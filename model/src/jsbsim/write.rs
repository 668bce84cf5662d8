//! The aircraft file of an import: the nondimensional body-axis format `analyze` reads
//! (`[flight]`, `[geometry]`, `[inertia]` with `ixz`, `[coefficients]`, `[limits]`), in SI,
//! with comments that say where every number came from, and `[import]` with the import's
//! warnings (tables read beyond their breakpoints), which the loader hands to `analyze`.

use super::coefficients::Coefficients;
use super::condition::{Condition, State};
use super::derivatives::Derivative;
use super::digits::{every_digit, short};
use super::mass::Totals;
use super::model::Model;
use super::surfaces::Surface;
use super::trim::Trim;
use super::units::{KG_PER_SLUG, M_PER_FT, SLUG_PER_LB};
use std::fmt::Write;

/// Kilogram square metres per slug square foot (exact SI).
const KGM2_PER_SLUGFT2: f64 = KG_PER_SLUG * M_PER_FT * M_PER_FT;

/// How the numbers were obtained, for the file's head.
const PROVENANCE: &str = "\
# Evaluated natively from the model's aerodynamic functions (no JSBSim at run time).
# Quasi-steady: the alpha-dot and beta-dot terms of the model are left out (not part of
# the paper's model); the configuration is clean and power off: these inputs of the
";

/// The conventions of the coefficients, for the head of `[coefficients]`.
const CONVENTIONS: &str = "\
# Per rad, body axes, moments about the CG (the forces moved from the AERORP); rates
# nondimensional as p b/(2V), q c/(2V), r b/(2V). Central differences, step 1e-6, of the
# evaluated coefficients. The aileron's sign is this project's (positive rolls left):
";

/// What the file is written from.
pub struct Import<'a> {
    /// The model.
    pub model: &'a Model,
    /// The condition.
    pub condition: Condition,
    /// The state the derivatives are taken at.
    pub state: State,
    /// The lift there over the weight.
    pub load_factor: f64,
    /// The trim the state is, if it is one (else alpha was given).
    pub trim: Option<Trim>,
    /// The surfaces.
    pub surfaces: &'a [Surface],
    /// The user's settings.
    pub settings: &'a [(String, f64)],
    /// The coefficients at the state.
    pub base: &'a Coefficients,
    /// The derivatives.
    pub derivatives: &'a [Derivative],
}

/// A number with every digit (shortest round trip).
fn num(x: f64) -> String {
    let s = format!("{x:?}");
    if s.contains('e') {
        format!("{x:e}")
    } else {
        s
    }
}

impl Import<'_> {
    /// The TOML text.
    pub fn toml(&self) -> String {
        let mut t = String::new();
        self.header(&mut t);
        self.warnings_table(&mut t);
        self.flight(&mut t);
        self.mass(&mut t, self.model.totals());
        self.coefficients(&mut t);
        self.limits(&mut t);
        t
    }

    fn header(&self, t: &mut String) {
        let m = self.model;
        let _ = writeln!(
            t,
            "# Imported from the JSBSim model {} (`model import jsbsim`).",
            m.file
        );
        t.push_str(PROVENANCE);
        let _ = writeln!(
            t,
            "# aerodynamics were set to zero: {}.",
            list(&self.base.zeroed)
        );
        if !self.settings.is_empty() {
            let set: Vec<String> = self
                .settings
                .iter()
                .map(|(k, v)| format!("{k} = {}", every_digit(*v)))
                .collect();
            let _ = writeln!(t, "# Set by --set: {}.", set.join(", "));
        }
        let name = if m.name.is_empty() { &m.file } else { &m.name };
        let _ = writeln!(t, "\nname = {:?}", format!("{name} (JSBSim)"));
    }

    /// The import's warnings: the tables the flight state reads beyond their breakpoints,
    /// except those that only axis functions read that are zero at the state and move none of
    /// the file's derivatives (a flap's increment with the flaps up, a hull's water forces in
    /// flight): no number of the file depends on them.
    pub fn warnings(&self) -> Vec<String> {
        let place = super::coefficients::place(&self.condition, &self.state);
        let model = self.model;
        let roots: Vec<usize> = model
            .aero
            .terms
            .iter()
            .zip(&self.base.terms)
            .filter(|(t, v)| {
                let name = &model.functions.list[t.function].name;
                **v != 0.0 || self.derivatives.iter().any(|d| d.functions.contains(name))
            })
            .map(|(t, _)| t.function)
            .collect();
        let read = super::clamp::read_by(&model.functions, &roots, model.aero.rp_shift.as_ref());
        let clamps: Vec<_> = (self.base.clamps.iter())
            .filter(|c| c.function.is_none_or(|f| read[f]))
            .cloned()
            .collect();
        super::clamp::warnings(&clamps, &model.functions, &place)
    }

    fn warnings_table(&self, t: &mut String) {
        let warnings = self.warnings();
        if warnings.is_empty() {
            return;
        }
        let _ = writeln!(t, "\n[import]");
        for w in &warnings {
            let _ = writeln!(t, "# Warning: {w}.");
        }
        let _ = writeln!(t, "warnings = [");
        for w in &warnings {
            let _ = writeln!(t, "    {},", toml_string(w));
        }
        let _ = writeln!(t, "]");
    }

    fn flight(&self, t: &mut String) {
        let c = &self.condition;
        let _ = writeln!(t, "\n[flight]");
        let _ = writeln!(
            t,
            "# Altitude {} m; U.S. Standard Atmosphere 1976 (JSBSim's standard day): {:.2} K,",
            c.altitude_m, c.air.temperature
        );
        let _ = writeln!(
            t,
            "# speed of sound {:.3} m/s; Mach {:.4}.",
            c.air.sound_speed, c.mach
        );
        self.point(t);
        let _ = writeln!(t, "speed = {}          # m/s, true airspeed", num(c.speed));
        let _ = writeln!(t, "density = {}        # kg/m^3", num(c.air.density));
        let _ = writeln!(
            t,
            "alpha = {}          # rad, body-axis angle of attack at the point",
            num(self.state.alpha)
        );
        let _ = writeln!(
            t,
            "load_factor = {}    # lift over weight at the point",
            num(self.load_factor)
        );
    }

    /// The comment that says where the derivatives are taken: the trim, or the alpha given.
    fn point(&self, t: &mut String) {
        let alpha = self.state.alpha.to_degrees();
        let cm = self.base.values[super::coefficients::CM];
        match &self.trim {
            Some(trim) => {
                let _ = writeln!(
                    t,
                    "# Trim (the point of linearisation): alpha {alpha:.4} deg, elevator {} \
                     (JSBSim's sign,\n# positive trailing edge down), n = {}, q = {:.6} rad/s.",
                    trim.elevator_text(),
                    trim.load_factor,
                    trim.q
                );
                let _ = writeln!(
                    t,
                    "# A wings-level pull-up through level flight, q = (n - 1) g / V: lift = n x \
                     weight\n# (thrust left out), pitching moment about the CG zero (Cm \
                     {cm:.1e}), the elevator within its\n# travel. The derivatives are taken \
                     there, the elevator at its trim position; delta_e is\n# an increment from \
                     it."
                );
            }
            None => {
                let _ = writeln!(
                    t,
                    "# Alpha {alpha:.4} deg as given, elevator neutral, q = 0: not a trim (Cm = \
                     {cm:.4} there);\n# load_factor is the lift there over the weight."
                );
            }
        }
    }

    fn mass(&self, t: &mut String, totals: Totals) {
        let m = self.model;
        let mass_kg = totals.weight * SLUG_PER_LB * KG_PER_SLUG;
        let _ = writeln!(t, "\n[geometry]");
        let parts: Vec<String> = m
            .mass
            .masses
            .iter()
            .map(|x| format!("{} {:.1} lbs", x.name, x.weight))
            .collect();
        let _ = writeln!(
            t,
            "# <mass_balance> and <propulsion> tanks as loaded: {} (total {:.1} lbs).",
            parts.join(", "),
            totals.weight
        );
        let _ = writeln!(t, "mass = {}           # kg", num(mass_kg));
        let _ = writeln!(
            t,
            "# <metrics>: wingarea {:.3} ft^2, wingspan {:.3} ft, chord {:.3} ft.",
            m.metrics.wing_area, m.metrics.span, m.metrics.chord
        );
        let _ = writeln!(
            t,
            "wing_area = {}      # m^2",
            num(m.metrics.wing_area * M_PER_FT * M_PER_FT)
        );
        let _ = writeln!(t, "span = {}           # m", num(m.metrics.span * M_PER_FT));
        let _ = writeln!(
            t,
            "chord = {}          # m",
            num(m.metrics.chord * M_PER_FT)
        );
        let [ix, iy, iz, ixz] = totals.moments();
        let _ = writeln!(t, "\n[inertia]");
        let _ = writeln!(t, "# Body axes about the CG as loaded (x {:.2}, y {:.2}, z {:.2} in, JSBSim's structural frame),", totals.cg[0], totals.cg[1], totals.cg[2]);
        let _ = writeln!(
            t,
            "# kg m^2; ixz is the integral of x z dm (JSBSim's <ixz> has the opposite sign)."
        );
        for (k, v) in [("ix", ix), ("iy", iy), ("iz", iz), ("ixz", ixz)] {
            let _ = writeln!(t, "{k} = {}", num(v * KGM2_PER_SLUGFT2));
        }
    }

    fn coefficients(&self, t: &mut String) {
        let _ = writeln!(t, "\n[coefficients]");
        t.push_str(CONVENTIONS);
        let _ = writeln!(
            t,
            "# minus JSBSim's, whose positive left aileron rolls right. At the point: {}.",
            {
                let v: Vec<String> = super::coefficients::NAMES
                    .iter()
                    .zip(self.base.values)
                    .map(|(n, v)| {
                        if v.abs() >= 1e9 {
                            format!("{n} {}", short(v))
                        } else {
                            format!("{n} {v:.5}")
                        }
                    })
                    .collect();
                v.join(", ")
            }
        );
        let kinks: Vec<&str> = self
            .derivatives
            .iter()
            .filter(|d| d.kink.is_some())
            .map(|d| d.key)
            .collect();
        if !kinks.is_empty() {
            let _ = writeln!(
                t,
                "# Kinks at the point (mean of the one-sided slopes given): {}.",
                kinks.join(", ")
            );
        }
        for d in self.derivatives {
            let mut note = if d.functions.is_empty() {
                "no function depends on it".to_string()
            } else {
                d.functions.join(", ")
            };
            if let Some((lo, hi)) = d.kink {
                note = format!("kink: slopes {lo:.6} / {hi:.6}; {note}");
            }
            let _ = writeln!(t, "{} = {}   # {}", d.key, num(d.value), note);
        }
    }

    fn limits(&self, t: &mut String) {
        let known: Vec<&Surface> = self
            .surfaces
            .iter()
            .filter(|s| s.range.is_some() && !s.per_unit_travel)
            .collect();
        for s in self.surfaces.iter().filter(|s| s.per_unit_travel) {
            let _ = writeln!(t, "# The {} is given only as normalised travel: its derivatives are per unit travel, no limit.", s.control.name());
        }
        for note in self.surfaces.iter().filter_map(|s| s.note.as_ref()) {
            let _ = writeln!(t, "# Warning: {note}.");
        }
        if known.is_empty() {
            return;
        }
        let _ = writeln!(t, "\n[limits]");
        t.push_str(LIMITS);
        for s in known {
            let r = s.range.as_ref().expect("known");
            let end = if r.at_plus == -r.at_minus {
                "both ends equal".to_string()
            } else {
                format!(
                    "the limit is the smaller end, at {:+}",
                    r.limiting_command()
                )
            };
            let _ = writeln!(
                t,
                "# {}: {:.4} deg at command +1, {:.4} deg at -1 ({end}); {}",
                s.control.name(),
                r.at_plus.to_degrees(),
                r.at_minus.to_degrees(),
                r.source
            );
            let _ = writeln!(t, "{} = {}", s.control.name(), num(r.limit().to_degrees()));
        }
    }
}

/// How the limits were read, for the head of `[limits]`.
const LIMITS: &str = "\
# Deflection limits, deg, as JSBSim moves the surfaces: the position the flight control
# system settles at with the pilot's command (fcs/*-cmd-norm) at +1 and at -1, trims neutral,
# wings level, no rates, no sideslip. The analysis takes one limit on |deflection|: the
# smaller end, the travel the surface reaches to either side.
";

/// `text` as a TOML basic string: quoted, with `"`, `\\` and control characters escaped.
fn toml_string(text: &str) -> String {
    let mut s = String::from('"');
    for c in text.chars() {
        match c {
            '"' => s.push_str("\\\""),
            '\\' => s.push_str("\\\\"),
            c if c.is_control() => s.push_str(&format!("\\u{:04X}", u32::from(c))),
            c => s.push(c),
        }
    }
    s.push('"');
    s
}

/// A list for a comment.
fn list(items: &[String]) -> String {
    if items.is_empty() {
        "none".into()
    } else {
        items.join(", ")
    }
}
