//! The generated criterion crate (`generated/`), checked as flight software would need it:
//! fresh, branch-free and panic-free by inspection of its syntax tree, and numerically equal
//! to independent computations on thousands of random states and aircraft.
//!
//! Error bounds: the generated functions are short straight-line f64 programs, so away from
//! roots and poles their relative error is a few hundred ulps (1e-9 is used); finite-difference
//! Jacobians of the quadratic model are exact to ~1e-16 / h^2 * h^2 ~ 1e-9 absolute (1e-6
//! relative is used); determinants compared against nalgebra use a bound relative to the sum of
//! the magnitudes of the products that form them, which is what stays meaningful near poles
//! of det K (where d -> 0 and det K blows up) and near roots (where the value is a cancellation
//! residue).

use model::aircraft::Aircraft;
use model::analysis::analyze;
use paper_tests::{fd_jacobian, random_params, real_eigenvalues, trim, Lcg, Params};
use roll_criterion as gen;
use std::path::Path;
use syn::visit::Visit;

fn derivatives(k: &Params) -> gen::Derivatives {
    paper_tests::generated_derivatives(k)
}

#[test]
fn generated_files_are_fresh() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let outputs = model::emit::generate().expect("emit");
    let stale = model::emit::stale(&root, &outputs);
    assert!(
        stale.is_empty(),
        "stale generated files {stale:?}: run `{}` and commit",
        model::emit::COMMAND
    );
    // Deterministic: a second run is byte-identical.
    assert_eq!(outputs, model::emit::generate().unwrap());
}

/// Fails on anything but straight-line arithmetic in a function body.
struct StraightLine {
    violations: Vec<String>,
    fn_name: String,
}

impl<'ast> Visit<'ast> for StraightLine {
    fn visit_item_fn(&mut self, f: &'ast syn::ItemFn) {
        self.fn_name = f.sig.ident.to_string();
        syn::visit::visit_item_fn(self, f);
    }

    fn visit_expr(&mut self, e: &'ast syn::Expr) {
        use syn::Expr::*;
        let bad = match e {
            Binary(b) => !matches!(
                b.op,
                syn::BinOp::Add(_) | syn::BinOp::Sub(_) | syn::BinOp::Mul(_) | syn::BinOp::Div(_)
            ),
            Unary(u) => !matches!(u.op, syn::UnOp::Neg(_)),
            Call(c) => {
                let path = match &*c.func {
                    Path(p) => quote_path(&p.path),
                    _ => String::new(),
                };
                path != "libm::sqrt"
            }
            Lit(_) | Paren(_) | Path(_) | Field(_) | Struct(_) | Array(_) | Block(_) => false,
            other => {
                self.violations
                    .push(format!("{}: {}", self.fn_name, kind(other)));
                false
            }
        };
        if bad {
            self.violations
                .push(format!("{}: forbidden operation {}", self.fn_name, kind(e)));
        }
        syn::visit::visit_expr(self, e);
    }

    fn visit_macro(&mut self, m: &'ast syn::Macro) {
        self.violations
            .push(format!("{}: macro {}", self.fn_name, quote_path(&m.path)));
    }
}

fn quote_path(p: &syn::Path) -> String {
    p.segments
        .iter()
        .map(|s| s.ident.to_string())
        .collect::<Vec<_>>()
        .join("::")
}

fn kind(e: &syn::Expr) -> &'static str {
    match e {
        syn::Expr::If(_) => "if",
        syn::Expr::Match(_) => "match",
        syn::Expr::Loop(_) | syn::Expr::While(_) | syn::Expr::ForLoop(_) => "loop",
        syn::Expr::Try(_) => "?",
        syn::Expr::Index(_) => "indexing",
        syn::Expr::MethodCall(_) => "method call",
        syn::Expr::Call(_) => "call",
        syn::Expr::Binary(_) => "binary operator",
        syn::Expr::Unary(_) => "unary operator",
        syn::Expr::Macro(_) => "macro",
        syn::Expr::Unsafe(_) => "unsafe",
        syn::Expr::Closure(_) => "closure",
        syn::Expr::Return(_) => "return",
        _ => "other expression",
    }
}

#[test]
fn generated_functions_are_straight_line_and_branch_free() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../generated/src");
    let mut files = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        let text = std::fs::read_to_string(&path).unwrap();
        let file = syn::parse_file(&text).unwrap();
        let mut v = StraightLine {
            violations: vec![],
            fn_name: String::new(),
        };
        v.visit_file(&file);
        assert!(
            v.violations.is_empty(),
            "{}: {:?}",
            path.display(),
            v.violations
        );
        assert!(!text.contains("unsafe {"), "{}", path.display());
        files += 1;
    }
    assert_eq!(files, 3, "lib.rs, aircraft_a.rs, aircraft_b.rs");
    let lib = std::fs::read_to_string(dir.join("lib.rs")).unwrap();
    assert!(lib.contains("#![no_std]") && lib.contains("#![forbid(unsafe_code)]"));
}

#[test]
fn the_branch_check_catches_a_branch() {
    // The checker must be able to fail.
    let file = syn::parse_file("fn f(x: f64) -> f64 { if x > 0.0 { x } else { -x } }").unwrap();
    let mut v = StraightLine {
        violations: vec![],
        fn_name: String::new(),
    };
    v.visit_file(&file);
    assert!(!v.violations.is_empty());
}

#[test]
fn jacobian5_equals_central_differences_on_random_states() {
    let mut rng = Lcg(99);
    for _ in 0..2000 {
        let k = random_params(&mut rng);
        let x: [f64; 5] = std::array::from_fn(|_| rng.range(-1.0, 1.0));
        let j = gen::jacobian5(&derivatives(&k), x[0], x[1], x[2], x[3], x[4]);
        let num = fd_jacobian(&k, &x, &[0.0; 3]);
        for r in 0..5 {
            for c in 0..5 {
                assert!((j[r][c] - num[(r, c)]).abs() < 1e-6 * (1.0 + j[r][c].abs()));
            }
        }
    }
}

#[test]
fn det_j5_equals_nalgebra_and_d_det_k_at_random_trims() {
    let mut rng = Lcg(5);
    let mut checked = 0;
    for _ in 0..3000 {
        let k = random_params(&mut rng);
        let g = derivatives(&k);
        let (p0, de, dr) = (
            rng.range(0.0, 6.0),
            rng.range(-0.1, 0.1),
            rng.range(-0.05, 0.05),
        );
        let Some((x, da)) = trim(&k, p0, de, dr) else {
            continue;
        };
        let [t, _] = gen::trim(&g, p0, de, dr);
        let scale_x = 1.0 + x.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        for (a, b) in [
            (t.alpha, x[0]),
            (t.beta, x[1]),
            (t.q, x[3]),
            (t.r, x[4]),
            (t.delta_a, da),
        ] {
            assert!((a - b).abs() < 1e-8 * scale_x, "trim: {a} vs LU {b}");
        }
        let jm = fd_jacobian(&k, &x, &[da, de, dr]);
        let det = jm.determinant();
        // Magnitude of the products forming det J5: the permanent of |J| bounds them.
        let abs = jm.abs();
        let mag = abs.determinant().abs().max(permanent_bound(&abs));
        let got = gen::det_j5(&g, p0, de, dr);
        assert!(
            (got - det).abs() < 1e-7 * mag,
            "det J5 {got} vs nalgebra {det} (mag {mag})"
        );
        let dk = gen::residual_denominator(&g, p0, de, dr) * gen::det_k(&g, p0, de, dr);
        assert!(
            (dk - got).abs() < 1e-7 * mag,
            "d det K {dk} vs det J5 {got}"
        );
        checked += 1;
    }
    assert!(checked > 2500);
}

/// A cheap upper bound of the permanent of a non-negative 5x5 matrix (product of row sums).
fn permanent_bound(m: &nalgebra::Matrix5<f64>) -> f64 {
    (0..5).map(|r| m.row(r).sum()).product()
}

#[test]
fn det_k_sign_changes_where_a_real_eigenvalue_of_j5_crosses_zero() {
    let mut rng = Lcg(31);
    let mut crossings = 0;
    for _ in 0..30 {
        let k = random_params(&mut rng);
        let g = derivatives(&k);
        let de = rng.range(-0.05, 0.05);
        let n = 300;
        for i in 0..n {
            let (p_lo, p_hi) = (
                6.0 * i as f64 / n as f64 + 1e-3,
                6.0 * (i + 1) as f64 / n as f64 + 1e-3,
            );
            let (a, b) = (gen::det_k(&g, p_lo, de, 0.0), gen::det_k(&g, p_hi, de, 0.0));
            let (da, db) = (
                gen::residual_denominator(&g, p_lo, de, 0.0),
                gen::residual_denominator(&g, p_hi, de, 0.0),
            );
            let (ta, tb) = (
                gen::trim(&g, p_lo, de, 0.0)[0],
                gen::trim(&g, p_hi, de, 0.0)[0],
            );
            let finite = [a, b, ta.alpha, tb.alpha]
                .iter()
                .all(|v| v.is_finite() && v.abs() < 1e6);
            // A sign change of det K with d of one sign and a regular trim is a root of det K.
            if finite && a * b < 0.0 && da * db > 0.0 && (a.abs() < 1e6 && b.abs() < 1e6) {
                let count = |p0: f64| {
                    let (x, dla) = trim(&k, p0, de, 0.0).unwrap();
                    real_eigenvalues(&fd_jacobian(&k, &x, &[dla, de, 0.0]))
                        .iter()
                        .filter(|l| **l > 0.0)
                        .count()
                };
                let (c0, c1) = (count(p_lo), count(p_hi));
                assert_eq!(
                    c0.abs_diff(c1) % 2,
                    1,
                    "an odd number of real eigenvalues crosses zero between {p_lo} and {p_hi}"
                );
                crossings += 1;
            }
        }
    }
    assert!(
        crossings > 5,
        "the random aircraft must show jumps ({crossings})"
    );
}

#[test]
fn emitted_jump_polynomial_has_the_jump_points_of_analyze() {
    for (ac, dk) in [
        (
            Aircraft::a(),
            gen::aircraft_a::jump_polynomial as fn(f64, f64) -> [f64; 13],
        ),
        (Aircraft::b(), gen::aircraft_b::jump_polynomial),
    ] {
        let de = 2f64.to_radians();
        let a = analyze(&ac, de).unwrap();
        let c = dk(de, 0.0);
        let eval = |p: f64| c.iter().rev().fold(0.0, |acc, ci| acc * p + ci);
        for j in &a.jump {
            let h = 1e-6 * j.p0;
            assert!(
                eval(j.p0 - h) * eval(j.p0 + h) < 0.0,
                "{}: no sign change at {}",
                ac.name,
                j.p0
            );
        }
    }
}
