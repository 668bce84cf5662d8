//! The symbolic algebra layer: exact polynomials and small matrices over them.
//!
//! Small on purpose: what the roll-coupling derivation needs and nothing more. Coefficients are
//! exact rationals ([`Q`]); polynomials ([`Poly`]) are sparse in interned symbols ([`Sym`]);
//! matrices ([`Matrix`]) give determinant, adjugate and Cramer solve. Rational functions are kept
//! as explicit numerator/denominator pairs by the derivation rather than normalized: the paper's
//! det K as a single normalized fraction is enormous, while d * det K is a modest polynomial.
//!
//! ```
//! use model::algebra::{Poly, Sym};
//!
//! let x = Poly::var(Sym::new("x"));
//! let one = Poly::int(1);
//! // (x + 1)^2 - (x^2 + 2x + 1) = 0, exactly
//! let lhs = (&x + &one).pow(2);
//! let rhs = &(&x * &x) + &(&(&Poly::int(2) * &x) + &one);
//! assert!((&lhs - &rhs).is_zero());
//! ```

pub mod big_rational;
mod matrix;
mod mono;
mod poly;
mod rational;
mod symbol;

pub use matrix::Matrix;
pub use mono::Mono;
pub use poly::{Poly, PolyF64};
pub use rational::Q;
pub use symbol::{Sym, MAX_SYMS};
