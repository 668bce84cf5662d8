//! Values of the wrong type, and an unknown built-in aircraft.
mod int {
    roll_criterion_derive::roll_criterion!(aircraft = 1);
}
mod byte_string {
    roll_criterion_derive::roll_criterion!(aircraft = b"aircraft/a.toml");
}
mod unknown_builtin {
    roll_criterion_derive::roll_criterion!(aircraft = C);
}
mod path_expr {
    roll_criterion_derive::roll_criterion!(aircraft = concat!("a", ".toml"));
}
fn main() {}
