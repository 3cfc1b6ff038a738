//! A vector file read for its inputs only (`check --allow-modified-vectors`): the
//! cases' inputs, checked against their nearest floats, and the expectations recomputed
//! with the exact reference.

use super::*;

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
fn same_floats(theirs: &VectorInput, ours: &VectorInput) -> Result<(), VectorError> {
    for i in 0..3 {
        let t32 = theirs.f32[i].trim().parse::<f32>();
        let t64 = theirs.f64[i].trim().parse::<f64>();
        let o32 = ours.f32[i].parse::<f32>();
        let o64 = ours.f64[i].parse::<f64>();
        if t32.ok().map(f32::to_bits) != o32.ok().map(f32::to_bits) {
            return Err(VectorError::file(format!(
                "component {}: the f32 form '{}' is not the nearest f32 to the exact value ({})",
                i + 1,
                crate::conformance::shown(&theirs.f32[i]),
                ours.f32[i]
            )));
        }
        if t64.ok().map(f64::to_bits) != o64.ok().map(f64::to_bits) {
            return Err(VectorError::file(format!(
                "component {}: the f64 form '{}' is not the nearest f64 to the exact value ({})",
                i + 1,
                crate::conformance::shown(&theirs.f64[i]),
                ours.f64[i]
            )));
        }
    }
    Ok(())
}

impl InputsFile {
    /// The file with the expectations of `method` computed from each case's inputs by
    /// the exact reference (with `specular`, also the specular ones for cases that
    /// have a half vector; without, the half vectors are dropped unread);
    /// `q_min`, `δ` and the adaptive decision are the span's. The result passes
    /// [`crate::conformance::integrity::validate`] whenever the inputs are valid.
    ///
    /// # Errors
    /// A case whose inputs are not exact unit vectors, whose `n` is out of range, whose
    /// shininess is outside `1..=`[`MAX_SHININESS`] (checked for every case before any
    /// work), or whose level or digits the exact run cannot decide (named).
    pub fn recompute(&self, method: Method, specular: bool) -> Result<VectorFile, VectorError> {
        if let Some(c) = self.cases.iter().find(|c| {
            c.specular
                .as_ref()
                .is_some_and(|sp| sp.s == 0 || sp.s > MAX_SHININESS)
        }) {
            return Err(VectorError::case(
                &crate::conformance::shown(&c.id),
                format!(
                    "shininess {} is outside 1..={MAX_SHININESS}",
                    c.specular.as_ref().map_or(0, |sp| sp.s)
                ),
            ));
        }
        let v = |c: &CaseInputs, x: &VectorInput, what: &str| {
            exact_input(x).ok_or_else(|| {
                VectorError::case(
                    &crate::conformance::shown(&c.id),
                    format!("{what} is not three exact numbers"),
                )
            })
        };
        let mut cases = Vec::with_capacity(self.cases.len());
        for c in &self.cases {
            if c.n == 0 || c.n > MAX_CASE_STEPS {
                return Err(VectorError::case(
                    &crate::conformance::shown(&c.id),
                    format!("n = {} is outside 1..={MAX_CASE_STEPS}", c.n),
                ));
            }
            let h = match &c.specular {
                Some(sp) if specular => Some((v(c, &sp.h, "h")?, sp.s)),
                _ => None,
            };
            // The adaptive scheme is judged against both of its methods where its test
            // is too close to call (`check::check_in`): their expectations too.
            let methods = method.with_picks();
            let exact = ExactCase {
                id: c.id.clone(),
                comment: &c.comment,
                na: v(c, &c.na, "na")?,
                nb: v(c, &c.nb, "nb")?,
                l: v(c, &c.l, "l")?,
                n: c.n,
                h,
            };
            let case = compute_case_for(&methods, exact)?;
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
                same_floats(theirs, ours).map_err(|e| {
                    VectorError::case(
                        &crate::conformance::shown(&c.id),
                        format!("{what}: {}", e.problem),
                    )
                })?;
            }
            cases.push(case);
        }
        Ok(VectorFile {
            version: self.version.clone(),
            generator: String::new(),
            set: self.set.clone(),
            notes: String::new(),
            methods: method.with_picks().into_iter().map(method_key).collect(),
            number_of_cases: self.number_of_cases,
            cases,
        })
    }
}
