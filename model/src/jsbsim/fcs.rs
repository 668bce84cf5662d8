//! The flight control system's components at steady state: what each writes once its
//! actuators and lags have settled, for given pilot commands, following the chain from the
//! stick to a surface position. The semantics are JSBSim's (learned from its FGGain, FGSummer,
//! FGActuator, FGKinemat, FGFilter, FGSwitch and FGFCSComponent, and checked against JSBSim
//! itself by the integration tests); a component whose steady output is not known (a table of
//! the flight state in the path, an integrator, a function) stops the chain with a message
//! naming it, never a guessed value.

use super::systems::{parse, SystemFile};
use super::xml::{child, children, parse_number, text};
use roxmltree::Node;
use std::collections::BTreeMap;

/// Flight-state properties that are zero in the analysed state (wings level, no rates, no
/// sideslip): feedback through them (a yaw damper, a roll-rate damper) adds nothing there.
const ZERO_IN_TRIM: [&str; 10] = [
    "velocities/p-rad_sec",
    "velocities/q-rad_sec",
    "velocities/r-rad_sec",
    "velocities/p-aero-rad_sec",
    "velocities/q-aero-rad_sec",
    "velocities/r-aero-rad_sec",
    "aero/beta-rad",
    "aero/beta-deg",
    "aero/mag-beta-rad",
    "aero/mag-beta-deg",
];

/// Property trees that the flight state, the environment or the engines write: not the
/// pilot's, so their values are not known without flying the model.
const STATE_TREES: [&str; 14] = [
    "velocities/",
    "aero/",
    "attitude/",
    "position/",
    "accelerations/",
    "gear/",
    "atmosphere/",
    "propulsion/",
    "forces/",
    "moments/",
    "inertia/",
    "simulation/",
    "systems/",
    "guidance/",
];

/// A number or a property (possibly negated, as JSBSim writes `-fcs/x`).
#[derive(Clone, Debug, PartialEq)]
pub enum Operand {
    /// A constant.
    Number(f64),
    /// A property, with its sign.
    Property(String, f64),
}

impl Operand {
    /// Reads the text of an input, gain or clip bound.
    pub fn parse(text: &str) -> Operand {
        let t = text.trim();
        match parse_number(t) {
            Some(v) => Operand::Number(v),
            None => match t.strip_prefix('-') {
                Some(p) => Operand::Property(p.trim().to_string(), -1.0),
                None => Operand::Property(t.to_string(), 1.0),
            },
        }
    }
}

/// A test of a switch: JSBSim's `<test>` (lines `a OP b`, nested tests, AND or OR).
#[derive(Clone, Debug, PartialEq)]
pub enum Condition {
    /// Every part holds (`logic="AND"`, JSBSim's default).
    All(Vec<Condition>),
    /// Some part holds (`logic="OR"`).
    Any(Vec<Condition>),
    /// A comparison.
    Compare(Operand, String, Operand),
}

/// What a component computes, at steady state.
#[derive(Clone, Debug, PartialEq)]
pub enum Kind {
    /// `aerosurface_scale`: the input mapped from its domain to its range, times the gain.
    Scale {
        /// `<gain>` (default 1).
        gain: Operand,
        /// `<domain>` min and max (default -1, 1).
        domain: (f64, f64),
        /// `<range>` min and max.
        range: (f64, f64),
        /// `<zero_centered>` (default true): each side scaled on its own.
        zero_centered: bool,
    },
    /// `pure_gain`: the input times the gain.
    Gain(Operand),
    /// `scheduled_gain`: the input times the gain times a table of the flight state.
    Scheduled(Operand),
    /// `summer`: the sum of the inputs plus the bias.
    Summer(f64),
    /// `actuator`: the input, less half a deadband or hysteresis width (reached from neutral),
    /// plus the bias; the lag and the rate limit only delay it.
    Actuator {
        /// `<bias>`.
        bias: f64,
        /// Half the `<deadband_width>` plus half the `<hysteresis_width>`.
        dead: f64,
    },
    /// `kinematic`: the input times the last setting (unless `<noscale/>`), held between the
    /// first and last setting.
    Kinematic {
        /// First and last `<position>` of the settings.
        ends: (f64, f64),
        /// Whether the input is scaled by the last setting.
        scale: bool,
    },
    /// `lag_filter`: the input (unit steady gain).
    Lag,
    /// A linear element whose steady output is not a fixed multiple of its input
    /// (`lead_lag_filter`, `washout_filter`, `second_order_filter`, `integrator`, `pid`): zero
    /// while its input stays zero (its states start at zero), else not followed.
    Linear,
    /// `switch`: the value of the first test that holds, else the default.
    Switch {
        /// Each test and its value, in order; `None` is the default.
        tests: Vec<(Option<Condition>, Operand)>,
    },
    /// Any other component: its steady output is not followed.
    Other,
}

/// One component.
#[derive(Clone, Debug, PartialEq)]
pub struct Component {
    /// Its element name (`summer`, ...).
    pub tag: String,
    /// Its `name`.
    pub name: String,
    /// Where it is: file and line.
    pub at: String,
    /// Its inputs.
    pub inputs: Vec<Operand>,
    /// What it computes.
    pub kind: Kind,
    /// `<clipto>` bounds.
    pub clip: Option<(Operand, Operand)>,
    /// Why it cannot be read, if so (a missing number).
    pub unreadable: Option<String>,
}

impl Component {
    /// How messages name it.
    pub fn label(&self) -> String {
        format!("<{}> \"{}\" ({})", self.tag, self.name, self.at)
    }
}

/// The components of the flight control system and the initial values of its interface
/// properties, indexed by the property each writes.
#[derive(Clone, Debug, Default)]
pub struct Fcs {
    /// Each written property with its writers (more than one: not followed).
    pub writers: BTreeMap<String, Vec<Component>>,
    /// `<property value="...">` initial values.
    pub initial: BTreeMap<String, f64>,
}

/// The property a component's name writes: `fcs/` and the name in lower case with spaces as
/// dashes, or the name itself when it is a path.
pub fn name_property(name: &str) -> String {
    if name.contains('/') {
        return name.to_string();
    }
    let p: String = name
        .chars()
        .map(|c| {
            if c.is_ascii_uppercase() {
                c.to_ascii_lowercase()
            } else if c.is_whitespace() {
                '-'
            } else {
                c
            }
        })
        .collect();
    format!("fcs/{p}")
}

impl Fcs {
    /// The components of `files` (the model's `<flight_control>`, `<autopilot>` and `<system>`
    /// elements and the files they reference).
    pub fn read(files: &[SystemFile]) -> Fcs {
        let mut fcs = Fcs::default();
        for file in files {
            let Ok(doc) = parse(&file.text) else {
                continue;
            };
            let systems = doc.descendants().filter(|n| {
                matches!(
                    n.tag_name().name(),
                    "system" | "flight_control" | "autopilot"
                )
            });
            for system in systems {
                let name = file.path.file_name().unwrap_or(file.path.as_os_str());
                fcs.add_system(system, &name.to_string_lossy());
            }
        }
        fcs
    }

    /// Adds the components of one system element.
    pub fn add_system(&mut self, system: Node, file: &str) {
        for p in children(system, "property") {
            let value = p.attribute("value").and_then(|v| parse_number(v.trim()));
            self.initial
                .insert(text(p).trim().to_string(), value.unwrap_or(0.0));
        }
        for channel in children(system, "channel") {
            for node in channel.children().filter(|n| n.is_element()) {
                let line = node.document().text_pos_at(node.range().start).row;
                let c = component(node, &format!("{file}:{line}"));
                let mut outputs: Vec<String> = children(node, "output")
                    .map(|o| text(o).trim().to_string())
                    .collect();
                outputs.push(name_property(&c.name));
                outputs.dedup();
                for o in outputs {
                    self.writers.entry(o).or_default().push(c.clone());
                }
            }
        }
    }

    /// The steady value of `property` with the pilot's `commands` set (every other pilot or
    /// autopilot setting at its initial value), or why it is not known.
    pub fn value(&self, property: &str, commands: &[(&str, f64)]) -> Result<f64, String> {
        Chain {
            fcs: self,
            commands,
        }
        .property(property, 0)
    }
}

impl Fcs {
    /// The components `property` depends on, nearest first: the chain a limit was read from.
    pub fn chain(&self, property: &str) -> Vec<String> {
        let mut seen: Vec<String> = Vec::new();
        let mut todo = vec![property.to_string()];
        while let Some(p) = todo.pop() {
            for c in self.writers.get(&p).into_iter().flatten() {
                let label = c.label();
                if seen.contains(&label) || seen.len() > MAX_DEPTH {
                    continue;
                }
                seen.push(label);
                todo.extend(c.inputs.iter().rev().filter_map(|i| match i {
                    Operand::Property(name, _) => Some(name.clone()),
                    Operand::Number(_) => None,
                }));
            }
        }
        seen
    }
}

/// Reads one component element.
fn component(node: Node, at: &str) -> Component {
    let tag = node.tag_name().name().to_string();
    let num = |n: Node| parse_number(text(n).trim());
    let pair = |name: &str| -> Option<Option<(f64, f64)>> {
        let e = child(node, name)?;
        Some(Some((num(child(e, "min")?)?, num(child(e, "max")?)?)))
    };
    let gain = child(node, "gain")
        .map(|g| Operand::parse(&text(g)))
        .unwrap_or(Operand::Number(1.0));
    let number = |name: &str| child(node, name).and_then(num).unwrap_or(0.0);
    let mut unreadable = None;
    let kind = match tag.as_str() {
        "aerosurface_scale" => {
            let range = pair("range").flatten();
            let domain = pair("domain").unwrap_or(Some((-1.0, 1.0)));
            let zero_centered = child(node, "zero_centered")
                .map(|z| !matches!(text(z).trim(), "0" | "false"))
                .unwrap_or(true);
            match (range, domain) {
                (Some(range), Some(domain)) => Kind::Scale {
                    gain,
                    domain,
                    range,
                    zero_centered,
                },
                _ => {
                    unreadable = Some("its <range> or <domain> lacks a numeric <min> or <max>");
                    Kind::Other
                }
            }
        }
        "pure_gain" => Kind::Gain(gain),
        "scheduled_gain" => Kind::Scheduled(gain),
        "summer" => Kind::Summer(number("bias")),
        "actuator" => Kind::Actuator {
            bias: number("bias"),
            dead: 0.5 * (number("deadband_width") + number("hysteresis_width")),
        },
        "kinematic" => {
            let positions: Vec<Option<f64>> = child(node, "traverse")
                .map(|t| {
                    children(t, "setting")
                        .map(|s| child(s, "position").and_then(num))
                        .collect()
                })
                .unwrap_or_default();
            match (positions.first(), positions.last()) {
                (Some(Some(a)), Some(Some(b))) if positions.len() > 1 => Kind::Kinematic {
                    ends: (*a, *b),
                    scale: child(node, "noscale").is_none(),
                },
                _ => {
                    unreadable = Some("its <traverse> lacks two numeric settings");
                    Kind::Other
                }
            }
        }
        "lag_filter" => Kind::Lag,
        "lead_lag_filter" | "washout_filter" | "second_order_filter" | "integrator" | "pid" => {
            Kind::Linear
        }
        "switch" => Kind::Switch {
            tests: switch_tests(node),
        },
        _ => Kind::Other,
    };
    let clip = child(node, "clipto").and_then(|c| {
        Some((
            Operand::parse(&text(child(c, "min")?)),
            Operand::parse(&text(child(c, "max")?)),
        ))
    });
    let cyclic = child(node, "clipto").and_then(|c| c.attribute("type")) == Some("cyclic");
    Component {
        tag,
        name: node.attribute("name").unwrap_or("").to_string(),
        at: at.to_string(),
        inputs: children(node, "input")
            .map(|i| Operand::parse(&text(i)))
            .collect(),
        kind: if cyclic { Kind::Other } else { kind },
        clip,
        unreadable: unreadable.map(str::to_string),
    }
}

/// The tests of a switch, in order, the default as `None`.
fn switch_tests(node: Node) -> Vec<(Option<Condition>, Operand)> {
    node.children()
        .filter(|n| n.is_element())
        .filter_map(|n| {
            let value = Operand::parse(n.attribute("value")?);
            match n.tag_name().name() {
                "default" => Some((None, value)),
                "test" => Some((Some(condition(n)), value)),
                _ => None,
            }
        })
        .collect()
}

/// A `<test>` element as a condition.
fn condition(node: Node) -> Condition {
    let mut parts: Vec<Condition> = text(node)
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty())
        .map(|l| {
            let w: Vec<&str> = l.split_whitespace().collect();
            match w.as_slice() {
                [a, op, b] => {
                    Condition::Compare(Operand::parse(a), op.to_string(), Operand::parse(b))
                }
                _ => Condition::Compare(
                    Operand::Number(f64::NAN),
                    l.to_string(),
                    Operand::Number(0.0),
                ),
            }
        })
        .collect();
    parts.extend(children(node, "test").map(condition));
    if node.attribute("logic") == Some("OR") {
        Condition::Any(parts)
    } else {
        Condition::All(parts)
    }
}

/// The deepest chain followed (a loop in the system is reported, not followed forever).
const MAX_DEPTH: usize = 64;

/// A steady-state evaluation with some pilot commands set.
struct Chain<'a> {
    fcs: &'a Fcs,
    commands: &'a [(&'a str, f64)],
}

impl Chain<'_> {
    /// The value of a property.
    fn property(&self, name: &str, depth: usize) -> Result<f64, String> {
        if let Some((_, v)) = self.commands.iter().find(|(n, _)| *n == name) {
            return Ok(*v);
        }
        if depth > MAX_DEPTH {
            return Err(format!("the chain through {name} loops back on itself"));
        }
        match self.fcs.writers.get(name).map(Vec::as_slice) {
            Some([one]) => self.component(one, depth + 1),
            Some(many) => Err(format!(
                "{name} is written by {} components ({}), which JSBSim runs in turn",
                many.len(),
                many.iter()
                    .map(Component::label)
                    .collect::<Vec<_>>()
                    .join(", ")
            )),
            None if ZERO_IN_TRIM.contains(&name) => Ok(0.0),
            None if STATE_TREES.iter().any(|t| name.starts_with(t)) => Err(format!(
                "{name} is the flight state, not known without flying the model"
            )),
            None => Ok(self.fcs.initial.get(name).copied().unwrap_or(0.0)),
        }
    }

    /// The value of an operand.
    fn operand(&self, o: &Operand, depth: usize) -> Result<f64, String> {
        match o {
            Operand::Number(v) => Ok(*v),
            Operand::Property(p, sign) => Ok(sign * self.property(p, depth)?),
        }
    }

    /// The steady output of a component.
    fn component(&self, c: &Component, depth: usize) -> Result<f64, String> {
        let at = |why: String| format!("{}: {why}", c.label());
        if let Some(why) = &c.unreadable {
            return Err(at(why.clone()));
        }
        let input = |k: usize| -> Result<f64, String> {
            let o = c
                .inputs
                .get(k)
                .ok_or_else(|| at("no <input>".to_string()))?;
            self.operand(o, depth)
        };
        let out = match &c.kind {
            Kind::Scale {
                gain,
                domain,
                range,
                zero_centered,
            } => scale(input(0)?, *domain, *range, *zero_centered) * self.operand(gain, depth)?,
            Kind::Gain(g) => input(0)? * self.operand(g, depth)?,
            // A table times zero: zero whatever the table gives.
            Kind::Scheduled(_) => zero_only(input(0)?)
                .ok_or_else(|| at("scales its input by a table of the flight state".into()))?,
            Kind::Summer(bias) => {
                let mut sum = *bias;
                for k in 0..c.inputs.len() {
                    sum += input(k)?;
                }
                sum
            }
            Kind::Actuator { bias, dead } => {
                let x = input(0)?;
                x.signum() * (x.abs() - dead).max(0.0) + bias
            }
            Kind::Kinematic { ends, scale } => {
                let x = input(0)? * if *scale { ends.1 } else { 1.0 };
                x.clamp(ends.0.min(ends.1), ends.1.max(ends.0))
            }
            Kind::Lag => input(0)?,
            Kind::Linear => zero_only(input(0)?).ok_or_else(|| {
                at("its steady output is not a fixed multiple of its input".into())
            })?,
            Kind::Switch { tests } => self.switch(tests, depth).map_err(at)?,
            Kind::Other => {
                return Err(at(
                    "its steady output is not followed (an element of this kind or a cyclic \
                     clip)"
                        .into(),
                ))
            }
        };
        match &c.clip {
            None => Ok(out),
            Some((lo, hi)) => {
                let (lo, hi) = (self.operand(lo, depth)?, self.operand(hi, depth)?);
                // JSBSim ignores a clip whose max is below its min.
                Ok(if hi < lo { out } else { out.clamp(lo, hi) })
            }
        }
    }

    /// The value of a switch.
    fn switch(&self, tests: &[(Option<Condition>, Operand)], depth: usize) -> Result<f64, String> {
        let mut default = 0.0;
        for (test, value) in tests {
            match test {
                None => default = self.operand(value, depth)?,
                Some(t) => {
                    if self.holds(t, depth)? {
                        return self.operand(value, depth);
                    }
                }
            }
        }
        Ok(default)
    }

    /// Whether a condition holds; an AND with a part known false is false, an OR with a part
    /// known true is true, whatever the unknown parts.
    fn holds(&self, c: &Condition, depth: usize) -> Result<bool, String> {
        match c {
            Condition::All(parts) | Condition::Any(parts) => {
                let decisive = matches!(c, Condition::Any(_));
                let mut unknown = None;
                for p in parts {
                    match self.holds(p, depth) {
                        Ok(v) if v == decisive => return Ok(decisive),
                        Ok(_) => {}
                        Err(e) => unknown = Some(e),
                    }
                }
                unknown.map_or(Ok(!decisive), Err)
            }
            Condition::Compare(a, op, b) => {
                let (x, y) = (self.operand(a, depth)?, self.operand(b, depth)?);
                compare(x, op, y).ok_or_else(|| format!("test `{op}` not understood"))
            }
        }
    }
}

/// The output of an element that stays at zero while its input does: zero for a zero input,
/// `None` (not known) otherwise.
fn zero_only(x: f64) -> Option<f64> {
    (x == 0.0).then_some(0.0)
}

/// JSBSim's comparisons.
fn compare(x: f64, op: &str, y: f64) -> Option<bool> {
    Some(match op {
        "==" | "eq" => x == y,
        "!=" | "ne" => x != y,
        "<" | "lt" => x < y,
        "<=" | "le" => x <= y,
        ">" | "gt" => x > y,
        ">=" | "ge" => x >= y,
        _ => return None,
    })
}

/// `aerosurface_scale`'s map of `x` from `domain` to `range`: each side of zero scaled by its
/// own end when zero centred, else linearly end to end.
pub fn scale(x: f64, domain: (f64, f64), range: (f64, f64), zero_centered: bool) -> f64 {
    if zero_centered {
        if x == 0.0 {
            0.0
        } else if x > 0.0 {
            x / domain.1 * range.1
        } else {
            x / domain.0 * range.0
        }
    } else {
        range.0 + (x - domain.0) / (domain.1 - domain.0) * (range.1 - range.0)
    }
}
