//! Size and derivation time of the parametric Hopf polynomial, release build:
//! `cargo run --release -p model --example hopf_parametric_size [full]`. Without `full` it stops
//! at Delta4 in the trim symbols; with it, it also substitutes the trim (n_delta_a = 0) and
//! clears det(A)^10.
use model::aircraft::Param;
use model::algebra::Poly;
use model::analysis::parametric_characteristic;
use model::derivation::hopf::{cleared_coefficients, hopf_at, orlando};
use model::equations::symbols;
use std::time::Instant;

fn main() {
    let s = symbols();
    let t = Instant::now();
    let c = parametric_characteristic();
    let d4_trim = model::derivation::hopf::at_coefficients(&orlando().delta4, c);
    println!(
        "c1..c5: {:?} terms; Delta4 in the trim symbols: {} terms ({:?})",
        c.iter().map(Poly::len).collect::<Vec<_>>(),
        d4_trim.len(),
        t.elapsed()
    );
    if std::env::args().any(|a| a == "full") {
        let par = model::analysis::parametric();
        let nda = s.param(Param::NDeltaA);
        let no_yaw = |p: &Poly| p.subs(nda, &Poly::zero());
        let trim: Vec<Poly> = par.trim.iter().map(no_yaw).collect();
        let det_a = no_yaw(&par.det_a);
        let t = Instant::now();
        let cc = cleared_coefficients(c, &[s.alpha0, s.beta0, s.q0, s.r0], &trim, &det_a);
        println!(
            "C1..C5 (det(A)^k c_k at the trim): {:?} terms ({:?})",
            cc.iter().map(Poly::len).collect::<Vec<_>>(),
            t.elapsed()
        );
        let h = hopf_at(&cc);
        println!(
            "parametric Hopf polynomial det(A)^10 Delta4: {} terms, degree {} in P0 ({:?})",
            h.len(),
            h.degree(s.p0),
            t.elapsed()
        );
    }
}
