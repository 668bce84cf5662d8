//! `generated/c/test_roll_criterion.c`: the C header's self-test, and the C half of the
//! cross-check against the Rust crate.
//!
//! Run without arguments, the program calls every function of the header (parametric with each
//! built-in aircraft's data, and each aircraft's own) at a few fixed inputs and compares the
//! results with exact reference values within a rigorous rounding-error bound
//! ([`super::reference`]), so it passes with any conforming compiler on any IEEE target.
//! Run as `test_roll_criterion --bits FILE`, it reads input records (see [`super::cross`]) and
//! writes every output's double in host byte order, for the workspace's bit-identity check.

use super::c::{c_name, data_name, double_literal, HEADER};
use super::cross::{arg_columns, calls, columns, Call, INTO_INPUTS, INTO_LEN};
use super::functions::{Function, Prepared};
use super::reference::{evaluate, Reference};
use super::shape::{access, c_type, C_PREFIX};
use super::{Builtin, COMMAND};
use crate::aircraft::Param;
use crate::algebra::Q;
use crate::specialise::exact_f64;
use std::fmt::Write;

/// Inputs of the self-test: three points per function. Values are chosen by argument name,
/// away from the paper's jump and divergence roll rates; an argument this table does not know
/// gets small generic values.
fn sample(name: &str, point: usize) -> f64 {
    let table: [f64; 3] = match name {
        "p0" | "p" => [0.5, 1.3, 2.45],
        "delta_e" => [2f64.to_radians(), -0.05, 0.0],
        "delta_r" => [0.0, 0.01, -0.02],
        "alpha" => [0.05, -0.1, 0.2],
        "beta" => [0.02, -0.05, 0.1],
        "q" => [0.1, -0.2, 0.3],
        "r" => [-0.05, 0.1, 0.02],
        _ => [0.25, -0.5, 0.75],
    };
    table[point]
}

/// Number of self-test points per function.
const POINTS: usize = 3;

fn lit(x: f64) -> String {
    double_literal(&exact_f64(x))
}

/// The `{ ... }` block that checks one call at one point.
fn check_block(call: &Call, b: &Builtin, point: usize) -> String {
    let f = call.f;
    let data: Vec<(String, f64)> = Param::ALL
        .iter()
        .map(|p| {
            let v = Q::from_big(b.aircraft.exact(*p).clone()).to_f64();
            (format!("k.{}", p.key().to_lowercase()), v)
        })
        .collect();
    let input = |name: &str| -> f64 {
        match data.iter().find(|(n, _)| n == name) {
            Some((_, v)) => *v,
            None => sample(name, point),
        }
    };
    let ids: Vec<_> = f.outputs.iter().map(|(_, id)| *id).collect();
    let refs = evaluate(&f.dag, &ids, &input);
    let (want, tol): (Vec<String>, Vec<String>) = refs
        .iter()
        .map(|r| match r {
            // Twice the first-order bound: room for its own second-order terms and rounding.
            Reference::Value(q, e) => (double_literal(q), lit(2.0 * e)),
            Reference::Nan => ("0.0".into(), "-1.0".into()),
            Reference::Unknown => ("0.0".into(), "-2.0".into()),
        })
        .unzip();
    let mut args = Vec::new();
    if call.module.is_none() {
        args.push(format!("&{}", data_name(b.module)));
    }
    args.extend(f.args.iter().map(|a| lit(sample(a.name, point))));
    let call_text = format!("{}({})", c_name(call.module, f), args.join(", "));
    let got: Vec<String> = access(f, true).iter().map(|a| format!("r{a}")).collect();
    let n = refs.len();
    let mut out = String::from("    {\n");
    writeln!(
        out,
        "        static const double want[{n}] = {{{}}};",
        want.join(", ")
    )
    .unwrap();
    writeln!(
        out,
        "        static const double tol[{n}] = {{{}}};",
        tol.join(", ")
    )
    .unwrap();
    writeln!(out, "        const {} r = {call_text};", c_type(&f.ret)).unwrap();
    writeln!(
        out,
        "        const double got[{n}] = {{{}}};",
        got.join(", ")
    )
    .unwrap();
    writeln!(
        out,
        "        check(\"{call_text}\", got, want, tol, {n});\n    }}"
    )
    .unwrap();
    out
}

/// The block that checks `Prepared::det_k` with the data of `b` at one point, against the
/// reference of the whole (unstaged) program: the two stages perform exactly its operations.
fn prepared_block(p: &Prepared, b: &Builtin, point: usize) -> String {
    let input = |name: &str| -> f64 {
        match Param::ALL
            .iter()
            .find(|q| format!("k.{}", q.key().to_lowercase()) == name)
        {
            Some(q) => Q::from_big(b.aircraft.exact(*q).clone()).to_f64(),
            None => sample(name, point),
        }
    };
    let ids: Vec<_> = p.full.outputs.iter().map(|(_, id)| *id).collect();
    let (want, tol) = match &evaluate(&p.full.dag, &ids, &input)[0] {
        Reference::Value(q, e) => (double_literal(q), lit(2.0 * e)),
        Reference::Nan => ("0.0".into(), "-1.0".into()),
        Reference::Unknown => ("0.0".into(), "-2.0".into()),
    };
    let new_args: Vec<String> = std::iter::once(format!("&{}", data_name(b.module)))
        .chain(p.new.args.iter().map(|a| lit(sample(a.name, point))))
        .collect();
    let new = format!("{}({})", c_name(None, &p.new), new_args.join(", "));
    let call = format!(
        "{}(&prepared, {})",
        c_name(None, &p.det_k),
        lit(sample("p0", point))
    );
    format!(
        "    {{\n        const struct {C_PREFIX}{} prepared = {new};\n        static const double want[1] = {{{want}}};\n        static const double tol[1] = {{{tol}}};\n        const double got[1] = {{{call}}};\n        check(\"{call} with prepared = {new}\", got, want, tol, 1);\n    }}\n",
        p.new.owner.expect("Prepared::new has an owner")
    )
}

/// The self-test of one aircraft: all its calls at all points, then the prepared det K.
fn self_test_fn(param: &[Function], prepared: &Prepared, b: &Builtin) -> String {
    let mut out = format!(
        "/* Every function with the data of {}, at {POINTS} points. */\nstatic void self_test_{}(void)\n{{\n",
        b.aircraft.name, b.module
    );
    for point in 0..POINTS {
        for call in calls(param, b) {
            out.push_str(&check_block(&call, b, point));
        }
        out.push_str(&prepared_block(prepared, b, point));
    }
    out.push_str("}\n\n");
    out
}

/// The `--bits` function of one aircraft: every output of a record, in record order.
fn bits_fn(param: &[Function], prepared: &Prepared, b: &Builtin, columns: &[&str]) -> String {
    let mut out = format!(
        "/* Every output for {}, in record order. */\nstatic void outputs_{}(const double *x, double *o)\n{{\n    const struct rc_derivatives *k = &{};\n",
        b.aircraft.name,
        b.module,
        data_name(b.module)
    );
    let mut slot = 0;
    for call in calls(param, b) {
        let mut args = Vec::new();
        if call.module.is_none() {
            args.push("k".to_string());
        }
        args.extend(
            arg_columns(call.f, columns)
                .iter()
                .map(|c| format!("x[{c}]")),
        );
        writeln!(
            out,
            "    {{\n        const {} r = {}({});",
            c_type(&call.f.ret),
            c_name(call.module, call.f),
            args.join(", ")
        )
        .unwrap();
        for acc in access(call.f, true) {
            writeln!(out, "        o[{slot}] = r{acc};").unwrap();
            slot += 1;
        }
        out.push_str("    }\n");
    }
    // The prepared det K with the aircraft's data, and its slice form.
    let x = |f: &Function| -> Vec<String> {
        arg_columns(f, columns)
            .iter()
            .map(|c| format!("x[{c}]"))
            .collect()
    };
    let p0 = x(&prepared.det_k).remove(0);
    let det_k = c_name(None, &prepared.det_k);
    writeln!(
        out,
        "    {{\n        const struct {C_PREFIX}{} p = {}(k, {});\n        double in[{INTO_LEN}];\n        double r[{INTO_LEN}];",
        prepared.new.owner.expect("Prepared::new has an owner"),
        c_name(None, &prepared.new),
        x(&prepared.new).join(", ")
    )
    .unwrap();
    for (i, e) in INTO_INPUTS.iter().enumerate() {
        writeln!(out, "        in[{i}] = {};", e.replace("p0", &p0)).unwrap();
    }
    writeln!(out, "        {det_k}_into(&p, in, r, {INTO_LEN});").unwrap();
    writeln!(out, "        o[{slot}] = {det_k}(&p, {p0});").unwrap();
    for i in 0..INTO_LEN {
        writeln!(out, "        o[{}] = r[{i}];", slot + 1 + i).unwrap();
    }
    out.push_str("    }\n}\n\n");
    out
}

const PRELUDE: &str = r#"#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

static int checks;
static int skipped;
static int failures;

/* Compares n results with their references: |got - want| <= tol, or NaN expected (tol = -1),
 * or no bound exists at this point (tol = -2, counted as skipped). */
static void check(const char *call, const double *got, const double *want, const double *tol,
                  int n)
{
    int i;
    for (i = 0; i < n; i++) {
        if (tol[i] == -2.0) {
            skipped++;
            continue;
        }
        checks++;
        if (tol[i] == -1.0 ? got[i] == got[i] : !(fabs(got[i] - want[i]) <= tol[i])) {
            failures++;
            printf("FAIL %s output %d: got %.17g, want %.17g (bound %.3g)\n", call, i, got[i],
                   want[i], tol[i]);
        }
    }
}

"#;

/// The text of `generated/c/test_roll_criterion.c`.
pub fn self_test(param: &[Function], prepared: &Prepared, builtins: &[Builtin]) -> String {
    let columns = columns(param, builtins);
    let n_out: usize = builtins.first().map_or(0, |b| {
        calls(param, b)
            .iter()
            .map(|c| c.f.outputs.len())
            .sum::<usize>()
            + 1
            + INTO_LEN
    });
    let mut out = format!(
        "// @generated by `{COMMAND}`. Do not edit.\n\
         // Self-test of {HEADER}: every function, parametric with the data of each built-in\n\
         // aircraft and with the data folded in, against exact reference values (the program's\n\
         // mathematics in rational arithmetic, square roots rounded once) within a rigorous\n\
         // rounding-error bound; passes on any IEEE double target. Build and run:\n\
         //   cc -std=c99 -O2 test_roll_criterion.c -lm && ./a.out\n\
         // It prints the number of checks and exits 1 on any failure.\n\
         // `./a.out --bits FILE` reads records \"<aircraft index> <hex bits of each column>\",\n\
         // columns {},\n\
         // and writes the {n_out} results of each record as doubles in host byte order: the C half\n\
         // of the workspace's bit-identity check (tests/tests/c_header.rs).\n\n\
         #include \"{HEADER}\"\n",
        columns.join(", ")
    );
    out.push_str(PRELUDE);
    for b in builtins {
        out.push_str(&self_test_fn(param, prepared, b));
        out.push_str(&bits_fn(param, prepared, b, &columns));
    }
    let nc = columns.len();
    writeln!(
        out,
        "/* The --bits mode: one record per line, {nc} columns, {n_out} outputs. */\n\
         static int bits(const char *path)\n{{\n\
         \x20   FILE *in = fopen(path, \"r\");\n\
         \x20   unsigned aircraft;\n\
         \x20   double x[{nc}];\n\
         \x20   double o[{n_out}];\n\
         \x20   if (!in) {{\n\
         \x20       perror(path);\n\
         \x20       return 2;\n\
         \x20   }}\n\
         \x20   while (fscanf(in, \"%u\", &aircraft) == 1) {{\n\
         \x20       int i;\n\
         \x20       for (i = 0; i < {nc}; i++) {{\n\
         \x20           uint64_t u;\n\
         \x20           if (fscanf(in, \"%\" SCNx64, &u) != 1) {{\n\
         \x20               fprintf(stderr, \"bad record\\n\");\n\
         \x20               return 2;\n\
         \x20           }}\n\
         \x20           memcpy(&x[i], &u, sizeof u);\n\
         \x20       }}"
    )
    .unwrap();
    let mut first = true;
    for (i, b) in builtins.iter().enumerate() {
        let kw = if first { "if" } else { "} else if" };
        first = false;
        writeln!(
            out,
            "        {kw} (aircraft == {i}u) {{\n            outputs_{}(x, o);",
            b.module
        )
        .unwrap();
    }
    out.push_str(
        "        } else {\n            fprintf(stderr, \"no built-in aircraft %u\\n\", aircraft);\n            return 2;\n        }\n",
    );
    out.push_str(
        "        if (fwrite(o, sizeof o[0], sizeof o / sizeof o[0], stdout) != sizeof o / sizeof o[0]) {\n            return 2;\n        }\n    }\n    fclose(in);\n    return 0;\n}\n\n",
    );
    out.push_str("int main(int argc, char **argv)\n{\n");
    out.push_str("    if (argc == 3 && strcmp(argv[1], \"--bits\") == 0) {\n        return bits(argv[2]);\n    }\n");
    for b in builtins {
        writeln!(out, "    self_test_{}();", b.module).unwrap();
    }
    out.push_str(
        "    printf(\"test_roll_criterion: %d checks, %d failed, %d skipped (no error bound at that point)\\n\",\n           checks, failures, skipped);\n    return failures == 0 ? 0 : 1;\n}\n",
    );
    out
}
