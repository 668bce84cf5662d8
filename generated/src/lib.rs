//! Placeholder: written by `cargo run -p model -- emit` once issue 3 lands.
#![no_std]
