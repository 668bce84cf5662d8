//! The generated crate's own tests, emitted with it.
//!
//! Expected values are computed here by exact rational arithmetic along a different route than
//! the emitted f64 code: det K from the jump polynomial, `det K = jump / (d det(A)^2)`,
//! evaluated exactly at a rational P0 and rounded once; trims from their exact numerators over
//! det A. The paper's values (Table 1) and the roots of an independent numeric computation
//! (continuation and eigenvalues, in `reference`) are checked too.

use super::functions::{Function, Prepared};
use super::rust::{float_literal, pretty};
use super::{aircraft_values, Builtin, COMMAND};
use crate::aircraft::Aircraft;
use crate::algebra::{Poly, Q};
use crate::derivation::Derivation;
use crate::equations::symbols;
use crate::reference;
use crate::specialise::{exact_f64, univariate};
use proc_macro2::{Ident, Span, TokenStream};
use quote::quote;

fn exact_at(p: &Poly, values: &[(crate::algebra::Sym, Q)]) -> Q {
    p.subs_values(values)
        .as_constant()
        .expect("every symbol given a value")
}

fn lit(x: f64) -> TokenStream {
    float_literal(&exact_f64(x))
}

fn q_lit(q: &Q) -> TokenStream {
    float_literal(q)
}

/// The text of `generated/tests/values.rs`.
pub fn values() -> Result<String, syn::Error> {
    let s = symbols();
    let de = 2f64.to_radians();
    let mut tests = TokenStream::new();
    for (m, ac, points, roots) in [
        (
            "aircraft_a",
            Aircraft::a(),
            vec![0.5, 1.0, 2.5, 4.0],
            reference::A_JUMP_P0.to_vec(),
        ),
        (
            "aircraft_b",
            Aircraft::b(),
            vec![0.5, 1.5, 2.2, 3.7, 4.3],
            reference::B_JUMP_P0.to_vec(),
        ),
    ] {
        let module = Ident::new(m, Span::call_site());
        let mut values = aircraft_values(&ac);
        values.push((s.delta_e, exact_f64(de)));
        values.push((s.delta_r, Q::ZERO));
        let d = Derivation::derive(&values);
        let (jump, det_a, dda) = (
            univariate(d.jump_at(), s.p0),
            univariate(&d.det_a, s.p0),
            univariate(d.d_at(), s.p0),
        );
        // det K = det J5 / d = (jump / det(A)^2) / (d_det_a / det(A)^2).
        let mut checks = TokenStream::new();
        for p in &points {
            let x = exact_f64(*p).to_big();
            let det_k = Q::from_big(jump.eval(&x) / dda.eval(&x));
            let den = det_a.eval(&x);
            let trims: Vec<TokenStream> = d
                .trim
                .iter()
                .map(|n| q_lit(&Q::from_big(univariate(n, s.p0).eval(&x) / den.clone())))
                .collect();
            let (pl, dk) = (lit(*p), q_lit(&det_k));
            let [ta, tb, tq, tr] = [&trims[0], &trims[1], &trims[2], &trims[3]];
            checks.extend(quote! {
                close(#module::det_k(#pl, DE, 0.0), #dk, 1e-9, "specialised det_k");
                close(det_k(&#module::DERIVATIVES, #pl, DE, 0.0), #dk, 1e-9, "parametric det_k");
                let [t, _] = #module::trim(#pl, DE, 0.0);
                close(t.alpha, #ta, 1e-10, "alpha0");
                close(t.beta, #tb, 1e-10, "beta0");
                close(t.q, #tq, 1e-10, "Q0");
                close(t.r, #tr, 1e-10, "R0");
                close(
                    #module::det_j5(#pl, DE, 0.0),
                    #module::residual_denominator(#pl, DE, 0.0) * #module::det_k(#pl, DE, 0.0),
                    1e-9,
                    "det J5 = d det K",
                );
            });
        }
        for r in &roots {
            let (lo, hi) = (lit(r - 1e-5), lit(r + 1e-5));
            checks.extend(quote! {
                assert!(
                    #module::det_k(#lo, DE, 0.0) * #module::det_k(#hi, DE, 0.0) < 0.0,
                    "det K changes sign at an independently computed jump root"
                );
            });
        }
        // Jump polynomial coefficients at this delta_e, exactly.
        let sym_only = Derivation::derive(&aircraft_values(&ac));
        let coeffs: Vec<TokenStream> = sym_only
            .jump_at()
            .coeffs(s.p0)
            .iter()
            .map(|c| {
                q_lit(&exact_at(
                    c,
                    &[(s.delta_e, exact_f64(de)), (s.delta_r, Q::ZERO)],
                ))
            })
            .collect();
        checks.extend(quote! {
            let c = #module::jump_polynomial(DE, 0.0);
            let want = [#(#coeffs),*];
            for (got, want) in c.iter().zip(want) {
                close(*got, want, 1e-10, "jump polynomial coefficient");
            }
        });
        let name = Ident::new(&format!("{m}_matches_exact_values"), Span::call_site());
        tests.extend(quote! {
            #[test]
            fn #name() {
                #checks
            }
        });
    }
    let [t1, t2] = reference::TABLE_1_B.map(proc_macro2::Literal::f64_unsuffixed);
    let file = quote! {
        //! Tests of the generated criterion against exact values of the same derivation:
        //! rational arithmetic in the generator (det K via the jump polynomial, a different
        //! route than the code under test, not an independent one), the paper's Table 1 and
        //! jump roots (AIAA 2006-6267, Figs 7-8). The independent check is `independent.rs`
        //! (SymPy values of `tests/oracle/write_values.py`).
        #![allow(clippy::excessive_precision, clippy::unreadable_literal)]

        use roll_criterion::{aircraft_a, aircraft_b, det_k};

        /// Elevator deflection of the paper's figures: 2 deg in rad.
        const DE: f64 = 0.03490658503988659;

        /// Relative closeness; values are checked away from roots and poles of det K, where
        /// straight-line f64 evaluation loses at most a few hundred ulps.
        fn close(got: f64, want: f64, rel: f64, what: &str) {
            let scale = want.abs().max(1e-300);
            assert!(
                (got - want).abs() <= rel * scale,
                "{what}: got {got:e}, want {want:e}"
            );
        }

        #tests

        #[test]
        fn table_1_divergence_roll_rates_of_aircraft_b() {
            let [p1, p2] = aircraft_b::divergence_roll_rates();
            assert!((p1 - #t1).abs() < 0.01 && (p2 - #t2).abs() < 0.01, "{p1} {p2}");
            let [a1, a2] = aircraft_a::divergence_roll_rates();
            assert!(a1.is_nan() && a2.is_nan(), "aircraft A has no divergence: {a1} {a2}");
        }
    };
    let mut text = format!("// @generated by `{COMMAND}`. Do not edit.\n");
    text.push_str(&pretty(file)?);
    Ok(text)
}

/// The text of `generated/tests/compiled.rs`: one call of every public function of the crate,
/// parametric, per built-in aircraft and of `Prepared`, with inputs the optimiser cannot see.
///
/// Why: the functions are `#[inline]`, and an `#[inline]` function is compiled only in a crate
/// that calls it; `cargo test -p roll-criterion --release --features no-panic-check` proves at
/// link time that no compiled function can panic, so a function no test calls would escape the
/// proof unnoticed. Calling each one here makes the proof cover all of them.
pub fn compiled(
    param: &[Function],
    prepared: &Prepared,
    builtins: &[Builtin],
) -> Result<String, syn::Error> {
    let call = |f: &Function, path: TokenStream| {
        let name = Ident::new(f.name, Span::call_site());
        let mut args = Vec::new();
        if f.takes_derivatives {
            args.push(quote!(&k));
        }
        args.extend(f.args.iter().map(|_| quote!(bb(0.5))));
        quote!(bb(#path::#name(#(#args),*));)
    };
    let mut calls = TokenStream::new();
    for f in param {
        calls.extend(call(f, quote!(roll_criterion)));
    }
    for b in builtins {
        let m = Ident::new(b.module, Span::call_site());
        for f in &b.functions {
            calls.extend(call(f, quote!(roll_criterion::#m)));
        }
    }
    let ty = Ident::new(super::functions::PREPARED_TYPE, Span::call_site());
    let new = Ident::new(prepared.new.name, Span::call_site());
    let det_k = Ident::new(prepared.det_k.name, Span::call_site());
    let file = quote! {
        //! Calls every public function of the crate once, with inputs the optimiser cannot see.
        //! The functions are `#[inline]`: one is compiled only in a crate that calls it, and
        //! `cargo test -p roll-criterion --release --features no-panic-check` proves at link
        //! time that no compiled function can panic; these calls put every function under that
        //! proof (a function no test calls would escape it).

        use core::hint::black_box as bb;

        #[test]
        fn every_function_is_compiled_and_returns() {
            let k = bb(roll_criterion::aircraft_b::DERIVATIVES);
            #calls
            let p = roll_criterion::#ty::#new(&k, bb(0.5), bb(0.5));
            bb(p.#det_k(bb(0.5)));
            // Lengths the optimiser cannot see: the four-lane chunks and the rest.
            let p0 = [0.5; 11];
            let mut out = [0.0; 13];
            p.det_k_into(&p0[..bb(11)], &mut out[..bb(13)]);
            bb(out);
        }
    };
    let mut text = format!("// @generated by `{COMMAND}`. Do not edit.\n");
    text.push_str(&pretty(file)?);
    Ok(text)
}
