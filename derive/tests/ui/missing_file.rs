//! A path that does not exist, relative to the invoking crate's directory.
mod missing {
    roll_criterion_derive::roll_criterion!(aircraft = "tests/ui/no_such_aircraft.toml");
}
fn main() {}
