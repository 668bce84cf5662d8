//! Rust code for the generated functions, through quote/proc-macro2 and prettyplease.
//!
//! Nodes used once are inlined into their parent, others get a `let tN`; parentheses follow
//! the DAG exactly (a right operand that is itself a sum is parenthesized, so floating-point
//! evaluation order is the DAG's, not a re-association). Constants are exact rationals rounded
//! once to the nearest f64 and printed as the shortest literal that round-trips.

use super::expr::{Dag, Id, Node};
use super::functions::{Function, Ret};
use crate::algebra::Q;
use proc_macro2::{Ident, Literal, Span, TokenStream};
use quote::{format_ident, quote};

/// Precedence of an emitted expression: atoms bind tightest.
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Prec {
    Atom,
    Unary,
    Product,
    Sum,
}

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

/// The body statements and the tokens of each output, for a function's DAG.
pub fn body(dag: &Dag, outputs: &[Id]) -> (Vec<TokenStream>, Vec<TokenStream>) {
    let live = dag.live(outputs);
    let n = dag.nodes().len();
    let mut uses = vec![0usize; n];
    for (i, l) in live.iter().enumerate() {
        if *l {
            for c in dag.children(Id(i as u32)) {
                uses[c.0 as usize] += 1;
            }
        }
    }
    for o in outputs {
        uses[o.0 as usize] += 1;
    }
    let mut expr: Vec<Option<(TokenStream, Prec)>> = vec![None; n];
    let mut stmts = Vec::new();
    let mut next = 0usize;
    for (i, node) in dag.nodes().iter().enumerate() {
        if !live[i] {
            continue;
        }
        let get = |id: &Id, expr: &Vec<Option<(TokenStream, Prec)>>| {
            expr[id.0 as usize]
                .clone()
                .expect("children are emitted before parents")
        };
        let wrap = |t: (TokenStream, Prec), max: Prec| {
            if t.1 > max {
                let inner = t.0;
                quote!((#inner))
            } else {
                t.0
            }
        };
        let (tokens, prec) = match node {
            Node::Const(q) => {
                let t = float_literal(q);
                (
                    t,
                    if q.is_negative() {
                        Prec::Unary
                    } else {
                        Prec::Atom
                    },
                )
            }
            Node::Input(k) => (input_tokens(&dag.inputs()[*k as usize]), Prec::Atom),
            Node::Add(a, b) => {
                let (x, y) = (
                    wrap(get(a, &expr), Prec::Sum),
                    wrap(get(b, &expr), Prec::Product),
                );
                (quote!(#x + #y), Prec::Sum)
            }
            Node::Sub(a, b) => {
                let (x, y) = (
                    wrap(get(a, &expr), Prec::Sum),
                    wrap(get(b, &expr), Prec::Product),
                );
                (quote!(#x - #y), Prec::Sum)
            }
            Node::Mul(a, b) => {
                let (x, y) = (
                    wrap(get(a, &expr), Prec::Product),
                    wrap(get(b, &expr), Prec::Atom),
                );
                (quote!(#x * #y), Prec::Product)
            }
            Node::Div(a, b) => {
                let (x, y) = (
                    wrap(get(a, &expr), Prec::Product),
                    wrap(get(b, &expr), Prec::Atom),
                );
                (quote!(#x / #y), Prec::Product)
            }
            Node::Neg(a) => {
                let x = wrap(get(a, &expr), Prec::Atom);
                (quote!(-#x), Prec::Unary)
            }
            Node::Sqrt(a) => {
                let x = get(a, &expr).0;
                (quote!(libm::sqrt(#x)), Prec::Atom)
            }
        };
        let is_leaf = matches!(node, Node::Const(_) | Node::Input(_));
        if is_leaf || uses[i] <= 1 {
            expr[i] = Some((tokens, prec));
        } else {
            let name = format_ident!("t{}", next);
            next += 1;
            stmts.push(quote!(let #name = #tokens;));
            expr[i] = Some((quote!(#name), Prec::Atom));
        }
    }
    let outs = outputs
        .iter()
        .map(|o| expr[o.0 as usize].clone().expect("output emitted").0)
        .collect();
    (stmts, outs)
}

/// The tokens of one function, with `extra_attrs` (e.g. `#[no_panic]`) before it.
pub fn function(f: &Function, header_doc: &[String]) -> TokenStream {
    let ids: Vec<Id> = f.outputs.iter().map(|(_, id)| *id).collect();
    let (stmts, outs) = body(&f.dag, &ids);
    let name = Ident::new(f.name, Span::call_site());
    let mut args = Vec::new();
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
    };
    let mut doc: Vec<String> = f.doc.clone();
    if !f.args.is_empty() {
        doc.push(String::new());
        doc.push("Arguments:".into());
        for a in &f.args {
            doc.push(format!("- `{}`: {}", a.name, a.doc));
        }
    }
    doc.extend_from_slice(header_doc);
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
