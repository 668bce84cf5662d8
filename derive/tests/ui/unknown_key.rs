//! Unknown keys; every error of one invocation is reported, not only the first.
mod foo {
    roll_criterion_derive::roll_criterion!(foo = 1);
}
mod two {
    roll_criterion_derive::roll_criterion!(type = "b.toml", aircraft = 2);
}
mod not_a_key {
    roll_criterion_derive::roll_criterion!("aircraft/a.toml");
}
mod empty {
    roll_criterion_derive::roll_criterion!();
}
fn main() {}
