//! The paper's methods as real shader kernels (`harness/gpu/`), run on a GPU adapter
//! through `wgpu` — lavapipe, Mesa's Vulkan driver on the CPU, in CI — and judged by
//! the test kit; and `phong-approx gpu-check` on kernels good, broken and bad.
//!
//! Feature `gpu` (and `cli`). These tests need a Vulkan adapter: without one they fail
//! naming what to install (Debian: `mesa-vulkan-drivers`; the GLSL ones need
//! `glslang-tools`). CI runs them as a stage of their own (`.ci/run`); every test is in
//! `on_device` so that the other stages can leave them out (`--skip on_device::`).

mod on_device {
    use phong_approx::gpu::kernels::{Language, KERNELS};
    use phong_approx::gpu::{judge, published_spans, unwritten, Gpu, Source};
    use phong_approx::tolerance::profile::Profile;
    use std::collections::HashMap;
    use std::path::{Path, PathBuf};
    use std::process::{Command, Output};
    use std::sync::OnceLock;
    use std::time::Duration;

    const TIMEOUT: Duration = Duration::from_secs(60);

    /// The device, opened once for the whole binary (tests share it under a lock).
    fn gpu() -> std::sync::MutexGuard<'static, Gpu> {
        static GPU: OnceLock<std::sync::Mutex<Gpu>> = OnceLock::new();
        GPU.get_or_init(|| match Gpu::new() {
            Ok(g) => std::sync::Mutex::new(g),
            Err(e) => panic!("{e}"),
        })
        .lock()
        .unwrap_or_else(|p| p.into_inner())
    }

    fn source(k: &phong_approx::gpu::kernels::Kernel) -> Source {
        match k.language {
            Language::Wgsl => Source::Wgsl(k.text.to_string()),
            Language::Glsl => Source::glsl(k.text, k.file).unwrap_or_else(|e| panic!("{e}")),
        }
    }

    /// A kernel's values on the device, by case id.
    fn values(source: &Source, name: &str) -> HashMap<String, Vec<f32>> {
        let spans = published_spans();
        let inputs: Vec<_> = spans.iter().map(|(_, s)| s.clone()).collect();
        let got = gpu()
            .run(source, name, &inputs, TIMEOUT)
            .unwrap_or_else(|e| panic!("{e}"));
        spans
            .iter()
            .zip(got)
            .map(|((_, s), v)| (s.id.to_string(), v))
            .collect()
    }

    #[test]
    fn every_kernel_passes_shader_and_the_planted_bugs_fail_every_profile() {
        eprintln!("adapter: {}", gpu().adapter());
        for k in KERNELS {
            let v = values(&source(&k), k.file);
            assert_eq!(v.len(), 71, "{}: every published case", k.file);
            assert_eq!(
                unwritten(&v.values().flatten().copied().collect::<Vec<_>>()),
                0
            );
            let shader = judge(k.method, Profile::Shader, &v);
            let ieee = judge(k.method, Profile::Ieee, &v);
            if k.mutant {
                assert!(!shader.is_ok(), "{} passes shader", k.file);
                assert!(!ieee.is_ok(), "{} passes ieee", k.file);
                let worst = shader.worst().expect("a failure");
                assert!(worst.ratio > 100.0, "{}: {}", k.file, worst.ratio);
            } else {
                assert!(shader.is_ok(), "{} on the device:\n{shader}", k.file);
            }
        }
    }

    #[test]
    fn the_comparison_with_the_cpu_sees_a_difference() {
        // The driver-differences table compares each kernel with its own source on the
        // CPU; here the device's Gouraud against corrected Euler's source on the CPU,
        // which must differ wherever the methods do.
        let gouraud = KERNELS
            .iter()
            .find(|k| k.file.ends_with("gouraud.wgsl"))
            .unwrap();
        let ce = KERNELS
            .iter()
            .find(|k| k.file.ends_with("corrected_euler.wgsl"))
            .unwrap();
        let v = values(&source(gouraud), gouraud.file);
        let (mut differ, mut pixels) = (0, 0);
        for (_, s) in published_spans() {
            let cpu = ce.cpu(&s);
            for (g, c) in v[s.id].iter().zip(&cpu) {
                pixels += 1;
                differ += usize::from(g.to_bits() != c.to_bits());
            }
        }
        assert!(differ > pixels / 2, "{differ} of {pixels}");
    }

    fn bin() -> Command {
        let mut c = Command::new(env!("CARGO_BIN_EXE_phong-approx"));
        c.env("XDG_RUNTIME_DIR", std::env::temp_dir());
        c
    }

    fn gpu_check(shader: &Path, method: &str, extra: &[&str]) -> Output {
        let _device = gpu(); // one device at a time on the machine
        bin()
            .args(["gpu-check", "--shader"])
            .arg(shader)
            .args(["--method", method])
            .args(extra)
            .output()
            .expect("runs")
    }

    fn repo(path: &str) -> PathBuf {
        Path::new(env!("CARGO_MANIFEST_DIR")).join(path)
    }

    /// A scratch folder of this test's own.
    fn scratch(name: &str) -> PathBuf {
        let d =
            std::env::temp_dir().join(format!("phong-approx-gpu-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    /// corrected_euler.wgsl with one line replaced.
    fn edited(name: &str, from: &str, to: &str) -> PathBuf {
        let text = std::fs::read_to_string(repo("harness/gpu/corrected_euler.wgsl")).unwrap();
        assert!(text.contains(from), "{from}");
        let path = scratch(name).join(format!("{name}.wgsl"));
        std::fs::write(&path, text.replacen(from, to, 1)).unwrap();
        path
    }

    fn text(o: &Output) -> (String, String) {
        (
            String::from_utf8_lossy(&o.stdout).into_owned(),
            String::from_utf8_lossy(&o.stderr).into_owned(),
        )
    }

    #[test]
    fn the_documented_example_kernel_passes() {
        // docs/conformance.md §6 shows harness/gpu/corrected_euler.wgsl, as it is.
        let doc = std::fs::read_to_string(repo("docs/conformance.md")).unwrap();
        let kernel = std::fs::read_to_string(repo("harness/gpu/corrected_euler.wgsl")).unwrap();
        let begin = "<!-- example kernel: begin -->\n```wgsl\n";
        let shown = &doc[doc.find(begin).expect("the example's markers") + begin.len()..];
        let shown = &shown[..shown.find("```\n<!-- example kernel: end -->").unwrap()];
        assert_eq!(shown, kernel, "docs/conformance.md §6 shows another kernel");
        let o = gpu_check(
            &repo("harness/gpu/corrected_euler.wgsl"),
            "corrected-euler",
            &[],
        );
        let (out, err) = text(&o);
        assert_eq!(o.status.code(), Some(0), "{out}{err}");
        assert!(out.starts_with("adapter: "), "{out}");
        assert_eq!(out.matches(" set '").count(), 3, "{out}");
        assert!(
            out.contains("tolerance: the shader profile's bound for f32"),
            "{out}"
        );
    }

    #[test]
    fn a_broken_kernel_fails_naming_the_worst_case() {
        let o = gpu_check(
            &repo("harness/gpu/mutants/corrected_euler_eps_n1.wgsl"),
            "corrected-euler",
            &[],
        );
        let (out, err) = text(&o);
        assert_eq!(o.status.code(), Some(1), "{out}{err}");
        assert!(
            err.contains("cases out of tolerance, worst: edge-003"),
            "{err}"
        );
        assert!(out.contains("FAIL"), "{out}");
    }

    #[test]
    fn a_kernel_that_does_not_compile_exits_2_with_the_compilers_lines() {
        let bad = edited("syntax", "let pb = dot(nb, l);", "let pb = dot(nb, l)");
        let o = gpu_check(&bad, "corrected-euler", &[]);
        let (out, err) = text(&o);
        assert_eq!(o.status.code(), Some(2), "{out}{err}");
        let first = err.lines().next().unwrap();
        assert!(
            first.starts_with("phong-approx: ") && first.contains("does not compile"),
            "{err}"
        );
        assert!(
            err.contains("syntax.wgsl:37:5: parsing error: expected `;`"),
            "{err}"
        );
        assert!(err.contains("37 │     let dqb"), "{err}");
    }

    #[test]
    fn a_glsl_kernel_that_does_not_compile_exits_2_with_glslangs_lines() {
        let text_ = std::fs::read_to_string(repo("harness/gpu/gouraud.comp")).unwrap();
        let path = scratch("glsl").join("bad.comp");
        std::fs::write(&path, text_.replacen("float g = pa;", "float g = pa", 1)).unwrap();
        let o = gpu_check(&path, "gouraud", &[]);
        let (out, err) = text(&o);
        assert_eq!(o.status.code(), Some(2), "{out}{err}");
        assert!(err.contains("does not compile"), "{err}");
        assert!(err.contains("bad.comp:"), "{err}");
    }

    /// Finding 6 of the fifth reliability round: glslang's output goes to a private
    /// folder of random name that is removed afterwards, so nothing planted in the
    /// temporary folder (a link at a guessable name) is written through; and a report
    /// over a file the tool did not write is refused (finding 4).
    #[test]
    fn glsl_compiles_in_a_private_folder_and_reports_spare_users_files() {
        let tmp = scratch("tmpdir");
        let victim = scratch("victim").join("precious.txt");
        std::fs::write(&victim, "keep\n").unwrap();
        for k in 0..4 {
            std::os::unix::fs::symlink(&victim, tmp.join(format!("phong-approx-spv-{k}.spv")))
                .unwrap();
        }
        let before: Vec<_> = std::fs::read_dir(&tmp)
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        let notes = scratch("notes").join("notes.txt");
        std::fs::write(&notes, "mine\n").unwrap();
        let _device = gpu();
        let o = bin()
            .env("TMPDIR", &tmp)
            .args(["gpu-check", "--shader"])
            .arg(repo("harness/gpu/gouraud.comp"))
            .args(["--method", "gouraud", "--report", "json"])
            .arg(&notes)
            .output()
            .unwrap();
        let (out, err) = text(&o);
        assert_eq!(o.status.code(), Some(2), "{out}{err}");
        assert!(err.contains("not a report phong-approx wrote"), "{err}");
        assert_eq!(std::fs::read_to_string(&notes).unwrap(), "mine\n");
        let o = bin()
            .env("TMPDIR", &tmp)
            .args(["gpu-check", "--shader"])
            .arg(repo("harness/gpu/gouraud.comp"))
            .args(["--method", "gouraud"])
            .output()
            .unwrap();
        let (out, err) = text(&o);
        assert_eq!(o.status.code(), Some(0), "{out}{err}");
        assert!(
            out.trim_end()
                .lines()
                .last()
                .unwrap()
                .starts_with("PASS: all "),
            "{out}"
        );
        let after: Vec<_> = std::fs::read_dir(&tmp)
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        assert_eq!(before.len(), after.len(), "{after:?}");
        assert_eq!(std::fs::read_to_string(&victim).unwrap(), "keep\n");
    }

    /// `gpu-check --form` (as `check --form`): a closed-form kernel with a drift of
    /// i·10⁻⁷ fails when declared closed, whose bound does not grow with n — and,
    /// since the bounds are per pixel from the operation graphs (docs/float.md §19),
    /// undeclared too.
    #[test]
    fn a_declared_closed_form_is_judged_by_its_own_bound() {
        let source =
            std::fs::read_to_string(repo("harness/gpu/corrected_euler_closed.wgsl")).unwrap();
        let from = "out[p] = pa + f32(i) * (t0 + h);";
        assert!(source.contains(from));
        let path = scratch("form").join("drift.wgsl");
        std::fs::write(
            &path,
            source.replace(from, "out[p] = pa + f32(i) * (t0 + h) + f32(i) * 1e-7;"),
        )
        .unwrap();
        let o = gpu_check(&path, "corrected-euler", &[]);
        let (out, err) = text(&o);
        assert_eq!(o.status.code(), Some(1), "{out}{err}");
        let o = gpu_check(&path, "corrected-euler", &["--form", "closed"]);
        let (out, err) = text(&o);
        assert_eq!(o.status.code(), Some(1), "{out}{err}");
        assert!(
            out.trim_end().lines().last().unwrap().starts_with("FAIL: "),
            "{out}"
        );
        // The kernel as written passes declared closed.
        let o = gpu_check(
            &repo("harness/gpu/corrected_euler_closed.wgsl"),
            "corrected-euler",
            &["--form", "closed"],
        );
        let (out, err) = text(&o);
        assert_eq!(o.status.code(), Some(0), "{out}{err}");
        // A form for a method whose forms no theorem tells apart is refused.
        let o = gpu_check(
            &repo("harness/gpu/phong.wgsl"),
            "phong",
            &["--form", "closed"],
        );
        let (_, err) = text(&o);
        assert_eq!(o.status.code(), Some(2), "{err}");
    }

    #[test]
    fn a_spirv_module_from_glslang_passes() {
        let spv = scratch("spirv").join("gouraud.spv");
        let o = Command::new("glslangValidator")
            .arg("-V")
            .arg(repo("harness/gpu/gouraud.comp"))
            .arg("-o")
            .arg(&spv)
            .output()
            .expect("glslangValidator (Debian: glslang-tools)");
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stdout));
        let o = gpu_check(&spv, "gouraud", &[]);
        let (out, err) = text(&o);
        assert_eq!(o.status.code(), Some(0), "{out}{err}");
        assert_eq!(out.matches(" set '").count(), 3, "{out}");
    }

    #[test]
    fn a_kernel_without_the_interface_exits_2() {
        let entry = edited("entry", "fn main(", "fn shade(");
        let o = gpu_check(&entry, "corrected-euler", &[]);
        let (_, err) = text(&o);
        assert_eq!(o.status.code(), Some(2), "{err}");
        assert!(
            err.contains("does not have the interface") && err.contains("'main'"),
            "{err}"
        );
        let binding = edited(
            "binding",
            "@binding(2) var<storage, read_write> out",
            "@binding(3) var<storage, read_write> out",
        );
        let o = gpu_check(&binding, "corrected-euler", &[]);
        let (_, err) = text(&o);
        assert_eq!(o.status.code(), Some(2), "{err}");
        assert!(err.contains("binding: 3"), "{err}");
    }

    #[test]
    fn nan_values_and_unwritten_pixels_fail_the_cases() {
        // A NaN written by the kernel (a quiet NaN's bits, which no compiler can fold
        // away as it may a division by zero) reads "not finite" ...
        let nan = edited(
            "nan",
            "out[s.first + i] = pi;",
            "out[s.first + i] = bitcast<f32>(0x7fc00000u);",
        );
        let o = gpu_check(&nan, "corrected-euler", &[]);
        let (out, err) = text(&o);
        assert_eq!(o.status.code(), Some(1), "{out}{err}");
        assert!(err.contains("is not finite"), "{err}");
        assert!(!err.contains("never written"), "{err}");
        assert!(
            out.trim_end().lines().last().unwrap().starts_with("FAIL: "),
            "{out}"
        );
        // Half the pixels never written: a workgroup of 32 where the dispatch counts 64.
        let half = edited("half", "@workgroup_size(64)", "@workgroup_size(32)");
        let o = gpu_check(&half, "corrected-euler", &[]);
        let (out, err) = text(&o);
        assert_eq!(o.status.code(), Some(1), "{out}{err}");
        assert!(
            out.contains("pixels were never written by the kernel"),
            "{out}"
        );
        // ... and a pixel the kernel never wrote is told apart on stderr too.
        assert!(err.contains("was never written by the kernel"), "{err}");
    }

    #[test]
    fn a_dispatch_past_its_time_limit_exits_2() {
        // lavapipe ends an invocation's loops after about 65535 iterations in all, so the
        // slow kernel is wide instead: every pixel spins 60000 × 64 multiply-adds.
        let spin = "h = h * 1664525u + j; ".repeat(64);
        let slow = edited(
            "slow",
            "    if (p != s.first) { return; }",
            &format!(
                "    var h = p;\n    for (var j = 0u; j < 60000u; j++) {{ {spin}}}\n    if (h == 12345u) {{ out[p] = 0.0; }}\n    if (p != s.first) {{ return; }}"
            ),
        );
        let start = std::time::Instant::now();
        let o = gpu_check(&slow, "corrected-euler", &["--timeout", "1"]);
        let (out, err) = text(&o);
        assert_eq!(o.status.code(), Some(2), "{out}{err}");
        assert!(err.contains("did not finish within 1 s"), "{err}");
        assert!(start.elapsed() < Duration::from_secs(30));
    }

    #[test]
    fn bad_files_and_no_adapter_are_one_line_and_exit_2() {
        let d = scratch("files");
        let spv = d.join("x.spv");
        std::fs::write(&spv, b"hello").unwrap();
        let hlsl = d.join("x.hlsl");
        std::fs::write(&hlsl, b"float4 main() {}").unwrap();
        for (path, says) in [
            (spv, "not a SPIR-V module"),
            (hlsl, "unknown kernel extension"),
            (d.join("missing.wgsl"), "cannot read it"),
        ] {
            let o = gpu_check(&path, "gouraud", &[]);
            let (_, err) = text(&o);
            assert_eq!(o.status.code(), Some(2), "{err}");
            assert_eq!(err.lines().count(), 1, "{err}");
            assert!(err.contains(says), "{err}");
        }
        let o = bin()
            .env("VK_ICD_FILENAMES", "/nonexistent/icd.json")
            .args(["gpu-check", "--method", "gouraud", "--shader"])
            .arg(repo("harness/gpu/gouraud.wgsl"))
            .output()
            .unwrap();
        let (_, err) = text(&o);
        assert_eq!(o.status.code(), Some(2), "{err}");
        assert!(
            err.contains("no GPU adapter") && err.contains("mesa-vulkan-drivers"),
            "{err}"
        );
    }

    #[test]
    fn the_junit_report_has_a_suite_per_set_naming_the_adapter() {
        let d = scratch("junit");
        let report = d.join("gpu.xml");
        let o = gpu_check(
            &repo("harness/gpu/mutants/corrected_euler_dq_sign.wgsl"),
            "corrected-euler",
            &["--report", "junit", report.to_str().unwrap()],
        );
        assert_eq!(o.status.code(), Some(1));
        let xml = std::fs::read_to_string(&report).unwrap();
        let doc = roxmltree::Document::parse(&xml).expect("JUnit XML");
        let suites: Vec<_> = doc
            .descendants()
            .filter(|n| n.has_tag_name("testsuite"))
            .collect();
        assert_eq!(suites.len(), 3);
        let adapter = gpu().adapter().name.clone();
        for s in &suites {
            assert!(s.attribute("name").unwrap().contains(&adapter), "{xml}");
        }
        let cases = doc
            .descendants()
            .filter(|n| n.has_tag_name("testcase"))
            .count();
        assert_eq!(cases, 71);
        assert!(doc.descendants().any(|n| n.has_tag_name("failure")));
    }

    #[test]
    fn the_json_report_on_standard_output_holds_the_adapter_and_every_set() {
        let o = gpu_check(
            &repo("harness/gpu/gouraud.wgsl"),
            "gouraud",
            &["--report", "json", "-"],
        );
        let (out, err) = text(&o);
        assert_eq!(o.status.code(), Some(0), "{out}{err}");
        // The report takes standard output; the human verdict goes to standard error.
        assert!(err.contains("adapter: ") && err.contains(" set '"), "{err}");
        let v: serde_json::Value = serde_json::from_str(&out).expect("JSON on standard output");
        assert_eq!(
            v["adapter"].as_str(),
            Some(gpu().adapter().to_string().as_str())
        );
        let sets = v["sets"].as_array().expect("the sets");
        assert_eq!(sets.len(), 3);
        assert!(sets.iter().all(|s| s.is_object()), "{out}");
    }

    #[test]
    fn builtin_runs_every_kernel_and_names_the_adapter() {
        let _device = gpu();
        let o = bin().args(["gpu-check", "--builtin"]).output().unwrap();
        let (out, err) = text(&o);
        assert_eq!(o.status.code(), Some(0), "{out}{err}");
        assert!(out.starts_with("adapter: "), "{out}");
        for k in KERNELS {
            assert!(
                out.contains(&format!("| `{}` |", k.name())),
                "{}: {out}",
                k.file
            );
        }
        assert_eq!(
            out.matches("**fail**").count(),
            6,
            "the three planted bugs, twice: {out}"
        );
        // docs/conformance.md's table is this run's wherever the adapter is the one it
        // names (other drivers may round otherwise).
        let docs =
            std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/conformance.md"))
                .unwrap();
        let adapter = out.lines().next().unwrap().trim_start_matches("adapter: ");
        if docs.contains(&format!("On {adapter},")) {
            let table = docs
                .split("<!-- gpu table: begin -->\n")
                .nth(1)
                .and_then(|t| t.split("<!-- gpu table: end -->").next())
                .expect("the GPU table's markers");
            let printed: String = out
                .lines()
                .filter(|l| l.starts_with('|'))
                .map(|l| format!("{l}\n"))
                .collect();
            assert_eq!(
                table, printed,
                "docs/conformance.md's GPU table is not this run's: paste `gpu-check --builtin`'s"
            );
        }
    }
}
