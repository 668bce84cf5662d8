//! How a generated function's outputs sit in its return value, in Rust and in C.
//!
//! Every question about a [`Ret`] that a non-Rust printer or a cross-language test asks is
//! answered here, so that a new function with an existing return shape (a scalar, an array, a
//! matrix, any struct listed in [`structs`]) reaches the C header and the cross-check with no
//! other edit. C cannot return an array, so arrays and matrices come back wrapped in a struct
//! (`struct rc_array3 { double v[3]; }`, `struct rc_matrix5x5 { double m[5][5]; }`).

use super::functions::{structs, Function, Ret};

/// The C prefix of every name the header declares.
pub const C_PREFIX: &str = "rc_";

/// The C type a function returns (`double`, `struct rc_Trim`, `struct rc_array3`).
pub fn c_type(ret: &Ret) -> String {
    match ret {
        Ret::Scalar => "double".into(),
        Ret::Array(n) => format!("struct {C_PREFIX}array{n}"),
        Ret::Matrix(r, c) => format!("struct {C_PREFIX}matrix{r}x{c}"),
        Ret::Struct(s) => format!("struct {C_PREFIX}{s}"),
        Ret::Structs(s, n) => format!("struct {C_PREFIX}{s}_array{n}"),
    }
}

/// The C definition of the struct a non-scalar return shape needs (None for a scalar).
pub fn c_struct(ret: &Ret) -> Option<String> {
    let (doc, fields) = match ret {
        Ret::Scalar => return None,
        Ret::Array(n) => (
            format!("/// `[f64; {n}]` of the Rust crate: C cannot return an array."),
            vec![(format!("double v[{n}];"), None)],
        ),
        Ret::Matrix(r, c) => (
            format!(
                "/// `[[f64; {c}]; {r}]` of the Rust crate (row-major): C cannot return an array."
            ),
            vec![(format!("double m[{r}][{c}];"), None)],
        ),
        Ret::Structs(s, n) => (
            format!("/// `[{s}; {n}]` of the Rust crate: C cannot return an array."),
            vec![(format!("{} v[{n}];", c_type(&Ret::Struct(s))), None)],
        ),
        Ret::Struct(s) => {
            let (_, doc, fields) = structs()
                .into_iter()
                .find(|(n, _, _)| n == s)
                .unwrap_or_else(|| panic!("struct {s} is returned but not listed in structs()"));
            (
                format!("/// {doc}"),
                fields
                    .iter()
                    .map(|(f, d)| (format!("double {f};"), Some(d.to_string())))
                    .collect(),
            )
        }
    };
    let mut out = format!("{doc}\n{} {{\n", c_type(ret));
    for (field, doc) in fields {
        if let Some(d) = doc {
            out.push_str(&format!("    /// {d}\n"));
        }
        out.push_str(&format!("    {field}\n"));
    }
    out.push_str("};\n");
    Some(out)
}

/// Every distinct return shape of `fs`, structs first in [`structs`] order, then arrays and
/// matrices by size: the order in which the header defines them.
pub fn shapes<'a>(fs: impl IntoIterator<Item = &'a Function>) -> Vec<Ret> {
    let mut all: Vec<Ret> = Vec::new();
    for f in fs {
        // An array of structs needs its struct defined first.
        let needs = match f.ret {
            Ret::Structs(s, _) => vec![Ret::Struct(s), f.ret.clone()],
            _ => vec![f.ret.clone()],
        };
        for r in needs {
            if r != Ret::Scalar && !all.contains(&r) {
                all.push(r);
            }
        }
    }
    let names: Vec<&str> = structs().iter().map(|(n, _, _)| *n).collect();
    let key = |r: &Ret| match r {
        Ret::Struct(s) => (
            0,
            names.iter().position(|n| n == s).unwrap_or(usize::MAX),
            0,
        ),
        Ret::Structs(s, n) => (
            0,
            names.iter().position(|x| x == s).unwrap_or(usize::MAX),
            *n,
        ),
        Ret::Array(n) => (1, *n, 0),
        Ret::Matrix(r, c) => (2, *r, *c),
        Ret::Scalar => (3, 0, 0),
    };
    all.sort_by_key(key);
    all
}

/// How each output is reached from a returned value `r`, as a suffix: `""` for a scalar,
/// `.alpha` for a struct field, `[i]`/`[i][j]` (Rust) or `.v[i]`/`.m[i][j]` (C) for arrays.
pub fn access(f: &Function, c: bool) -> Vec<String> {
    let (v, m) = if c { (".v", ".m") } else { ("", "") };
    (0..f.outputs.len())
        .map(|i| match &f.ret {
            Ret::Scalar => String::new(),
            Ret::Array(_) => format!("{v}[{i}]"),
            Ret::Matrix(_, cols) => format!("{m}[{}][{}]", i / cols, i % cols),
            Ret::Struct(_) => format!(".{}", f.outputs[i].0),
            Ret::Structs(_, n) => {
                let per = f.outputs.len() / n;
                format!("{v}[{}].{}", i / per, f.outputs[i].0)
            }
        })
        .collect()
}
