//! The layout of the C-versus-Rust cross-check, and its Rust half.
//!
//! An input record is a built-in aircraft (by index) and one double per argument name that any
//! generated function takes (sorted, so the columns do not depend on the order of the
//! functions). For each record, both sides compute every output of every function in the same
//! order: the parametric functions with the aircraft's data, then the aircraft's own functions
//! with the data folded in, then `Prepared::det_k` and `Prepared::det_k_into` of the
//! parametric `Prepared` with the aircraft's data. `test_roll_criterion --bits` prints the C results
//! ([`super::c_self_test`]); `tests/tests/c_header/calls.rs`, written here, computes the Rust ones.
//! Both are generated from the same function list, so a new function is cross-checked without
//! an edit.

use super::c::{c_name, data_name};
use super::functions::{Function, Prepared};
use super::rust::pretty;
use super::shape::access;
use super::{Builtin, COMMAND};
use proc_macro2::{Ident, Literal, Span, TokenStream};
use quote::quote;

/// One function call of a record: the function and the built-in module it belongs to (None
/// for a parametric function, called with the record's aircraft data).
#[derive(Clone, Copy)]
pub struct Call<'a> {
    /// The built-in module, for a function with the data folded in.
    pub module: Option<&'static str>,
    /// The function.
    pub f: &'a Function,
}

/// The calls of a record for aircraft `b`, in output order.
pub fn calls<'a>(param: &'a [Function], b: &'a Builtin) -> Vec<Call<'a>> {
    let folded = b.functions.iter().map(|f| Call {
        module: Some(b.module),
        f,
    });
    param
        .iter()
        .map(|f| Call { module: None, f })
        .chain(folded)
        .collect()
}

/// The argument names of all functions, sorted and deduplicated: the columns of a record.
pub fn columns(param: &[Function], builtins: &[Builtin]) -> Vec<&'static str> {
    let mut names: Vec<&'static str> = param
        .iter()
        .chain(builtins.iter().flat_map(|b| &b.functions))
        .flat_map(|f| f.args.iter().map(|a| a.name))
        .collect();
    names.sort_unstable();
    names.dedup();
    names
}

/// The column of each argument of `f`.
pub fn arg_columns(f: &Function, columns: &[&str]) -> Vec<usize> {
    f.args
        .iter()
        .map(|a| {
            columns
                .iter()
                .position(|c| *c == a.name)
                .expect("every argument is a column")
        })
        .collect()
}

/// How many roll rates the cross-check passes to `det_k_into`: six expressions of the record's
/// `p0` ([`INTO_INPUTS`], the same arithmetic in both languages), so that the Rust slice form
/// runs both its four-lane loop and its scalar rest against C's scalar loop.
pub const INTO_LEN: usize = 6;

/// The roll rates of `det_k_into` as expressions of the record's `p0`, in Rust and C alike.
pub const INTO_INPUTS: [&str; INTO_LEN] = [
    "p0",
    "p0 * 0.5",
    "p0 + 1.0",
    "p0 * 0.25",
    "p0 + 0.5",
    "p0 * 1.5",
];

/// The labels of the prepared outputs of a record for aircraft `b` (after its calls).
pub fn prepared_labels(p: &Prepared, b: &Builtin) -> Vec<String> {
    let new = format!("{}(&{})", c_name(None, &p.new), data_name(b.module));
    let det_k = c_name(None, &p.det_k);
    let mut out = vec![format!("{det_k}(&{new})")];
    out.extend((0..INTO_LEN).map(|i| format!("{det_k}_into(&{new})[{i}]")));
    out
}

/// The labels of every output of a record for aircraft `b`, in record order.
pub fn record_labels(param: &[Function], prepared: &Prepared, b: &Builtin) -> Vec<String> {
    let mut out: Vec<String> = calls(param, b).iter().flat_map(|c| labels(c, b)).collect();
    out.extend(prepared_labels(prepared, b));
    out
}

/// The C-style label of each output of a call, for failure messages.
pub fn labels(call: &Call, b: &Builtin) -> Vec<String> {
    let name = c_name(call.module, call.f);
    let k = if call.module.is_none() {
        format!("&{}", data_name(b.module))
    } else {
        String::new()
    };
    access(call.f, true)
        .iter()
        .map(|acc| format!("{name}({k}){acc}"))
        .collect()
}

fn record_fn(
    param: &[Function],
    prepared: &Prepared,
    b: &Builtin,
    columns: &[&str],
    n_out: usize,
) -> TokenStream {
    let name = Ident::new(b.module, Span::call_site());
    let mut lets = Vec::new();
    let mut outs = Vec::new();
    for (i, call) in calls(param, b).iter().enumerate() {
        let r = Ident::new(&format!("r{i}"), Span::call_site());
        let f = Ident::new(call.f.name, Span::call_site());
        let mut args: Vec<TokenStream> = Vec::new();
        let path = match call.module {
            Some(m) => {
                let m = Ident::new(m, Span::call_site());
                quote!(rc::#m::#f)
            }
            None => {
                args.push(quote!(k));
                quote!(rc::#f)
            }
        };
        for c in arg_columns(call.f, columns) {
            let c = Literal::usize_unsuffixed(c);
            args.push(quote!(x[#c]));
        }
        lets.push(quote!(let #r = #path(#(#args),*);));
        for acc in access(call.f, false) {
            let e: TokenStream = format!("{r}{acc}").parse().expect("an access path");
            outs.push(e);
        }
    }
    // The prepared det K with this aircraft's data.
    let col = |f: &Function| -> Vec<TokenStream> {
        arg_columns(f, columns)
            .iter()
            .map(|c| {
                let c = Literal::usize_unsuffixed(*c);
                quote!(x[#c])
            })
            .collect()
    };
    let new_args = col(&prepared.new);
    let p0 = col(&prepared.det_k);
    let p0 = &p0[0];
    let into: Vec<TokenStream> = INTO_INPUTS
        .iter()
        .map(|e| {
            e.replace("p0", &p0.to_string())
                .parse()
                .expect("an expression")
        })
        .collect();
    let n_into = Literal::usize_unsuffixed(INTO_LEN);
    lets.push(quote! {
        let prepared = rc::Prepared::new(k, #(#new_args),*);
        let mut into = [0.0; #n_into];
        prepared.det_k_into(&[#(#into),*], &mut into);
    });
    outs.push(quote!(prepared.det_k(#p0)));
    for i in 0..INTO_LEN {
        let i = Literal::usize_unsuffixed(i);
        outs.push(quote!(into[#i]));
    }
    assert_eq!(outs.len(), n_out, "every aircraft has the same outputs");
    let (nc, no) = (
        Literal::usize_unsuffixed(columns.len()),
        Literal::usize_unsuffixed(n_out),
    );
    let doc = format!(" Every output for {}, in record order.", b.aircraft.name);
    quote! {
        #[doc = #doc]
        fn #name(x: &[f64; #nc]) -> [f64; #no] {
            let k = &rc::#name::DERIVATIVES;
            #(#lets)*
            [#(#outs),*]
        }
    }
}

/// The text of `tests/tests/c_header/calls.rs`.
pub fn rust_calls(
    param: &[Function],
    prepared: &Prepared,
    builtins: &[Builtin],
) -> Result<String, syn::Error> {
    let columns = columns(param, builtins);
    let labels: Vec<Vec<String>> = builtins
        .iter()
        .map(|b| record_labels(param, prepared, b))
        .collect();
    let n_out = labels.first().map_or(0, Vec::len);
    let (nc, no, na) = (
        Literal::usize_unsuffixed(columns.len()),
        Literal::usize_unsuffixed(n_out),
        Literal::usize_unsuffixed(builtins.len()),
    );
    let modules: Vec<&str> = builtins.iter().map(|b| b.module).collect();
    let fns = builtins
        .iter()
        .map(|b| record_fn(param, prepared, b, &columns, n_out));
    let arms = builtins.iter().enumerate().map(|(i, b)| {
        let i = Literal::usize_unsuffixed(i);
        let m = Ident::new(b.module, Span::call_site());
        quote!(#i => #m(x),)
    });
    let label_rows = labels.iter().map(|row| quote!([#(#row),*]));
    let file = quote! {
        //! Every function of roll-criterion on one input record, in the order in which
        //! `test_roll_criterion --bits` writes the C results (see model/src/emit/cross.rs).
        use roll_criterion as rc;

        /// Argument names: the columns of a record.
        pub const COLUMNS: [&str; #nc] = [#(#columns),*];
        /// The built-in aircraft, by their index in a record.
        pub const AIRCRAFT: [&str; #na] = [#(#modules),*];
        /// What each output is, per aircraft (C names).
        pub const LABELS: [[&str; #no]; #na] = [#(#label_rows),*];

        /// Every output for the aircraft with index `aircraft`, in record order.
        pub fn outputs(aircraft: usize, x: &[f64; #nc]) -> [f64; #no] {
            match aircraft {
                #(#arms)*
                _ => panic!("no built-in aircraft {aircraft}"),
            }
        }

        #(#fns)*
    };
    Ok(format!(
        "// @generated by `{COMMAND}`. Do not edit.\n{}",
        pretty(file)?
    ))
}
