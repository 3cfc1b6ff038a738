//! Every command's files, pipes, exit codes and messages: a user's file is never
//! replaced and a link never followed, closed pipes and full disks keep the exit-code
//! contract, interrupted commits are completed, messages are one line saying what is
//! wrong.

use super::*;

/// Defect d7 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn outputs_never_replace_a_users_file_or_follow_a_link() {
    let d = scratch("d7");
    let out = d.join("out");
    std::fs::create_dir_all(&out).unwrap();
    std::fs::write(out.join("tables.md"), "mine").unwrap();
    std::fs::write(out.join(".write-test"), "mine too").unwrap();
    let o = run(&[
        "reproduce",
        "--frames",
        "1",
        "--size",
        "80x60",
        "--out",
        out.to_str().unwrap(),
    ]);
    refused(&o, "was not written by phong-approx");
    assert_eq!(
        std::fs::read_to_string(out.join("tables.md")).unwrap(),
        "mine"
    );
    assert_eq!(
        std::fs::read_to_string(out.join(".write-test")).unwrap(),
        "mine too"
    );
    // With --force it writes, and then may write again.
    let o = run(&[
        "reproduce",
        "--frames",
        "1",
        "--size",
        "80x60",
        "--out",
        out.to_str().unwrap(),
        "--force",
    ]);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let o = run(&[
        "reproduce",
        "--frames",
        "1",
        "--size",
        "80x60",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    // A symbolic link among the outputs is not written through.
    let target = d.join("precious.csv");
    std::fs::write(&target, "precious").unwrap();
    std::fs::remove_file(out.join("table1.csv")).unwrap();
    std::os::unix::fs::symlink(&target, out.join("table1.csv")).unwrap();
    let o = run(&[
        "reproduce",
        "--frames",
        "1",
        "--size",
        "80x60",
        "--out",
        out.to_str().unwrap(),
        "--force",
    ]);
    refused(&o, "symbolic link");
    assert_eq!(std::fs::read_to_string(&target).unwrap(), "precious");
    // No temporary file is left behind by a refused run.
    let leftovers: Vec<_> = std::fs::read_dir(&out)
        .unwrap()
        .filter_map(|e| e.ok())
        .filter(|e| e.file_name().to_string_lossy().contains(".partial-"))
        .collect();
    assert!(leftovers.is_empty(), "{leftovers:?}");
    // vectors: the CSV twins of my.json are the user's.
    std::fs::write(d.join("my.csv"), "mine").unwrap();
    let my = d.join("my.json");
    let o = run(&["vectors", "--set", "paper", "--out", my.to_str().unwrap()]);
    refused(&o, "my.csv");
    assert_eq!(std::fs::read_to_string(d.join("my.csv")).unwrap(), "mine");
    assert!(!my.exists(), "nothing is written when one name is refused");
}

/// Defect d8 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn closed_pipe_and_full_disk_keep_the_exit_code_contract() {
    let mut child = bin()
        .args([
            "span",
            "--method",
            "phong",
            "--na",
            "0,0,1",
            "--nb",
            "0.6,0,0.8",
            "--light",
            "0,0,1",
            "--steps",
            "200000",
        ])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut head = [0u8; 10];
    child.stdout.take().unwrap().read_exact(&mut head).unwrap();
    // The reader is gone (its end of the pipe was dropped with it).
    let o = child.wait_with_output().unwrap();
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    assert!(!stderr(&o).contains("panicked"));
    let full = std::fs::OpenOptions::new()
        .write(true)
        .open("/dev/full")
        .unwrap();
    let v = root().join("vectors/typical.json").display().to_string();
    let d = scratch("d8");
    let r = write(&d, "r.csv", &results_csv(&typical()));
    let o = bin()
        .args(["check", "--vectors", &v, "--results", &r])
        .stdout(full)
        .output()
        .unwrap();
    refused(&o, "No space left");
}

/// Defect d13 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn pictures_follow_size() {
    let d = scratch("d13");
    let o = run(&[
        "reproduce",
        "--frames",
        "1",
        "--size",
        "150x100",
        "--out",
        d.to_str().unwrap(),
    ]);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    // Scaled by a whole factor to at least 400 pixels on the shorter side.
    assert_eq!(
        png_size(&d.join("fig4_torus800_corrected_euler.png")),
        (600, 400)
    );
}

/// Item 8: writing to a standard error that cannot take it never panics (exit 2, not
/// 101); `--help` and `--version` to a full disk exit 2.
///
/// Defect r8 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn stderr_and_stdout_failures_keep_the_exit_code_contract() {
    let full = || {
        std::fs::OpenOptions::new()
            .write(true)
            .open("/dev/full")
            .unwrap()
    };
    // A bad request whose one line cannot be written.
    let o = bin()
        .args(["span", "--method", "nope"])
        .stderr(full())
        .output()
        .unwrap();
    assert_eq!(code(&o), 2);
    let o = bin()
        .args(["span", "--bogus"])
        .stderr(full())
        .output()
        .unwrap();
    assert_eq!(code(&o), 2);
    for args in [&["span", "--help"][..], &["--version"], &["--help"]] {
        let o = bin().args(args).stdout(full()).output().unwrap();
        assert_eq!(code(&o), 2, "{args:?}");
        assert!(stderr(&o).contains("standard output"), "{args:?}");
        // And to a pipe that stays open, exit 0.
        let o = run(args);
        assert_eq!(code(&o), 0, "{args:?}");
    }
    // stderr is a closed pipe.
    let mut child = bin()
        .args(["span", "--method", "nope"])
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stderr.take());
    assert_eq!(child.wait().unwrap().code(), Some(2));
}

/// Item 5: an `--out` folder that is a symbolic link is refused (nothing is written
/// into the folder it points to), by `reproduce`, `compare` and `vectors`.
///
/// Defect r5 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn an_out_folder_that_is_a_symlink_is_refused() {
    let d = scratch("r5");
    let real = d.join("real");
    std::fs::create_dir_all(&real).unwrap();
    let link = d.join("link");
    std::os::unix::fs::symlink(&real, &link).unwrap();
    let o = quick_reproduce(&link, &[]);
    refused(&o, "symbolic link");
    let o = run(&[
        "compare",
        "--frames",
        "1",
        "--size",
        "80x60",
        "--out",
        link.to_str().unwrap(),
    ]);
    refused(&o, "symbolic link");
    let o = run(&["vectors", "--out", link.to_str().unwrap()]);
    refused(&o, "symbolic link");
    assert_eq!(std::fs::read_dir(&real).unwrap().count(), 0);
}

/// Item 7: a commit that was killed during its renames (its journal left behind) is
/// completed by the next run in the folder, stale temporary files of dead runs are
/// removed, and a manifest that is a folder is refused before any output is written.
///
/// Defect r7 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn interrupted_commits_are_completed_and_stale_temporaries_removed() {
    let d = scratch("r7");
    let out = d.join("out");
    std::fs::create_dir_all(&out).unwrap();
    // As a run killed between two renames leaves it: one temporary not yet renamed,
    // listed in the journal. (PID 4294967295 is no process.)
    std::fs::write(out.join(".partial-4294967295-1.extra.txt"), "NEW").unwrap();
    std::fs::write(
        out.join(".phong-approx-commit"),
        ".partial-4294967295-1.extra.txt\textra.txt\n",
    )
    .unwrap();
    std::fs::write(out.join(".partial-4294967295-2.table1.csv"), "stale").unwrap();
    let o = quick_reproduce(&out, &[]);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    assert_eq!(
        std::fs::read_to_string(out.join("extra.txt")).unwrap(),
        "NEW"
    );
    assert!(!out.join(".phong-approx-commit").exists());
    let manifest = std::fs::read_to_string(out.join(".phong-approx-written")).unwrap();
    assert!(manifest.lines().any(|l| l == "extra.txt"), "{manifest}");
    let partials: Vec<_> = std::fs::read_dir(&out)
        .unwrap()
        .flatten()
        .filter(|e| e.file_name().to_string_lossy().starts_with(".partial-"))
        .collect();
    assert!(partials.is_empty(), "{partials:?}");
    // A manifest that is a folder: refused before anything is written.
    let out2 = d.join("out2");
    std::fs::create_dir_all(out2.join(".phong-approx-written")).unwrap();
    let o = quick_reproduce(&out2, &[]);
    refused(&o, "not a regular file");
    assert_eq!(std::fs::read_dir(&out2).unwrap().count(), 1);
}

/// Defect q12 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn dot_named_outputs_are_written() {
    let d = scratch("q12");
    let out = d.join(".r.json");
    let o = check_typical(&d, &["--report", "json", out.to_str().unwrap()]);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    assert!(out.is_file());
}

/// Defect q13 of the reliability rounds (docs/conformance.md, "Limits and exit codes"):
/// an output folder in use by another run is refused, naming it; the lock file is gone
/// when a run ends.
#[test]
fn a_second_run_into_a_folder_in_use_exits_2_naming_it() {
    use std::os::unix::io::AsRawFd;
    let d = scratch("q13");
    let out = d.join("out");
    std::fs::create_dir_all(&out).unwrap();
    // Hold the folder's lock as a running phong-approx would.
    std::fs::write(out.join(".phong-approx-lock"), "12345").unwrap();
    let lock = std::fs::OpenOptions::new()
        .read(true)
        .write(true)
        .open(out.join(".phong-approx-lock"))
        .unwrap();
    // SAFETY: flock on a descriptor this test owns.
    assert_eq!(
        unsafe { libc::flock(lock.as_raw_fd(), libc::LOCK_EX | libc::LOCK_NB) },
        0
    );
    let o = quick_reproduce(&out, &[]);
    refused(
        &o,
        "being written by another phong-approx run (process 12345)",
    );
    drop(lock);
    let o = quick_reproduce(&out, &[]);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    assert!(
        !out.join(".phong-approx-lock").exists(),
        "the lock file is left"
    );
}

/// Finding 4 of the fifth reliability round: a report never replaces a file the tool
/// did not write (without --force), replaces its own, and leaves nothing else behind.
#[test]
fn a_report_never_replaces_a_users_file() {
    let d = scratch("f50-reports");
    let notes = d.join("notes.txt");
    std::fs::write(&notes, "my notes\n").unwrap();
    for format in ["json", "junit"] {
        let o = check_typical(&d, &["--report", format, notes.to_str().unwrap()]);
        refused(&o, "not a report phong-approx wrote: pass --force");
        assert_eq!(std::fs::read_to_string(&notes).unwrap(), "my notes\n");
    }
    // Its own report, from a run before, is replaced; so is an older JSON report
    // without the "generator" key; and a user's file with --force.
    let own = d.join("own.json");
    for _ in 0..2 {
        let o = check_typical(&d, &["--report", "json", own.to_str().unwrap()]);
        assert_eq!(code(&o), 0, "{}", stderr(&o));
    }
    let mut old: Value = serde_json::from_str(&std::fs::read_to_string(&own).unwrap()).unwrap();
    assert!(old["generator"]
        .as_str()
        .unwrap()
        .starts_with("phong-approx "));
    old.as_object_mut().unwrap().remove("generator");
    std::fs::write(&own, serde_json::to_string_pretty(&old).unwrap()).unwrap();
    let o = check_typical(&d, &["--report", "json", own.to_str().unwrap()]);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let o = check_typical(
        &d,
        &["--report", "junit", notes.to_str().unwrap(), "--force"],
    );
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    assert!(std::fs::read_to_string(&notes)
        .unwrap()
        .contains("<testsuites name=\"phong-approx"));
    // Nothing but the inputs and the reports is left in the folder.
    let mut left: Vec<String> = std::fs::read_dir(&d)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    left.sort();
    assert_eq!(left, ["notes.txt", "own.json", "r.csv"]);
}

/// Finding 7 of the fifth reliability round: parallel runs writing different reports
/// into one folder all succeed.
#[test]
fn eight_parallel_reports_into_one_folder_all_succeed() {
    let d = scratch("f50-parallel");
    let r = write(&d, "r.csv", &results_csv(&typical()));
    let v = root().join("vectors/typical.json").display().to_string();
    let children: Vec<_> = (0..8)
        .map(|k| {
            let report = d.join(format!("report-{k}.xml")).display().to_string();
            bin()
                .args([
                    "check",
                    "--vectors",
                    &v,
                    "--results",
                    &r,
                    "--report",
                    "junit",
                    &report,
                ])
                .stdout(Stdio::null())
                .stderr(Stdio::piped())
                .spawn()
                .unwrap()
        })
        .collect();
    for (k, c) in children.into_iter().enumerate() {
        let o = c.wait_with_output().unwrap();
        assert_eq!(code(&o), 0, "run {k}: {}", stderr(&o));
        let text = std::fs::read_to_string(d.join(format!("report-{k}.xml"))).unwrap();
        assert!(text.ends_with("</testsuites>\n"), "run {k}");
    }
    let left = std::fs::read_dir(&d).unwrap().count();
    assert_eq!(left, 9, "only r.csv and the eight reports");
}

/// Finding 5 of the fifth reliability round: a stale journal that names a file the
/// tool did not write does not replace it.
#[test]
fn a_stale_journal_never_renames_over_a_users_file() {
    let d = scratch("f50-journal");
    let out = d.join("out");
    std::fs::create_dir_all(&out).unwrap();
    std::fs::write(out.join("important.txt"), "keep me\n").unwrap();
    std::fs::write(out.join(".partial-1-x"), "replacement\n").unwrap();
    std::fs::write(
        out.join(".phong-approx-commit"),
        ".partial-1-x\timportant.txt\n",
    )
    .unwrap();
    let o = quick_reproduce(&out, &[]);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    assert_eq!(
        std::fs::read_to_string(out.join("important.txt")).unwrap(),
        "keep me\n"
    );
    assert!(
        stderr(&o).contains("did not write: not replacing it"),
        "{}",
        stderr(&o)
    );
}

/// Defect d13 of the reliability rounds (docs/conformance.md, "Limits and exit codes").
#[test]
fn vectors_into_a_folder_it_cannot_write_fails_before_computing() {
    let t = Instant::now();
    let o = run(&["vectors", "--out", "/proc/phong-approx-test"]);
    assert_eq!(code(&o), 2);
    assert!(
        t.elapsed() < Duration::from_secs(3),
        "fails before computing"
    );
}
