//! Rust code for the generated functions, through quote/proc-macro2 and prettyplease.
//!
//! The statements, temporaries, named constants and parentheses come from [`super::program`],
//! shared with the C printer so that both evaluate the same operations in the same order.
//! Constants are exact rationals rounded once to the nearest f64 and printed as the shortest
//! literal that round-trips; a named constant's doc comment gives its exact value.

use super::expr::{Dag, Id};
use super::functions::{Function, Ret};
use super::program::{exact_text, program, Expr, Op};
use crate::algebra::Q;
use proc_macro2::{Ident, Literal, Span, TokenStream};
use quote::{format_ident, quote};

/// An f64 literal for an exact constant, rounded once to the nearest f64. A constant beyond
/// the range of f64 (an aircraft file with absurd magnitudes) rounds to +-infinity, as IEEE
/// rounding does, and is written `f64::INFINITY`: the generated code then returns infinities
/// or NaN for that aircraft instead of the emitter panicking.
pub fn float_literal(q: &Q) -> TokenStream {
    let x = q.to_f64();
    if x.is_nan() {
        return quote!(f64::NAN);
    }
    if x.is_infinite() {
        return if x > 0.0 {
            quote!(f64::INFINITY)
        } else {
            quote!(-f64::INFINITY)
        };
    }
    let lit = Literal::f64_unsuffixed(x.abs());
    if x.is_sign_negative() && x != 0.0 {
        quote!(-#lit)
    } else {
        quote!(#lit)
    }
}

fn input_tokens(name: &str) -> TokenStream {
    match name.split_once('.') {
        Some((base, field)) => {
            let b = Ident::new(base, Span::call_site());
            let f = Ident::new(field, Span::call_site());
            quote!(#b.#f)
        }
        None => {
            let i = Ident::new(name, Span::call_site());
            quote!(#i)
        }
    }
}

/// The tokens of an expression; its grouping is already explicit in [`Expr::Paren`].
fn tokens(e: &Expr) -> TokenStream {
    match e {
        Expr::Const(q) => float_literal(q),
        Expr::Named(n) => {
            let k = format_ident!("K{}", n);
            quote!(#k)
        }
        Expr::Input(name) => input_tokens(name),
        Expr::Temp(n) => {
            let t = format_ident!("t{}", n);
            quote!(#t)
        }
        Expr::Binary(op, a, b) => {
            let (x, y) = (tokens(a), tokens(b));
            match op {
                Op::Add => quote!(#x + #y),
                Op::Sub => quote!(#x - #y),
                Op::Mul => quote!(#x * #y),
                Op::Div => quote!(#x / #y),
            }
        }
        Expr::Neg(a) => {
            let x = tokens(a);
            quote!(-#x)
        }
        Expr::Sqrt(a) => {
            let x = tokens(a);
            quote!(libm::sqrt(#x))
        }
        Expr::CopySign(a, b) => {
            // core's `f64::copysign` (the `llvm.copysign` intrinsic: inlined, cannot unwind, so the
            // no-panic proof holds even where the arguments are constants), a method call: its
            // receiver is parenthesized unless it is an atom.
            let atom = match &**a {
                Expr::Const(q) => !q.is_negative(),
                Expr::Named(_) | Expr::Input(_) | Expr::Temp(_) => true,
                Expr::Sqrt(_) | Expr::CopySign(..) | Expr::Paren(_) => true,
                Expr::Binary(..) | Expr::Neg(_) => false,
            };
            let x = tokens(a);
            let x = if atom { x } else { quote!((#x)) };
            let y = tokens(b);
            quote!(#x.copysign(#y))
        }
        Expr::Paren(a) => {
            let x = tokens(a);
            quote!((#x))
        }
    }
}

/// The body statements and the tokens of each output, for a function's DAG: the named
/// constants (`const KN: f64`, their exact value in a doc comment), then the temporaries.
pub fn body(dag: &Dag, outputs: &[Id]) -> (Vec<TokenStream>, Vec<TokenStream>) {
    let p = program(dag, outputs);
    let constants = p.constants.iter().enumerate().map(|(n, q)| {
        let name = format_ident!("K{}", n);
        let doc = format!(" exact: {}", exact_text(q));
        let v = float_literal(q);
        quote!(#[doc = #doc] const #name: f64 = #v;)
    });
    let temps = p.temps.iter().enumerate().map(|(n, e)| {
        let name = format_ident!("t{}", n);
        let e = tokens(e);
        quote!(let #name = #e;)
    });
    let stmts = constants.chain(temps).collect();
    (stmts, p.outputs.iter().map(tokens).collect())
}

/// The tokens of one function, with `extra_attrs` (e.g. `#[no_panic]`) before it.
pub fn function(f: &Function, header_doc: &[String]) -> TokenStream {
    let ids: Vec<Id> = f.outputs.iter().map(|(_, id)| *id).collect();
    let (stmts, outs) = body(&f.dag, &ids);
    let name = Ident::new(f.name, Span::call_site());
    let mut args = Vec::new();
    if f.takes_self() {
        args.push(quote!(&self));
    }
    if f.takes_derivatives {
        args.push(quote!(k: &Derivatives));
    }
    for a in &f.args {
        let i = Ident::new(a.name, Span::call_site());
        args.push(quote!(#i: f64));
    }
    let (ret_ty, ret_expr) = match &f.ret {
        Ret::Scalar => (quote!(f64), outs[0].clone()),
        Ret::Array(n) => {
            let n = Literal::usize_unsuffixed(*n);
            (quote!([f64; #n]), quote!([#(#outs),*]))
        }
        Ret::Matrix(r, c) => {
            let rows: Vec<TokenStream> = outs.chunks(*c).map(|row| quote!([#(#row),*])).collect();
            let (r, c) = (Literal::usize_unsuffixed(*r), Literal::usize_unsuffixed(*c));
            (quote!([[f64; #c]; #r]), quote!([#(#rows),*]))
        }
        Ret::Struct(s) => {
            let s = Ident::new(s, Span::call_site());
            let fields: Vec<Ident> = f
                .outputs
                .iter()
                .map(|(n, _)| Ident::new(n, Span::call_site()))
                .collect();
            (quote!(#s), quote!(#s { #(#fields: #outs),* }))
        }
        Ret::Structs(s, n) => {
            let per = f.outputs.len() / n;
            let values: Vec<TokenStream> = f
                .outputs
                .chunks(per)
                .zip(outs.chunks(per))
                .map(|(fs, vs)| {
                    let s = Ident::new(s, Span::call_site());
                    let fields = fs.iter().map(|(n, _)| Ident::new(n, Span::call_site()));
                    quote!(#s { #(#fields: #vs),* })
                })
                .collect();
            let (s, n) = (
                Ident::new(s, Span::call_site()),
                Literal::usize_unsuffixed(*n),
            );
            (quote!([#s; #n]), quote!([#(#values),*]))
        }
    };
    let doc = super::doc_lines(f, header_doc);
    let doc = doc.iter().map(|l| format!(" {l}"));
    quote! {
        #(#[doc = #doc])*
        #[must_use]
        #[inline]
        pub fn #name(#(#args),*) -> #ret_ty {
            #(#stmts)*
            #ret_expr
        }
    }
}

/// Pretty-prints tokens of a whole file (prettyplease, the golden format).
pub fn pretty(tokens: TokenStream) -> Result<String, syn::Error> {
    let file: syn::File = syn::parse2(tokens)?;
    Ok(prettyplease::unparse(&file))
}
