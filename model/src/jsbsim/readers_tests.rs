//! Tests of the functions' readers and of the evaluations that keep the values of functions
//! whose inputs did not change: the readers against hand-written models, and a sequence of
//! evaluations of every catalogue model against fresh evaluations of the same states, bit for
//! bit and error for error.

use super::catalogue;
use super::condition::{Condition, Speed, State};
use super::import::Loaded;
use super::model::Model;

fn model(aero: &str) -> Model {
    let xml = format!(
        r#"<?xml version="1.0"?>
<fdm_config name="Test">
 <metrics>
   <wingarea unit="FT2">100</wingarea><wingspan unit="FT">20</wingspan><chord unit="FT">5</chord>
   <location name="AERORP" unit="IN"><x>100</x><y>0</y><z>0</z></location>
 </metrics>
 <mass_balance>
   <ixx unit="SLUG*FT2">1000</ixx><iyy unit="SLUG*FT2">2000</iyy><izz unit="SLUG*FT2">3000</izz>
   <emptywt unit="LBS">5000</emptywt>
   <location name="CG" unit="IN"><x>100</x><y>0</y><z>0</z></location>
 </mass_balance>
 <aerodynamics>{aero}</aerodynamics>
</fdm_config>"#
    );
    Model::parse(&xml, "test.xml").unwrap_or_else(|e| panic!("{e}"))
}

/// The functions named `names`, as indices.
fn indices(m: &Model, names: &[&str]) -> Vec<usize> {
    names
        .iter()
        .map(|n| m.functions.list.iter().position(|f| f.name == *n).unwrap())
        .collect()
}

#[test]
fn the_readers_of_a_property_are_the_functions_reading_it_in_any_branch() {
    let m = model(
        r#"<function name="a1"><product><property>aero/alpha-rad</property><value>2</value></product></function>
           <function name="m1"><product><property>velocities/mach</property><value>3</value></product></function>
           <function name="branch"><ifthen><lt><property>velocities/mach</property><value>1</value></lt>
             <value>0</value><property>a1</property></ifthen></function>
           <axis name="LIFT"><function name="lift"><sum><property>m1</property><property>branch</property></sum></function></axis>"#,
    );
    let r = m.readers().expect("no loop");
    let symbol = |n: &str| m.functions.symbols.get(n).unwrap();
    let sorted = |mut v: Vec<usize>| {
        v.sort_unstable();
        v
    };
    assert_eq!(
        sorted(r.of_symbol(symbol("aero/alpha-rad")).to_vec()),
        sorted(indices(&m, &["a1", "branch", "lift"]))
    );
    assert_eq!(
        sorted(r.of_symbol(symbol("velocities/mach")).to_vec()),
        sorted(indices(&m, &["m1", "branch", "lift"]))
    );
    assert_eq!(
        r.of_function(indices(&m, &["m1"])[0]),
        indices(&m, &["lift"])
    );
    assert!(r.of_function(indices(&m, &["lift"])[0]).is_empty());
}

#[test]
fn no_readers_where_functions_loop_or_chain_beyond_the_limit() {
    let looped = model(
        r#"<function name="a"><property>b</property></function>
           <function name="b"><sum><property>a</property><value>1</value></sum></function>"#,
    );
    assert!(looped.readers().is_none());
    let chain = |n: usize| {
        let links: String = (0..n)
            .map(|k| {
                format!(
                    "<function name=\"f{k}\"><property>f{}</property></function>",
                    k + 1
                )
            })
            .collect();
        model(&format!(
            "{links}<function name=\"f{n}\"><value>1</value></function>"
        ))
    };
    // f0 .. f100: 101 functions in one chain, one more than an evaluation follows.
    assert!(chain(100).readers().is_none());
    assert!(chain(99).readers().is_some());
}

/// A pseudo-random number in [0, 1) from `seed` (an LCG: reproducible, no dependency).
fn next(seed: &mut u64) -> f64 {
    *seed = seed
        .wrapping_mul(6_364_136_223_846_793_005)
        .wrapping_add(1_442_695_040_888_963_407);
    (*seed >> 11) as f64 / (1u64 << 53) as f64
}

/// States as a trim and a linearisation visit them: runs that move one variable at a time
/// (alpha, then the elevator at that alpha), some repeated, and jumps in every variable.
fn states(seed: &mut u64, count: usize) -> Vec<State> {
    let mut s = State {
        alpha: 0.0,
        beta: 0.0,
        rates: [0.0; 3],
        surfaces: [0.0; 3],
    };
    let mut out = Vec::with_capacity(count);
    while out.len() < count {
        let pick = next(seed);
        if pick < 0.4 {
            s.surfaces[1] = (next(seed) - 0.5) * 2.4;
        } else if pick < 0.7 {
            s.alpha = (next(seed) * 50.0 - 15.0).to_radians();
        } else if pick < 0.8 {
            // The same state again.
        } else {
            s.beta = (next(seed) - 0.5) * 0.3;
            s.rates = [0, 1, 2].map(|_| (next(seed) - 0.5) * 0.5);
            s.surfaces = [0, 1, 2].map(|_| (next(seed) - 0.5) * 0.8);
        }
        out.push(s);
    }
    out
}

/// Every catalogue model that loads, at a few conditions: each state of a sequence evaluated
/// with the values kept from the previous state gives the fresh evaluation's coefficients to
/// the bit, or its error word for word.
#[test]
fn a_sequence_of_evaluations_gives_the_fresh_coefficients_bit_for_bit() {
    let Some(root) = catalogue::root(None) else {
        return;
    };
    let mut seed = 46;
    let mut compared = 0;
    for name in catalogue::names(&root) {
        let Ok(loaded) = Loaded::new(&name, Some(&root), &[]) else {
            continue;
        };
        for (altitude, mach) in [(0.0, 0.3), (9000.0, 0.9)] {
            let setup = loaded.setup(Condition::new(altitude, Speed::Mach(mach)).unwrap());
            let mut sequence = setup.sequence();
            for s in states(&mut seed, 30) {
                let kept = sequence.values(&s).map_err(|e| e.to_string());
                let fresh = setup.coefficients(&s).map(|c| c.values);
                let fresh = fresh.map_err(|e| e.to_string());
                let bits = |v: &Result<[f64; 6], String>| {
                    v.as_ref()
                        .map(|v| v.map(f64::to_bits))
                        .map_err(Clone::clone)
                };
                assert_eq!(bits(&kept), bits(&fresh), "{name} at {s:?}");
                compared += 1;
            }
        }
    }
    assert!(compared > 1000, "{compared} states compared");
}
