//! Compiles CasADi's generated C for det K (`oracle/casadi_det_k.c`, written by
//! `oracle/casadi_det_k.py`) into this crate, for the benchmark and the agreement test of
//! `Prepared` (tests/tests/prepared.rs), and sets `cfg(casadi)` when it did. It needs a C compiler
//! (gcc, as for the C header tests): without one the CasADi comparisons are skipped visibly, unless
//! `CI` is set, when the build fails.

fn main() {
    println!("cargo::rustc-check-cfg=cfg(casadi)");
    println!("cargo::rerun-if-changed=oracle/casadi_det_k.c");
    println!("cargo::rerun-if-env-changed=CI");
    // -O2, the optimisation the README's CasADi figure is measured at.
    let built = cc::Build::new()
        .file("oracle/casadi_det_k.c")
        .opt_level(2)
        .warnings(false)
        .try_compile("casadi_det_k");
    match built {
        Ok(()) => println!("cargo::rustc-cfg=casadi"),
        Err(e) if std::env::var_os("CI").is_some() => {
            panic!("CI is set but CasADi's C does not compile (install gcc): {e}")
        }
        Err(e) => println!(
            "cargo::warning=SKIPPED CasADi's generated C (no C compiler?): the CasADi benchmark and agreement test are left out: {e}"
        ),
    }
}
