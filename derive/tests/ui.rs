//! trybuild UI tests: the compile errors of `roll_criterion!`, pinned in `tests/ui/*.stderr`.
//! Regenerate them with `TRYBUILD=overwrite cargo test -p roll-criterion-derive --test ui`
//! and read the diff.

#[test]
fn ui() {
    // trybuild compiles each case in a crate of its own under `target/tests/trybuild/`; point
    // the macro's relative paths back at this crate (dtolnay/trybuild#202).
    std::env::set_var("ROLL_CRITERION_MANIFEST_DIR", env!("CARGO_MANIFEST_DIR"));
    // That crate gets cargo's default dev profile (full debug info: 267 MB under
    // target/tests/trybuild); compile errors need none (124 MB, same time).
    std::env::set_var("CARGO_PROFILE_DEV_DEBUG", "false");
    trybuild::TestCases::new().compile_fail("tests/ui/*.rs");
}
