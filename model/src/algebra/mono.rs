//! Monomials as packed exponent vectors.
//!
//! Exponents are bytes packed eight to a `u64`, symbol 0 in the most significant byte, so that
//! multiplying monomials is six word additions and comparing them is a lexicographic comparison
//! of six words (lex order with symbol 0 the most significant). Exponents stay below 128; a
//! product that would overflow is a programming error and panics with a message.

use super::symbol::{Sym, MAX_SYMS};
use std::fmt;

const WORDS: usize = MAX_SYMS / 8;
const HIGH_BITS: u64 = 0x8080_8080_8080_8080;

/// A monomial: the product of symbols raised to small non-negative powers.
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Default)]
pub struct Mono([u64; WORDS]);

#[inline]
fn slot(s: Sym) -> (usize, u32) {
    let i = s.index();
    (i / 8, (7 - (i % 8) as u32) * 8)
}

impl Mono {
    /// The monomial 1.
    pub const ONE: Mono = Mono([0; WORDS]);

    /// `s^e`.
    pub fn var(s: Sym, e: u32) -> Mono {
        let mut m = Mono::ONE;
        m.set(s, e);
        m
    }

    /// The exponent of `s`.
    #[inline]
    pub fn exp(&self, s: Sym) -> u32 {
        let (w, sh) = slot(s);
        ((self.0[w] >> sh) & 0xff) as u32
    }

    /// Sets the exponent of `s` to `e` (< 128).
    #[inline]
    pub fn set(&mut self, s: Sym, e: u32) {
        assert!(e < 128, "exponent overflow for {s}");
        let (w, sh) = slot(s);
        self.0[w] = (self.0[w] & !(0xff << sh)) | ((e as u64) << sh);
    }

    /// The product of two monomials.
    #[inline]
    pub fn mul(&self, o: &Mono) -> Mono {
        let mut r = [0u64; WORDS];
        let mut high = 0;
        for (i, slot) in r.iter_mut().enumerate() {
            *slot = self.0[i] + o.0[i];
            high |= *slot;
        }
        assert!(
            high & HIGH_BITS == 0,
            "exponent overflow in monomial product"
        );
        Mono(r)
    }

    /// True for the monomial 1.
    pub fn is_one(&self) -> bool {
        self.0.iter().all(|w| *w == 0)
    }

    /// Total degree.
    pub fn total_degree(&self) -> u32 {
        self.0
            .iter()
            .map(|w| w.to_be_bytes().iter().map(|b| *b as u32).sum::<u32>())
            .sum()
    }

    /// The symbols present with their exponents, in symbol order.
    pub fn factors(&self) -> Vec<(Sym, u32)> {
        let mut out = Vec::new();
        for (w, word) in self.0.iter().enumerate() {
            if *word == 0 {
                continue;
            }
            for (b, byte) in word.to_be_bytes().iter().enumerate() {
                if *byte != 0 {
                    out.push((Sym((w * 8 + b) as u8), *byte as u32));
                }
            }
        }
        out
    }

    /// True when this monomial divides `o`.
    pub fn divides(&self, o: &Mono) -> bool {
        self.factors().iter().all(|(s, e)| o.exp(*s) >= *e)
    }
}

impl fmt::Debug for Mono {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.is_one() {
            return f.write_str("1");
        }
        let parts: Vec<String> = self
            .factors()
            .iter()
            .map(|(s, e)| {
                if *e == 1 {
                    s.name().to_string()
                } else {
                    format!("{}^{e}", s.name())
                }
            })
            .collect();
        f.write_str(&parts.join("*"))
    }
}
