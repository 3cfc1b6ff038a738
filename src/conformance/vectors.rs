//! Test vectors: scan-line cases with exact inputs and the exact expected values of
//! every method, for other implementations to test against.

use crate::adaptive;
use crate::method::Method;
use crate::reference::unit::unit_from_stereo;
use crate::scalar::Scalar;
use crate::span::Span;
use crate::specular::power;
use crate::vector::Vec3;
use num_bigint::BigInt;
use num_rational::BigRational;
use serde::{Deserialize, Serialize};

/// The largest `n` of a case `check` accepts (the published sets go to 4096).
pub const MAX_CASE_STEPS: u32 = 65_536;

/// Version of the vector format (semantic: a major change breaks readers).
pub const FORMAT_VERSION: &str = "1.2.0";

/// Significant digits of the expected values.
pub const DIGITS: usize = 30;

/// The name of a method in the vector files: its catalogue name
/// ([`Method::name`], e.g. `angular-table256`), which parses back.
pub fn method_key(m: Method) -> String {
    m.name().into_owned()
}

/// The keys of every catalogued method, in the catalogue's order: the methods of a
/// published set, and the only keys a vector file may use.
pub fn method_keys() -> Vec<String> {
    Method::ALL.iter().map(|&m| method_key(m)).collect()
}

/// A vector as exact fractions and as the nearest `f32` and `f64`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct VectorInput {
    /// Exact components as fractions, e.g. `"3/5"`.
    pub exact: [String; 3],
    /// Nearest `f32` to each component (shortest round-trip decimal).
    pub f32: [String; 3],
    /// Nearest `f64` to each component.
    pub f64: [String; 3],
}

/// The expected output of one method on one case.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct Expected {
    /// Values at pixels `0..=n` as decimal strings with 30 significant digits.
    #[cfg_attr(feature = "schema", schemars(length(min = 2)))]
    pub values: Vec<String>,
    /// The exact 8-bit levels `floor(255·clamp(v, 0, 1))`.
    #[cfg_attr(feature = "schema", schemars(length(min = 2)))]
    pub levels: Vec<u8>,
}

/// The specular part of a case: a half vector and a shininess.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct SpecularCase {
    /// The unit half vector `H`.
    pub h: VectorInput,
    /// The shininess `s`.
    pub s: u32,
    /// Per method: `max(0, method(N·H))^s`.
    #[cfg_attr(feature = "schema", schemars(schema_with = "schema::per_method"))]
    pub expected: std::collections::BTreeMap<String, Expected>,
}

/// One scan-line case.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct Case {
    /// A stable id, e.g. `edge-007`.
    pub id: String,
    /// Why the case is there.
    pub comment: String,
    /// `N_a`.
    pub na: VectorInput,
    /// `N_b`.
    pub nb: VectorInput,
    /// `L`.
    pub l: VectorInput,
    /// Steps `n`; the span has `n + 1` pixels.
    #[cfg_attr(feature = "schema", schemars(range(min = 1)))]
    pub n: u32,
    /// The smallest `q_i` of the span (to scale float tolerances; see
    /// `src/tolerance.rs`).
    #[cfg_attr(feature = "schema", schemars(range(min = 0.0)))]
    pub q_min: f64,
    /// The adaptive test's `δ` (eq. 24) and decision with `K_d = 1`.
    pub delta: String,
    /// `"gouraud"` or `"corrected-euler"`.
    #[cfg_attr(feature = "schema", schemars(schema_with = "schema::decision"))]
    pub decision: String,
    /// Per method: expected values and levels.
    #[cfg_attr(feature = "schema", schemars(schema_with = "schema::per_method"))]
    pub expected: std::collections::BTreeMap<String, Expected>,
    /// Specular expectations, for some cases.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub specular: Option<SpecularCase>,
}

impl Case {
    /// The `phong-approx span` command that computes this case's exact values for the
    /// method `key` (for the specular part, the values on `N·H` with `H` as the light:
    /// then raise them to `s`, as the command's tail says).
    pub fn reproduce(&self, key: &str, specular: bool) -> String {
        self.reproduce_shown(key, specular, |x| x.to_string())
    }

    /// [`Case::reproduce`] with each number of the file passed through `show` (a
    /// report of an untrusted file cuts and escapes them).
    pub fn reproduce_shown(
        &self,
        key: &str,
        specular: bool,
        show: impl Fn(&str) -> String,
    ) -> String {
        let q = |v: &[String; 3]| v.iter().map(|x| show(x)).collect::<Vec<_>>().join(",");
        let (light, then) = match (&self.specular, specular) {
            (Some(sp), true) => (q(&sp.h.exact), format!(" (then max(0, v)^{})", sp.s)),
            _ => (q(&self.l.exact), String::new()),
        };
        span_command(
            key,
            [&q(&self.na.exact), &q(&self.nb.exact), &light],
            self.n,
        ) + &then
    }
}

/// The `phong-approx span` command that prints method `key`'s exact values on the
/// span with the inputs `[N_a, N_b, L]` (each `x,y,z`) and `n` steps.
pub fn span_command(key: &str, inputs: [&str; 3], n: u32) -> String {
    let [na, nb, l] = inputs;
    format!("phong-approx span --method {key} --na={na} --nb={nb} --light={l} --steps {n} --scalar exact")
}

/// A vector file.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
#[cfg_attr(
    feature = "schema",
    schemars(
        title = "phong-approx scan-line test vectors",
        description = "One set of scan-line cases with exact inputs and exact expected values per method.",
        extend("$id" = "phong-approx/vectors/schema.json")
    )
)]
pub struct VectorFile {
    /// The format version (semantic: a major change breaks readers).
    #[cfg_attr(feature = "schema", schemars(schema_with = "schema::version"))]
    pub version: String,
    /// `phong-approx <crate version>`.
    pub generator: String,
    /// The set: `typical`, `edge` or `paper`.
    #[cfg_attr(feature = "schema", schemars(schema_with = "schema::set"))]
    pub set: String,
    /// Notes on how the values were computed.
    pub notes: String,
    /// The method keys present in every case.
    #[cfg_attr(feature = "schema", schemars(schema_with = "schema::methods"))]
    pub methods: Vec<String>,
    /// Number of cases.
    #[cfg_attr(feature = "schema", schemars(range(min = 1)))]
    pub number_of_cases: usize,
    /// The cases.
    pub cases: Vec<Case>,
}

/// The JSON Schema of the vector files (`vectors/schema.json`), derived from
/// [`VectorFile`] and its parts, with the enumerations read from the catalogue
/// ([`Method::ALL`]), [`SETS`] and [`FORMAT_VERSION`]; written by `phong-approx
/// vectors` beside the sets.
#[cfg(feature = "schema")]
pub fn schema() -> String {
    serde_json::to_string_pretty(&schemars::schema_for!(VectorFile)).expect("plain data") + "\n"
}

/// The enumerations of [`schema`].
#[cfg(feature = "schema")]
mod schema {
    use schemars::{json_schema, Schema, SchemaGenerator};

    pub fn version(_: &mut SchemaGenerator) -> Schema {
        json_schema!({ "type": "string", "enum": [super::FORMAT_VERSION],
            "description": "The format version (semantic: a major change breaks readers)." })
    }

    pub fn set(_: &mut SchemaGenerator) -> Schema {
        json_schema!({ "type": "string", "enum": super::SETS })
    }

    pub fn methods(_: &mut SchemaGenerator) -> Schema {
        json_schema!({ "type": "array", "items": { "type": "string", "enum": super::method_keys() } })
    }

    pub fn decision(_: &mut SchemaGenerator) -> Schema {
        json_schema!({ "type": "string", "enum": ["gouraud", "corrected-euler"] })
    }

    pub fn per_method(g: &mut SchemaGenerator) -> Schema {
        let expected = g.subschema_for::<super::Expected>();
        json_schema!({
            "type": "object",
            "propertyNames": { "enum": super::method_keys() },
            "additionalProperties": expected
        })
    }
}

/// The sets there are.
pub const SETS: [&str; 3] = ["typical", "edge", "paper"];

fn fraction(x: &BigRational) -> String {
    x.to_string()
}

fn input(v: &Vec3<BigRational>) -> VectorInput {
    let c = [&v.x, &v.y, &v.z];
    VectorInput {
        exact: c.map(fraction),
        f32: c.map(|x| format!("{:?}", f32::from_rational(x))),
        f64: c.map(|x| format!("{:?}", f64::from_rational(x))),
    }
}

/// Decided levels, or the message naming the first pixel whose level the exact run
/// cannot decide (its value within its error of a level boundary).
fn decided(levels: Vec<Option<u8>>, method: Method, what: &str) -> Result<Vec<u8>, String> {
    levels
        .into_iter()
        .enumerate()
        .map(|(i, l)| {
            l.ok_or_else(|| {
                format!("{method}: the {what} level of pixel {i} is not decided by the exact run")
            })
        })
        .collect()
}

/// The exact run of `method` on `span` with every one of the [`DIGITS`] digits known
/// (square roots, `acos` and `cos` taken to more bits until they are:
/// [`crate::span_report::exact_run`], the path `span --scalar exact` takes).
fn exact_run(
    method: Method,
    span: &Span<BigRational>,
) -> Result<crate::span_report::ExactRun, String> {
    use crate::span_report::{exact_run, Arithmetic, Request};
    exact_run(&Request {
        method,
        na: span.na.clone(),
        nb: span.nb.clone(),
        l: span.l.clone(),
        n: span.n,
        kd: BigRational::from_integer(1.into()),
        normalize: false,
        digits: DIGITS,
        arithmetic: Arithmetic::Exact,
    })
    .map_err(|e| format!("{method}: {}", e.message))
}

/// The exact expectations of `method` on `span` (values to [`DIGITS`] digits, every
/// one known; levels decided exactly, [`Method::exact_levels`]).
fn expected(method: Method, span: &Span<BigRational>) -> Result<Expected, String> {
    let run = exact_run(method, span)?;
    let levels = decided(run.levels, method, "diffuse")?;
    Ok(Expected {
        values: run.decimals,
        levels,
    })
}

/// The specular expectations `max(0, v)^s` of `method` on `span_h` (`N·H`): the base
/// values with every digit known, and each power's [`DIGITS`] digits checked against
/// the powers of the base's bounds `v ± 2^-bits` (refused where they differ).
fn specular_expected(
    method: Method,
    span_h: &Span<BigRational>,
    s: u32,
) -> Result<Expected, String> {
    let run = exact_run(method, span_h)?;
    let base = run.values;
    let v: Vec<BigRational> = base.iter().map(|x| power(x, s)).collect();
    if let Some(bits) = run.bits {
        let e = BigRational::new(1.into(), BigInt::from(1) << bits.max(0) as usize);
        for (i, x) in base.iter().enumerate() {
            let (lo, hi) = (power(&(x - &e), s), power(&(x + &e), s));
            if lo.to_decimal(DIGITS) != hi.to_decimal(DIGITS) {
                return Err(format!(
                    "{method}: the specular value of pixel {i} is not known to {DIGITS} digits"
                ));
            }
        }
    }
    let levels = decided(
        method.exact_power_levels(span_h, &base, s),
        method,
        "specular",
    )?;
    Ok(Expected {
        values: v.iter().map(|x| x.to_decimal(DIGITS)).collect(),
        levels,
    })
}

/// The largest shininess `s` a vector file may give (`check` refuses a file with a
/// larger one before any work: the exact power `v^s` grows with `s`).
pub const MAX_SHININESS: u32 = 10_000;

/// One case of a set before its expectations are computed: its id, comment and exact
/// unit inputs. [`specs`] lists a set's cases; [`CaseSpec::compute`] computes one, so a
/// part of a set can be regenerated without the rest (the default test tier checks the
/// short cases, the extensive tier every file byte for byte).
#[derive(Clone, Debug)]
pub struct CaseSpec {
    /// The case id, e.g. `edge-003`.
    pub id: String,
    /// Why the case is there.
    pub comment: &'static str,
    /// `N_a`, exactly unit.
    pub na: Vec3<BigRational>,
    /// `N_b`, exactly unit.
    pub nb: Vec3<BigRational>,
    /// `L`, exactly unit.
    pub l: Vec3<BigRational>,
    /// Steps.
    pub n: u32,
    /// The half vector and exponent of the specular expectations, if any.
    pub h: Option<(Vec3<BigRational>, u32)>,
}

/// A case spec from its parts.
fn make_case(
    id: String,
    comment: &'static str,
    na: Vec3<BigRational>,
    nb: Vec3<BigRational>,
    l: Vec3<BigRational>,
    n: u32,
    h: Option<(Vec3<BigRational>, u32)>,
) -> CaseSpec {
    CaseSpec {
        id,
        comment,
        na,
        nb,
        l,
        n,
        h,
    }
}

impl CaseSpec {
    /// The case with its exact expectations.
    ///
    /// # Errors
    /// A level at some pixel that the exact run cannot decide (named, with the method
    /// and pixel).
    pub fn compute(self) -> Result<Case, String> {
        let CaseSpec {
            id,
            comment,
            na,
            nb,
            l,
            n,
            h,
        } = self;
        compute_case_for(&Method::ALL, id, comment, na, nb, l, n, h)
    }
}

/// A case from an exact span (exactly unit inputs), with the expectations of
/// `methods` only: what the test kit's `check_span` judges against.
///
/// # Errors
/// As [`CaseSpec::compute`].
pub(crate) fn case_for_span(
    methods: &[Method],
    id: &str,
    comment: &str,
    span: &Span<BigRational>,
) -> Result<Case, String> {
    let (na, nb, l) = (span.na.clone(), span.nb.clone(), span.l.clone());
    compute_case_for(methods, id.to_string(), comment, na, nb, l, span.n, None)
}

/// A case from exact unit inputs, with the expectations of `methods`.
#[allow(clippy::too_many_arguments)]
fn compute_case_for(
    methods: &[Method],
    id: String,
    comment: &str,
    na: Vec3<BigRational>,
    nb: Vec3<BigRational>,
    l: Vec3<BigRational>,
    n: u32,
    h: Option<(Vec3<BigRational>, u32)>,
) -> Result<Case, String> {
    let at = |e: String| format!("{id}: {e}");
    let span = Span::new(na.clone(), nb.clone(), l.clone(), n).map_err(|e| format!("{id}: {e}"))?;
    let q_min = (0..=n)
        .map(|i| span.q_at(i).to_f64())
        .fold(f64::INFINITY, f64::min);
    let d = adaptive::decide(&span, &BigRational::from_i64(1));
    let expected = methods
        .iter()
        .map(|&m| Ok((method_key(m), self::expected(m, &span)?)))
        .collect::<Result<_, String>>()
        .map_err(at)?;
    let specular = h.map(|(h, s)| -> Result<SpecularCase, String> {
        let span_h = Span::new(na.clone(), nb.clone(), h.clone(), n)
            .map_err(|e| format!("specular: {e}"))?;
        let expected = methods
            .iter()
            .map(|&m| Ok((method_key(m), specular_expected(m, &span_h, s)?)))
            .collect::<Result<_, String>>()?;
        Ok(SpecularCase {
            h: input(&h),
            s,
            expected,
        })
    });
    let specular = specular.transpose().map_err(at)?;
    Ok(Case {
        id,
        comment: comment.to_string(),
        na: input(&na),
        nb: input(&nb),
        l: input(&l),
        n,
        q_min,
        delta: d.delta.to_decimal(DIGITS),
        decision: d.choice.name().to_string(),
        expected,
        specular,
    })
}

/// A case as `check` reads it from a vector file that is not published
/// (`--allow-modified-vectors`): its inputs only. Whatever expectations the file holds
/// are skipped without being stored; [`InputsFile::recompute`] computes them from the
/// inputs with the exact reference, so a modified file supplies cases, not truth.
#[derive(Clone, Debug, Deserialize)]
pub struct CaseInputs {
    /// The case id.
    pub id: String,
    /// Why the case is there (untrusted text: shown escaped and cut).
    #[serde(default)]
    pub comment: String,
    /// `N_a`.
    pub na: VectorInput,
    /// `N_b`.
    pub nb: VectorInput,
    /// `L`.
    pub l: VectorInput,
    /// Steps `n`.
    pub n: u32,
    /// The half vector and shininess of the specular expectations, if any.
    #[serde(default)]
    pub specular: Option<SpecularInputs>,
}

/// The specular inputs of a [`CaseInputs`].
#[derive(Clone, Debug, Deserialize)]
pub struct SpecularInputs {
    /// The unit half vector `H`.
    pub h: VectorInput,
    /// The shininess `s`.
    pub s: u32,
}

/// A vector file read for its inputs only (see [`CaseInputs`]).
#[derive(Clone, Debug, Deserialize)]
pub struct InputsFile {
    /// The format version.
    pub version: String,
    /// The set's name (untrusted text).
    #[serde(default)]
    pub set: String,
    /// The method keys the file lists.
    pub methods: Vec<String>,
    /// Number of cases.
    pub number_of_cases: usize,
    /// The cases.
    pub cases: Vec<CaseInputs>,
}

/// The exact vector of a vector-file input, `None` unless all three components are
/// exact decimals or fractions.
pub fn exact_input(v: &VectorInput) -> Option<Vec3<BigRational>> {
    let [x, y, z] = &v.exact;
    Some(Vec3::new(
        crate::parse::parse_rational(x).ok()?,
        crate::parse::parse_rational(y).ok()?,
        crate::parse::parse_rational(z).ok()?,
    ))
}

/// Whether a file's `f32` and `f64` forms of an input are the nearest floats to its
/// exact value (`ours`, as [`input`] writes them).
fn same_floats(theirs: &VectorInput, ours: &VectorInput) -> Result<(), String> {
    for i in 0..3 {
        let t32 = theirs.f32[i].trim().parse::<f32>();
        let t64 = theirs.f64[i].trim().parse::<f64>();
        let o32 = ours.f32[i].parse::<f32>();
        let o64 = ours.f64[i].parse::<f64>();
        if t32.ok().map(f32::to_bits) != o32.ok().map(f32::to_bits) {
            return Err(format!(
                "component {}: the f32 form '{}' is not the nearest f32 to the exact value ({})",
                i + 1,
                super::shown(&theirs.f32[i]),
                ours.f32[i]
            ));
        }
        if t64.ok().map(f64::to_bits) != o64.ok().map(f64::to_bits) {
            return Err(format!(
                "component {}: the f64 form '{}' is not the nearest f64 to the exact value ({})",
                i + 1,
                super::shown(&theirs.f64[i]),
                ours.f64[i]
            ));
        }
    }
    Ok(())
}

impl InputsFile {
    /// The file with the expectations of `method` computed from each case's inputs by
    /// the exact reference (with `specular`, also the specular ones for cases that
    /// have a half vector; without, the half vectors are dropped unread);
    /// `q_min`, `δ` and the adaptive decision are the span's. The result passes
    /// [`super::integrity::validate`] whenever the inputs are valid.
    ///
    /// # Errors
    /// A case whose inputs are not exact unit vectors, whose `n` is out of range, whose
    /// shininess is outside `1..=`[`MAX_SHININESS`] (checked for every case before any
    /// work), or whose level or digits the exact run cannot decide (named).
    pub fn recompute(&self, method: Method, specular: bool) -> Result<VectorFile, String> {
        if let Some(c) = self.cases.iter().find(|c| {
            c.specular
                .as_ref()
                .is_some_and(|sp| sp.s == 0 || sp.s > MAX_SHININESS)
        }) {
            return Err(format!(
                "case {}: shininess {} is outside 1..={MAX_SHININESS}",
                super::shown(&c.id),
                c.specular.as_ref().map_or(0, |sp| sp.s)
            ));
        }
        let v = |c: &CaseInputs, x: &VectorInput, what: &str| {
            exact_input(x).ok_or_else(|| {
                format!(
                    "case {}: {what} is not three exact numbers",
                    super::shown(&c.id)
                )
            })
        };
        let mut cases = Vec::with_capacity(self.cases.len());
        for c in &self.cases {
            if c.n == 0 || c.n > MAX_CASE_STEPS {
                return Err(format!(
                    "case {}: n = {} is outside 1..={}",
                    super::shown(&c.id),
                    c.n,
                    MAX_CASE_STEPS
                ));
            }
            let h = match &c.specular {
                Some(sp) if specular => Some((v(c, &sp.h, "h")?, sp.s)),
                _ => None,
            };
            // The adaptive scheme is judged against both of its methods where its test
            // is too close to call (`check::check_in`): their expectations too.
            let methods: &[Method] = if method == Method::Adaptive {
                &[Method::Adaptive, Method::Gouraud, Method::CorrectedEuler]
            } else {
                std::slice::from_ref(&method)
            };
            let case = compute_case_for(
                methods,
                c.id.clone(),
                &c.comment,
                v(c, &c.na, "na")?,
                v(c, &c.nb, "nb")?,
                v(c, &c.l, "l")?,
                c.n,
                h,
            )?;
            // The f32 and f64 forms an implementation reads must be the nearest floats
            // to the exact inputs the reference runs on.
            let mut pairs = vec![
                ("na", &c.na, &case.na),
                ("nb", &c.nb, &case.nb),
                ("l", &c.l, &case.l),
            ];
            if let (Some(sp), Some(mine)) = (&c.specular, case.specular.as_ref()) {
                pairs.push(("h", &sp.h, &mine.h));
            }
            for (what, theirs, ours) in pairs {
                same_floats(theirs, ours)
                    .map_err(|e| format!("case {}: {what}: {e}", super::shown(&c.id)))?;
            }
            cases.push(case);
        }
        Ok(VectorFile {
            version: self.version.clone(),
            generator: String::new(),
            set: self.set.clone(),
            notes: String::new(),
            methods: if method == Method::Adaptive {
                [Method::Adaptive, Method::Gouraud, Method::CorrectedEuler]
                    .map(method_key)
                    .to_vec()
            } else {
                vec![method_key(method)]
            },
            number_of_cases: self.number_of_cases,
            cases,
        })
    }
}

fn q(n: i64, d: i64) -> BigRational {
    BigRational::new(BigInt::from(n), BigInt::from(d))
}

fn stereo(a: i64, b: i64, d: i64) -> Vec3<BigRational> {
    unit_from_stereo(&q(a, d), &q(b, d))
}

/// The half vector `normalize(L + V)` for `V = (0, 0, 1)`, made exactly unit by
/// stereographic projection of its direction's rational approximation.
fn half_vector(l: &Vec3<BigRational>) -> Vec3<BigRational> {
    // Stereographic parameters of H = (L + V)/|L + V| are (h_x, h_y)/(1 + h_z); round
    // them to 1/10^6 so that H is an exact rational unit vector close to the true one.
    let (x, y, z) = (l.x.to_f64(), l.y.to_f64(), l.z.to_f64() + 1.0);
    let len = (x * x + y * y + z * z).sqrt();
    let (hx, hy, hz) = (x / len, y / len, z / len);
    let r = |t: f64| (t / (1.0 + hz) * 1e6).round() as i64;
    stereo(r(hx), r(hy), 1_000_000)
}

/// splitmix64: a tiny deterministic generator so the typical set never changes.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    fn range(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.next() % (hi - lo + 1) as u64) as i64
    }
}

/// The `typical` set: spans like a torus produces — unit normals a few degrees apart,
/// a light anywhere in front, 2 to 64 steps.
fn typical() -> Vec<CaseSpec> {
    let mut rng = Rng(0x5EED_0001);
    let mut cases = Vec::new();
    for k in 0..40 {
        let d = 1000;
        let (a, b) = (rng.range(-900, 900), rng.range(-900, 900));
        let (da, db) = (rng.range(-60, 60), rng.range(-60, 60));
        let na = stereo(a, b, d);
        let nb = stereo(a + da, b + db, d);
        let l = stereo(rng.range(-700, 700), rng.range(-700, 700), d);
        let n = [2u32, 3, 5, 8, 13, 21, 34, 64][k % 8];
        let h = (k % 4 == 0).then(|| (half_vector(&l), [10u32, 50, 200][k % 3]));
        let comment = "torus-like span: nearby unit normals, light in front";
        cases.push(make_case(
            format!("typical-{:03}", k + 1),
            comment,
            na,
            nb,
            l,
            n,
            h,
        ));
    }
    // The adaptive test on both sides of its threshold (eq. 24, K_d = 1), normals
    // about 10° apart, 3·10^-3 from it (outside what f32 rounding can move δ by at
    // n = 2 under every profile, inside what |256δ| < 1 or |255δ| < 2 changes): an
    // implementation with the wrong threshold, or that always picks one method, fails
    // this set too.
    let (na, l) = (stereo(100, -50, 1000), stereo(-200, 150, 1000));
    for (k, (a, comment)) in [
        (
            209_735_223,
            "adaptive threshold: |255δ| = 1 + 3·10^-3 (corrected Euler)",
        ),
        (
            209_380_164,
            "adaptive threshold: |255δ| = 1 − 3·10^-3 (Gouraud)",
        ),
    ]
    .into_iter()
    .enumerate()
    {
        let nb = stereo(a, -50_000_000, 1_000_000_000);
        cases.push(make_case(
            format!("typical-{:03}", 41 + k),
            comment,
            na.clone(),
            nb,
            l.clone(),
            2,
            None,
        ));
    }
    cases
}

/// An edge case: comment, `N_a`, `N_b`, `L`, `n`.
type EdgeCase = (
    &'static str,
    Vec3<BigRational>,
    Vec3<BigRational>,
    Vec3<BigRational>,
    u32,
);

/// The `edge` set: the cases an implementation most often gets wrong.
fn edge() -> Vec<CaseSpec> {
    let up = stereo(0, 0, 1);
    let tilt = stereo(1, 0, 3); // (3/5, 0, 4/5)
    let tilt_back = stereo(-1, 0, 3); // (−3/5, 0, 4/5)
    let side = stereo(1, 0, 1); // (1, 0, 0)
    let oblique = stereo(2, 1, 5);
    let far = stereo(11430, 0, 1000); // 170.0° from +z
    let list: Vec<EdgeCase> = vec![
        (
            "n = 1: only the two exact edge values",
            up.clone(),
            tilt.clone(),
            oblique.clone(),
            1,
        ),
        (
            "n = 2: one interior pixel",
            up.clone(),
            tilt.clone(),
            oblique.clone(),
            2,
        ),
        (
            "n = 2, equal edge angles: angular interpolation is constant, Phong is not",
            tilt.clone(),
            tilt_back.clone(),
            up.clone(),
            2,
        ),
        (
            "Na = Nb: every method is constant and exact",
            tilt.clone(),
            tilt.clone(),
            oblique.clone(),
            7,
        ),
        (
            "normals 170° apart: q_min ≈ 0.0076, Euler far off",
            up.clone(),
            far.clone(),
            oblique.clone(),
            33,
        ),
        (
            "normals 170° apart, even n, light on the axis",
            up.clone(),
            far.clone(),
            up.clone(),
            64,
        ),
        (
            "N·L crosses zero inside the span (negative values, level 0)",
            up.clone(),
            side.clone(),
            stereo(-1, 0, 2),
            9,
        ),
        (
            "90° apart, light between: N·L ≥ 0 with a maximum inside",
            up.clone(),
            side.clone(),
            stereo(1, 0, 2),
            16,
        ),
        (
            "grazing light: N·L ≈ 0.001 at one edge",
            up.clone(),
            tilt.clone(),
            stereo(999, 0, 1000),
            12,
        ),
        (
            "light behind the surface: every level 0, |δ·255| ≥ 1",
            tilt.clone(),
            tilt_back.clone(),
            stereo(0, 0, 1).scale(&q(-1, 1)),
            2,
        ),
        (
            "the eq. 24 counterexample: |δ·255| < 1 yet levels 214 vs 215",
            stereo(0, 1, 3),
            stereo(0, 1, 4),
            up.clone(),
            2,
        ),
        (
            "tiny components: Na within 2e-9 of +z",
            stereo(1, 0, 1_000_000_000),
            tilt.clone(),
            oblique.clone(),
            10,
        ),
        (
            "components near ±1 with huge denominators",
            stereo(999_999_999, 7, 1_000_000),
            stereo(999_999_000, -3, 1_000_000),
            stereo(-5, 1_000_000, 1_000_000),
            20,
        ),
        (
            "n = 4096: long span, float accumulation",
            up.clone(),
            tilt.clone(),
            oblique.clone(),
            4096,
        ),
        (
            "n = 4096, normals 170° apart",
            up.clone(),
            far.clone(),
            oblique.clone(),
            4096,
        ),
    ];
    // The adaptive test (eq. 24, K_d = 1) on both sides of its threshold: N_b =
    // (11/61, 0, 60/61), L in the x–z plane, stereographic parameter a/d, with
    // |255δ| = 1 ± 3·10^-3 (outside f32's rounding of δ), 1 ± 10^-3, 1 ± 10^-6, and
    // 1 ± a few 10^-15, where f32 and f64 runs may pick either method (check then
    // accepts either, docs/float.md §10).
    let threshold: [(&'static str, i64, i64); 8] = [
        (
            "adaptive threshold: |255δ| = 1 + 3·10^-3 (corrected Euler)",
            182_465_060,
            1_000_000_000,
        ),
        (
            "adaptive threshold: |255δ| = 1 − 3·10^-3 (Gouraud)",
            193_237_157,
            1_000_000_000,
        ),
        (
            "adaptive threshold: |255δ| = 1 + 10^-3 (corrected Euler)",
            186_138_483,
            1_000_000_000,
        ),
        (
            "adaptive threshold: |255δ| = 1 − 10^-3 (Gouraud)",
            189_727_128,
            1_000_000_000,
        ),
        (
            "adaptive threshold: |255δ| = 1 + 10^-6 (corrected Euler)",
            187_941_205,
            1_000_000_000,
        ),
        (
            "adaptive threshold: |255δ| = 1 − 10^-6 (Gouraud)",
            187_944_794,
            1_000_000_000,
        ),
        (
            "adaptive threshold: |255δ| = 1 + 1.9·10^-15, within float rounding (either method)",
            187_942_999_602_488_765,
            1_000_000_000_000_000_000,
        ),
        (
            "adaptive threshold: |255δ| = 1 − 4.1·10^-15, within float rounding (either method)",
            187_942_999_602_499_517,
            1_000_000_000_000_000_000,
        ),
    ];
    let list = list.into_iter().chain(
        threshold
            .into_iter()
            .map(|(c, a, d)| (c, up.clone(), stereo(1, 0, 11), stereo(a, 0, d), 2)),
    );
    list.enumerate()
        .map(|(k, (c, na, nb, l, n))| {
            make_case(format!("edge-{:03}", k + 1), c, na, nb, l, n, None)
        })
        .collect()
}

/// The `paper` set: the spans behind Figures 1–3 — unit normals 60° apart in the x–z
/// plane (exact rational approximations, 60.0000° to 10^-4), the reproduction's light,
/// and the same with specular highlights.
fn paper() -> Vec<CaseSpec> {
    // tan(15°) = 2 − √3 ≈ 0.267949: stereographic parameters of (∓sin 30°, 0, cos 30°).
    let na = stereo(-267_949, 0, 1_000_000);
    let nb = stereo(267_949, 0, 1_000_000);
    // normalize(−1, 1, 2): stereographic parameters (−0.224745, 0.224745).
    let l = stereo(-224_745, 224_745, 1_000_000);
    let l_plane = stereo(-100_000, 0, 1_000_000); // light in the plane of the normals
    let h = half_vector(&l);
    vec![
        make_case(
            "paper-001".into(),
            "Figures 1–3: normals 60° apart, 100 steps, the reproduction's light",
            na.clone(),
            nb.clone(),
            l.clone(),
            100,
            Some((h.clone(), 30)),
        ),
        make_case(
            "paper-002".into(),
            "Figures 1–3 with the light in the plane of the normals",
            na.clone(),
            nb.clone(),
            l_plane,
            100,
            None,
        ),
        make_case(
            "paper-003".into(),
            "normals 60° apart, 10 steps",
            na.clone(),
            nb.clone(),
            l.clone(),
            10,
            Some((h, 50)),
        ),
        make_case(
            "paper-004".into(),
            "normals 60° apart, 1000 steps",
            na,
            nb,
            l.clone(),
            1000,
            None,
        ),
        // The adaptive test (eq. 24, K_d = 1) on both sides of its threshold, with the
        // reproduction's light: normals about 11° apart, 3·10^-3 from the threshold,
        // n = 2 (f32's rounding of δ grows with n: at n = 100 it reaches 6·10^-3).
        make_case(
            "paper-005".into(),
            "adaptive threshold: |255δ| = 1 + 3·10^-3 (corrected Euler)",
            stereo(-49_317_329, 0, 1_000_000_000),
            stereo(49_317_329, 0, 1_000_000_000),
            l.clone(),
            2,
            None,
        ),
        make_case(
            "paper-006".into(),
            "adaptive threshold: |255δ| = 1 − 3·10^-3 (Gouraud)",
            stereo(-49_168_155, 0, 1_000_000_000),
            stereo(49_168_155, 0, 1_000_000_000),
            l,
            2,
            None,
        ),
    ]
}

/// The cases of `set`, not yet computed.
///
/// # Errors
/// The unknown set's name.
pub fn specs(set: &str) -> Result<Vec<CaseSpec>, String> {
    match set {
        "typical" => Ok(typical()),
        "edge" => Ok(edge()),
        "paper" => Ok(paper()),
        other => Err(format!(
            "unknown set '{other}' (expected typical, edge or paper)"
        )),
    }
}

/// Generates the vector file of `set`.
///
/// # Errors
/// The unknown set's name; a case whose level at some pixel the exact run cannot
/// decide (named, with the method and pixel).
pub fn generate(set: &str) -> Result<VectorFile, String> {
    let cases = specs(set)?
        .into_iter()
        .map(CaseSpec::compute)
        .collect::<Result<Vec<Case>, String>>()?;
    Ok(file_of(set, cases))
}

/// The vector file of `set` with these cases: the header (format version, generator,
/// notes, methods) and the cases.
pub fn file_of(set: &str, cases: Vec<Case>) -> VectorFile {
    // The notes name the methods of a kind from the catalogue.
    let keys = |kind: fn(&Method) -> bool| {
        Method::ALL
            .iter()
            .filter(|m| kind(m))
            .map(|&m| method_key(m))
            .collect::<Vec<_>>()
            .join(", ")
    };
    VectorFile {
        version: FORMAT_VERSION.to_string(),
        generator: format!("phong-approx {}", env!("CARGO_PKG_VERSION")),
        set: set.to_string(),
        notes: format!(
            "Inputs are exact rational unit vectors (inverse stereographic projection). Expected values are computed exactly in rationals; \
             Phong-valued methods ({}), the angular ones and the related methods ({}) use square roots, arc cosines and cosines accurate to 2^-256, \
             and are printed to 30 significant digits. Levels are floor(255*clamp(v,0,1)), decided exactly (for p/sqrt(q) by comparing squares). \
             Recurrences are unclamped; specular values are max(0, v)^s.",
            keys(Method::is_phong_valued),
            keys(Method::is_related)
        ),
        methods: method_keys(),
        number_of_cases: cases.len(),
        cases,
    }
}

/// The CSV twin of a vector file: one row per case, method and pixel:
/// `set,case,method,kind,n,pixel,value,level` (`kind` is `diffuse` or `specular`).
#[cfg(feature = "csv")]
pub fn to_csv(file: &VectorFile) -> String {
    /// A line of the CSV twin.
    #[derive(Serialize)]
    struct Row<'a> {
        set: &'a str,
        case: &'a str,
        method: &'a str,
        kind: &'a str,
        n: u32,
        pixel: usize,
        value: &'a str,
        level: u8,
    }
    let mut rows = Vec::new();
    for c in &file.cases {
        let parts = std::iter::once(("diffuse", &c.expected))
            .chain(c.specular.iter().map(|sp| ("specular", &sp.expected)));
        for (kind, exp) in parts {
            for (m, e) in exp {
                for (i, (v, l)) in e.values.iter().zip(&e.levels).enumerate() {
                    rows.push(Row {
                        set: &file.set,
                        case: &c.id,
                        method: m,
                        kind,
                        n: c.n,
                        pixel: i,
                        value: v,
                        level: *l,
                    });
                }
            }
        }
    }
    crate::table::csv(rows)
}

/// The names of the inputs CSV's twelve input columns (`h_*` for the specular half
/// vector), in order.
#[cfg(feature = "csv")]
const INPUT_COLUMNS: [&str; 12] = [
    "na_x", "na_y", "na_z", "nb_x", "nb_y", "nb_z", "l_x", "l_y", "l_z", "h_x", "h_y", "h_z",
];

/// The inputs of every case as CSV, for readers in any language: `case,n`, the twelve
/// inputs as exact fractions (`na_x … l_z, h_x, h_y, h_z`), `s`, then the nearest
/// `f32` of each input as its bit pattern (`na_x_f32 … h_z_f32`, `0x` and 8 hex
/// digits) and the nearest `f64` likewise (`na_x_f64 … h_z_f64`, 16 hex digits), so a
/// C harness reads floats with `strtoul` and `memcpy` and parses no fraction. The
/// cells of H and s are empty where a case has no specular part.
///
/// # Panics
/// If a case's float forms do not parse (the file was not validated).
#[cfg(feature = "csv")]
pub fn inputs_csv(file: &VectorFile) -> String {
    let mut w = csv::Writer::from_writer(Vec::new());
    let mut head = vec!["case".to_string(), "n".to_string()];
    head.extend(INPUT_COLUMNS.map(String::from));
    head.push("s".into());
    for suffix in ["_f32", "_f64"] {
        head.extend(INPUT_COLUMNS.map(|c| format!("{c}{suffix}")));
    }
    w.write_record(&head).expect("writing to memory");
    for c in &file.cases {
        let h = c.specular.as_ref().map(|sp| &sp.h);
        let inputs: [Option<&VectorInput>; 4] = [Some(&c.na), Some(&c.nb), Some(&c.l), h];
        let cells = |pick: &dyn Fn(&VectorInput, usize) -> String| -> Vec<String> {
            inputs
                .iter()
                .flat_map(|v| (0..3).map(move |k| v.map_or(String::new(), |v| pick(v, k))))
                .collect()
        };
        let mut row = vec![c.id.clone(), c.n.to_string()];
        row.extend(cells(&|v, k| v.exact[k].clone()));
        row.push(
            c.specular
                .as_ref()
                .map_or(String::new(), |sp| sp.s.to_string()),
        );
        row.extend(cells(&|v, k| {
            let x: f32 = v.f32[k].parse().expect("a validated f32 input");
            format!("0x{:08x}", x.to_bits())
        }));
        row.extend(cells(&|v, k| {
            let x: f64 = v.f64[k].parse().expect("a validated f64 input");
            format!("0x{:016x}", x.to_bits())
        }));
        w.write_record(&row).expect("writing to memory");
    }
    String::from_utf8(w.into_inner().expect("writing to memory")).expect("the cells are UTF-8")
}
