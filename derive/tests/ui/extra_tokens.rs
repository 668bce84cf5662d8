//! Tokens after a complete entry; duplicate and conflicting keys.
mod extra {
    roll_criterion_derive::roll_criterion!(aircraft = A B);
}
mod extra_after_parametric {
    roll_criterion_derive::roll_criterion!(parametric; aircraft = A);
}
mod duplicate {
    roll_criterion_derive::roll_criterion!(aircraft = A, aircraft = B);
}
mod conflict {
    roll_criterion_derive::roll_criterion!(parametric, aircraft = "aircraft/a.toml");
}
fn main() {}
