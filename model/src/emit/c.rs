//! C99 for the generated functions: `generated/c/roll_criterion.h`, header-only.
//!
//! The functions are printed from the same [`super::statements::Program`] as the Rust crate, so
//! they perform the same IEEE operations in the same order; with `FLT_EVAL_METHOD == 0` (every
//! SSE2 or AArch64 target) and no floating-point contraction (`-ffp-contract=off`) their results
//! are bit-identical to Rust's at every optimisation level. gcc's vectoriser fuses multiplies
//! into add/subtract pairs whatever `-ffp-contract` says, so the header compiles its functions
//! without it (`NO_VECTORISER`). Nothing here knows a function, a struct or a parameter by name:
//! whatever [`super::functions::functions`], [`super::functions::structs`] and [`Param::ALL`]
//! hold is printed.

use super::functions::{Function, Prepared};
use super::shape::{access, c_struct, c_type, shapes, C_PREFIX};
use super::statements::{exact_text, inputs_used, program, Expr};
use super::{cost_doc, doc_lines, op_count_lines, prepared_doc, Builtin, COMMAND};
use crate::aircraft::{Aircraft, Param};
use crate::algebra::Q;
use std::fmt::Write;

/// Where the header lives and how a C file includes it.
pub const HEADER: &str = "roll_criterion.h";

/// The linkage macro users may define before including the header.
const API: &str = "ROLL_CRITERION_API";

/// The header's functions are compiled by gcc without its vectoriser: gcc 12's SLP vectoriser
/// turns a multiply feeding one lane of an add/subtract pair into a fused multiply-add-subtract
/// (`vfmaddsub`, `vfmsubadd` on x86 with FMA, e.g. `-O3 -march=x86-64-v3`) even under
/// `-ffp-contract=off`, which rounds once where the Rust code rounds twice. gcc does not inline
/// a function with its own optimisation options into code compiled with others, so the caller's
/// vectoriser does not see the arithmetic either. Clang keeps its vectorised code uncontracted
/// under `-ffp-contract=off`, and does not know the pragma (`-Wunknown-pragmas`), so the
/// condition names gcc proper (clang also defines `__GNUC__`).
const NO_VECTORISER: (&str, &str) = (
    "// gcc's vectoriser fuses a multiply into an add/subtract pair (vfmaddsub, vfmsubadd on x86\n\
     // with FMA) even under -ffp-contract=off, which would round differently from the Rust code:\n\
     // gcc compiles the functions below without it, and so does not inline them into code\n\
     // compiled with other options. Clang honours -ffp-contract=off in vectorised code too.\n\
     #if defined(__GNUC__) && !defined(__clang__)\n\
     #pragma GCC push_options\n\
     #pragma GCC optimize(\"no-tree-vectorize\")\n\
     #endif\n",
    "#if defined(__GNUC__) && !defined(__clang__)\n#pragma GCC pop_options\n#endif\n",
);

/// Lines longer than this are broken between tokens (C99 only promises 4095 characters).
const WIDTH: usize = 100;

/// A `double` literal for an exact constant, rounded once to the nearest f64: the shortest
/// decimal that reads back as the same double (Rust's `{:?}`, which always has a `.` or an
/// exponent, so C reads it as a `double`, never an `int`). Out-of-range constants round to
/// infinity, as in the Rust crate, written with `<math.h>`'s `HUGE_VAL`.
pub fn double_literal(q: &Q) -> String {
    let x = q.to_f64();
    let sign = if x.is_sign_negative() && x != 0.0 {
        "-"
    } else {
        ""
    };
    if x.is_infinite() {
        format!("{sign}HUGE_VAL")
    } else {
        format!("{sign}{:?}", x.abs())
    }
}

/// The C name of a generated function: `rc_det_k`, `rc_aircraft_a_det_k` for the function of a
/// built-in aircraft module, `rc_prepared_det_k` for `Prepared::det_k`.
pub fn c_name(module: Option<&str>, f: &Function) -> String {
    match (module, f.owner) {
        (_, Some(owner)) => format!("{C_PREFIX}{}_{}", owner.to_lowercase(), f.name),
        (Some(m), None) => format!("{C_PREFIX}{m}_{}", f.name),
        (None, None) => format!("{C_PREFIX}{}", f.name),
    }
}

/// The C name of a built-in aircraft's data, `rc_aircraft_a_derivatives`.
pub fn data_name(module: &str) -> String {
    format!("{C_PREFIX}{module}_derivatives")
}

fn expr(e: &Expr, out: &mut String) {
    match e {
        Expr::Const(q) => out.push_str(&double_literal(q)),
        Expr::Named(n) => write!(out, "K{n}").expect("write to String"),
        Expr::Input(name) => out.push_str(&name.replacen('.', "->", 1)),
        Expr::Temp(n) => write!(out, "t{n}").expect("write to String"),
        Expr::Binary(op, a, b) => {
            expr(a, out);
            write!(out, " {} ", op.symbol()).expect("write to String");
            expr(b, out);
        }
        Expr::Neg(a) => {
            out.push('-');
            expr(a, out);
        }
        Expr::Sqrt(a) => {
            out.push_str("sqrt(");
            expr(a, out);
            out.push(')');
        }
        Expr::CopySign(a, b) => {
            out.push_str("copysign(");
            expr(a, out);
            out.push_str(", ");
            expr(b, out);
            out.push(')');
        }
        Expr::Paren(a) => {
            out.push('(');
            expr(a, out);
            out.push(')');
        }
    }
}

/// `line` (starting with `indent`) broken at spaces into lines of at most [`WIDTH`] characters
/// where possible; continuation lines are indented four more. Spaces only ever separate tokens
/// in the printed C, so a break never changes its meaning.
fn wrap(line: &str, indent: &str) -> String {
    let words: Vec<&str> = line.trim_start().split(' ').collect();
    wrap_chunks(&words, indent)
}

/// `chunks` joined by spaces, broken between chunks as [`wrap`] does.
fn wrap_chunks(chunks: &[&str], indent: &str) -> String {
    let mut out = String::new();
    let mut current = String::new();
    for word in chunks {
        if !current.is_empty() && indent.len() + current.len() + 1 + word.len() > WIDTH {
            writeln!(out, "{indent}{current}").expect("write to String");
            current = format!("    {word}");
        } else {
            if !current.is_empty() {
                current.push(' ');
            }
            current.push_str(word);
        }
    }
    writeln!(out, "{indent}{current}").expect("write to String");
    out
}

/// A line of a `//` comment. A trailing backslash would continue the comment onto the next
/// line, and `-std=c99` reads trigraphs (`??/` is a backslash), so both are defused.
pub fn comment(line: &str) -> String {
    let mut s = line.replace("??", "? ?");
    if s.ends_with('\\') {
        s.push_str(" (backslash)");
    }
    if s.is_empty() {
        "///".into()
    } else {
        format!("/// {s}")
    }
}

/// The definition of one function: doc comment, signature, `const double tN` temporaries, one
/// `return`. Arguments a program does not read are cast to void (`-Wunused-parameter`).
pub fn function(f: &Function, module: Option<&str>) -> String {
    let ids: Vec<_> = f.outputs.iter().map(|(_, id)| *id).collect();
    let p = program(&f.dag, &ids);
    let used = inputs_used(&f.dag, &ids);
    let rust_path = match (module, f.owner) {
        (_, Some(owner)) => format!("roll_criterion::{owner}::{}", f.name),
        (Some(m), None) => format!("roll_criterion::{m}::{}", f.name),
        (None, None) => format!("roll_criterion::{}", f.name),
    };
    let mut tail = cost_doc(f);
    tail.push(format!("Rust: `{rust_path}`, bit-identical."));
    let mut out = String::new();
    for l in doc_lines(f, &tail) {
        out.push_str(&comment(&l));
        out.push('\n');
    }
    let mut params = Vec::new();
    let mut unused = Vec::new();
    if let (true, Some(owner)) = (f.takes_self(), f.owner) {
        params.push(format!("const struct {C_PREFIX}{owner} *self"));
    }
    if f.takes_derivatives {
        params.push(format!("const struct {C_PREFIX}derivatives *k"));
        if !used.iter().any(|u| u.starts_with("k.")) {
            unused.push("k");
        }
    }
    for a in &f.args {
        params.push(format!("double {}", a.name));
        if !used.iter().any(|u| u == a.name) {
            unused.push(a.name);
        }
    }
    if params.is_empty() {
        params.push("void".into());
    }
    let ret = c_type(&f.ret);
    // The signature breaks only between parameters.
    let last = params.len() - 1;
    let mut chunks: Vec<String> = params
        .iter()
        .enumerate()
        .map(|(i, p)| format!("{p}{}", if i == last { ")" } else { "," }))
        .collect();
    chunks[0] = format!("{API} {ret} {}({}", c_name(module, f), chunks[0]);
    let chunks: Vec<&str> = chunks.iter().map(String::as_str).collect();
    out.push_str(&wrap_chunks(&chunks, ""));
    out.push_str("{\n");
    for u in unused {
        writeln!(out, "    (void){u};").expect("write to String");
    }
    for (n, q) in p.constants.iter().enumerate() {
        writeln!(out, "    // exact: {}", exact_text(q)).expect("write to String");
        writeln!(out, "    const double K{n} = {};", double_literal(q)).expect("write to String");
    }
    for (n, e) in p.temps.iter().enumerate() {
        let mut s = format!("const double t{n} = ");
        expr(e, &mut s);
        s.push(';');
        out.push_str(&wrap(&s, "    "));
    }
    let text: Vec<String> = p
        .outputs
        .iter()
        .map(|e| {
            let mut s = String::new();
            expr(e, &mut s);
            s
        })
        .collect();
    if p.outputs.len() == 1 && ret == "double" {
        out.push_str(&wrap(&format!("return {};", text[0]), "    "));
    } else {
        writeln!(out, "    {ret} result;").expect("write to String");
        for (acc, t) in access(f, true).iter().zip(&text) {
            out.push_str(&wrap(&format!("result{acc} = {t};"), "    "));
        }
        out.push_str("    return result;\n");
    }
    out.push_str("}\n");
    out
}

/// `struct rc_derivatives`, field for field the Rust `Derivatives`.
fn derivatives_struct() -> String {
    let mut out = String::from(
        "/// The inertia coefficients and dimensional derivatives of an aircraft (Table A.1),\n\
         /// angles in rad: C = (Iz - Ix)/Iy, D = (Iy - Ix)/Iz, E = (Iz - Iy)/Ix.\n",
    );
    writeln!(out, "struct {C_PREFIX}derivatives {{").expect("write to String");
    for p in Param::ALL {
        writeln!(out, "    /// `{}`, {} (Table A.1).", p.key(), p.unit()).expect("write to String");
        writeln!(out, "    double {};", p.key().to_lowercase()).expect("write to String");
    }
    out.push_str("};\n");
    out
}

/// The data of a built-in aircraft as a `static const struct rc_derivatives` (positional
/// initializers, which C++ also accepts), each value rounded once.
fn derivatives_data(module: &str, ac: &Aircraft) -> String {
    let mut out = format!(
        "/// The data of {} (Table A.1), for the parametric functions.\n",
        ac.name
    );
    writeln!(
        out,
        "static const struct {C_PREFIX}derivatives {} = {{",
        data_name(module)
    )
    .expect("write to String");
    for p in Param::ALL {
        let v = double_literal(&Q::from_big(ac.exact(p).clone()));
        writeln!(out, "    {v}, // {}", p.key().to_lowercase()).expect("write to String");
    }
    out.push_str("};\n");
    out
}

fn op_counts(out: &mut String, fs: &[Function]) {
    for l in op_count_lines(fs) {
        writeln!(out, "//   {l}").expect("write to String");
    }
}

/// `struct rc_Prepared` and its functions: `rc_prepared_new`, `rc_prepared_det_k` and the slice
/// form `rc_prepared_det_k_into` (a loop over `rc_prepared_det_k`; `n` elements of `p0` and
/// `out`, which the caller provides).
fn prepared_section(p: &Prepared) -> String {
    let owner = p.new.owner.expect("Prepared::new has an owner");
    let mut out = String::new();
    for l in prepared_doc(p) {
        out.push_str(&comment(&l));
        out.push('\n');
    }
    writeln!(out, "struct {C_PREFIX}{owner} {{").expect("write to String");
    for (field, _) in &p.new.outputs {
        writeln!(out, "    double {field};").expect("write to String");
    }
    out.push_str("};\n\n");
    out.push_str(&function(&p.new, None));
    out.push('\n');
    out.push_str(&function(&p.det_k, None));
    out.push('\n');
    let name = c_name(None, &p.det_k);
    for l in [
        format!(
            "det K at `n` roll rates: `out[i] = {name}(self, p0[i])` for i < n (the slice form"
        ),
        "of the Rust crate's `Prepared::det_k_into`); `p0` and `out` hold at least n doubles."
            .into(),
        "No allocation; the loop body is the straight-line det_k.".into(),
    ] {
        out.push_str(&comment(&l));
        out.push('\n');
    }
    writeln!(
        out,
        "{API} void {name}_into(const struct {C_PREFIX}{owner} *self, const double *p0,\n    double *out, size_t n)\n{{\n    size_t i;\n    for (i = 0; i < n; i++) {{\n        out[i] = {name}(self, p0[i]);\n    }}\n}}"
    )
    .expect("write to String");
    out
}

/// The text of `generated/c/roll_criterion.h`.
pub fn header(param: &[Function], prepared: &Prepared, builtins: &[Builtin]) -> String {
    let mut out = format!(
        "// @generated by `{COMMAND}`. Do not edit.\n\
         // Header-only C99 library: the roll-coupling jump criterion (AIAA 2006-6267), the same\n\
         // functions as the Rust crate roll-criterion, printed from the same expression DAGs.\n\
         // Derived from model/src/equations.rs (Appendix A.2 of AIAA 2006-6267) by model/src/derivation.rs;\n\
         // inputs: symbolic parameters, {}; model {}; inputs hash {} (model::emit::inputs_hash).\n\
         // Operation counts after common-subexpression elimination (parametric; the functions of\n\
         // each built-in aircraft are counted in its section):\n",
        builtins
            .iter()
            .map(|b| format!("{} (model::aircraft)", b.aircraft.name))
            .collect::<Vec<_>>()
            .join(", "),
        env!("CARGO_PKG_VERSION"),
        super::inputs_hash(&builtins.iter().map(|b| &b.aircraft).collect::<Vec<_>>())
    );
    let counted: Vec<Function> = param
        .iter()
        .cloned()
        .chain([prepared.new.clone(), prepared.det_k.clone()])
        .collect();
    op_counts(&mut out, &counted);
    out.push_str(
        "//\n\
         // Use: `#include \"roll_criterion.h\"` and link with -lm (for sqrt and copysign). Every\n\
         // function is straight-line double arithmetic: no allocation, no recursion, no loops or\n\
         // branches, one return, nothing from the C library but sqrt and copysign (C99). A named\n\
         // constant KN is a folded exact rational rounded once; its comment gives the exact value.\n\
         // Results are bit-identical to the Rust crate when FLT_EVAL_METHOD == 0 and\n\
         // floating-point contraction is off (gcc/clang: -ffp-contract=off), at any optimisation\n\
         // level and -march (not with -ffast-math); otherwise they differ by rounding only.\n\
         // Define ROLL_CRITERION_API before the include to choose the linkage of the functions\n\
         // (default: static inline); the built-in aircraft data are static const objects.\n\n",
    );
    out.push_str(
        "#ifndef ROLL_CRITERION_H\n#define ROLL_CRITERION_H\n\n#include <math.h>\n#include <stddef.h>\n\n",
    );
    writeln!(out, "#ifndef {API}\n#define {API} static inline\n#endif\n").expect("write to String");
    out.push_str(NO_VECTORISER.0);
    out.push_str("\n#ifdef __cplusplus\nextern \"C\" {\n#endif\n\n");
    out.push_str(&derivatives_struct());
    let all = param
        .iter()
        .chain(builtins.iter().flat_map(|b| &b.functions));
    for shape in shapes(all) {
        out.push('\n');
        out.push_str(&c_struct(&shape).expect("non-scalar shape"));
    }
    for f in param {
        out.push('\n');
        out.push_str(&function(f, None));
    }
    out.push('\n');
    out.push_str(&prepared_section(prepared));
    for b in builtins {
        writeln!(
            out,
            "\n// {}: every constant folded exactly, then rounded once to double.\n\
             // Operation counts after common-subexpression elimination:",
            b.aircraft.name
        )
        .expect("write to String");
        op_counts(&mut out, &b.functions);
        out.push('\n');
        out.push_str(&derivatives_data(b.module, &b.aircraft));
        for f in &b.functions {
            out.push('\n');
            out.push_str(&function(f, Some(b.module)));
        }
    }
    out.push_str("\n#ifdef __cplusplus\n}\n#endif\n\n");
    out.push_str(NO_VECTORISER.1);
    out.push_str("\n#endif // ROLL_CRITERION_H\n");
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::emit::functions::{Arg, Ret};
    use crate::program::expr::Dag;
    use crate::specialise::exact_f64;

    #[test]
    fn double_literals_are_doubles_that_round_trip_exactly() {
        let mut values: Vec<Q> = [
            0.959,
            -13.52504,
            0.1,
            1e-300,
            5e-324,
            1e16,
            123456789.0,
            -2.5,
            f64::MAX,
        ]
        .iter()
        .map(|x| exact_f64(*x))
        .collect();
        values.extend([Q::ratio(1, 3), Q::ratio(-22, 7), Q::int(4), Q::ZERO]);
        for q in &values {
            let lit = double_literal(q);
            assert!(
                lit.contains('.') || lit.contains('e'),
                "{lit} is not a double"
            );
            // Rust's parser rounds correctly, as C compilers do for decimal constants.
            let back: f64 = lit.parse().unwrap();
            assert_eq!(back.to_bits(), q.to_f64().to_bits(), "{lit}");
        }
        let huge = Q::from_big(exact_f64(f64::MAX).to_big() * exact_f64(4.0).to_big());
        assert_eq!(double_literal(&huge), "HUGE_VAL");
        assert_eq!(double_literal(&-huge), "-HUGE_VAL");
    }

    /// A function of a shape and with an argument no generated function has today prints
    /// without any change here: a new return struct, a new argument, an unused argument.
    #[test]
    fn prints_any_array_shape_and_argument_name() {
        let mut dag = Dag::new();
        let x = dag.input("new_arg");
        dag.input("ignored");
        let k = dag.input("k.l_p");
        let minus_half = dag.constant(Q::ratio(-1, 2));
        let s = dag.sub(x, minus_half); // x - (-1/2) folds to x + 0.5
        let m = dag.mul(s, k);
        let n = dag.neg(m);
        let r = dag.sqrt(n);
        let f = Function {
            name: "future",
            doc: vec!["A function of the future.".into()],
            takes_derivatives: true,
            args: vec![
                Arg {
                    name: "new_arg",
                    doc: "a new argument",
                },
                Arg {
                    name: "ignored",
                    doc: "not read",
                },
            ],
            dag,
            outputs: vec![
                (String::new(), r),
                (String::new(), s),
                (String::new(), n),
                (String::new(), m),
            ],
            ret: Ret::Array(4),
            owner: None,
        };
        let text = function(&f, Some("aircraft_z"));
        for want in [
            "ROLL_CRITERION_API struct rc_array4 rc_aircraft_z_future(const struct rc_derivatives *k,\n",
            "    double new_arg, double ignored)\n{\n    (void)ignored;\n",
            // A negative constant stays a separate token: `- -0.5`, never `--0.5`.
            "    const double t0 = new_arg - -0.5;\n",
            "    const double t1 = k->l_p * t0;\n",
            "    result.v[0] = sqrt(t2);\n",
        ] {
            assert!(text.contains(want), "{want:?} not in\n{text}");
        }
        assert_eq!(text.matches("return").count(), 1);
        let def = super::super::shape::c_struct(&f.ret).unwrap();
        assert!(
            def.contains("struct rc_array4 {\n    double v[4];\n};"),
            "{def}"
        );
    }
}
