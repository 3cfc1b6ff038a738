//! One verdict, as data: the vector file, the results, what judged them and a report
//! per case, built once by [`judge`] — for `check`, the test kit and the GPU runner
//! alike — and rendered by each caller: as text ([`Judgement::text`]), as JUnit or
//! JSON ([`Judgement::junit`], [`Judgement::json`], in `export.rs`), as a one-line failure
//! ([`Judgement::failure`]) or case by case ([`Judgement::failing`]).

use super::check::{check_in, Advice, CaseReport, Criteria, JudgeError, Results, Tolerance};
use super::vectors::{Case, VectorFile};
use crate::tolerance::Shape;
use crate::{Format, Method};
use std::collections::HashMap;

/// A judged set: the file and the results it judged, how, and the verdict per case.
#[derive(Clone, Debug)]
pub struct Judgement<'a> {
    /// The vector file.
    pub vectors: &'a VectorFile,
    /// The results judged, by case id.
    pub results: &'a Results,
    /// The method.
    pub method: Method,
    /// Its key in the vector files.
    pub key: String,
    /// What judged the results.
    pub tolerance: Tolerance,
    /// Whether the specular cases were judged (else the diffuse ones).
    pub specular: bool,
    /// The implementation's float format (its ulps in the reports).
    pub format: Format,
    /// The verdict per case, in the file's order.
    pub reports: Vec<CaseReport>,
}

/// Judges `results` against `vectors` by `criteria` ([`check_in`]): the one verdict
/// every caller renders. `shapes`: the file's exact spans' ([`super::check::shapes`],
/// or what [`super::integrity::validate`] or [`super::verdict::load_vectors`] read).
///
/// # Errors
/// As [`check_in`]: a method the file does not hold, a tolerance that means nothing.
pub fn judge<'a>(
    vectors: &'a VectorFile,
    shapes: &[Option<Shape>],
    results: &'a Results,
    criteria: &Criteria,
) -> Result<Judgement<'a>, JudgeError> {
    let reports = check_in(vectors, shapes, results, criteria)?;
    Ok(Judgement {
        vectors,
        results,
        method: criteria.method,
        key: criteria.key(),
        tolerance: criteria.tolerance,
        specular: criteria.specular,
        format: criteria.format,
        reports,
    })
}

impl Judgement<'_> {
    /// Whether every case passed.
    pub fn passes(&self) -> bool {
        self.reports.iter().all(|r| r.pass)
    }

    /// The verdict as text: a heading line, a Markdown table with a row per case, the
    /// overall figures and the worst case with its inputs; a case with no bound says
    /// why, with `advice`.
    pub fn text(&self, advice: Advice) -> String {
        super::verdict::text(
            self.vectors,
            &self.reports,
            self.results,
            &self.key,
            self.specular,
            advice,
        )
    }

    /// The one-line message of a failed check ([`super::verdict::failure`]); `None`
    /// when every case passes.
    pub fn failure(&self) -> Option<String> {
        super::verdict::failure(&self.reports)
    }

    /// Each failing case with its report and the values judged, in the file's order
    /// (cases found by id once, not searched per case).
    pub fn failing(&self) -> Vec<(&Case, &CaseReport, &[f64])> {
        let by_id: HashMap<&str, &Case> = self
            .vectors
            .cases
            .iter()
            .map(|c| (c.id.as_str(), c))
            .collect();
        self.reports
            .iter()
            .filter(|r| !r.pass)
            .filter_map(|r| {
                let c = by_id.get(r.id.as_str())?;
                Some((*c, r, self.results.get(&r.id)?.as_slice()))
            })
            .collect()
    }
}
