//! Timing breakdown of the Hopf part of `analyze`, release build:
//! `cargo run --release -p model --example hopf_timing`.
use model::aircraft::Aircraft;
use model::analysis::{analyze, analyze_with, parametric, CriterionPolys, HopfPolys};
use std::time::Instant;
fn main() {
    let de = 2f64.to_radians();
    let _ = analyze(&Aircraft::a(), de);
    for ac in [Aircraft::a(), Aircraft::b()] {
        let t = Instant::now();
        let cp = CriterionPolys::new(parametric(), &ac, de);
        let t1 = t.elapsed();
        let t = Instant::now();
        let hp = HopfPolys::new(&cp, &ac, de);
        let t2 = t.elapsed();
        let t = Instant::now();
        let r = model::roots::positive_roots(&hp.hopf);
        let t3 = t.elapsed();
        let t = Instant::now();
        let _ = analyze(&ac, de).unwrap();
        let t4 = t.elapsed();
        let t = Instant::now();
        let _ = analyze_with(&ac, de, false).unwrap();
        let t5 = t.elapsed();
        println!(
            "{}: criterion polys {t1:?}, hopf polys {t2:?}, hopf roots {t3:?} ({} positive, degree {:?}, zero-sideslip degree {:?}), analyze {t4:?}, without the Hopf part {t5:?}",
            ac.name,
            r.len(),
            hp.hopf.degree(),
            hp.zs_hopf.degree()
        );
    }
}
