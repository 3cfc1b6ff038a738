//! The test kit: check your own shading code against the published vectors from your
//! own `cargo test`, with the same verdicts as `phong-approx check`.
//!
//! ```
//! use phong_approx::testkit::prelude::*;
//!
//! // An implementation under test: corrected Euler (eqs. 15–17) in f32, written in
//! // its own operation order.
//! fn my_corrected_euler(na: [f32; 3], nb: [f32; 3], l: [f32; 3], n: u32) -> Vec<f32> {
//!     let dot = |a: [f32; 3], b: [f32; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
//!     let nf = n as f32;
//!     let k = [0, 1, 2].map(|j| (nb[j] - na[j]) / nf);
//!     let (a, pa, pb) = (dot(k, l), dot(na, l), dot(nb, l));
//!     let (c, d) = (dot(k, k), 2.0 * dot(k, na));
//!     let dia = a - pa / 2.0 * d;
//!     let dib = a - pb / 2.0 * (2.0 * nf * c + d);
//!     let ds = (dib - dia) / nf;
//!     let eps = pa + nf * dia + nf * (nf - 1.0) / 2.0 * ds - pb;
//!     let (mut p, mut t) = (pa, dia - eps / nf);
//!     let mut out = vec![p];
//!     for _ in 0..n {
//!         p += t;
//!         t += ds;
//!         out.push(p);
//!     }
//!     out
//! }
//!
//! Suite::published()
//!     .method(Method::CorrectedEuler)
//!     .profile(Profile::Ieee)
//!     .check_f32(|s| my_corrected_euler(s.na, s.nb, s.l, s.n))
//!     .assert_ok();
//! ```
//!
//! Files: `inputs.rs` holds the embedded sets and what your function receives
//! (published sets, inputs), `suite.rs` the runs over the published sets, `outcome.rs` the
//! verdict as data, `span.rs` the oracle, the intervals and `check_span` on spans of
//! your own, `strategy.rs` the proptest generators.
//!
//! The published sets (`vectors/*.json`) are embedded in the crate and verified
//! against their SHA-256 digests ([`crate::conformance::integrity::SHA256SUMS`]) when
//! first used; each case gives your function its inputs as the nearest floats of the
//! exact unit vectors and the number of steps, and takes back `n + 1` values. The
//! verdict is [`crate::conformance::check::check`]'s: the bound of the chosen
//! [`Profile`] (`docs/float.md` §18) for the method, format and case, or a
//! [`Tolerance`] of your own. A failing [`Report`] names, for each failing case, its
//! id and comment, the worst pixel, the inputs in decimal and as hex bits, the
//! expected value and level, yours, the difference in ulps and in 8-bit levels, the
//! tolerance and its profile, and the `phong-approx span` command that reproduces the
//! span exactly.

mod inputs;
mod outcome;
mod span;
#[cfg(feature = "proptest")]
pub mod strategy;
mod suite;

pub use crate::conformance::check::Tolerance;
pub use crate::tolerance::profile::{Form, Profile};
pub use crate::Format;
pub use crate::Method;
pub use inputs::{published, published_shapes, Float, Inputs, SETS};
pub use outcome::{Failure, FailureInputs, Report, SetSummary};
pub use span::{
    acceptance, check_span, oracle, oracle_without_budget, KitError, Oracle, MAX_STEPS,
};
pub use suite::Suite;

/// Everything a test of your own needs, in one import:
/// `use phong_approx::testkit::prelude::*;` — the suite of published vectors, the
/// verdict on a span of your own, the oracle and the intervals, and what makes an
/// exact span (`Span`, `unit_from_ints`).
pub mod prelude {
    #[cfg(feature = "proptest")]
    pub use super::strategy;
    #[cfg(feature = "quickcheck")]
    pub use super::ArbSpan;
    pub use super::{
        acceptance, check_span, command, oracle, Failure, Form, Format, Inputs, KitError, Method,
        Profile, Report, Suite, Tolerance,
    };
    pub use crate::reference::unit::unit_from_ints;
    pub use crate::Span;
}

/// The `phong-approx span` command that prints `method`'s exact values on `span` (its
/// exact fractions), for a test's failure message.
///
/// ```
/// use phong_approx::testkit::prelude::*;
/// let span = Span::new(unit_from_ints(0, 0, 1), unit_from_ints(1, 0, 3), unit_from_ints(0, 0, 1), 4).unwrap();
/// assert_eq!(
///     command(Method::Gouraud, &span),
///     "phong-approx span --method gouraud --na=0,0,1 --nb=3/5,0,4/5 --light=0,0,1 --steps 4 --scalar exact"
/// );
/// ```
pub fn command(method: Method, span: &crate::Span<crate::BigRational>) -> String {
    let v = |v: &crate::Vec3<crate::BigRational>| v.components().map(|x| x.to_string()).join(",");
    crate::conformance::vectors::span_command(
        &crate::conformance::vectors::method_key(method),
        [&v(&span.na), &v(&span.nb), &v(&span.l)],
        span.n,
    )
}

/// A random span for `quickcheck` (feature `quickcheck`): a mesh-like span of 1 to
/// 32 steps with exact unit inputs, or nearly opposite normals.
///
/// ```
/// # #[cfg(feature = "quickcheck")] {
/// use phong_approx::testkit::prelude::*;
/// fn ends_exact(s: ArbSpan) -> bool {
///     let o = oracle(Method::CorrectedEuler, &s.0).unwrap();
///     o.values[0] == s.0.p_a && o.values[s.0.n as usize] == s.0.p_b
/// }
/// quickcheck::QuickCheck::new().tests(8).quickcheck(ends_exact as fn(ArbSpan) -> bool);
/// # }
/// ```
#[cfg(feature = "quickcheck")]
#[derive(Clone, Debug)]
pub struct ArbSpan(pub crate::Span<crate::BigRational>);

#[cfg(feature = "quickcheck")]
impl quickcheck::Arbitrary for ArbSpan {
    fn arbitrary(g: &mut quickcheck::Gen) -> Self {
        use crate::reference::unit::unit_from_ints;
        let mut int = |lo: i64, hi: i64| lo + (u64::arbitrary(g) % (hi - lo + 1) as u64) as i64;
        loop {
            let (a, b, d) = (int(-30, 30), int(-30, 30), int(1, 20));
            let (da, db) = (int(-3, 3), int(-3, 3));
            let l = unit_from_ints(int(-40, 40), int(-40, 40), int(1, 24));
            let n = int(1, 32) as u32;
            let na = unit_from_ints(8 * a, 8 * b, 8 * d);
            let nb = if int(0, 7) == 0 {
                // (2m, 0, 1 − m²)/(1 + m²): near (0, 0, −1) for large m.
                unit_from_ints(1i64 << int(3, 10), 0, 1)
            } else {
                unit_from_ints(8 * a + da, 8 * b + db, 8 * d)
            };
            if let Ok(s) = crate::Span::new(na, nb, l, n) {
                if !s.is_opposite() {
                    return ArbSpan(s);
                }
            }
        }
    }
}
