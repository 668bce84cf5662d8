//! `aircraft` without a value, or without `=`; `parametric` with one.
mod no_eq {
    roll_criterion_derive::roll_criterion!(aircraft);
}
mod no_value {
    roll_criterion_derive::roll_criterion!(aircraft =);
}
mod colon {
    roll_criterion_derive::roll_criterion!(aircraft: A);
}
mod parametric_value {
    roll_criterion_derive::roll_criterion!(parametric = true);
}
fn main() {}
