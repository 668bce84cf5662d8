//! JSBSim's function language (`<function>`): the expression tree of `<product>`, `<sum>`,
//! `<difference>`, `<quotient>`, `<pow>`, the one-argument mathematical functions, `<min>`/`<max>`,
//! comparisons, `<and>`/`<or>`/`<not>`, `<ifthen>`, `<value>`, `<pi>`, `<property>` (a leading
//! `-` negates it) and `<table>`, read from the XML. Property names are interned in a
//! [`Symbols`] table so that evaluation indexes a vector.

use super::error::JsbsimError;
use super::table::TableData;
use super::xml::Source;
use roxmltree::Node;
use rustc_hash::FxHashMap;

/// Property names seen in a model, each with a stable index.
#[derive(Clone, Debug, Default)]
pub struct Symbols {
    names: Vec<String>,
    /// FxHash: names are looked up at every evaluation of the coefficients (the trim of one
    /// envelope point makes hundreds), where SipHash's resistance to collisions buys nothing.
    index: FxHashMap<String, usize>,
}

impl Symbols {
    /// The index of `name`, added if new.
    pub fn intern(&mut self, name: &str) -> usize {
        if let Some(&i) = self.index.get(name) {
            return i;
        }
        self.names.push(name.to_string());
        self.index.insert(name.to_string(), self.names.len() - 1);
        self.names.len() - 1
    }

    /// The index of `name`, if it was seen.
    pub fn get(&self, name: &str) -> Option<usize> {
        self.index.get(name).copied()
    }

    /// The name of symbol `i`.
    pub fn name(&self, i: usize) -> &str {
        &self.names[i]
    }

    /// How many symbols there are.
    pub fn len(&self) -> usize {
        self.names.len()
    }

    /// Whether there are none.
    pub fn is_empty(&self) -> bool {
        self.names.is_empty()
    }
}

/// A property read, possibly negated (`-aero/beta-rad`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PropertyRef {
    /// The symbol index.
    pub symbol: usize,
    /// Whether the value is negated.
    pub negated: bool,
}

/// An operation of the function language.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Op {
    /// Product of all arguments.
    Product,
    /// Sum of all arguments.
    Sum,
    /// Mean of all arguments.
    Avg,
    /// The first argument minus the others.
    Difference,
    /// Smallest argument.
    Min,
    /// Largest argument.
    Max,
    /// a / b (JSBSim gives HUGE_VAL for b = 0).
    Quotient,
    /// a^b.
    Pow,
    /// atan2(a, b).
    Atan2,
    /// fmod(a, b).
    Fmod,
    /// A one-argument function of the C library (abs, sin, ..., todegrees).
    Unary(Unary),
    /// Comparison, 1 or 0.
    Compare(Compare),
    /// 1 when every argument is true.
    And,
    /// 1 when some argument is true.
    Or,
    /// 1 when the argument is false.
    Not,
    /// The second argument when the first is true, else the third.
    IfThen,
}

/// One-argument functions.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Unary {
    /// |x|.
    Abs,
    /// sin x.
    Sin,
    /// cos x.
    Cos,
    /// tan x.
    Tan,
    /// asin x.
    Asin,
    /// acos x.
    Acos,
    /// atan x.
    Atan,
    /// e^x.
    Exp,
    /// sqrt x (JSBSim gives -HUGE_VAL for x < 0).
    Sqrt,
    /// ln x.
    Ln,
    /// log10 x.
    Log10,
    /// -1 for x < 0, else 1.
    Sign,
    /// floor x.
    Floor,
    /// ceil x.
    Ceil,
    /// Degrees to radians.
    ToRadians,
    /// Radians to degrees.
    ToDegrees,
    /// Integer part.
    Integer,
    /// Fractional part.
    Fraction,
}

/// A comparison.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Compare {
    /// a < b.
    Lt,
    /// a <= b.
    Le,
    /// a > b.
    Gt,
    /// a >= b.
    Ge,
    /// a == b.
    Eq,
    /// a != b.
    Nq,
}

/// A table with the properties of its row, column and table lookups.
#[derive(Clone, Debug, PartialEq)]
pub struct Table {
    /// Independent variables in lookup order (row, column, table).
    pub keys: Vec<PropertyRef>,
    /// The data.
    pub data: TableData,
    /// The line of its `<table>` element.
    pub line: u32,
}

/// An expression of the function language.
#[derive(Clone, Debug, PartialEq)]
pub enum Expr {
    /// A constant.
    Value(f64),
    /// A property.
    Property(PropertyRef),
    /// A table lookup.
    Table(Box<Table>),
    /// An operation on arguments.
    Apply(Op, Vec<Expr>),
}

/// The operation an element names, with its allowed number of arguments.
fn operation(name: &str) -> Option<(Op, usize, usize)> {
    use Compare::*;
    use Unary::*;
    let many = usize::MAX;
    let unary = |u| Some((Op::Unary(u), 1, 1));
    let compare = |c| Some((Op::Compare(c), 2, 2));
    match name {
        "product" => Some((Op::Product, 1, many)),
        "sum" => Some((Op::Sum, 1, many)),
        "avg" => Some((Op::Avg, 1, many)),
        "difference" => Some((Op::Difference, 1, many)),
        "min" => Some((Op::Min, 1, many)),
        "max" => Some((Op::Max, 1, many)),
        "and" => Some((Op::And, 1, many)),
        "or" => Some((Op::Or, 1, many)),
        "quotient" => Some((Op::Quotient, 2, 2)),
        "pow" => Some((Op::Pow, 2, 2)),
        "atan2" => Some((Op::Atan2, 2, 2)),
        "fmod" => Some((Op::Fmod, 2, 2)),
        "not" => Some((Op::Not, 1, 1)),
        "ifthen" => Some((Op::IfThen, 3, 3)),
        "abs" => unary(Abs),
        "sin" => unary(Sin),
        "cos" => unary(Cos),
        "tan" => unary(Tan),
        "asin" => unary(Asin),
        "acos" => unary(Acos),
        "atan" => unary(Atan),
        "exp" => unary(Exp),
        "sqrt" => unary(Sqrt),
        "ln" => unary(Ln),
        "log10" => unary(Log10),
        "sign" => unary(Sign),
        "floor" => unary(Floor),
        "ceil" => unary(Ceil),
        "toradians" => unary(ToRadians),
        "todegrees" => unary(ToDegrees),
        "integer" => unary(Integer),
        "fraction" => unary(Fraction),
        "lt" => compare(Lt),
        "le" => compare(Le),
        "gt" => compare(Gt),
        "ge" => compare(Ge),
        "eq" => compare(Eq),
        "nq" => compare(Nq),
        _ => None,
    }
}

/// The elements a function may hold, for messages.
const EXPECTED: &str = "property, value, pi, table, product, sum, avg, difference, min, max, \
     quotient, pow, atan2, fmod, abs, sin, cos, tan, asin, acos, atan, exp, sqrt, ln, log10, \
     sign, floor, ceil, toradians, todegrees, integer, fraction, lt, le, gt, ge, eq, nq, and, or, \
     not or ifthen";

/// Whether `node` is an element that holds no value (documentation).
fn is_comment(node: Node) -> bool {
    matches!(node.tag_name().name(), "description" | "documentation")
}

/// A property reference from the text of `node` (`-` in front negates).
pub fn property_ref(
    src: Source,
    node: Node,
    symbols: &mut Symbols,
) -> Result<PropertyRef, JsbsimError> {
    let text = super::xml::text(node);
    let text = text.trim();
    let (negated, name) = match text.strip_prefix('-') {
        Some(rest) => (true, rest.trim()),
        None => (false, text),
    };
    if name.is_empty() || name.contains(char::is_whitespace) {
        return Err(src.error(node, format!("`{text}` is not a property name")));
    }
    Ok(PropertyRef {
        symbol: symbols.intern(name),
        negated,
    })
}

/// The expression of `<function>` element `node`: its single non-documentation child.
pub fn parse_function(src: Source, node: Node, symbols: &mut Symbols) -> Result<Expr, JsbsimError> {
    let args = parse_args(src, node, symbols)?;
    let mut args = args.into_iter();
    match (args.next(), args.next()) {
        (Some(e), None) => Ok(e),
        _ => Err(src.error(
            node,
            "a function holds exactly one expression (expected one element)",
        )),
    }
}

/// The arguments of an operation element: every element child but documentation.
fn parse_args(src: Source, node: Node, symbols: &mut Symbols) -> Result<Vec<Expr>, JsbsimError> {
    node.children()
        .filter(|c| c.is_element() && !is_comment(*c))
        .map(|c| parse_expr(src, c, symbols))
        .collect()
}

/// How deep elements may nest in a model: far beyond the catalogue's (about 12), shallow enough
/// that reading and evaluating cannot exhaust the stack.
pub const MAX_DEPTH: usize = 200;

/// One expression element.
pub fn parse_expr(src: Source, node: Node, symbols: &mut Symbols) -> Result<Expr, JsbsimError> {
    let name = node.tag_name().name();
    if node.ancestors().nth(MAX_DEPTH).is_some() {
        return Err(src.error(node, format!("elements nested more than {MAX_DEPTH} deep")));
    }
    match name {
        "value" | "v" => Ok(Expr::Value(src.number(node)?)),
        "pi" => Ok(Expr::Value(std::f64::consts::PI)),
        "property" | "p" => {
            if node.attribute("apply").is_some() {
                return Err(src.error(node, "template functions (`apply`) are not supported"));
            }
            Ok(Expr::Property(property_ref(src, node, symbols)?))
        }
        "table" | "t" => Ok(Expr::Table(Box::new(super::table_xml::parse_table(
            src, node, symbols,
        )?))),
        _ => {
            let (op, min, max) = operation(name).ok_or_else(|| {
                src.error(
                    node,
                    format!("unknown element in a function (expected {EXPECTED})"),
                )
            })?;
            let args = parse_args(src, node, symbols)?;
            if args.len() < min || args.len() > max {
                let want = if min == max {
                    format!("{min}")
                } else {
                    format!("at least {min}")
                };
                return Err(src.error(
                    node,
                    format!("{} arguments given (expected {want})", args.len()),
                ));
            }
            Ok(Expr::Apply(op, args))
        }
    }
}
