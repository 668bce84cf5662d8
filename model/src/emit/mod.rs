//! The emitter: derived formulas to closed-form, branch-free Rust and to LaTeX.
//!
//! One emitter serves both front ends: `cargo run -p model -- emit` writes the generated crate
//! (`generated/`) and `docs/formulas.tex`; the `roll_criterion!` proc-macro (`derive/`) calls
//! [`macro_items`] and returns the same functions as tokens. Output is deterministic: the DAG
//! is built in a fixed order, nothing iterates a hash map into output, and prettyplease (pinned)
//! formats it.
//!
//! ```
//! // The proc-macro's expansion of the parametric functions holds det K (Eq. 27) and its
//! // prepared form.
//! let items = model::emit::macro_items(None).to_string();
//! assert!(items.contains("fn det_k") && items.contains("struct Prepared"));
//! ```

pub(crate) mod c;
pub(crate) mod c_self_test;
pub(crate) mod cross;
pub(crate) mod formulas;
pub(crate) mod functions;
pub mod latex;
pub mod paper;
pub(crate) mod reference;
pub(crate) mod rust;
pub(crate) mod shape;
pub mod statements;

use crate::aircraft::{Aircraft, Param};
use crate::algebra::Q;
use crate::derivation::Derivation;
use crate::program::expr::OpCount;
use functions::{functions, structs, Function, Prepared};
use proc_macro2::{Ident, Span, TokenStream};
use quote::quote;
use std::path::{Path, PathBuf};

/// One file the emitter produces, relative to the workspace root.
#[derive(Clone, Debug, PartialEq)]
pub struct Output {
    /// Path relative to the workspace root.
    pub path: PathBuf,
    /// Full contents.
    pub contents: String,
}

/// Errors of the emitter.
#[derive(Debug, thiserror::Error)]
pub enum EmitError {
    /// Generated tokens did not parse (a bug in the emitter).
    #[error("generated code does not parse: {0}")]
    Parse(#[from] syn::Error),
    /// Writing an output failed.
    #[error("cannot write {path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
}

/// The command that regenerates the outputs, quoted in headers and in `--check` messages.
pub const COMMAND: &str = "cargo run -p model -- emit";

pub use crate::specialise::aircraft_values;

/// The functions with every parameter an argument (`k: &Derivatives`).
pub fn parametric_functions() -> Vec<Function> {
    functions(&Derivation::parametric(), true)
}

/// The functions with an aircraft's data folded in exactly, then rounded once to f64.
pub fn specialised_functions(ac: &Aircraft) -> Vec<Function> {
    let d = Derivation::derive(&aircraft_values(ac));
    let mut fs = functions(&d, false);
    // Only per aircraft: the parametric Hopf polynomial is out of reach (functions/hopf.rs).
    fs.push(functions::hopf_polynomial(ac, &d));
    fs
}

/// Operation counts per function, as the header lines of a generated file.
pub fn op_count_lines(fs: &[Function]) -> Vec<String> {
    let mut lines = vec![format!(
        "{:<32} {:>7} {:>7} {:>7} {:>7} {:>7} {:>7}",
        "function", "add/sub", "mul", "div", "neg", "libm", "total"
    )];
    for f in fs {
        let c = op_count(f);
        let name = match f.owner {
            Some(owner) => format!("{owner}::{}", f.name),
            None => f.name.to_string(),
        };
        lines.push(format!(
            "{:<32} {:>7} {:>7} {:>7} {:>7} {:>7} {:>7}",
            name,
            c.add,
            c.mul,
            c.div,
            c.neg,
            c.libm,
            c.total()
        ));
    }
    lines
}

/// Operation count of one function after CSE.
pub fn op_count(f: &Function) -> OpCount {
    let ids: Vec<crate::program::expr::Id> = f.outputs.iter().map(|(_, id)| *id).collect();
    f.dag.op_count(&ids)
}

fn struct_items(with_derivatives: bool) -> TokenStream {
    let mut out = TokenStream::new();
    if with_derivatives {
        let fields = Param::ALL.iter().map(|p| {
            let name = Ident::new(&p.key().to_lowercase(), Span::call_site());
            let doc = format!(" `{}`, {} (Table A.1).", p.key(), p.unit());
            quote!(#[doc = #doc] pub #name: f64,)
        });
        out.extend(quote! {
            /// The inertia coefficients and dimensional derivatives of an aircraft (Table A.1),
            /// angles in rad: C = (Iz - Ix)/Iy, D = (Iy - Ix)/Iz, E = (Iz - Iy)/Ix.
            #[derive(Clone, Copy, Debug, PartialEq)]
            pub struct Derivatives { #(#fields)* }
        });
    }
    for (name, doc, fields) in structs() {
        let name = Ident::new(name, Span::call_site());
        let doc = format!(" {doc}");
        let fs = fields.iter().map(|(f, d)| {
            let f = Ident::new(f, Span::call_site());
            let d = format!(" {d}");
            quote!(#[doc = #d] pub #f: f64,)
        });
        out.extend(quote! {
            #[doc = #doc]
            #[derive(Clone, Copy, Debug, PartialEq)]
            pub struct #name { #(#fs)* }
        });
    }
    out
}

/// The doc comment of a generated function, in every language: what it computes (formula,
/// equation numbers, units), its arguments, then `tail`.
pub fn doc_lines(f: &Function, tail: &[String]) -> Vec<String> {
    let mut doc: Vec<String> = f.doc.clone();
    if !f.args.is_empty() {
        doc.push(String::new());
        doc.push("Arguments:".into());
        for a in &f.args {
            doc.push(format!("- `{}`: {}", a.name, a.doc));
        }
    }
    doc.extend_from_slice(tail);
    doc
}

/// The cost paragraph of a function's doc comment (its operation count after CSE).
pub fn cost_doc(f: &Function) -> Vec<String> {
    let c = op_count(f);
    vec![
        String::new(),
        format!(
            "Cost after CSE: {} add/sub, {} mul, {} div, {} neg, {} libm ({} operations); straight-line, no branches.",
            c.add, c.mul, c.div, c.neg, c.libm, c.total()
        ),
    ]
}

fn fn_items(fs: &[Function], attrs: &TokenStream) -> TokenStream {
    let mut out = TokenStream::new();
    for f in fs {
        let item = rust::function(f, &cost_doc(f));
        out.extend(quote!(#attrs #item));
    }
    out
}

/// The items the proc-macro expands to: the structs and the functions, parametric (`None`,
/// with the `Prepared` struct) or specialised to an aircraft.
pub fn macro_items(aircraft: Option<&Aircraft>) -> TokenStream {
    let fs = match aircraft {
        None => parametric_functions(),
        Some(ac) => specialised_functions(ac),
    };
    let mut out = struct_items(aircraft.is_none());
    out.extend(fn_items(&fs, &TokenStream::new()));
    if aircraft.is_none() {
        out.extend(prepared_items(&prepared(), &TokenStream::new()));
    }
    out
}

/// The prepared det K of the parametric derivation.
pub fn prepared() -> Prepared {
    functions::prepared(crate::specialise::parametric())
}

/// `struct Prepared` and its `impl`: `new`, `det_k` and the slice form `det_k_into`, each with
/// `attrs` (the no-panic proof), the private generic `det_k_lanes` that holds `det_k`'s
/// statements once for both, and the private module `prepared_lanes` of its four-lane type.
fn prepared_items(p: &Prepared, attrs: &TokenStream) -> TokenStream {
    let fields = p
        .new
        .outputs
        .iter()
        .map(|(n, _)| Ident::new(n, Span::call_site()));
    let new = rust::function(&p.new, &cost_doc(&p.new));
    let lanes = Ident::new("det_k_lanes", Span::call_site());
    let det_k = rust::delegating_function(&p.det_k, &cost_doc(&p.det_k), &lanes);
    let det_k_lanes = rust::lane_function(&p.det_k, &lanes);
    let lane_items = rust::lane_items();
    let doc = prepared_doc(p).into_iter().map(|l| format!(" {l}"));
    let into_doc = det_k_into_doc().into_iter().map(|l| format!(" {l}"));
    quote! {
        #(#[doc = #doc])*
        #[derive(Clone, Copy, Debug, PartialEq)]
        pub struct Prepared { #(#fields: f64,)* }

        impl Prepared {
            #attrs
            #new
            #attrs
            #det_k
            #det_k_lanes
            #(#[doc = #into_doc])*
            #attrs
            #[inline]
            pub fn det_k_into(&self, p0: &[f64], out: &mut [f64]) {
                let n = core::cmp::min(p0.len(), out.len());
                let (p0, out) = (p0.split_at(n).0, out.split_at_mut(n).0);
                let (mut o4, mut p4) = (out.chunks_exact_mut(4), p0.chunks_exact(4));
                for (o, p) in core::iter::zip(&mut o4, &mut p4) {
                    let lanes = prepared_lanes::Lanes([p[0], p[1], p[2], p[3]]);
                    o.copy_from_slice(&self.det_k_lanes(lanes).0);
                }
                for (o, p) in core::iter::zip(o4.into_remainder(), p4.remainder()) {
                    *o = self.det_k(*p);
                }
            }
        }

        #lane_items
    }
}

/// The doc of the `Prepared` type, in every language.
pub fn prepared_doc(p: &Prepared) -> Vec<String> {
    vec![
        "det K (Eq. 27) of one aircraft and control setting, prepared for many roll rates:".into(),
        "`Prepared::new(k, delta_e, delta_r)` computes once everything of `det_k` that does not"
            .into(),
        "depend on P0; `det_k(p0)` and the slice form `det_k_into` do the rest, on the trim branch"
            .into(),
        "of the free `det_k` (element 0 of `trim`, with aileron yaw too). The per-call program is"
            .into(),
        "the roll-rate-dependent part of one straight-line program (model/src/program/stage.rs), with"
            .into(),
        format!(
            "{} fields; per call {} operations against {} for `Prepared::new`.",
            p.new.outputs.len(),
            op_count(&p.det_k).total(),
            op_count(&p.new).total()
        ),
    ]
}

/// The doc of the slice form, in every language.
pub fn det_k_into_doc() -> Vec<String> {
    vec![
        "det K at each roll rate of `p0`, written to `out`: element i of `out` is".into(),
        "`self.det_k(p0[i])` for i below the shorter length; the rest of `out` is not touched."
            .into(),
        "No allocation, no panic. Four roll rates at a time: the statements of `det_k` over four"
            .into(),
        "lanes, which the compiler turns into packed (SIMD) arithmetic; each lane is the same"
            .into(),
        "operations in the same order as `det_k`, so the results are bit for bit `det_k`'s (NaN"
            .into(),
        "where `det_k` is NaN; IEEE leaves a NaN's sign and payload open).".into(),
    ]
}

fn derivatives_const(ac: &Aircraft) -> TokenStream {
    let fields = Param::ALL.iter().map(|p| {
        let name = Ident::new(&p.key().to_lowercase(), Span::call_site());
        let v = rust::float_literal(&Q::from_big(ac.exact(*p).clone()));
        quote!(#name: #v,)
    });
    let doc = format!(
        " The data of {} (Table A.1), for the parametric functions.",
        ac.name
    );
    quote! {
        #[doc = #doc]
        pub const DERIVATIVES: super::Derivatives = super::Derivatives { #(#fields)* };
    }
}

/// A hash of what a generation is made from: the model equations (the PSS right-hand sides of
/// [`crate::equations::pss`], term by term), the exact data of `aircraft` and the model (emitter)
/// version; FNV-1a 64, as 16 hex digits. Two generated files with the same hash came from the
/// same inputs; a reviewer can tell two generations apart by it.
///
/// ```
/// use model::aircraft::Aircraft;
/// use model::emit::inputs_hash;
///
/// let a = Aircraft::a();
/// assert_eq!(inputs_hash(&[&a]), inputs_hash(&[&a]));
/// assert_ne!(inputs_hash(&[&a]), inputs_hash(&[]));
/// ```
pub fn inputs_hash(aircraft: &[&Aircraft]) -> String {
    let mut text = format!("model {}\n", env!("CARGO_PKG_VERSION"));
    for f in crate::equations::pss() {
        for (m, c) in f.terms() {
            let exps: Vec<String> = m
                .factors()
                .iter()
                .map(|(sym, e)| format!("{}^{e}", sym.name()))
                .collect();
            text.push_str(&format!("{} {}\n", c.to_big(), exps.join("*")));
        }
        text.push_str(";\n");
    }
    for ac in aircraft {
        text.push_str(&format!("aircraft {}\n", ac.name));
        for p in Param::ALL {
            text.push_str(&format!("{} = {}\n", p.key(), ac.exact(p)));
        }
    }
    let h = text.bytes().fold(0xcbf2_9ce4_8422_2325_u64, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
    });
    format!("{h:016x}")
}

fn header(title: &str, fs: &[Function], inputs: &str, hash: &str) -> String {
    let mut h = format!(
        "// @generated by `{COMMAND}`. Do not edit.\n// {title}\n// Derived from model/src/equations.rs (Appendix A.2 of AIAA 2006-6267) by model/src/derivation.rs;\n// inputs: {inputs}; model {}; inputs hash {hash} (model::emit::inputs_hash).\n// Operation counts after common-subexpression elimination:\n",
        env!("CARGO_PKG_VERSION")
    );
    for l in op_count_lines(fs) {
        h.push_str("//   ");
        h.push_str(&l);
        h.push('\n');
    }
    h.push('\n');
    h
}

/// A built-in aircraft as the generated code has it: a module of functions with its data
/// folded in.
pub struct Builtin {
    /// Module name (`aircraft_a`); C names are prefixed with it.
    pub module: &'static str,
    /// The aircraft.
    pub aircraft: Aircraft,
    /// Its functions, data folded in.
    pub functions: Vec<Function>,
}

/// The built-in aircraft of Table A.1 with their functions.
pub fn builtins() -> Vec<Builtin> {
    [("aircraft_a", Aircraft::a()), ("aircraft_b", Aircraft::b())]
        .into_iter()
        .map(|(module, aircraft)| Builtin {
            module,
            functions: specialised_functions(&aircraft),
            aircraft,
        })
        .collect()
}

/// Everything `emit` writes: the generated crate, its C twin and the LaTeX dump.
pub fn generate() -> Result<Vec<Output>, EmitError> {
    let param = parametric_functions();
    let builtins = builtins();
    let attrs = quote!(#[cfg_attr(feature = "no-panic-check", no_panic::no_panic)]);
    let prepared = prepared();
    let mut outputs = vec![lib_rs(&param, &prepared, &builtins, &attrs)?];
    for b in &builtins {
        outputs.push(builtin_module(b, &attrs)?);
    }
    outputs.push(Output {
        path: "generated/Cargo.toml".into(),
        contents: cargo_toml(),
    });
    outputs.push(Output {
        path: "generated/rustfmt.toml".into(),
        contents: format!(
            "# @generated by `{COMMAND}`. Do not edit.\n# The generated sources are formatted by prettyplease (pinned), their golden format;\n# `cargo fmt --all` must leave them alone or `emit --check` would see them as stale.\ndisable_all_formatting = true\n"
        ),
    });
    outputs.push(Output {
        path: "generated/tests/values.rs".into(),
        contents: generated_tests::values()?,
    });
    outputs.push(Output {
        path: "generated/tests/compiled.rs".into(),
        contents: generated_tests::compiled(&param, &prepared, &builtins)?,
    });
    outputs.push(Output {
        path: format!("generated/c/{}", c::HEADER).into(),
        contents: c::header(&param, &prepared, &builtins),
    });
    outputs.push(Output {
        path: "generated/c/test_roll_criterion.c".into(),
        contents: c_self_test::self_test(&param, &prepared, &builtins),
    });
    outputs.push(Output {
        path: "tests/tests/c_header/calls.rs".into(),
        contents: cross::rust_calls(&param, &prepared, &builtins)?,
    });
    outputs.push(Output {
        path: "docs/formulas.tex".into(),
        contents: latex::document(),
    });
    Ok(outputs)
}

/// `generated/src/lib.rs`: the crate root with the structs, the parametric functions and
/// `Prepared`, and the modules of the built-in aircraft.
fn lib_rs(
    param: &[Function],
    prepared: &Prepared,
    builtins: &[Builtin],
    attrs: &TokenStream,
) -> Result<Output, EmitError> {
    let mods = builtins
        .iter()
        .map(|b| Ident::new(b.module, Span::call_site()));
    let structs = struct_items(true);
    let fns = fn_items(param, attrs);
    let prepared_tokens = prepared_items(prepared, attrs);
    let example = "```\n\
        use roll_criterion::{aircraft_a, det_k};\n\n\
        let de = 2f64.to_radians();\n\
        // det K of aircraft A is positive at P0 = 0.5 rad/s, below its first jump (1.706 rad/s)\n\
        let specialised = aircraft_a::det_k(0.5, de, 0.0);\n\
        assert!(specialised > 0.0);\n\
        // the parametric function with A's data agrees\n\
        let parametric = det_k(&aircraft_a::DERIVATIVES, 0.5, de, 0.0);\n\
        assert!((parametric - specialised).abs() <= 1e-12 * specialised.abs());\n\
        ```";
    let lib = quote! {
        //! Closed-form roll-coupling jump criterion (Mahale & Ananthkrishnan, AIAA 2006-6267),
        //! generated from the model equations by exact symbolic derivation.
        //!
        //! Every function is straight-line, branch-free f64 arithmetic (square roots through
        //! `libm`), except the slice form `Prepared::det_k_into`, a loop over its slices whose
        //! body is straight-line: no allocation, no panics, no `unsafe`. The parametric functions take the
        //! aircraft's [`Derivatives`]; the modules [`aircraft_a`] and [`aircraft_b`] hold the
        //! same functions with the data of Table A.1 folded in exactly and rounded once.
        //!
        // The example is left out of the link-time no-panic proof: a doctest is built without
        // optimisation, so the `#[inline]` functions it calls keep their panic guards.
        #![cfg_attr(not(feature = "no-panic-check"), doc = #example)]
        #![no_std]
        #![forbid(unsafe_code)]
        #![warn(missing_docs)]
        #(pub mod #mods;)*
        #structs
        #fns
        #prepared_tokens
    };
    let counted: Vec<Function> = param
        .iter()
        .cloned()
        .chain([prepared.new.clone(), prepared.det_k.clone()])
        .collect();
    let mut text = header(
        "Parametric functions.",
        &counted,
        "symbolic parameters",
        &inputs_hash(&[]),
    );
    text.push_str(&rust::pretty(lib)?);
    Ok(Output {
        path: "generated/src/lib.rs".into(),
        contents: text,
    })
}

/// `generated/src/<module>.rs`: a built-in aircraft's functions with its data folded in.
fn builtin_module(b: &Builtin, attrs: &TokenStream) -> Result<Output, EmitError> {
    let Builtin {
        module: m,
        aircraft: ac,
        functions: fs,
    } = b;
    let konst = derivatives_const(ac);
    let fns = fn_items(fs, attrs);
    let doc = format!(
        " The criterion for {} of Table A.1: every constant folded exactly, then rounded once to f64.",
        ac.name
    );
    let tokens = quote! {
        #![doc = #doc]
        use super::{Trim, ZeroSideslipTrim};
        #konst
        #fns
    };
    let mut text = header(
        &format!("{}, data folded in.", ac.name),
        fs,
        &format!("{} (model::aircraft)", ac.name),
        &inputs_hash(&[ac]),
    );
    text.push_str(&rust::pretty(tokens)?);
    Ok(Output {
        path: format!("generated/src/{m}.rs").into(),
        contents: text,
    })
}

mod generated_tests;

fn cargo_toml() -> String {
    format!(
        r#"# @generated by `{COMMAND}`. Do not edit.
[package]
name = "roll-criterion"
description = "Closed-form roll-coupling jump criterion (AIAA 2006-6267), generated; no_std, no allocation, no panics"
version = "{}"
edition = "2021"
license = "MIT OR Apache-2.0"
publish = false

[dependencies]
libm = "0.2"
# Only for the workspace's link-time proof that no function can panic (`--features no-panic-check`
# in release); never enabled by flight software.
no-panic = {{ version = "0.1", optional = true }}

[features]
no-panic-check = ["dep:no-panic"]
"#,
        env!("CARGO_PKG_VERSION")
    )
}

/// Files whose contents differ from `outputs` under `root` (missing files count as stale).
pub fn stale(root: &Path, outputs: &[Output]) -> Vec<PathBuf> {
    outputs
        .iter()
        .filter(|o| {
            std::fs::read_to_string(root.join(&o.path))
                .map(|s| s.replace("\r\n", "\n") != o.contents)
                .unwrap_or(true)
        })
        .map(|o| o.path.clone())
        .collect()
}

/// The journal of an interrupted [`write()`] under the workspace root (see
/// [`crate::files::replace_all`]).
pub const JOURNAL: &str = ".emit-journal";

/// Writes every changed output, all at once or not at all ([`crate::files::replace_all`]:
/// each file staged to a temporary name, then renamed); unchanged files are not touched.
/// Returns the files written.
pub fn write(root: &Path, outputs: &[Output]) -> Result<Vec<PathBuf>, EmitError> {
    let io = |source| EmitError::Io {
        path: root.to_path_buf(),
        source,
    };
    tidy(root, outputs).map_err(io)?;
    let changed: Vec<(PathBuf, &[u8])> = outputs
        .iter()
        .filter(|o| std::fs::read_to_string(root.join(&o.path)).map_or(true, |s| s != o.contents))
        .map(|o| (o.path.clone(), o.contents.as_bytes()))
        .collect();
    crate::files::replace_all(root, JOURNAL, &changed).map_err(io)?;
    Ok(changed.into_iter().map(|(p, _)| p).collect())
}

/// Finishes an emit that was killed after staging every file and removes the temporary files
/// of killed runs (run first by [`write()`] and by `emit --check`).
pub fn tidy(root: &Path, outputs: &[Output]) -> std::io::Result<()> {
    crate::files::recover(root, JOURNAL, outputs.iter().map(|o| o.path.as_path()))
}
