//! Every claim of the sources, checked exactly in rationals on random exact-unit
//! inputs and on enumerated edge cases.
//!
//! One name per claim: each test here has the name of a Coq theorem in `proofs/`
//! (checked by `tests/claims_index.rs`) and is explained in `docs/derivations.md`.
//! The float error of the same quantities is measured in `tests/float_bounds.rs`.

use crate::common;

/// Eqs. 2–24 (`claims::equations::*`).
mod equations;
/// Beyond the paper's spans: the second source, general closed forms, §7 (`claims::general::*`).
mod general;

// The helpers the modules share (their `pub(crate)` items).
use equations::*;

use common::*;
use num_traits::{One, Signed, Zero};
use phong_approx::adaptive::{self, Choice};
use phong_approx::duff::Recurrence;
use phong_approx::quantize::level;
use phong_approx::reference::transcendental;
use phong_approx::{Method, Real, Span};

pub(crate) const CASES: u32 = 96;

pub(crate) fn values(m: Method, s: &Span<Q>) -> Vec<Q> {
    m.values(s).expect("span methods accept n + 1 outputs")
}

/// The Phong value `p/√q` at a real `x` through the interpolated vector, with the
/// 2^-256-accurate rational square root.
pub(crate) fn phong_at(s: &Span<Q>, x: &Q) -> Q {
    let nx = s.na.add(&s.k.scale(x));
    nx.dot(&s.l) / nx.length_squared().sqrt()
}

pub(crate) fn two_pow(e: i32) -> Q {
    if e >= 0 {
        Q::from_integer(num_bigint::BigInt::one() << e)
    } else {
        Q::new(1.into(), num_bigint::BigInt::one() << (-e))
    }
}
