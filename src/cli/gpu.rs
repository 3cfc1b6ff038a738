//! `phong-approx gpu-check`: a compute kernel (WGSL, SPIR-V, GLSL) run on a GPU adapter
//! over every published case and judged as `check` judges results; `--builtin` runs
//! this repository's kernels (`harness/gpu/`) and tells what the driver did.

use super::CliError;
use clap::Args;
use phong_approx::tolerance::profile::{Form, Profile};
use phong_approx::Method;

/// Arguments of `phong-approx gpu-check`.
#[derive(Args, Debug)]
pub struct GpuCheckArgs {
    /// Your kernel: `.wgsl`, `.spv`, or `.comp`/`.glsl` (GLSL, compiled by
    /// glslangValidator). The interface (entry point `main`, `@workgroup_size(64)`,
    /// bindings 0 spans, 1 pixel_span, 2 out): docs/conformance.md §6.
    #[arg(
        long,
        value_name = "FILE",
        required_unless_present = "builtin",
        conflicts_with = "builtin"
    )]
    pub shader: Option<String>,
    /// The method your kernel computes.
    #[arg(long, value_name = "NAME", required_unless_present = "builtin",
          help = super::methods_help(), value_parser = |s: &str| s.parse::<Method>())]
    pub method: Option<Method>,
    /// This repository's kernels instead (harness/gpu/): each judged under shader and
    /// ieee, and compared with its own source evaluated on the CPU; exit 0 when every
    /// correct kernel passes shader and both planted bugs fail.
    #[arg(long)]
    pub builtin: bool,
    /// The profile that judges your kernel: shader (the default: Vulkan/WGSL 32-bit
    /// rules), ieee or reference.
    #[arg(long, value_name = "NAME", default_value = "shader",
          value_parser = |s: &str| s.parse::<Profile>())]
    pub profile: Profile,
    /// The form your kernel computes, for the profile's bound (as `check --form`): any
    /// (the default: the largest bound over every form), recurrence or closed. For
    /// euler and corrected-euler a closed form's bound does not grow with n, so a
    /// closed-form kernel declared closed is judged by it; other methods take any.
    #[arg(long, value_name = "FORM", default_value = "any",
          value_parser = |s: &str| s.parse::<Form>())]
    pub form: Form,
    /// Also write the verdict for a CI system: `--report junit FILE` or `--report json
    /// FILE` (FILE `-`: standard output), as `check` does: an existing file only if it
    /// is a report of this tool, or with --force.
    #[arg(long, num_args = 2, value_names = ["FORMAT", "FILE"])]
    pub report: Option<Vec<String>>,
    /// Let --report replace an existing file that is not a report of this tool.
    #[arg(long)]
    pub force: bool,
    /// The most the dispatch may take, in seconds (1 to 3600).
    #[arg(long, value_name = "SECONDS", default_value = "60",
          value_parser = |s: &str| super::whole(s, 1, 3600, "the timeout"))]
    pub timeout: u32,
}

/// Runs `phong-approx gpu-check`: exit 0 when the kernel passes, 1 when it does not, 2
/// on bad input (the kernel does not compile, lacks the interface, does not finish in
/// time) or when there is no GPU adapter.
///
/// # Errors
/// A [`CliError`] with code 2 for bad input, 1 for values out of tolerance.
#[cfg(not(feature = "gpu"))]
pub fn run(_: &GpuCheckArgs) -> Result<(), CliError> {
    Err(CliError {
        message: "this phong-approx was built without the GPU runner: build it with `cargo build --release --features gpu` (Vulkan drivers needed at run time; Debian: mesa-vulkan-drivers)".into(),
        code: 2, details: Vec::new() })
}

#[cfg(feature = "gpu")]
pub use with_gpu::run;

#[cfg(feature = "gpu")]
mod with_gpu {
    use super::{CliError, GpuCheckArgs};
    use crate::cli::check::{ReportArg, ReportFormat};
    use phong_approx::conformance::check::{CaseReport, Criteria, Results, Tolerance};
    use phong_approx::conformance::judgement::{judge, Judgement};
    use phong_approx::conformance::vectors::method_key;
    use phong_approx::conformance::verdict;
    use phong_approx::gpu::kernels::{Kernel, Language, KERNELS};
    use phong_approx::gpu::{published_spans, unwritten, Gpu, GpuError, Source};
    use phong_approx::testkit::{published, published_shapes, SETS};
    use phong_approx::tolerance::profile::{Form, Profile};
    use phong_approx::{Format, Method};
    use std::time::{Duration, Instant};

    /// A [`GpuError`] as the command's failure: the first line names the problem; a
    /// compiler's messages follow on standard error, their line numbers kept.
    fn gpu_error(e: GpuError) -> CliError {
        let text = e.to_string();
        let mut lines = text.lines();
        let first = lines.next().unwrap_or("").to_string();
        CliError {
            message: first,
            code: 2,
            details: lines.map(str::to_string).collect(),
        }
    }

    /// A kernel's run: its values as `check` reads them, the same as `f32` by case id,
    /// and the seconds the device took.
    type Run = (Results, Vec<(String, Vec<f32>)>, f64);

    /// One kernel's values over every published case, by id, and the time it took.
    fn values(gpu: &Gpu, source: &Source, name: &str, timeout: Duration) -> Result<Run, CliError> {
        let spans = published_spans();
        let inputs: Vec<_> = spans.iter().map(|(_, s)| s.clone()).collect();
        let start = Instant::now();
        let got = gpu.run(source, name, &inputs, timeout).map_err(gpu_error)?;
        let seconds = start.elapsed().as_secs_f64();
        let mut results = Results::new();
        let mut raw = Vec::new();
        for ((_, s), v) in spans.iter().zip(got) {
            results.insert(s.id.to_string(), v.iter().map(|x| f64::from(*x)).collect());
            raw.push((s.id.to_string(), v));
        }
        Ok((results, raw, seconds))
    }

    /// Judges `results` set by set; the reports per set.
    /// Each published set's judgement of the kernel's results.
    type Sets<'a> = Vec<(&'static str, Judgement<'a>)>;

    fn judge_sets(
        results: &Results,
        method: Method,
        profile: Profile,
        form: Form,
    ) -> Result<Sets<'_>, CliError> {
        let tol = Tolerance::Profile {
            profile,
            format: Format::Binary32,
            form,
        };
        SETS.iter()
            .filter_map(|set| Some((*set, published(set)?, published_shapes(set)?)))
            .map(|(set, file, shapes)| {
                judge(file, shapes, results, &Criteria::new(method, tol))
                    .map(|j| (set, j))
                    .map_err(|e| crate::cli::judge_error(e, "--profile"))
            })
            .collect()
    }

    fn worst(sets: &Sets) -> f64 {
        sets.iter()
            .flat_map(|(_, j)| j.reports.iter().map(|c| c.ratio))
            .fold(0.0, f64::max)
    }

    fn passes(sets: &Sets) -> bool {
        sets.iter().all(|(_, j)| j.passes())
    }

    /// Runs the command.
    ///
    /// # Errors
    /// See [`super::run`].
    pub fn run(a: &GpuCheckArgs) -> Result<(), CliError> {
        if a.form != Form::Any && !Form::applies_to(a.method.unwrap_or(Method::Gouraud)) {
            return Err(CliError::arg(
                "--form",
                "a declared form tells apart only euler's and corrected-euler's theorems: this method takes --form any",
            ));
        }
        if matches!(a.profile, Profile::Fixed { .. }) {
            return Err(CliError::arg(
                "--profile",
                "a kernel computes in 32-bit floats: shader, ieee or reference",
            ));
        }
        // Read (and refused) before the device is opened.
        let report = ReportArg::parse(a.report.as_deref(), a.force)?;
        if let Some(r) = &report {
            r.check(&[a.shader.as_deref().unwrap_or("-")])?;
        }
        let timeout = Duration::from_secs(u64::from(a.timeout));
        // The kernel is read (and GLSL compiled) before the device is opened: a bad
        // file is bad input whether or not there is a GPU.
        let user = match &a.shader {
            Some(path) => Some(Source::from_file(std::path::Path::new(path)).map_err(gpu_error)?),
            None => None,
        };
        if std::env::var_os("XDG_RUNTIME_DIR").is_none() {
            // Mesa's drivers complain on every start without one (a headless machine,
            // a container); the folder is not used for computing.
            std::env::set_var("XDG_RUNTIME_DIR", std::env::temp_dir());
        }
        let gpu = Gpu::new().map_err(gpu_error)?;
        let adapter = gpu.adapter().to_string();
        let device = Device {
            gpu: &gpu,
            adapter: &adapter,
            timeout,
        };
        match (user, &a.shader, a.method) {
            (Some(source), Some(path), Some(method)) => {
                user_kernel(a, report.as_ref(), &device, &source, path, method)
            }
            _ => builtin(&device),
        }
    }

    /// The device a run uses: the GPU, its adapter's name and the time an invocation
    /// may take.
    struct Device<'a> {
        gpu: &'a Gpu,
        adapter: &'a str,
        timeout: Duration,
    }

    fn user_kernel(
        a: &GpuCheckArgs,
        report: Option<&ReportArg>,
        device: &Device,
        source: &Source,
        path: &str,
        method: Method,
    ) -> Result<(), CliError> {
        let Device {
            gpu,
            adapter,
            timeout,
        } = *device;
        let human = crate::cli::check::human_verdict(report);
        human(&format!("adapter: {adapter}\n"))?;
        let (results, raw, seconds) = values(gpu, source, path, timeout)?;
        human(&format!(
            "kernel: {path}, {} cases, {:.3} s on the device\n",
            results.len(),
            seconds
        ))?;
        let missing: usize = raw.iter().map(|(_, v)| unwritten(v)).sum();
        if missing > 0 {
            human(&format!(
                "{missing} pixels were never written by the kernel (a loop the driver cut short: lavapipe stops an invocation's loops after about 65535 iterations in all; a workgroup size other than 64; an early return; a struct layout other than the interface's, such as a vec3 where it has a vec4, which moves every later field: docs/conformance.md §6)\n"
            ))?;
        }
        let sets = judge_sets(&results, method, a.profile, a.form)?;
        for (_, j) in &sets {
            human(&j.text(advice))?;
        }
        human(&format!(
            "tolerance: the {} profile's bound for f32 (docs/float.md §18)\n",
            a.profile
        ))?;
        if let Some(r) = report {
            r.write(
                &write_report(r.format, &sets, method, a.profile, adapter),
                &[path],
            )?;
        }
        let all: Vec<CaseReport> = sets.into_iter().flat_map(|(_, j)| j.reports).collect();
        // A pixel the kernel never wrote is told apart from one it wrote as NaN or
        // infinity (both are not finite to the verdict).
        let never = |message: String| {
            match verdict::worst(&all) {
            Some(w) => match w.not_finite {
                Some(p)
                    if raw
                        .iter()
                        .find(|(id, _)| *id == w.id)
                        .and_then(|(_, v)| v.get(p))
                        .is_some_and(|x| x.to_bits() == phong_approx::gpu::UNWRITTEN) =>
                {
                    message.replace(
                        &format!("(pixel {p} is not finite)"),
                        &format!("(pixel {p} was never written by the kernel: {missing} pixels in all, see above)"),
                    )
                }
                _ => message,
            },
            None => message,
        }
        };
        human(&format!(
            "{}\n",
            never(verdict::verdict_line(
                &all,
                &format!(
                    "{} on {adapter}, {} profile, f32, sets {}",
                    method_key(method),
                    a.profile,
                    SETS.join(", ")
                )
            ))
        ))?;
        match verdict::failure(&all) {
            None => Ok(()),
            Some(message) => Err(CliError {
                message: never(message),
                code: 1,
                details: Vec::new(),
            }),
        }
    }

    /// What `gpu-check` tells its user to do about a case with no bound: its own
    /// options only (it has no `--tolerance`; `check` has).
    fn advice(u: &phong_approx::conformance::check::Unbounded) -> Option<&'static str> {
        use phong_approx::conformance::check::Unbounded;
        match u {
            Unbounded::NoBound { .. } => Some(
                "--profile reference judges this crate's own evaluation; for a tolerance of your own, write the kernel's values to a file and run `phong-approx check --tolerance`",
            ),
            Unbounded::SpecularNotModelled { .. }
            | Unbounded::OutOfRange { .. }
            | Unbounded::NoDerivedBound => Some(
                "for a tolerance of your own, write the kernel's values to a file and run `phong-approx check --tolerance`",
            ),
            _ => None,
        }
    }

    /// The report over the three sets: JUnit with one `<testsuite>` per set, or a JSON
    /// object holding the adapter and each set's `check` report.
    fn write_report(
        format: ReportFormat,
        sets: &Sets,
        method: Method,
        profile: Profile,
        adapter: &str,
    ) -> String {
        let key = method_key(method);
        let suite = |set: &str| format!("{set} {key} {profile} profile (f32) on {adapter}");
        if format == ReportFormat::Json {
            let per: Vec<serde_json::Value> = sets
                .iter()
                .map(|(set, j)| {
                    serde_json::from_str(&j.json(&suite(set), advice))
                        .unwrap_or(serde_json::Value::Null)
                })
                .collect();
            let v = serde_json::json!({
                "generator": concat!("phong-approx ", env!("CARGO_PKG_VERSION"), " gpu-check"),
                "adapter": adapter,
                "sets": per,
            });
            return serde_json::to_string_pretty(&v).unwrap_or_default() + "\n";
        }
        let (mut tests, mut failures, mut body) = (0, 0, String::new());
        for (set, j) in sets {
            let one = j.junit(&suite(set), advice);
            tests += j.reports.len();
            failures += j.reports.iter().filter(|c| !c.pass).count();
            // Keep the <testsuite> element: the lines between <testsuites> and its end.
            let lines: Vec<&str> = one.lines().collect();
            for l in &lines[2..lines.len() - 1] {
                body += l;
                body += "\n";
            }
        }
        format!(
            "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"phong-approx gpu-check\" tests=\"{tests}\" failures=\"{failures}\">\n{body}</testsuites>\n"
        )
    }

    /// Ordered distance in ulps between two finite `f32`.
    fn ulps(a: f32, b: f32) -> u64 {
        let key = |x: f32| {
            let b = x.to_bits() as i32;
            i64::from(if b < 0 { i32::MIN - b } else { b })
        };
        key(a).abs_diff(key(b))
    }

    /// Every kernel of `harness/gpu/`: the table of docs/conformance.md §6.
    fn builtin(device: &Device) -> Result<(), CliError> {
        let Device {
            gpu,
            adapter,
            timeout,
        } = *device;
        outln!("adapter: {adapter}")?;
        outln!("| kernel | method | form | shader: worst × allowed | ieee: worst × allowed | pixels ≠ CPU | largest difference | of the shader bound |")?;
        outln!("|---|---|---|---|---|---|---|---|")?;
        let mut wrong = Vec::new();
        let spans = published_spans();
        for k in KERNELS {
            let source = match k.language {
                Language::Wgsl => Source::Wgsl(k.text.to_string()),
                Language::Glsl => Source::glsl(k.text, k.file).map_err(gpu_error)?,
            };
            let (results, raw, _) = values(gpu, &source, k.file, timeout)?;
            let shader = judge_sets(&results, k.method, Profile::Shader, Form::Any)?;
            let ieee = judge_sets(&results, k.method, Profile::Ieee, Form::Any)?;
            let (differ, max_ulps, of_bound) = differences(&k, &spans, &raw, &shader);
            let verdict = |sets: &Sets| {
                format!(
                    "{} {}",
                    ratio(worst(sets)),
                    if passes(sets) { "pass" } else { "**fail**" }
                )
            };
            let pixels: usize = raw.iter().map(|(_, v)| v.len()).sum();
            outln!(
                "| `{}` | {} | {} | {} | {} | {differ} of {pixels} | {max_ulps} ulp | {} |",
                k.name(),
                k.method.name(),
                k.form,
                verdict(&shader),
                verdict(&ieee),
                if differ == 0 {
                    "0".to_string()
                } else {
                    format!("{of_bound:.2e}")
                }
            )?;
            if passes(&shader) == k.mutant {
                wrong.push(format!(
                    "{} {} under shader",
                    k.file,
                    if k.mutant { "passes" } else { "fails" }
                ));
            }
        }
        outln!("(shader and ieee: the largest |GPU − exact| over the allowed error, every published case; pixels ≠ CPU: values that differ from the kernel's source evaluated on the CPU in round-to-nearest f32 without contraction; the largest difference between the two in ulps of f32, and over the shader bound of its case)")?;
        let mutants = KERNELS.iter().filter(|k| k.mutant).count();
        let good = KERNELS.len() - mutants;
        if wrong.is_empty() {
            outln!("PASS: all {good} correct kernels pass under shader and all {mutants} planted bugs fail (on {adapter})")?;
            Ok(())
        } else {
            outln!(
                "FAIL: {} of {} kernels got the wrong verdict: {} (on {adapter})",
                wrong.len(),
                KERNELS.len(),
                wrong.join("; ")
            )?;
            Err(CliError {
                message: format!("wrong verdicts: {}", wrong.join("; ")),
                code: 1,
                details: Vec::new(),
            })
        }
    }

    /// How a kernel's device values differ from its source on the CPU: pixels, the
    /// largest difference in ulps, and the largest difference over its case's shader
    /// bound.
    fn differences(
        k: &Kernel,
        spans: &[(&str, phong_approx::testkit::Inputs<'static, f32>)],
        raw: &[(String, Vec<f32>)],
        shader: &Sets,
    ) -> (usize, u64, f64) {
        let allowed: std::collections::HashMap<&str, f64> = shader
            .iter()
            .flat_map(|(_, j)| j.reports.iter())
            .filter_map(|c| Some((c.id.as_str(), c.allowed_abs?)))
            .collect();
        let (mut differ, mut max_ulps, mut of_bound) = (0, 0, 0.0f64);
        for ((_, s), (id, got)) in spans.iter().zip(raw) {
            let cpu = k.cpu(s);
            for (g, c) in got.iter().zip(&cpu) {
                if g.to_bits() != c.to_bits() {
                    differ += 1;
                    if g.is_finite() && c.is_finite() {
                        max_ulps = max_ulps.max(ulps(*g, *c));
                        if let Some(b) = allowed.get(id.as_str()) {
                            of_bound = of_bound.max((f64::from(*g) - f64::from(*c)).abs() / b);
                        }
                    }
                }
            }
        }
        (differ, max_ulps, of_bound)
    }

    /// A ratio to allowed in three digits, `∞` where infinite.
    fn ratio(r: f64) -> String {
        if r.is_finite() {
            format!("{r:.3}")
        } else {
            "∞".into()
        }
    }
}
