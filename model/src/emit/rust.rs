//! Rust code for the generated functions, through quote/proc-macro2 and prettyplease.
//!
//! The statements, temporaries, named constants and parentheses come from [`super::program`],
//! shared with the C printer so that both evaluate the same operations in the same order.
//! Constants are exact rationals rounded once to the nearest f64 and printed as the shortest
//! literal that round-trips; a named constant's doc comment gives its exact value.

use super::functions::{Function, Ret};
use super::statements::{exact_text, program, Expr, Op};
use crate::algebra::Q;
use crate::program::expr::{Dag, Id};
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

/// The type of the values of a body: `f64`, or the lanes type `T` of a generic body (the
/// per-call program of `Prepared`, evaluated for one roll rate or for four at once). Either way
/// the statements are the same operations in the same order, so each lane of a generic body
/// equals the f64 body bit for bit (a NaN lane is NaN there too; IEEE leaves a NaN's sign and
/// payload open).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Values {
    /// Plain f64.
    F64,
    /// `T: Lane` (see [`lane_items`]): an input through `self` (an f64 field `self.fN`) is
    /// spelled `fN`, bound once at the top of the body to `T::splat(self.fN)`; the other inputs
    /// are `T`, constants are splat where used.
    Lanes,
}

fn input_tokens(name: &str, values: Values) -> TokenStream {
    match name.split_once('.') {
        Some((base, field)) => {
            let b = Ident::new(base, Span::call_site());
            let f = Ident::new(field, Span::call_site());
            match values {
                Values::F64 => quote!(#b.#f),
                Values::Lanes => quote!(#f),
            }
        }
        None => {
            let i = Ident::new(name, Span::call_site());
            quote!(#i)
        }
    }
}

/// The tokens of an expression; its grouping is already explicit in [`Expr::Paren`].
fn tokens(e: &Expr, values: Values) -> TokenStream {
    let lanes = values == Values::Lanes;
    match e {
        Expr::Const(q) => {
            let x = float_literal(q);
            if lanes {
                quote!(T::splat(#x))
            } else {
                x
            }
        }
        Expr::Named(n) => {
            let k = format_ident!("K{}", n);
            if lanes {
                quote!(T::splat(#k))
            } else {
                quote!(#k)
            }
        }
        Expr::Input(name) => input_tokens(name, values),
        Expr::Temp(n) => {
            let t = format_ident!("t{}", n);
            quote!(#t)
        }
        Expr::Binary(op, a, b) => {
            let (x, y) = (tokens(a, values), tokens(b, values));
            match op {
                Op::Add => quote!(#x + #y),
                Op::Sub => quote!(#x - #y),
                Op::Mul => quote!(#x * #y),
                Op::Div => quote!(#x / #y),
            }
        }
        Expr::Neg(a) => {
            let x = tokens(a, values);
            quote!(-#x)
        }
        Expr::Sqrt(a) => {
            let x = tokens(a, values);
            if lanes {
                quote!(T::sqrt(#x))
            } else {
                quote!(libm::sqrt(#x))
            }
        }
        Expr::CopySign(a, b) => {
            let (x, y) = (tokens(a, values), tokens(b, values));
            if lanes {
                return quote!(T::copysign(#x, #y));
            }
            // core's `f64::copysign` (the `llvm.copysign` intrinsic: inlined, cannot unwind, so the
            // no-panic proof holds even where the arguments are constants), a method call: its
            // receiver is parenthesized unless it is an atom.
            let atom = match &**a {
                Expr::Const(q) => !q.is_negative(),
                Expr::Named(_) | Expr::Input(_) | Expr::Temp(_) => true,
                Expr::Sqrt(_) | Expr::CopySign(..) | Expr::Paren(_) => true,
                Expr::Binary(..) | Expr::Neg(_) => false,
            };
            let x = if atom { x } else { quote!((#x)) };
            quote!(#x.copysign(#y))
        }
        Expr::Paren(a) => {
            let x = tokens(a, values);
            quote!((#x))
        }
    }
}

/// The body statements and the tokens of each output, for a function's DAG: the named
/// constants (`const KN: f64`, their exact value in a doc comment), then the temporaries.
pub fn body(dag: &Dag, outputs: &[Id], values: Values) -> (Vec<TokenStream>, Vec<TokenStream>) {
    let p = program(dag, outputs);
    let constants = p.constants.iter().enumerate().map(|(n, q)| {
        let name = format_ident!("K{}", n);
        let doc = format!(" exact: {}", exact_text(q));
        let v = float_literal(q);
        quote!(#[doc = #doc] const #name: f64 = #v;)
    });
    let temps = p.temps.iter().enumerate().map(|(n, e)| {
        let name = format_ident!("t{}", n);
        let e = tokens(e, values);
        quote!(let #name = #e;)
    });
    let stmts = constants.chain(temps).collect();
    let outs = p.outputs.iter().map(|e| tokens(e, values)).collect();
    (stmts, outs)
}

/// The tokens of one function, its doc (`header_doc` first) and its body of straight-line f64
/// statements.
pub fn function(f: &Function, header_doc: &[String]) -> TokenStream {
    let ids: Vec<Id> = f.outputs.iter().map(|(_, id)| *id).collect();
    let (stmts, outs) = body(&f.dag, &ids, Values::F64);
    signature_and_body(f, header_doc, stmts, outs)
}

/// The tokens of a scalar method `f` (inputs `&self` and f64 arguments, one output) whose body
/// calls the generic `lanes` (made by [`lane_function`] from the same `f`) with `T = f64`: the
/// same doc and signature as [`function`] gives, the statements written once for both.
pub fn delegating_function(f: &Function, header_doc: &[String], lanes: &Ident) -> TokenStream {
    let args = f.args.iter().map(|a| Ident::new(a.name, Span::call_site()));
    let call = quote!(self.#lanes(#(#args),*));
    signature_and_body(f, header_doc, Vec::new(), vec![call])
}

/// The generic form of the scalar method `f`, named `name`: its statements over `T: Lane`
/// ([`lane_items`]), so that one body serves one roll rate (`T = f64`) and four (`Lanes`).
pub fn lane_function(f: &Function, name: &Ident) -> TokenStream {
    let ids: Vec<Id> = f.outputs.iter().map(|(_, id)| *id).collect();
    let (stmts, outs) = body(&f.dag, &ids, Values::Lanes);
    let fields = f.dag.inputs().iter().filter_map(|i| {
        let field = Ident::new(i.strip_prefix("self.")?, Span::call_site());
        Some(quote!(let #field = T::splat(self.#field);))
    });
    let args = f.args.iter().map(|a| Ident::new(a.name, Span::call_site()));
    let out = &outs[0];
    let doc = format!(
        " The statements of [`{}`](Self::{}), over f64 or four lanes (`T`).",
        f.name, f.name
    );
    quote! {
        #[doc = #doc]
        #[inline(always)]
        fn #name<T: prepared_lanes::Lane>(&self, #(#args: T),*) -> T {
            #(#fields)*
            #(#stmts)*
            #out
        }
    }
}

/// The private module `prepared_lanes`: the arithmetic a [`lane_function`] needs, for `f64`
/// (libm's square root, core's copysign, as [`function`] writes them) and for `Lanes`, four
/// f64 side by side, lane by lane the same operations: a loop over `Lanes` is what the
/// compiler turns into packed (SIMD) arithmetic, without `unsafe` or target features.
pub fn lane_items() -> TokenStream {
    let ops = [
        (quote!(Add), quote!(add), quote!(+)),
        (quote!(Sub), quote!(sub), quote!(-)),
        (quote!(Mul), quote!(mul), quote!(*)),
        (quote!(Div), quote!(div), quote!(/)),
    ];
    let impls = ops.iter().map(|(tr, f, op)| {
        quote! {
            impl #tr for Lanes {
                type Output = Lanes;
                #[inline(always)]
                fn #f(self, b: Lanes) -> Lanes {
                    Lanes([
                        self.0[0] #op b.0[0],
                        self.0[1] #op b.0[1],
                        self.0[2] #op b.0[2],
                        self.0[3] #op b.0[3],
                    ])
                }
            }
        }
    });
    quote! {
        /// Four roll rates at once for [`Prepared::det_k_into`]: the per-call statements are
        /// written once, generic over [`Lane`](prepared_lanes::Lane), and each lane of
        /// `Lanes` computes exactly what `f64` does (only arithmetic on array elements at
        /// constant indices: no branch, no closure, no panic).
        mod prepared_lanes {
            use core::ops::{Add, Div, Mul, Neg, Sub};
            /// The arithmetic of the per-call statements.
            pub(super) trait Lane: Copy
            where
                Self: Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self>,
                Self: Div<Output = Self> + Neg<Output = Self>,
            {
                /// The same f64 in every lane.
                fn splat(x: f64) -> Self;
                /// The square root (IEEE, correctly rounded), lane by lane.
                fn sqrt(x: Self) -> Self;
                /// `x` with the sign of `sign`, lane by lane.
                fn copysign(x: Self, sign: Self) -> Self;
            }
            impl Lane for f64 {
                #[inline(always)]
                fn splat(x: f64) -> f64 {
                    x
                }
                #[inline(always)]
                fn sqrt(x: f64) -> f64 {
                    libm::sqrt(x)
                }
                #[inline(always)]
                fn copysign(x: f64, sign: f64) -> f64 {
                    x.copysign(sign)
                }
            }
            /// Four f64, one roll rate each.
            #[derive(Clone, Copy)]
            pub(super) struct Lanes(pub(super) [f64; 4]);
            #(#impls)*
            impl Neg for Lanes {
                type Output = Lanes;
                #[inline(always)]
                fn neg(self) -> Lanes {
                    Lanes([-self.0[0], -self.0[1], -self.0[2], -self.0[3]])
                }
            }
            impl Lane for Lanes {
                #[inline(always)]
                fn splat(x: f64) -> Lanes {
                    Lanes([x; 4])
                }
                #[inline(always)]
                fn sqrt(x: Lanes) -> Lanes {
                    Lanes([
                        libm::sqrt(x.0[0]),
                        libm::sqrt(x.0[1]),
                        libm::sqrt(x.0[2]),
                        libm::sqrt(x.0[3]),
                    ])
                }
                #[inline(always)]
                fn copysign(x: Lanes, sign: Lanes) -> Lanes {
                    Lanes([
                        x.0[0].copysign(sign.0[0]),
                        x.0[1].copysign(sign.0[1]),
                        x.0[2].copysign(sign.0[2]),
                        x.0[3].copysign(sign.0[3]),
                    ])
                }
            }
        }
    }
}

/// The signature, doc and attributes of `f` around the given statements and outputs.
fn signature_and_body(
    f: &Function,
    header_doc: &[String],
    stmts: Vec<TokenStream>,
    outs: Vec<TokenStream>,
) -> TokenStream {
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
