//! Values a model's functions cannot give an aircraft: NaN and infinity. JSBSim computes on with
//! them (its `<quotient>` by zero is HUGE_VAL, and that times a zero rate is NaN), and so did the
//! evaluation here, to stay JSBSim's; the import refuses them instead, since a NaN derivative is
//! no aircraft. The refusal names the function, the operation where the first non-finite value
//! arose from finite operands (the divisor that is zero, the negative number under a root) with
//! the properties it read, and the flight state.

use super::digits::every_digit;
use super::error::JsbsimError;
use super::evaluate::{Env, Functions};
use super::function::{Compare, Expr, Op, Unary};

/// The name of the element of operation `op`.
fn op_name(op: Op) -> &'static str {
    match op {
        Op::Product => "product",
        Op::Sum => "sum",
        Op::Avg => "avg",
        Op::Difference => "difference",
        Op::Min => "min",
        Op::Max => "max",
        Op::Quotient => "quotient",
        Op::Pow => "pow",
        Op::Atan2 => "atan2",
        Op::Fmod => "fmod",
        Op::Unary(u) => unary_name(u),
        Op::Compare(c) => match c {
            Compare::Lt => "lt",
            Compare::Le => "le",
            Compare::Gt => "gt",
            Compare::Ge => "ge",
            Compare::Eq => "eq",
            Compare::Nq => "nq",
        },
        Op::And => "and",
        Op::Or => "or",
        Op::Not => "not",
        Op::IfThen => "ifthen",
    }
}

/// The name of the element of one-argument function `u`.
fn unary_name(u: Unary) -> &'static str {
    match u {
        Unary::Abs => "abs",
        Unary::Sin => "sin",
        Unary::Cos => "cos",
        Unary::Tan => "tan",
        Unary::Asin => "asin",
        Unary::Acos => "acos",
        Unary::Atan => "atan",
        Unary::Exp => "exp",
        Unary::Sqrt => "sqrt",
        Unary::Ln => "ln",
        Unary::Log10 => "log10",
        Unary::Sign => "sign",
        Unary::Floor => "floor",
        Unary::Ceil => "ceil",
        Unary::ToRadians => "toradians",
        Unary::ToDegrees => "todegrees",
        Unary::Integer => "integer",
        Unary::Fraction => "fraction",
    }
}

/// An expression in words, for a message: a property by name, a number, or the element.
fn shown(e: &Expr, functions: &Functions) -> String {
    match e {
        Expr::Value(v) => every_digit(*v),
        Expr::Property(r) => format!(
            "`{}{}`",
            if r.negated { "-" } else { "" },
            functions.symbols.name(r.symbol)
        ),
        Expr::Table(t) => format!("the <table> at line {}", t.line),
        Expr::Apply(op, _) => format!("<{}>", op_name(*op)),
    }
}

/// The operands `e` evaluates to reach its value: every argument, or for `<ifthen>` the
/// condition and the branch it takes.
fn operands<'e>(env: &mut Env, e: &'e Expr) -> Vec<(&'e Expr, f64)> {
    let mut value = |a: &Expr| env.eval(a).unwrap_or(f64::NAN);
    match e {
        Expr::Apply(Op::IfThen, args) => {
            let c = value(&args[0]);
            let taken = &args[if c != 0.0 { 1 } else { 2 }];
            vec![(&args[0], c), (taken, value(taken))]
        }
        Expr::Apply(_, args) => args.iter().map(|a| (a, value(a))).collect(),
        _ => Vec::new(),
    }
}

/// Where the non-finite value of `e` (evaluated in `env`) first arose: the operation whose
/// operands are all finite, in words, and the properties it read. Follows properties into the
/// functions that define them.
pub fn origin(env: &mut Env, e: &Expr) -> (String, Vec<usize>) {
    let functions = env.functions();
    if let Expr::Property(r) = e {
        if let Some(f) = functions.defined_by[r.symbol] {
            let func = &functions.list[f];
            let (inner, read) = origin(env, &func.expr);
            let v = env.function(f).unwrap_or(f64::NAN);
            return (
                format!(
                    "it reads `{}` = {} (line {}), where {inner}",
                    func.name,
                    every_digit(v),
                    func.line
                ),
                read,
            );
        }
        return (
            format!("{} is not finite", shown(e, functions)),
            vec![r.symbol],
        );
    }
    let Expr::Apply(op, _) = e else {
        return (format!("{} is not finite", shown(e, functions)), Vec::new());
    };
    let args = operands(env, e);
    if let Some((a, _)) = args.iter().find(|(_, v)| !v.is_finite()) {
        return origin(env, a);
    }
    let read: Vec<usize> = args
        .iter()
        .filter_map(|(a, _)| match a {
            Expr::Property(r) => Some(r.symbol),
            _ => None,
        })
        .collect();
    let operand = |k: usize| match args[k].0 {
        Expr::Value(v) => every_digit(*v),
        a => format!("{} = {}", shown(a, functions), every_digit(args[k].1)),
    };
    let text = match op {
        Op::Quotient | Op::Fmod if args[1].1 == 0.0 => format!(
            "<{}> divides {} by {} (JSBSim gives HUGE_VAL there)",
            op_name(*op),
            operand(0),
            operand(1)
        ),
        _ => {
            let all: Vec<String> = (0..args.len()).map(operand).collect();
            let value = env.eval(e).unwrap_or(f64::NAN);
            format!("<{}> of {} is {value}", op_name(*op), all.join(", "))
        }
    };
    (text, read)
}

/// The refusal of function `f`, whose value in `env` is `value` (not finite) at the flight state
/// `place` (in words); `zeroed` are the inputs the import set to zero, named when the origin
/// reads one.
pub fn refusal(env: &mut Env, f: usize, value: f64, place: &str, zeroed: &[String]) -> JsbsimError {
    let functions = env.functions();
    let func = &functions.list[f];
    let (cause, read) = origin(env, &func.expr);
    let zero: Vec<&str> = read
        .iter()
        .map(|&s| functions.symbols.name(s))
        .filter(|n| zeroed.iter().any(|z| z == n))
        .collect();
    let hint = if zero.is_empty() {
        String::new()
    } else {
        format!(
            "; {} is an output of the model's systems, zero in the clean configuration the \
             import takes (give it with --set NAME=VALUE)",
            zero.join(", ")
        )
    };
    JsbsimError::new(
        env.file(),
        func.line,
        "function",
        format!(
            "`{}` is {value} at {place}: {cause}{hint} (expected a finite value: a NaN or \
             infinite coefficient is no aircraft)",
            func.name
        ),
    )
}
