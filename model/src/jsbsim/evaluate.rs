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

/// One evaluation: the inputs' values and the functions' values computed so far.
pub struct Env<'m> {
    functions: &'m Functions,
    file: &'m str,
    inputs: Vec<Option<f64>>,
    slots: Vec<Slot>,
    depth: usize,
    current: Option<usize>,
    clamps: Vec<Clamp>,
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
        }
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
        if let Some(s) = self.functions.symbols.get(name) {
            match self.functions.defined_by[s] {
                Some(f) => self.slots[f] = Slot::Done(value),
                None => self.inputs[s] = Some(value),
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
                let v = v?;
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
                for (k, range) in t.data.outside(&keys).into_iter().enumerate() {
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

    /// The value of an operation.
    fn apply(&mut self, op: Op, args: &[Expr]) -> Result<f64, JsbsimError> {
        let mut v = Vec::with_capacity(args.len());
        if op == Op::IfThen {
            let c = self.eval(&args[0])?;
            return self.eval(&args[if c != 0.0 { 1 } else { 2 }]);
        }
        for a in args {
            v.push(self.eval(a)?);
        }
        Ok(match op {
            Op::Product => v.iter().product(),
            Op::Sum => v.iter().sum(),
            Op::Avg => v.iter().sum::<f64>() / v.len() as f64,
            Op::Difference => v[1..].iter().fold(v[0], |acc, x| acc - x),
            Op::Min => v.iter().copied().fold(f64::INFINITY, f64::min),
            Op::Max => v.iter().copied().fold(f64::NEG_INFINITY, f64::max),
            Op::Quotient => {
                if v[1] != 0.0 {
                    v[0] / v[1]
                } else {
                    f64::INFINITY
                }
            }
            Op::Pow => v[0].powf(v[1]),
            Op::Atan2 => v[0].atan2(v[1]),
            Op::Fmod => {
                if v[1] != 0.0 {
                    v[0] % v[1]
                } else {
                    f64::INFINITY
                }
            }
            Op::Unary(u) => unary(u, v[0]),
            Op::Compare(c) => f64::from(compare(c, v[0], v[1])),
            Op::And => f64::from(v.iter().all(|&x| x != 0.0)),
            Op::Or => f64::from(v.iter().any(|&x| x != 0.0)),
            Op::Not => f64::from(v[0] == 0.0),
            Op::IfThen => unreachable!("handled above"),
        })
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
