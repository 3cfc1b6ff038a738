//! [`Suite`]: the published vectors for one method, run through your function and
//! judged as `check` judges them.

use super::inputs::{published, published_shapes, Float, Inputs, SETS};
use super::outcome::{self, case_inputs, Failure, Report};
use crate::conformance::check::{Criteria, Results, Tolerance};
use crate::conformance::vectors::VectorFile;
use crate::tolerance::profile::{Form, Profile};
use crate::Method;

/// The published vectors for one method, judged by one profile or tolerance.
#[derive(Clone, Debug)]
pub struct Suite {
    sets: Vec<&'static str>,
    method: Method,
    profile: Profile,
    form: Form,
    tolerance: Option<Tolerance>,
    specular: bool,
    /// One case only ([`Suite::case`]).
    case: Option<String>,
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
            method: Method::PAPER,
            profile: Profile::Ieee,
            form: Form::Any,
            tolerance: None,
            specular: false,
            case: None,
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

    /// One case only, by id (`edge-003`), to rerun the one a report names; an id no
    /// chosen set holds gives a report that fails, naming it.
    ///
    /// ```
    /// use phong_approx::testkit::prelude::*;
    /// let r = Suite::published().case("paper-001").check_f64(|s| vec![0.0; s.n as usize + 1]);
    /// assert_eq!(r.cases(), 1);
    /// assert_eq!(r.worst().unwrap().case, "paper-001");
    /// ```
    pub fn case(mut self, id: &str) -> Suite {
        self.case = Some(id.to_string());
        self
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

    /// The form your implementation computes ([`Form`]): for Euler and corrected
    /// Euler, whose recurrences and closed forms have theorems of their own, the
    /// profile's bound is then that form's alone — a closed form's does not grow with
    /// `n`. Undeclared ([`Form::Any`]), the bound is the largest over every form. A
    /// declared form for another method gives a report that fails, saying so.
    ///
    /// ```
    /// use phong_approx::testkit::prelude::*;
    /// // Corrected Euler in closed form, p_a + i·(t0 + (i − 1)/2·ds), in f64.
    /// let r = Suite::published().form(Form::Closed).check_f64(|s| {
    ///     let d = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    ///     let n = f64::from(s.n);
    ///     let k = [0, 1, 2].map(|j| (s.nb[j] - s.na[j]) / n);
    ///     let (a, pa, pb) = (d(k, s.l), d(s.na, s.l), d(s.nb, s.l));
    ///     let (c, dd) = (d(k, k), 2.0 * d(k, s.na));
    ///     let dia = a - pa / 2.0 * dd;
    ///     let dib = a - pb / 2.0 * (2.0 * n * c + dd);
    ///     let ds = (dib - dia) / n;
    ///     let pn = pa + n * dia + n * (n - 1.0) / 2.0 * ds;
    ///     let t0 = dia - (pn - pb) / n;
    ///     (0..=s.n)
    ///         .map(|i| {
    ///             let i = f64::from(i);
    ///             pa + i * (t0 + (i - 1.0) / 2.0 * ds)
    ///         })
    ///         .collect()
    /// });
    /// assert!(r.is_ok(), "{r}");
    /// ```
    pub fn form(mut self, form: Form) -> Suite {
        self.form = form;
        self
    }

    /// A tolerance of your own instead of the profile's bound (`levels`, `abs`,
    /// `ulps`).
    pub fn tolerance(mut self, tolerance: Tolerance) -> Suite {
        self.tolerance = Some(tolerance);
        self
    }

    /// The specular cases instead of the diffuse ones: each case with a specular part
    /// gives your function the half vector [`Inputs::h`] and shininess [`Inputs::s`],
    /// and takes back `max(0, v_i)^s` with `v_i` your method's values on `N·H` (the
    /// same as `phong-approx check --specular`). Judged by the `ieee` and `reference`
    /// bounds raised to the power (`docs/float.md` §18.6) or a tolerance; the `shader`
    /// and fixed-point profiles do not model the power, and their reports say so.
    ///
    /// ```
    /// use phong_approx::testkit::prelude::*;
    /// // Gouraud's specular in f64: interpolate N·H, then raise it.
    /// let r = Suite::published().method(Method::Gouraud).specular().check_f64(|s| {
    ///     let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    ///     let h = s.h.unwrap();
    ///     let (pa, pb) = (dot(s.na, h), dot(s.nb, h));
    ///     (0..=s.n)
    ///         .map(|i| (pa + (pb - pa) * f64::from(i) / f64::from(s.n)).max(0.0).powi(s.s.unwrap() as i32))
    ///         .collect()
    /// });
    /// assert!(r.is_ok(), "{r}");
    /// assert!(r.cases() > 0);
    /// ```
    pub fn specular(mut self) -> Suite {
        self.specular = true;
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

    /// What judges the results, in words.
    fn judged_by(&self) -> String {
        match self.tolerance {
            Some(t) => format!("tolerance {t}"),
            None if self.form == Form::Any => format!("the {} profile's bound", self.profile),
            None => format!(
                "the {} profile's bound for the {} form",
                self.profile, self.form
            ),
        }
    }

    fn run<T: Float, F: FnMut(&Inputs<T>) -> Vec<T>>(&self, mut shade: F) -> Report {
        let judged_by = self.judged_by();
        let tol = self.tolerance.unwrap_or(Tolerance::Profile {
            profile: self.profile,
            format: T::FORMAT,
            form: self.form,
        });
        let mut report = Report::new(self.method, judged_by.clone(), T::FORMAT.name());
        if let Some(name) = &self.unknown_set {
            report.add_failure(Failure::of_suite(
                "?",
                format!("(set '{name}')"),
                &judged_by,
                format!("no published set '{name}' (there are {})", SETS.join(", ")),
            ));
        }
        let mut found = false;
        for set in &self.sets {
            let (Some(file), Some(shapes)) = (published(set), published_shapes(set)) else {
                continue;
            };
            let chosen;
            let chosen_shapes;
            let (file, shapes) = match &self.case {
                None => (file, shapes),
                Some(id) => {
                    let Some(k) = file.cases.iter().position(|c| &c.id == id) else {
                        continue;
                    };
                    let cases = vec![file.cases[k].clone()];
                    chosen = crate::conformance::vectors::file_of(&file.set, cases);
                    chosen_shapes = [shapes[k]];
                    (&chosen, &chosen_shapes[..])
                }
            };
            found = true;
            let criteria = Criteria::new(self.method, tol)
                .specular(self.specular)
                .in_format(T::FORMAT);
            judge(&mut report, set, file, shapes, &criteria, &mut shade);
        }
        if let (Some(id), false) = (&self.case, found) {
            report.add_failure(Failure::of_suite(
                "?",
                format!("(case '{}')", crate::error::shown(id)),
                &judged_by,
                format!(
                    "no case '{}' in the chosen sets ({})",
                    crate::error::shown(id),
                    self.sets.join(", ")
                ),
            ));
        }
        report
    }
}

/// Runs `shade` on every case of `file` (the specular ones where `criteria` are
/// specular), judges the values as `check` does, and adds the set to `report`.
pub(crate) fn judge<T: Float>(
    report: &mut Report,
    set: &'static str,
    file: &VectorFile,
    shapes: &[Option<crate::tolerance::Shape>],
    criteria: &Criteria,
    shade: &mut dyn FnMut(&Inputs<T>) -> Vec<T>,
) {
    let specular = criteria.specular;
    let mut results = Results::new();
    for c in file
        .cases
        .iter()
        .filter(|c| !specular || c.specular.is_some())
    {
        let got: Vec<f64> = shade(&case_inputs::<T>(c))
            .into_iter()
            .map(T::to_f64)
            .collect();
        results.insert(c.id.clone(), got);
    }
    let judged_by = report.judged_by.clone();
    let judged = match crate::conformance::judgement::judge(file, shapes, &results, criteria) {
        Ok(j) => j,
        // A method the published sets do not hold (a cosine table of another size), or
        // a tolerance that means nothing: a failure, not a panic.
        Err(e) => {
            report.add_failure(Failure::of_suite(
                set,
                format!("(the {set} set)"),
                &judged_by,
                e.to_string(),
            ));
            return;
        }
    };
    let j = outcome::Judged {
        set,
        key: &judged.key,
        profile: &judged_by,
        specular,
        format: T::FORMAT,
    };
    let failures = judged
        .failing()
        .into_iter()
        .map(|(c, r, got)| Failure::new::<T>(&j, c, r, got))
        .collect();
    report.add_set(set, &judged.reports, failures);
}
