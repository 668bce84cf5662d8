//! Named symbols, interned once per process into small indices.
//!
//! A symbol is an index into a process-wide table of names. Indices are handed out in the order
//! symbols are first created; the model creates all of its symbols in one fixed order
//! (see `crate::equations::Symbols`), so every run numbers them identically and every output
//! that depends on the order is deterministic.

use std::fmt;
use std::sync::Mutex;

/// Maximum number of distinct symbols in one process (the width of a [`super::Mono`]).
pub const MAX_SYMS: usize = 48;

static NAMES: Mutex<Vec<&'static str>> = Mutex::new(Vec::new());

/// A symbol (variable) of the polynomial ring.
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Sym(pub(crate) u8);

impl Sym {
    /// The symbol called `name`, created on first use.
    ///
    /// Panics if more than [`MAX_SYMS`] distinct names are created: the model needs fewer than 40,
    /// so that would be a programming error, not a data error.
    pub fn new(name: &str) -> Sym {
        let mut names = NAMES.lock().unwrap_or_else(|e| e.into_inner());
        if let Some(i) = names.iter().position(|n| *n == name) {
            return Sym(i as u8);
        }
        assert!(names.len() < MAX_SYMS, "too many symbols (max {MAX_SYMS})");
        names.push(Box::leak(name.to_owned().into_boxed_str()));
        Sym((names.len() - 1) as u8)
    }

    /// The symbol's name.
    pub fn name(self) -> &'static str {
        let names = NAMES.lock().unwrap_or_else(|e| e.into_inner());
        names[self.0 as usize]
    }

    /// The symbol's index (position in the intern table).
    pub fn index(self) -> usize {
        self.0 as usize
    }
}

impl fmt::Debug for Sym {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl fmt::Display for Sym {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}
