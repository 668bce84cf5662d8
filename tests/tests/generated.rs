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

use model::aircraft::{Aircraft, Param};
use model::analysis::analyze;
use paper_tests::{fd_jacobian, random_trimmed_params, real_eigenvalues, trim, Lcg, Params};
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

/// Fails on anything but straight-line arithmetic in a function body. `Prepared`'s slice form
/// and its four lanes are held to their exact intended shape.
struct StraightLine {
    violations: Vec<String>,
    fn_name: String,
    /// Inside `mod prepared_lanes`: array elements at constant indices 0 to 3 and the lanes
    /// constructor are allowed there (and nowhere else).
    in_lanes: bool,
}

impl StraightLine {
    fn new() -> StraightLine {
        StraightLine {
            violations: vec![],
            fn_name: String::new(),
            in_lanes: false,
        }
    }

    /// Requires `f`'s body to be exactly `want`.
    fn exactly(&mut self, f: &syn::ImplItemFn, want: syn::Block, what: &str) {
        let text = |b: &syn::Block| quote::ToTokens::to_token_stream(b).to_string();
        if text(&f.block) != text(&want) {
            self.violations
                .push(format!("{}: not {what}", self.fn_name));
        }
    }
}

impl<'ast> Visit<'ast> for StraightLine {
    fn visit_item_fn(&mut self, f: &'ast syn::ItemFn) {
        self.fn_name = f.sig.ident.to_string();
        syn::visit::visit_item_fn(self, f);
    }

    fn visit_item_mod(&mut self, m: &'ast syn::ItemMod) {
        self.in_lanes = m.ident == "prepared_lanes";
        syn::visit::visit_item_mod(self, m);
        self.in_lanes = false;
    }

    fn visit_impl_item_fn(&mut self, f: &'ast syn::ImplItemFn) {
        self.fn_name = f.sig.ident.to_string();
        match self.fn_name.as_str() {
            // The slice form: the shorter length, four roll rates at a time through the
            // statements of det_k over lanes, the rest through det_k; exactly this.
            "det_k_into" => self.exactly(
                f,
                syn::parse_quote!({
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
                }),
                "the four-lane slice form",
            ),
            // det K of one roll rate: the lanes statements with f64 for the lanes.
            "det_k" if f.sig.inputs.len() == 2 => self.exactly(
                f,
                syn::parse_quote!({ self.det_k_lanes(p0) }),
                "det_k_lanes",
            ),
            _ => syn::visit::visit_impl_item_fn(self, f),
        }
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
                // libm's square root; in the generic statements the lanes' arithmetic
                // (`T::splat`, `T::sqrt`, `T::copysign`, lane by lane the f64 operations).
                let lanes = ["T::splat", "T::sqrt", "T::copysign"];
                !(path == "libm::sqrt"
                    || lanes.contains(&path.as_str())
                    || (self.in_lanes && path == "Lanes"))
            }
            // core's f64::copysign, exact and branch-free.
            MethodCall(m) => m.method != "copysign" || m.args.len() != 1,
            // `x.0[i]` of the four lanes, at a constant index below 4: no bounds check left.
            Index(i) if self.in_lanes => !matches!(
                &*i.index,
                Lit(syn::ExprLit { lit: syn::Lit::Int(n), .. })
                    if n.base10_parse::<usize>().is_ok_and(|n| n < 4)
            ),
            Repeat(_) => !self.in_lanes,
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
        let mut v = StraightLine::new();
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
    let mut v = StraightLine::new();
    v.visit_file(&file);
    assert!(!v.violations.is_empty());
}

#[test]
fn the_lanes_check_catches_an_index_past_the_fourth_lane_and_indexing_elsewhere() {
    let check = |src: &str| {
        let mut v = StraightLine::new();
        v.visit_file(&syn::parse_file(src).unwrap());
        v.violations
    };
    let lanes = |i: &str| format!("mod prepared_lanes {{ fn f(x: [f64; 4]) -> f64 {{ x[{i}] }} }}");
    assert!(check(&lanes("3")).is_empty());
    assert!(!check(&lanes("4")).is_empty());
    assert!(!check(&lanes("i")).is_empty());
    assert!(!check("fn f(x: [f64; 4]) -> f64 { x[0] }").is_empty());
}

#[test]
fn jacobian5_equals_central_differences_on_random_states() {
    let mut rng = Lcg(99);
    for _ in 0..2000 {
        let k = random_trimmed_params(&mut rng);
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
        let k = random_trimmed_params(&mut rng);
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
        let k = random_trimmed_params(&mut rng);
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

/// An exact rational.
type Exact = num_rational::BigRational;

fn exact(x: f64) -> Exact {
    Exact::from_float(x).expect("finite")
}

/// det A(P0) of Eq. 2, `[[z_alpha, -P0, 1, 0], [P0, y_beta, 0, -1], [m_alpha, 0, m_q, C P0],
/// [0, n_beta, -D P0, n_r]]`, typed in here from the paper and expanded exactly (Laplace).
fn exact_det_a(k: &gen::Derivatives, p0: i64) -> Exact {
    let p = Exact::from_integer(p0.into());
    let z = Exact::from_integer(0.into());
    let one = Exact::from_integer(1.into());
    let m = vec![
        vec![exact(k.z_alpha), -p.clone(), one.clone(), z.clone()],
        vec![p.clone(), exact(k.y_beta), z.clone(), -one],
        vec![exact(k.m_alpha), z.clone(), exact(k.m_q), exact(k.c) * &p],
        vec![z, exact(k.n_beta), -(exact(k.d) * &p), exact(k.n_r)],
    ];
    fn det(m: &[Vec<Exact>]) -> Exact {
        if m.len() == 1 {
            return m[0][0].clone();
        }
        let mut acc = Exact::from_integer(0.into());
        for (j, a) in m[0].iter().enumerate() {
            let minor: Vec<Vec<Exact>> = m[1..]
                .iter()
                .map(|row| {
                    row.iter()
                        .enumerate()
                        .filter(|(c, _)| *c != j)
                        .map(|(_, v)| v.clone())
                        .collect()
                })
                .collect();
            let t = a * det(&minor);
            acc = if j % 2 == 0 { acc + t } else { acc - t };
        }
        acc
    }
    det(&m)
}

/// Whether the exact `f(x) = c4 x^2 + c2 x + c0` changes sign between `(p (1 - rel))^2` and
/// `(p (1 + rel))^2`: then a root of det A in P0 lies within `rel` of `p`.
fn brackets_a_root(c: &[Exact; 3], p: f64, rel: f64) -> bool {
    let f = |scale: f64| {
        let x = exact(p) * (Exact::from_integer(1.into()) + exact(scale));
        let x2 = &x * &x;
        &c[2] * &x2 * &x2 + &c[1] * &x2 + &c[0]
    };
    let (lo, hi) = (f(-rel), f(rel));
    let zero = Exact::from_integer(0.into());
    (lo < zero) != (hi < zero)
}

/// Eq. 5's divergence roll rates when the two roots of det A in P0^2 lie ten orders of magnitude
/// apart (aircraft A with C = 1e-9, Iz nearly Ix): both are within 1e-14 of the exact roots
/// of det A, computed here in rational arithmetic from the matrix of Eq. 2; the textbook
/// quadratic formula on the same coefficients loses the smaller root to cancellation (the test
/// shows it is off by more than 1e-11), so this test fails on the textbook form.
#[test]
fn divergence_roll_rates_keep_the_small_root_when_the_roots_are_far_apart() {
    let mut k = gen::aircraft_a::DERIVATIVES;
    k.c = 1e-9;
    // det A is c4 P0^4 + c2 P0^2 + c0 exactly: three values give the coefficients, a fourth
    // checks that there is nothing else.
    let d: Vec<Exact> = (0..4).map(|p| exact_det_a(&k, p)).collect();
    let a = &d[1] - &d[0];
    let b = &d[2] - &d[0];
    let c4 = (&b - &a * Exact::from_integer(4.into())) / Exact::from_integer(12.into());
    let c2 = &a - &c4;
    let c = [d[0].clone(), c2, c4];
    assert_eq!(
        d[3],
        &c[2] * Exact::from_integer(81.into()) + &c[1] * Exact::from_integer(9.into()) + &c[0],
        "det A is a biquadratic in P0"
    );
    let [p1, p2] = gen::divergence_roll_rates(&k);
    assert!(p1 > 2.0 && p1 < 3.0 && p2 > 1e5, "{p1} {p2}");
    for p in [p1, p2] {
        assert!(
            brackets_a_root(&c, p, 1e-14),
            "{p} is not within 1e-14 of a root of det A"
        );
    }
    // The textbook formula on the generated coefficients misses the small root by far more.
    let [c0, c2, c4] = gen::divergence_biquadratic(&k);
    let textbook = ((-c2 - (c2 * c2 - 4.0 * c4 * c0).sqrt()) / (2.0 * c4)).sqrt();
    assert!(
        !brackets_a_root(&c, textbook, 1e-11),
        "the case has no cancellation: textbook {textbook} is within 1e-11 of the root"
    );
}

/// The expressions of a function body as prettyplease prints them, on one line: the value of
/// every `let` and `const`, and every element of the returned value (array elements, struct
/// fields, recursively).
fn body_expressions(block: &syn::Block, out: &mut Vec<String>) {
    fn one_line(e: &syn::Expr) -> String {
        let file: syn::File = syn::parse_quote!(fn f() { let x = #e; });
        let text = prettyplease::unparse(&file);
        let text = text.split_whitespace().collect::<Vec<_>>().join(" ");
        text["fn f() { let x = ".len()..text.len() - "; }".len()].to_string()
    }
    fn returned(e: &syn::Expr, out: &mut Vec<String>) {
        match e {
            syn::Expr::Array(a) => a.elems.iter().for_each(|x| returned(x, out)),
            syn::Expr::Struct(s) => s.fields.iter().for_each(|f| returned(&f.expr, out)),
            other => out.push(one_line(other)),
        }
    }
    for stmt in &block.stmts {
        match stmt {
            syn::Stmt::Local(l) => {
                if let Some(init) = &l.init {
                    out.push(one_line(&init.expr));
                }
            }
            syn::Stmt::Item(syn::Item::Const(c)) => out.push(one_line(&c.expr)),
            syn::Stmt::Expr(e, None) => returned(e, out),
            _ => {}
        }
    }
}

/// No expression of the generated crate is longer than the emitter's cap, so that a
/// reviewer can follow each against the derivation (the split into temporaries is checked to
/// change no bit by the C cross-check and the emitter's own tests).
#[test]
fn generated_expressions_are_within_the_width_cap() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../generated/src");
    let cap = model::emit::statements::MAX_WIDTH;
    for name in ["lib.rs", "aircraft_a.rs", "aircraft_b.rs"] {
        let file = syn::parse_file(&std::fs::read_to_string(dir.join(name)).unwrap()).unwrap();
        let mut exprs = Vec::new();
        for item in &file.items {
            match item {
                syn::Item::Fn(f) => body_expressions(&f.block, &mut exprs),
                syn::Item::Impl(i) => {
                    for it in &i.items {
                        // The slice form's loops are no formula: the straight-line check
                        // pins their exact text.
                        if let syn::ImplItem::Fn(f) = it {
                            if f.sig.ident != "det_k_into" {
                                body_expressions(&f.block, &mut exprs);
                            }
                        }
                    }
                }
                _ => {}
            }
        }
        let widest = exprs.iter().max_by_key(|e| e.len()).unwrap();
        println!(
            "{name}: {} expressions, widest {} characters",
            exprs.len(),
            widest.len()
        );
        assert!(exprs.len() > 100, "{name}: expressions not found");
        assert!(
            widest.len() <= cap,
            "{name}: an expression of {} characters (cap {cap}): {widest}",
            widest.len()
        );
    }
}

/// The exact value a named constant's comment states: a decimal (`-81.084922887`) or `p/q`.
fn stated_exact(text: &str) -> Exact {
    if let Some((p, q)) = text.split_once('/') {
        return Exact::new(p.parse().unwrap(), q.parse().unwrap());
    }
    let (int, frac) = text.split_once('.').unwrap_or((text, ""));
    let digits: num_bigint::BigInt = format!("{int}{frac}").parse().unwrap();
    Exact::new(digits, num_bigint::BigInt::from(10).pow(frac.len() as u32))
}

/// `(exact value, literal)` of every named constant of a generated file: a comment line
/// `exact: X` (`///` in Rust, `//` in C) followed by `const ... KN ... = LITERAL;`.
fn named_constants(text: &str) -> Vec<(Exact, f64)> {
    let lines: Vec<&str> = text.lines().map(str::trim).collect();
    lines
        .windows(2)
        .filter_map(|w| {
            let exact = w[0]
                .trim_start_matches('/')
                .trim()
                .strip_prefix("exact: ")?;
            let lit = w[1]
                .strip_prefix("const ")?
                .split(" = ")
                .nth(1)?
                .trim_end_matches(';');
            Some((stated_exact(exact), lit.parse().expect("a double literal")))
        })
        .collect()
}

/// Every folded constant that is not written exactly carries its exact rational, and
/// its literal is that rational rounded once to the nearest double; the constants written inline
/// are the data of Table A.1 and small integers, whose literals are exact (checked in the
/// emitter, `model::emit::statements`).
#[test]
fn named_constants_are_their_exact_rationals_rounded_once() {
    use num_traits::ToPrimitive;
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../generated");
    for name in [
        "src/lib.rs",
        "src/aircraft_a.rs",
        "src/aircraft_b.rs",
        "c/roll_criterion.h",
    ] {
        let text = std::fs::read_to_string(root.join(name)).unwrap();
        let constants = named_constants(&text);
        let declared = text.matches("const K").count() + text.matches("const double K").count();
        assert_eq!(
            constants.len(),
            declared,
            "{name}: a named constant without its exact value"
        );
        for (exact, lit) in &constants {
            assert_eq!(
                exact.to_f64().unwrap().to_bits(),
                lit.to_bits(),
                "{name}: {exact} -> {lit:?}"
            );
            assert_ne!(
                &Exact::from_float(*lit).unwrap(),
                exact,
                "{name}: {lit:?} is exact, not named"
            );
        }
        println!("{name}: {} named constants", constants.len());
        if name != "src/lib.rs" {
            assert!(constants.len() > 20, "{name}: too few named constants");
        }
    }
}

/// The `name = formula` items of the ```text blocks of a doc comment (continuation lines
/// joined).
fn doc_formulas(attrs: &[syn::Attribute]) -> Vec<(String, String)> {
    let lines: Vec<String> = attrs
        .iter()
        .filter_map(|a| match &a.meta {
            syn::Meta::NameValue(nv) if nv.path.is_ident("doc") => match &nv.value {
                syn::Expr::Lit(syn::ExprLit {
                    lit: syn::Lit::Str(s),
                    ..
                }) => Some(
                    s.value()
                        .strip_prefix(' ')
                        .unwrap_or(&s.value())
                        .to_string(),
                ),
                _ => None,
            },
            _ => None,
        })
        .collect();
    let mut out: Vec<(String, String)> = Vec::new();
    let mut inside = false;
    for l in lines {
        if l.starts_with("```") {
            inside = l == "```text";
            continue;
        }
        if !inside {
            continue;
        }
        if l.starts_with(' ') {
            let last = out.last_mut().expect("a continuation follows a formula");
            last.1.push(' ');
            last.1.push_str(l.trim());
        } else {
            let (name, rhs) = l.split_once(" = ").expect("name = formula");
            out.push((name.to_string(), rhs.to_string()));
        }
    }
    out
}

/// A formula's polynomials: one, the entries of `[a, b]` or `[[a, b], [c, d]]` row by row, or the
/// numerator and denominator of `(num) / (den)`.
fn parse_formula(rhs: &str) -> Vec<model::algebra::Poly> {
    use model::emit::paper::parse;
    if let Some(inner) = rhs.strip_prefix("[[") {
        let inner = inner.strip_suffix("]]").expect("a matrix");
        return inner
            .split("], [")
            .flat_map(|row| row.split(", ").map(parse).collect::<Vec<_>>())
            .collect();
    }
    if let Some(inner) = rhs.strip_prefix('[') {
        return inner
            .strip_suffix(']')
            .unwrap()
            .split(", ")
            .map(parse)
            .collect();
    }
    if let Some((num, den)) = rhs.split_once(") / (") {
        let num = num.strip_prefix('(').unwrap();
        let den = den.strip_suffix(')').unwrap();
        return vec![parse(num), parse(den)];
    }
    vec![parse(rhs)]
}

/// Every formula in the generated crate's doc comments is the derivation's (parsed
/// back with the paper-formula parser of `model::emit::paper` and compared exactly), and where
/// the paper prints the same quantity correctly, the paper's (Eqs 2, 16 and 22): no formula of
/// the docs is typed by hand.
#[test]
fn doc_formulas_are_the_derivations_and_the_papers() {
    use model::derivation::hopf::{characteristic_coefficients, orlando};
    use model::emit::paper::{self, parse};
    let par = model::derivation::Derivation::parametric();
    let matrix = |m: &model::algebra::Matrix| -> Vec<model::algebra::Poly> {
        (0..m.rows())
            .flat_map(|i| (0..m.cols()).map(move |j| m.get(i, j).clone()))
            .collect()
    };
    let coeffs = characteristic_coefficients(&par.jacobian);
    let o = orlando();
    let stiffness = |name: &str| match name {
        "K0" => Some(par.k0.iter().flatten().cloned().collect()),
        "g" => Some(par.g.to_vec()),
        "h" => Some(par.h.to_vec()),
        "d" => Some(vec![par.d.clone()]),
        _ => None,
    };
    let expected = |f: &str, name: &str| -> Option<Vec<model::algebra::Poly>> {
        match (f, name) {
            ("trim", "A") => Some(matrix(&par.a)),
            ("trim", "b") => Some(par.a_rhs.clone()),
            ("trim", "p_dot") => Some(vec![par.roll_at_trim.clone()]),
            ("zero_sideslip_trim", "A1") => Some(matrix(&par.zs_a)),
            ("zero_sideslip_trim", "b1") => Some(par.zs_rhs.clone()),
            ("zero_sideslip_trim", "delta_a") => {
                Some(vec![par.zs_delta_a.num.clone(), par.zs_delta_a.den.clone()])
            }
            ("zero_sideslip_trim", "delta_r") => {
                Some(vec![par.zs_delta_r.num.clone(), par.zs_delta_r.den.clone()])
            }
            ("jacobian5", "J5") => Some(matrix(&par.jacobian)),
            ("residual_denominator" | "stiffness" | "det_k", n) => stiffness(n),
            ("divergence_biquadratic", "c0") => Some(vec![par.biquadratic[0].clone()]),
            ("divergence_biquadratic", "c2") => Some(vec![par.biquadratic[1].clone()]),
            ("divergence_biquadratic", "c4") => Some(vec![par.biquadratic[2].clone()]),
            ("characteristic_coefficients", "c1") => Some(vec![coeffs[0].clone()]),
            ("characteristic_coefficients", "c2") => Some(vec![coeffs[1].clone()]),
            ("hurwitz_delta4", "Delta4") => Some(vec![o.delta4.clone()]),
            ("hopf_omega_squared", "omega^2") => {
                Some(vec![o.omega_sq.num.clone(), o.omega_sq.den.clone()])
            }
            _ => None,
        }
    };
    // The paper's printed formulas where they agree with the derivation.
    let papers: Vec<(&str, &str, Vec<model::algebra::Poly>)> = vec![
        (
            "trim",
            "A",
            paper::EQ2_A.iter().flatten().map(|e| parse(e)).collect(),
        ),
        ("residual_denominator", "d", vec![parse(paper::EQ22_D)]),
        (
            "stiffness",
            "h",
            paper::EQ22_H.iter().map(|e| parse(e)).collect(),
        ),
        (
            "stiffness",
            "K0",
            paper::EQ16_K0.iter().flatten().map(|e| parse(e)).collect(),
        ),
    ];
    let lib = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../generated/src/lib.rs"),
    )
    .unwrap();
    let file = syn::parse_file(&lib).unwrap();
    let mut seen = Vec::new();
    for item in &file.items {
        let syn::Item::Fn(f) = item else { continue };
        let name = f.sig.ident.to_string();
        for (symbol, rhs) in doc_formulas(&f.attrs) {
            let want = expected(&name, &symbol)
                .unwrap_or_else(|| panic!("{name}: no derivation result called {symbol}"));
            assert_eq!(parse_formula(&rhs), want, "{name}: {symbol} = {rhs}");
            if let Some((_, _, p)) = papers.iter().find(|(f, s, _)| *f == name && *s == symbol) {
                // The paper prints its case: no trim lift, the principal axis on the path.
                let s = model::equations::symbols();
                let zero = model::algebra::Poly::zero();
                let papers_case: Vec<_> = want
                    .iter()
                    .map(|w| {
                        w.subs(s.param(Param::Z0), &zero)
                            .subs(s.param(Param::AlphaT), &zero)
                    })
                    .collect();
                assert_eq!(
                    &papers_case, p,
                    "{name}: {symbol} differs from the paper's print"
                );
            }
            seen.push(format!("{name}.{symbol}"));
        }
    }
    assert_eq!(seen.len(), 24, "formulas found: {seen:?}");
}
