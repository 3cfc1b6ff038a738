//! What the kit gives your function: the published sets, embedded and verified
//! ([`published`]), and one span's inputs in your float format ([`Inputs`],
//! [`Float`]).

pub use crate::conformance::vectors::SETS;

use crate::conformance::integrity::{published_set, sha256_hex};
use crate::conformance::vectors::{VectorFile, VectorInput};
use crate::tolerance::Shape;
use std::fmt;
use std::sync::OnceLock;

/// The published sets, embedded: name and JSON text.
const EMBEDDED: [(&str, &str); 3] = [
    ("typical", include_str!("../../vectors/typical.json")),
    ("edge", include_str!("../../vectors/edge.json")),
    ("paper", include_str!("../../vectors/paper.json")),
];

/// A published set (`typical`, `edge`, `paper`), parsed once and verified against its
/// SHA-256 digest; `None` for another name. Its cases carry their inputs in exact
/// (`case.na.exact`), `f32` and `f64` form, and
/// [`crate::conformance::integrity::case_span`] makes a case's exact span for
/// [`super::oracle`] and [`super::acceptance`].
///
/// ```
/// let typical = phong_approx::testkit::published("typical").unwrap();
/// let c = &typical.cases[0];
/// assert_eq!(c.na.exact.len(), 3);
/// let span = phong_approx::conformance::integrity::case_span(c).unwrap();
/// assert_eq!(span.n, c.n);
/// ```
///
/// # Panics
/// If the embedded text is not the published set (the crate's own files changed
/// without their digests: a packaging error, caught by this crate's tests).
pub fn published(set: &str) -> Option<&'static VectorFile> {
    static FILES: [OnceLock<VectorFile>; 3] = [OnceLock::new(), OnceLock::new(), OnceLock::new()];
    let k = EMBEDDED.iter().position(|(name, _)| *name == set)?;
    Some(FILES[k].get_or_init(|| {
        let (name, text) = EMBEDDED[k];
        let digest = sha256_hex(text.as_bytes());
        assert_eq!(
            published_set(&digest),
            Some(name),
            "the embedded vectors/{name}.json is not the published set (SHA-256 {digest})"
        );
        serde_json::from_str(text).expect("the published sets parse")
    }))
}

/// The shape of each case's exact span of the published set `set`, in its case order
/// ([`crate::conformance::check::shapes`]), read once per process: what
/// [`crate::conformance::judgement::judge`] takes with [`published`]'s file.
pub fn published_shapes(set: &str) -> Option<&'static [Option<Shape>]> {
    static SHAPES: [OnceLock<Vec<Option<Shape>>>; 3] =
        [OnceLock::new(), OnceLock::new(), OnceLock::new()];
    let k = EMBEDDED.iter().position(|(name, _)| *name == set)?;
    let file = published(set)?;
    Some(SHAPES[k].get_or_init(|| crate::conformance::check::shapes(file)))
}

/// One span as your function receives it: the nearest floats of the exact unit inputs
/// and the number of steps; return `n + 1` values, pixel `0` at `N_a`, pixel `n` at
/// `N_b`. For [`super::Suite::specular`] the half vector `H` and the shininess `s` too: shade
/// `max(0, v)^s` with `v` your method's value on `N·H`.
#[derive(Clone, Debug, PartialEq)]
pub struct Inputs<'a, T> {
    /// The case id, e.g. `edge-007` (`span` for [`super::check_span`]).
    pub id: &'a str,
    /// Why the case is there.
    pub comment: &'a str,
    /// `N_a`.
    pub na: [T; 3],
    /// `N_b`.
    pub nb: [T; 3],
    /// `L`.
    pub l: [T; 3],
    /// Steps `n`.
    pub n: u32,
    /// The unit half vector `H` of a specular case.
    pub h: Option<[T; 3]>,
    /// The shininess `s` of a specular case.
    pub s: Option<u32>,
}

impl<'a, T: Float> Inputs<'a, T> {
    /// A published case's inputs in `T`, as [`super::Suite`] gives them to your
    /// function.
    pub fn of_case(c: &'a crate::conformance::vectors::Case) -> Inputs<'a, T> {
        Inputs {
            id: &c.id,
            comment: &c.comment,
            na: pick(&c.na),
            nb: pick(&c.nb),
            l: pick(&c.l),
            n: c.n,
            h: c.specular.as_ref().map(|sp| pick(&sp.h)),
            s: c.specular.as_ref().map(|sp| sp.s),
        }
    }
}

impl<T: Float> Inputs<'static, T> {
    /// The inputs of an exact span of your own as your function receives them: each
    /// component of `N_a`, `N_b` and `L` rounded once to the nearest `T` (ties to
    /// even), as the published sets give theirs. The id is `span`.
    ///
    /// ```
    /// use phong_approx::testkit::prelude::*;
    /// let span = Span::new(unit_from_ints(1, 0, 3), unit_from_ints(0, 1, 3), unit_from_ints(0, 0, 1), 4).unwrap();
    /// let i = Inputs::<f32>::nearest(&span);
    /// assert_eq!(i.na, [0.6, 0.0, 0.8]); // (2·1, 0, 3² − 1)/(3² + 1), to nearest
    /// assert_eq!(i.n, 4);
    /// ```
    pub fn nearest(span: &crate::Span<crate::BigRational>) -> Inputs<'static, T> {
        let v = |x: &crate::Vec3<crate::BigRational>| x.components().map(T::nearest);
        Inputs {
            id: "span",
            comment: "",
            na: v(&span.na),
            nb: v(&span.nb),
            l: v(&span.l),
            n: span.n,
            h: None,
            s: None,
        }
    }
}

/// The float inputs of one kind (`N_a`, `N_b`, `L`) in the format `T`.
fn pick<T: Float>(v: &VectorInput) -> [T; 3] {
    T::inputs(v)
        .clone()
        .map(|s| T::parse(&s).expect("the published sets' float inputs parse"))
}

/// A float type your implementation computes in: `f32` or `f64`.
pub trait Float: Copy + fmt::Display + fmt::LowerExp + 'static {
    /// Its format (the bounds, the ulps and the reports read it).
    const FORMAT: crate::Format;
    /// Parses a vector file's input of this format.
    fn parse(s: &str) -> Option<Self>;
    /// The vector file's inputs of this format (`VectorInput::f32` or `::f64`).
    fn inputs(v: &VectorInput) -> &[String; 3];
    /// The nearest value of this format to an exact rational (ties to even).
    fn nearest(x: &crate::BigRational) -> Self;
    /// As `f64` (exactly).
    fn to_f64(self) -> f64;
    /// From an `f64` that holds a value of this format (exactly).
    fn from_f64(x: f64) -> Self;
    /// The hex form of its bits.
    fn hex(self) -> String;
}

impl Float for f32 {
    const FORMAT: crate::Format = crate::Format::Binary32;
    fn parse(s: &str) -> Option<Self> {
        s.trim().parse().ok()
    }
    fn inputs(v: &VectorInput) -> &[String; 3] {
        &v.f32
    }
    fn nearest(x: &crate::BigRational) -> Self {
        <f32 as crate::Scalar>::from_rational(x)
    }
    fn to_f64(self) -> f64 {
        f64::from(self)
    }
    fn from_f64(x: f64) -> Self {
        x as f32
    }
    fn hex(self) -> String {
        format!("0x{:08x}", self.to_bits())
    }
}

impl Float for f64 {
    const FORMAT: crate::Format = crate::Format::Binary64;
    fn parse(s: &str) -> Option<Self> {
        s.trim().parse().ok()
    }
    fn inputs(v: &VectorInput) -> &[String; 3] {
        &v.f64
    }
    fn nearest(x: &crate::BigRational) -> Self {
        <f64 as crate::Scalar>::from_rational(x)
    }
    fn to_f64(self) -> f64 {
        self
    }
    fn from_f64(x: f64) -> Self {
        x
    }
    fn hex(self) -> String {
        format!("0x{:016x}", self.to_bits())
    }
}
