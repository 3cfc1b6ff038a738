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

mod compute;
mod inputs;
mod sets;
#[cfg(feature = "csv")]
mod twins;

pub(crate) use compute::case_for_span;
use compute::{compute_case_for, make_case, ExactCase};
pub use compute::{CaseSpec, MAX_SHININESS};
pub use inputs::{exact_input, CaseInputs, InputsFile, SpecularInputs};
pub use sets::specs;
#[cfg(feature = "csv")]
pub use twins::{inputs_csv, to_csv};

/// The largest `n` of a case `check` accepts (the published sets go to 4096).
pub const MAX_CASE_STEPS: u32 = 65_536;

/// Version of the vector format (semantic: a major change breaks readers).
pub const FORMAT_VERSION: &str = "1.3.0";

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

/// What is wrong with a vector file: the case at fault (`None` for the file as a
/// whole: its version, its case count, its method list) and the problem in words.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub struct VectorError {
    /// The id of the case at fault, if one is.
    pub case: Option<String>,
    /// The problem, in words.
    pub problem: String,
}

impl std::fmt::Display for VectorError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match &self.case {
            Some(id) => write!(f, "case {id}: {}", self.problem),
            None => f.write_str(&self.problem),
        }
    }
}

impl std::error::Error for VectorError {}

impl VectorError {
    /// A problem of the case `id`.
    pub fn case(id: &str, problem: impl Into<String>) -> Self {
        VectorError {
            case: Some(id.to_string()),
            problem: problem.into(),
        }
    }

    /// A problem of the file as a whole.
    pub fn file(problem: impl Into<String>) -> Self {
        VectorError {
            case: None,
            problem: problem.into(),
        }
    }
}

/// Generates the vector file of `set`.
///
/// # Errors
/// The unknown set's name; a case whose level at some pixel the exact run cannot
/// decide (named, with the method and pixel).
pub fn generate(set: &str) -> Result<VectorFile, VectorError> {
    let cases = specs(set)?
        .into_iter()
        .map(CaseSpec::compute)
        .collect::<Result<Vec<Case>, _>>()?;
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
