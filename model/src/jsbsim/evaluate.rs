//! Evaluating a model's functions at one flight state: every property is either a named
//! function of the model (computed once per state, on demand, so a function may read one
//! defined after it) or an input given by the caller (the flight state, the surface positions,
//! the other systems' outputs). A function that reads itself, directly or through others, is an
//! error naming the loop, never a hang. Every table lookup beyond the table's breakpoints is
//! recorded with the function that made it ([`Env::clamps`]).

use super::clamp::{record, Clamp};
use super::error::JsbsimError;
use super::function::{Compare, Expr, Op, PropertyRef, Symbols, Unary};

/// A named function of the model.
#[derive(Clone, Debug)]
pub struct Function {
    /// Its property name (`aero/coefficient/CLalpha`).
    pub name: String,
    /// The line of its `<function>` element.
    pub line: u32,
    /// Its expression.
    pub expr: Expr,
}

/// The functions of a model and the symbols they read.
#[derive(Clone, Debug, Default)]
pub struct Functions {
    /// Every property name read or defined.
    pub symbols: Symbols,
    /// The named functions.
    pub list: Vec<Function>,
    /// For each symbol, the function that defines it, if any.
    pub defined_by: Vec<Option<usize>>,
}

impl Functions {
    /// Records which symbols are functions; call once every function is read.
    pub fn link(&mut self) {
        self.defined_by = vec![None; self.symbols.len()];
        for (i, f) in self.list.iter().enumerate() {
            if let Some(s) = self.symbols.get(&f.name) {
                self.defined_by[s] = Some(i);
            }
        }
    }

    /// The symbols no function defines: what the caller must give.
    pub fn inputs(&self) -> Vec<&str> {
        (0..self.symbols.len())
            .filter(|&s| self.defined_by[s].is_none())
            .map(|s| self.symbols.name(s))
            .collect()
    }
}

/// How many functions may read one another in a chain before the evaluation refuses (the
/// catalogue's longest chains are a few functions; this keeps the stack bounded).
pub const MAX_CHAIN: usize = 100;

/// The state of one function's value during an evaluation.
#[derive(Clone, Copy, Debug)]
enum Slot {
    Unknown,
    Busy,
    Done(f64),
}

/// What setting a property sets: an input, or a function's value overridden.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Target {
    /// The input of this symbol.
    Input(usize),
    /// The value of this function.
    Function(usize),
}

/// One evaluation: the inputs' values and the functions' values computed so far.
#[derive(Clone)]
pub struct Env<'m> {
    functions: &'m Functions,
    file: &'m str,
    inputs: Vec<Option<f64>>,
    slots: Vec<Slot>,
    depth: usize,
    current: Option<usize>,
    clamps: Vec<Clamp>,
    recording: bool,
}

impl<'m> Env<'m> {
    /// An evaluation of `functions` (of `file`, for messages) with no input set yet.
    pub fn new(functions: &'m Functions, file: &'m str) -> Env<'m> {
        Env {
            functions,
            file,
            inputs: vec![None; functions.symbols.len()],
            slots: vec![Slot::Unknown; functions.list.len()],
            depth: 0,
            current: None,
            clamps: Vec::new(),
            recording: true,
        }
    }

    /// Whether table lookups beyond the breakpoints are recorded ([`Env::clamps`]; on by
    /// default): a simulation that does not report them saves the check at every lookup.
    pub fn record_clamps(&mut self, on: bool) {
        self.recording = on;
    }

    /// The functions evaluated.
    pub fn functions(&self) -> &'m Functions {
        self.functions
    }

    /// The model's file, for messages.
    pub fn file(&self) -> &'m str {
        self.file
    }

    /// The table lookups beyond a table's breakpoints made so far, one per table and variable.
    pub fn clamps(&self) -> &[Clamp] {
        &self.clamps
    }

    /// Sets input `name` (ignored if the model never reads it). A name that is one of the
    /// model's functions overrides that function.
    pub fn set(&mut self, name: &str, value: f64) {
        if let Some(t) = self.target(name) {
            self.set_target(t, value);
        }
    }

    /// What setting `name` sets, if the model reads it: found once, so that a caller setting
    /// the same names at every step of a simulation looks no name up again.
    pub fn target(&self, name: &str) -> Option<Target> {
        let s = self.functions.symbols.get(name)?;
        Some(match self.functions.defined_by[s] {
            Some(f) => Target::Function(f),
            None => Target::Input(s),
        })
    }

    /// Sets `target` to `value` (as [`Env::set`] its name).
    pub fn set_target(&mut self, target: Target, value: f64) {
        match target {
            Target::Function(f) => self.slots[f] = Slot::Done(value),
            Target::Input(s) => self.inputs[s] = Some(value),
        }
    }

    /// Makes this evaluation the same as `base` (an evaluation of the same functions), its
    /// inputs and the functions' values, keeping its own memory: a simulation's fresh start at
    /// each step from the inputs that do not change.
    pub fn reset_to(&mut self, base: &Env) {
        self.inputs.clone_from_slice(&base.inputs);
        self.slots.clone_from_slice(&base.slots);
        self.clamps.clear();
        self.clamps.extend_from_slice(&base.clamps);
    }

    /// Keeps from `previous` (an evaluation of the same functions, with every value it
    /// computed) the value of each function that reads no input set differently here, directly
    /// or through others, so that this evaluation computes only the others. Its numbers and
    /// errors are those of a fresh evaluation: a kept value is what the function gives with
    /// these inputs. `readers` gives for each symbol the functions that read it, directly or
    /// through others (of every branch), and for each function its symbol; they must never loop
    /// nor chain beyond [`MAX_CHAIN`], whose checks a kept value skips
    /// ([`super::readers::Readers`]). `stale` is scratch memory. Table lookups beyond the
    /// breakpoints inside the kept functions are not recorded again.
    pub fn keep_from(
        &mut self,
        previous: &Env,
        (of_symbol, symbol_of): (&[Vec<usize>], &[usize]),
        stale: &mut Vec<bool>,
    ) {
        stale.clear();
        stale.resize(self.slots.len(), false);
        let mut mark = |fs: &[usize]| fs.iter().for_each(|&f| stale[f] = true);
        for (s, (now, then)) in self.inputs.iter().zip(&previous.inputs).enumerate() {
            if now.map(f64::to_bits) != then.map(f64::to_bits) {
                mark(&of_symbol[s]);
            }
        }
        for (f, (now, then)) in self.slots.iter().zip(&previous.slots).enumerate() {
            if let Slot::Done(v) = now {
                if !matches!(then, Slot::Done(w) if w.to_bits() == v.to_bits()) {
                    mark(&of_symbol[symbol_of[f]]);
                }
            }
        }
        for ((now, then), &stale) in self.slots.iter_mut().zip(&previous.slots).zip(stale.iter()) {
            if matches!((&now, then), (Slot::Unknown, Slot::Done(_))) && !stale {
                *now = *then;
            }
        }
    }

    /// The value given for input `name`, if the model reads it and it was set.
    pub fn input(&self, name: &str) -> Option<f64> {
        let s = self.functions.symbols.get(name)?;
        self.inputs[s]
    }

    /// Whether input `name` is read by the model and not yet set.
    pub fn is_unset(&self, name: &str) -> bool {
        self.functions
            .symbols
            .get(name)
            .is_some_and(|s| self.functions.defined_by[s].is_none() && self.inputs[s].is_none())
    }

    /// Forgets every function value (after an input changed).
    pub fn clear(&mut self) {
        self.slots.iter_mut().for_each(|s| *s = Slot::Unknown);
    }

    /// The value of function `f`.
    pub fn function(&mut self, f: usize) -> Result<f64, JsbsimError> {
        match self.slots[f] {
            Slot::Done(v) => Ok(v),
            Slot::Busy => {
                let func = &self.functions.list[f];
                Err(JsbsimError::new(
                    self.file,
                    func.line,
                    "function",
                    format!("`{}` reads its own value (a property loop)", func.name),
                ))
            }
            Slot::Unknown => {
                let func = &self.functions.list[f];
                if self.depth >= MAX_CHAIN {
                    return Err(JsbsimError::new(
                        self.file,
                        func.line,
                        "function",
                        format!(
                            "`{}` is read through a chain of more than {MAX_CHAIN} functions",
                            func.name
                        ),
                    ));
                }
                self.slots[f] = Slot::Busy;
                self.depth += 1;
                let caller = self.current.replace(f);
                let v = self.eval(&func.expr);
                self.current = caller;
                self.depth -= 1;
                let v = v.inspect_err(|_| self.slots[f] = Slot::Unknown)?;
                self.slots[f] = Slot::Done(v);
                Ok(v)
            }
        }
    }

    /// The value of property `name`: a function's or an input's.
    pub fn property(&mut self, name: &str) -> Result<f64, JsbsimError> {
        let s = self.functions.symbols.get(name).ok_or_else(|| {
            JsbsimError::new(
                self.file,
                0,
                name,
                "the model neither reads nor defines this property",
            )
        })?;
        self.symbol(PropertyRef {
            symbol: s,
            negated: false,
        })
    }

    /// The value of a property reference.
    fn symbol(&mut self, r: PropertyRef) -> Result<f64, JsbsimError> {
        let v = match self.functions.defined_by[r.symbol] {
            Some(f) => self.function(f)?,
            None => self.inputs[r.symbol].ok_or_else(|| {
                JsbsimError::new(
                    self.file,
                    0,
                    self.functions.symbols.name(r.symbol),
                    "the aerodynamics read this property but nothing sets it (give it with \
                     --set NAME=VALUE)",
                )
            })?,
        };
        Ok(if r.negated { -v } else { v })
    }

    /// The value of an expression.
    pub fn eval(&mut self, e: &Expr) -> Result<f64, JsbsimError> {
        match e {
            Expr::Value(v) => Ok(*v),
            Expr::Property(r) => self.symbol(*r),
            Expr::Table(t) => {
                let mut keys = [0.0; 3];
                for (k, r) in t.keys.iter().enumerate() {
                    keys[k] = self.symbol(*r)?;
                }
                let outside = if self.recording {
                    t.data.outside(&keys)
                } else {
                    [None; 3]
                };
                for (k, range) in outside.into_iter().enumerate() {
                    let ground =
                        |k: usize| is_ground_effect(self.functions.symbols.name(t.keys[k].symbol));
                    if let Some(range) = range.filter(|_| !ground(k)) {
                        let clamp = Clamp {
                            function: self.current,
                            line: t.line,
                            symbol: t.keys[k].symbol,
                            negated: t.keys[k].negated,
                            value: keys[k],
                            range,
                        };
                        record(&mut self.clamps, clamp);
                    }
                }
                Ok(t.data.lookup(&keys))
            }
            Expr::Apply(op, args) => self.apply(*op, args),
        }
    }

    /// The value of an operation. The arguments are folded as they are evaluated (no list of
    /// them is made: the simulation evaluates the functions at every step), all of them, in
    /// order, as JSBSim does.
    fn apply(&mut self, op: Op, args: &[Expr]) -> Result<f64, JsbsimError> {
        let fold = |env: &mut Self, init: f64, f: fn(f64, f64) -> f64| {
            args.iter()
                .try_fold(init, |acc, a| env.eval(a).map(|x| f(acc, x)))
        };
        Ok(match op {
            Op::Product => fold(self, 1.0, |a, x| a * x)?,
            Op::Sum => fold(self, 0.0, |a, x| a + x)?,
            Op::Avg => fold(self, 0.0, |a, x| a + x)? / args.len() as f64,
            Op::Difference => {
                let first = self.eval(&args[0])?;
                args[1..]
                    .iter()
                    .try_fold(first, |acc, a| self.eval(a).map(|x| acc - x))?
            }
            Op::Min => fold(self, f64::INFINITY, f64::min)?,
            Op::Max => fold(self, f64::NEG_INFINITY, f64::max)?,
            Op::And => fold(self, 1.0, |a, x| f64::from(a != 0.0 && x != 0.0))?,
            Op::Or => fold(self, 0.0, |a, x| f64::from(a != 0.0 || x != 0.0))?,
            Op::IfThen => {
                let c = self.eval(&args[0])?;
                self.eval(&args[if c != 0.0 { 1 } else { 2 }])?
            }
            Op::Unary(u) => unary(u, self.eval(&args[0])?),
            Op::Not => f64::from(self.eval(&args[0])? == 0.0),
            Op::Quotient | Op::Pow | Op::Atan2 | Op::Fmod | Op::Compare(_) => {
                let (a, b) = (self.eval(&args[0])?, self.eval(&args[1])?);
                binary(op, a, b)
            }
        })
    }
}

/// A two-argument operation, with JSBSim's values where it is undefined.
fn binary(op: Op, a: f64, b: f64) -> f64 {
    match op {
        Op::Quotient if b != 0.0 => a / b,
        Op::Fmod if b != 0.0 => a % b,
        Op::Quotient | Op::Fmod => f64::INFINITY,
        Op::Pow => a.powf(b),
        Op::Atan2 => a.atan2(b),
        Op::Compare(c) => f64::from(compare(c, a, b)),
        _ => unreachable!("binary operations only"),
    }
}

/// Whether `name` is the height over span of ground-effect tables, whose last breakpoint is
/// where ground effect ends: held beyond it by design, not extrapolated data.
fn is_ground_effect(name: &str) -> bool {
    name.starts_with("aero/h_b-")
}

/// A one-argument function, with JSBSim's values outside the domain.
fn unary(u: Unary, x: f64) -> f64 {
    match u {
        Unary::Abs => x.abs(),
        Unary::Sin => x.sin(),
        Unary::Cos => x.cos(),
        Unary::Tan => x.tan(),
        Unary::Asin => x.asin(),
        Unary::Acos => x.acos(),
        Unary::Atan => x.atan(),
        Unary::Exp => x.exp(),
        Unary::Sqrt if x >= 0.0 => x.sqrt(),
        Unary::Ln if x > 0.0 => x.ln(),
        Unary::Log10 if x > 0.0 => x.log10(),
        Unary::Sqrt | Unary::Ln | Unary::Log10 => f64::NEG_INFINITY,
        Unary::Sign => {
            if x < 0.0 {
                -1.0
            } else {
                1.0
            }
        }
        Unary::Floor => x.floor(),
        Unary::Ceil => x.ceil(),
        Unary::ToRadians => x * std::f64::consts::PI / 180.0,
        Unary::ToDegrees => x * 180.0 / std::f64::consts::PI,
        Unary::Integer => x.trunc(),
        Unary::Fraction => x.fract(),
    }
}

/// A comparison.
fn compare(c: Compare, a: f64, b: f64) -> bool {
    match c {
        Compare::Lt => a < b,
        Compare::Le => a <= b,
        Compare::Gt => a > b,
        Compare::Ge => a >= b,
        Compare::Eq => a == b,
        Compare::Nq => a != b,
    }
}
