//! The test kit: check your own shading code against the published vectors from your
//! own `cargo test`, with the same verdicts as `phong-approx check`.
//!
//! ```
//! use phong_approx::testkit::Suite;
//! use phong_approx::tolerance::profile::Profile;
//! use phong_approx::Method;
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

use crate::conformance::check::{check_in, CaseReport, Results, Tolerance};
use crate::conformance::integrity::{published_set, sha256_hex};
use crate::conformance::vectors::{method_key, Case, VectorFile};
use crate::quantize::level;
use crate::tolerance::profile::Profile;
use crate::Method;
use std::fmt;
use std::sync::OnceLock;

/// The published sets, embedded: name and JSON text.
const EMBEDDED: [(&str, &str); 3] = [
    ("typical", include_str!("../vectors/typical.json")),
    ("edge", include_str!("../vectors/edge.json")),
    ("paper", include_str!("../vectors/paper.json")),
];

/// A published set (`typical`, `edge`, `paper`), parsed once and verified against its
/// SHA-256 digest; `None` for another name. Its cases carry their inputs in exact
/// (`case.na.exact`), `f32` and `f64` form, and
/// [`crate::conformance::integrity::case_span`] makes a case's exact span for
/// [`oracle`] and [`acceptance`].
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

/// The names of the published sets.
pub const SETS: [&str; 3] = ["typical", "edge", "paper"];

/// One span as your function receives it: the nearest floats of the exact unit inputs
/// and the number of steps; return `n + 1` values, pixel `0` at `N_a`, pixel `n` at
/// `N_b`.
#[derive(Clone, Debug)]
pub struct Inputs<'a, T> {
    /// The case id, e.g. `edge-007`.
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
}

/// A float format your implementation computes in.
pub trait Format: Copy + fmt::Display + fmt::LowerExp {
    /// `f32` or `f64`.
    const NAME: &'static str;
    /// Its unit roundoff.
    const U: f64;
    /// Parses a vector file's input of this format.
    fn parse(s: &str) -> Option<Self>;
    /// As `f64` (exactly).
    fn to_f64(self) -> f64;
    /// From an `f64` that holds a value of this format (exactly).
    fn from_f64(x: f64) -> Self;
    /// The hex form of its bits.
    fn hex(self) -> String;
    /// The spacing of the format at `x` (its ulp).
    fn ulp(x: f64) -> f64;
}

impl Format for f32 {
    const NAME: &'static str = "f32";
    const U: f64 = 1.0 / 16_777_216.0;
    fn parse(s: &str) -> Option<Self> {
        s.trim().parse().ok()
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
    fn ulp(x: f64) -> f64 {
        crate::conformance::check::f32_ulp(x)
    }
}

impl Format for f64 {
    const NAME: &'static str = "f64";
    const U: f64 = f64::EPSILON / 2.0;
    fn parse(s: &str) -> Option<Self> {
        s.trim().parse().ok()
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
    fn ulp(x: f64) -> f64 {
        let a = x.abs().max(f64::MIN_POSITIVE);
        2f64.powi(a.log2().floor() as i32 - 52)
    }
}

/// The published vectors for one method, judged by one profile or tolerance.
#[derive(Clone, Debug)]
pub struct Suite {
    sets: Vec<&'static str>,
    method: Method,
    profile: Profile,
    tolerance: Option<Tolerance>,
    /// A set asked for by a name that is not published (reported as a failure).
    unknown_set: Option<String>,
}

impl Suite {
    /// Every published set (`typical`, `edge`, `paper`), for corrected Euler under the
    /// `ieee` profile (what outside code is: any order, FMA, reciprocals) until
    /// [`Suite::method`] and [`Suite::profile`] say otherwise.
    pub fn published() -> Suite {
        Suite {
            sets: SETS.to_vec(),
            method: Method::CorrectedEuler,
            profile: Profile::Ieee,
            tolerance: None,
            unknown_set: None,
        }
    }

    /// One published set only (`typical`, `edge` or `paper`); any other name gives a
    /// suite whose report fails, naming it (no panic: the test that asked sees why).
    pub fn set(set: &str) -> Suite {
        match SETS.iter().position(|s| *s == set) {
            Some(k) => Suite {
                sets: vec![SETS[k]],
                ..Suite::published()
            },
            None => Suite {
                sets: Vec::new(),
                unknown_set: Some(crate::error::shown(set)),
                ..Suite::published()
            },
        }
    }

    /// The method your function implements.
    pub fn method(mut self, method: Method) -> Suite {
        self.method = method;
        self
    }

    /// The arithmetic profile your implementation belongs to (`docs/float.md` §18):
    /// its bounds judge the results.
    pub fn profile(mut self, profile: Profile) -> Suite {
        self.profile = profile;
        self
    }

    /// A tolerance of your own instead of the profile's bound (`levels`, `abs`,
    /// `ulps`).
    pub fn tolerance(mut self, tolerance: Tolerance) -> Suite {
        self.tolerance = Some(tolerance);
        self
    }

    /// Runs `shade` on every case in `f32` and judges the values.
    pub fn check_f32<F: FnMut(&Inputs<f32>) -> Vec<f32>>(&self, shade: F) -> Report {
        self.run(shade)
    }

    /// Runs `shade` on every case in `f64` and judges the values.
    pub fn check_f64<F: FnMut(&Inputs<f64>) -> Vec<f64>>(&self, shade: F) -> Report {
        self.run(shade)
    }

    /// Runs `shade`, an implementation that outputs 8-bit levels (fixed point, a
    /// hardware span unit), on every case with `f64` inputs (convert them to your
    /// format), and compares its levels with the exact levels: within
    /// [`Suite::tolerance`]`(Tolerance::Levels(k))`, one level if not set (no profile
    /// bounds 8-bit outputs yet; `docs/float.md` §14 derives the fractional bits that
    /// keep corrected Euler within half a level).
    pub fn check_levels<F: FnMut(&Inputs<f64>) -> Vec<u8>>(&self, mut shade: F) -> Report {
        let mut suite = self.clone();
        if !matches!(suite.tolerance, Some(Tolerance::Levels(_))) {
            suite.tolerance = Some(Tolerance::Levels(1));
        }
        // Each level ℓ as the middle of its interval, (ℓ + ½)/255, whose level is ℓ.
        let mut r = suite.run::<f64, _>(|s| {
            shade(s)
                .into_iter()
                .map(|l| (f64::from(l) + 0.5) / 255.0)
                .collect()
        });
        r.format = "8-bit levels";
        r
    }

    fn run<T: Format, F: FnMut(&Inputs<T>) -> Vec<T>>(&self, mut shade: F) -> Report {
        let key = method_key(self.method);
        let tol = self.tolerance.unwrap_or(Tolerance::Profile {
            profile: self.profile,
            u: T::U,
        });
        let mut report = Report {
            method: self.method,
            judged_by: match self.tolerance {
                Some(t) => format!("tolerance {t}"),
                None => format!("the {} profile's bound", self.profile),
            },
            format: T::NAME,
            cases: 0,
            failures: Vec::new(),
        };
        if let Some(name) = &self.unknown_set {
            report.failures.push(Failure {
                set: "?",
                id: format!("(set '{name}')"),
                lines: vec![format!(
                    "no published set '{name}' (there are {})",
                    SETS.join(", ")
                )],
            });
        }
        for set in &self.sets {
            let Some(file) = published(set) else {
                continue;
            };
            let mut results = Results::new();
            let mut wrong_length = Vec::new();
            for c in &file.cases {
                let v = |x: &[String; 3]| x.clone().map(|s| T::parse(&s).expect("float input"));
                let inputs = Inputs {
                    id: &c.id,
                    comment: &c.comment,
                    na: v(if T::NAME == "f32" {
                        &c.na.f32
                    } else {
                        &c.na.f64
                    }),
                    nb: v(if T::NAME == "f32" {
                        &c.nb.f32
                    } else {
                        &c.nb.f64
                    }),
                    l: v(if T::NAME == "f32" { &c.l.f32 } else { &c.l.f64 }),
                    n: c.n,
                };
                let got: Vec<f64> = shade(&inputs).into_iter().map(T::to_f64).collect();
                if got.len() != c.n as usize + 1 {
                    wrong_length.push((c, got.len()));
                }
                results.insert(c.id.clone(), got);
            }
            let reports = match check_in(file, &results, self.method, &key, tol, false, T::U) {
                Ok(r) => r,
                // A method the published sets do not hold (a cosine table of another
                // size), or a tolerance that means nothing: a failure, not a panic.
                Err(e) => {
                    report.failures.push(Failure {
                        set,
                        id: format!("(the {set} set)"),
                        lines: vec![e],
                    });
                    continue;
                }
            };
            report.cases += reports.len();
            for r in reports.iter().filter(|r| !r.pass) {
                let c = file.cases.iter().find(|c| c.id == r.id).expect("case");
                let length = wrong_length
                    .iter()
                    .find(|(w, _)| w.id == c.id)
                    .map(|(_, len)| *len);
                report
                    .failures
                    .push(Failure::new::<T>(set, c, r, &results[&c.id], &key, length));
            }
        }
        report
    }
}

/// One failing case, at its worst pixel.
#[derive(Clone, Debug)]
pub struct Failure {
    /// The set.
    pub set: &'static str,
    /// The case id.
    pub id: String,
    /// What the failure says, in the lines the report prints.
    pub lines: Vec<String>,
}

fn shown_inputs<T: Format>(what: &str, v: &[String; 3]) -> String {
    let parsed: Vec<String> = v
        .iter()
        .map(|s| match T::parse(s) {
            Some(x) => format!("{s} ({})", x.hex()),
            None => s.clone(),
        })
        .collect();
    format!("{what:<9} = ({})", parsed.join(", "))
}

impl Failure {
    fn new<T: Format>(
        set: &'static str,
        c: &Case,
        r: &CaseReport,
        got: &[f64],
        key: &str,
        length: Option<usize>,
    ) -> Failure {
        let pick = |v: &crate::conformance::vectors::VectorInput| {
            if T::NAME == "f32" {
                v.f32.clone()
            } else {
                v.f64.clone()
            }
        };
        let mut lines = vec![format!("{set}/{} (n = {}): {}", c.id, c.n, c.comment)];
        lines.push(shown_inputs::<T>("N_a", &pick(&c.na)));
        lines.push(shown_inputs::<T>("N_b", &pick(&c.nb)));
        lines.push(shown_inputs::<T>("L", &pick(&c.l)));
        if let Some(len) = length {
            lines.push(format!(
                "returned {len} values; the span has n + 1 = {} pixels",
                c.n + 1
            ));
        } else {
            let i = r.worst_pixel;
            let exp = &c.expected[key];
            let e: f64 = exp.values[i].parse().unwrap_or(f64::NAN);
            let g = got[i];
            let gl = if g.is_finite() {
                level(&g).to_string()
            } else {
                "none".into()
            };
            lines.push(format!("pixel     = {i} (the worst of the case)"));
            lines.push(format!(
                "expected  = {} (level {})",
                exp.values[i], exp.levels[i]
            ));
            let gt = T::from_f64(g);
            lines.push(format!("got       = {gt} ({}) (level {gl})", gt.hex()));
            if g.is_finite() {
                lines.push(format!(
                    "off by    = {:.3e} = {:.1} {} ulps, {} levels",
                    (g - e).abs(),
                    (g - e).abs() / T::ulp(e),
                    T::NAME,
                    level(&g).abs_diff(exp.levels[i])
                ));
            } else {
                lines.push("off by    = not finite".into());
            }
        }
        lines.push(format!("allowed   = {}", r.allowed));
        lines.push(format!(
            "reproduce = phong-approx span --method {key} --na={} --nb={} --light={} --steps {} --scalar exact",
            c.na.exact.join(","),
            c.nb.exact.join(","),
            c.l.exact.join(","),
            c.n
        ));
        Failure {
            set,
            id: c.id.clone(),
            lines,
        }
    }
}

/// The verdict on every case: inspect it, or [`Report::assert_ok`] in a test.
#[derive(Clone, Debug)]
pub struct Report {
    method: Method,
    judged_by: String,
    format: &'static str,
    cases: usize,
    failures: Vec<Failure>,
}

/// How many failures a report prints in full.
const SHOWN_FAILURES: usize = 5;

impl Report {
    /// Whether every case passed.
    pub fn is_ok(&self) -> bool {
        self.failures.is_empty()
    }

    /// The failing cases.
    pub fn failures(&self) -> &[Failure] {
        &self.failures
    }

    /// The number of cases judged.
    pub fn cases(&self) -> usize {
        self.cases
    }

    /// Panics with the report when a case failed.
    ///
    /// # Panics
    /// When [`Report::is_ok`] is false.
    #[track_caller]
    pub fn assert_ok(&self) {
        if !self.is_ok() {
            panic!("{self}");
        }
    }
}

impl fmt::Display for Report {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            f,
            "{} in {} judged by {}: {} of {} cases fail",
            self.method,
            self.format,
            self.judged_by,
            self.failures.len(),
            self.cases
        )?;
        for fl in self.failures.iter().take(SHOWN_FAILURES) {
            writeln!(f)?;
            for l in &fl.lines {
                writeln!(f, "  {l}")?;
            }
        }
        if self.failures.len() > SHOWN_FAILURES {
            let rest: Vec<&str> = self.failures[SHOWN_FAILURES..]
                .iter()
                .map(|fl| fl.id.as_str())
                .collect();
            writeln!(f, "\n  and {} more: {}", rest.len(), rest.join(", "))?;
        }
        Ok(())
    }
}

// ------------------------------------------------ beyond the published vectors

/// The exact reference on a span of your own: the values (exact for the rational
/// methods, to 2^-250 for the others, [`Method::exact_bits`]), as 30-digit decimals
/// and their 8-bit levels (decided exactly, `None` only where a non-rational
/// method's value is within its error of a level boundary).
#[derive(Clone, Debug)]
pub struct Oracle {
    /// The values, pixel `0..=n`.
    pub values: Vec<crate::BigRational>,
    /// The values to 30 significant digits.
    pub decimals: Vec<String>,
    /// The levels `floor(255·clamp(v, 0, 1))`.
    pub levels: Vec<Option<u8>>,
}

/// The exact values and levels of `method` on `span` (exact unit inputs:
/// [`crate::reference::unit`] makes them). Cost: exact rationals, so about `n`
/// times a few microseconds for the rational methods and a few hundred for the ones
/// with square roots, `acos` or `cos` (`docs/conformance.md`, budgets): keep `n` in
/// the hundreds in property tests.
///
/// ```
/// use phong_approx::reference::unit::unit_from_ints;
/// use phong_approx::testkit::oracle;
/// use phong_approx::{Method, Span};
/// let span = Span::new(unit_from_ints(0, 0, 1), unit_from_ints(1, 0, 3), unit_from_ints(0, 0, 1), 4).unwrap();
/// let o = oracle(Method::Gouraud, &span).unwrap();
/// assert_eq!(o.decimals[0], "1.00000000000000000000000000000");
/// assert_eq!(o.levels[4], Some(204)); // p_b = 0.8
/// ```
///
/// # Errors
/// The method's [`crate::SpanError`] on this span (a normal that vanishes, say).
pub fn oracle(
    method: Method,
    span: &crate::Span<crate::BigRational>,
) -> Result<Oracle, crate::SpanError> {
    use crate::Scalar;
    let values = method.values(span)?;
    let one = crate::BigRational::from_integer(1.into());
    let levels = method.exact_levels(span, &values, &one);
    let decimals = values.iter().map(|v| v.to_decimal(30)).collect();
    Ok(Oracle {
        values,
        decimals,
        levels,
    })
}

/// The interval `[lo, hi]` every pixel of a correct implementation of `method` in
/// the format `T` (`f32`, `f64`) and `profile` falls in, on `span`: the exact value
/// plus and minus the profile's bound for the case (its Coq theorem or derivation,
/// `docs/float.md` §18; the crate's derived bound for `Reference`), rounded outward.
/// `None` where the profile has no bound for the method, format and span — as
/// `check` then fails the case.
///
/// ```
/// use phong_approx::reference::unit::unit_from_ints;
/// use phong_approx::testkit::acceptance;
/// use phong_approx::tolerance::profile::Profile;
/// use phong_approx::{Method, Span};
/// let span = Span::new(unit_from_ints(0, 0, 1), unit_from_ints(1, 0, 3), unit_from_ints(0, 0, 1), 4).unwrap();
/// let iv = acceptance::<f32>(Method::CorrectedEuler, &span, Profile::Ieee).unwrap();
/// let mine = 0.8f32; // pixel 4 of some implementation
/// assert!(iv[4].0 <= f64::from(mine) && f64::from(mine) <= iv[4].1);
/// ```
pub fn acceptance<T: Format>(
    method: Method,
    span: &crate::Span<crate::BigRational>,
    profile: Profile,
) -> Option<Vec<(f64, f64)>> {
    use crate::Scalar;
    let shape = crate::tolerance::Shape::of(span);
    let b = match profile {
        Profile::Reference => crate::tolerance::span_bound(method, &shape, T::U),
        p => crate::tolerance::profile::profile_bound(method, p, span.n, shape.q_min, T::U),
    }?;
    let values = method.values(span).ok()?;
    let interval = |x: f64, b: f64| {
        // The f64 of the exact value is within half an f64 ulp: widen by one.
        let slack = f64::EPSILON * x.abs().max(f64::MIN_POSITIVE);
        let lo = (x - b) - slack - f64::EPSILON * (x - b).abs();
        let hi = (x + b) + slack + f64::EPSILON * (x + b).abs();
        (lo, hi)
    };
    let mut iv: Vec<(f64, f64)> = values.iter().map(|v| interval(v.to_f64(), b)).collect();
    // The adaptive scheme where its test is too close to call (docs/float.md §10): an
    // implementation may pick either method, so each pixel's interval also holds the
    // other method's (the hull of the two; `check` asks one method for the whole span).
    if method == Method::Adaptive {
        let bound = |m: Method| match profile {
            Profile::Reference => crate::tolerance::span_bound(m, &shape, T::U),
            p => crate::tolerance::profile::profile_bound(m, p, span.n, shape.q_min, T::U),
        };
        let (bg, bce) = (bound(Method::Gouraud)?, bound(Method::CorrectedEuler)?);
        let d = crate::adaptive::decide(span, &crate::BigRational::from_integer(1.into()));
        if crate::tolerance::adaptive_too_close(d.delta.to_f64(), 1.0, bg, bce, T::U) {
            for (m, b) in [(Method::Gouraud, bg), (Method::CorrectedEuler, bce)] {
                for (i, v) in m.values(span).ok()?.iter().enumerate() {
                    let (lo, hi) = interval(v.to_f64(), b);
                    iv[i] = (iv[i].0.min(lo), iv[i].1.max(hi));
                }
            }
        }
    }
    Some(iv)
}

/// Exact unit vectors and spans for property tests of your own code (feature
/// `proptest`): `prop_compose!`-style strategies whose defaults stay fast (`n ≤ 64`
/// unless asked).
///
/// ```
/// # #[cfg(feature = "proptest")] {
/// use phong_approx::testkit::{acceptance, strategy};
/// use phong_approx::tolerance::profile::Profile;
/// use phong_approx::Method;
/// use proptest::prelude::*;
/// proptest!(ProptestConfig::with_cases(16), |(span in strategy::mesh_span(1..=16))| {
///     let iv = acceptance::<f32>(Method::Gouraud, &span, Profile::Ieee).unwrap();
///     prop_assert_eq!(iv.len(), span.n as usize + 1);
/// });
/// # }
/// ```
#[cfg(feature = "proptest")]
pub mod strategy {
    use crate::reference::unit::unit_from_ints;
    use crate::{BigRational, Span, Vec3};
    use proptest::prelude::*;

    /// An exact unit vector from integer stereographic parameters `(a, b)/d`.
    pub fn unit_vector() -> impl Strategy<Value = Vec3<BigRational>> {
        (-40i64..=40, -40i64..=40, 1i64..=24).prop_map(|(a, b, d)| unit_from_ints(a, b, d))
    }

    fn span(
        na: Vec3<BigRational>,
        nb: Vec3<BigRational>,
        l: Vec3<BigRational>,
        n: u32,
    ) -> Option<Span<BigRational>> {
        Span::new(na, nb, l, n).ok().filter(|s| !s.is_opposite())
    }

    /// A span as a mesh gives one: nearby edge normals (a few degrees apart), light
    /// anywhere, `n` in `steps`.
    pub fn mesh_span(
        steps: std::ops::RangeInclusive<u32>,
    ) -> impl Strategy<Value = Span<BigRational>> {
        (
            (-30i64..=30, -30i64..=30, 1i64..=20),
            -3i64..=3,
            -3i64..=3,
            unit_vector(),
            steps,
        )
            .prop_filter_map("a valid span", |((a, b, d), da, db, l, n)| {
                let na = unit_from_ints(8 * a, 8 * b, 8 * d);
                let nb = unit_from_ints(8 * a + da, 8 * b + db, 8 * d);
                span(na, nb, l, n)
            })
    }

    /// Edge normals nearly opposite (`q` nearly vanishes mid-span): `(0, 0, 1)` and
    /// the reflection of a vector `1/m` from `(0, 0, −1)`, `m` from 8 to 4096.
    pub fn nearly_opposite(
        steps: std::ops::RangeInclusive<u32>,
    ) -> impl Strategy<Value = Span<BigRational>> {
        (3u32..=12, unit_vector(), steps).prop_filter_map("a valid span", |(k, l, n)| {
            let m = 1i64 << k;
            // (2m, 0, 1 − m²)/(1 + m²) with m large is near (0, 0, −1).
            let nb = unit_from_ints(m, 0, 1);
            span(unit_from_ints(0, 0, 1), nb, l, n)
        })
    }

    /// Any span whose `n` is `2^k − 1`, `2^k` or `2^k + 1` (`k ≤ max_k`), where
    /// slopes sit next to powers of two.
    pub fn around_powers_of_two(max_k: u32) -> impl Strategy<Value = Span<BigRational>> {
        (
            unit_vector(),
            unit_vector(),
            unit_vector(),
            1u32..=max_k.max(1),
            -1i64..=1,
        )
            .prop_filter_map("a valid span", |(na, nb, l, k, d)| {
                let n = ((1i64 << k) + d).max(1) as u32;
                span(na, nb, l, n)
            })
    }

    /// A mesh span with the light at a grazing angle to `N_a` (`N_a·L` below about
    /// 0.05 in magnitude).
    pub fn grazing_light(
        steps: std::ops::RangeInclusive<u32>,
    ) -> impl Strategy<Value = Span<BigRational>> {
        mesh_span(steps).prop_filter("grazing light", |s| {
            use crate::Scalar;
            s.p_a.to_f64().abs() < 0.05
        })
    }
}

/// A random span for `quickcheck` (feature `quickcheck`): a mesh-like span of 1 to
/// 32 steps with exact unit inputs, or nearly opposite normals.
///
/// ```
/// # #[cfg(feature = "quickcheck")] {
/// use phong_approx::testkit::{oracle, ArbSpan};
/// use phong_approx::Method;
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
