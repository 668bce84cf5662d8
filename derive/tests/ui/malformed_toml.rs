//! Aircraft files the loader rejects: a TOML syntax error, and valid TOML with a bad value.
mod syntax {
    roll_criterion_derive::roll_criterion!(aircraft = "tests/ui/malformed.toml");
}
mod wrong_type {
    roll_criterion_derive::roll_criterion!(aircraft = "tests/ui/wrong_type.toml");
}
fn main() {}
