//! `autostereo-bench`: its report regenerated from saved results, its flags' refusals and
//! what it says it wrote (moved from the CLI's tests with the bench itself).

use std::path::PathBuf;
use std::process::Command;

/// Run the bench with `args`: (success, stdout, stderr).
fn run_any(args: &[&str]) -> (bool, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_autostereo-bench"))
        .args(args)
        .output()
        .unwrap();
    let text = |b: Vec<u8>| String::from_utf8_lossy(&b).into_owned();
    (out.status.success(), text(out.stdout), text(out.stderr))
}

/// Run the bench with `args`, which must succeed; its stdout.
fn run(args: &[&str]) -> String {
    let (ok, stdout, stderr) = run_any(args);
    assert!(ok, "{args:?} failed: {stderr}");
    stdout
}

/// (success, stderr).
fn bench(args: &[&str]) -> (bool, String) {
    let (ok, _, stderr) = run_any(args);
    (ok, stderr)
}

/// `--json`'s object.
fn bench_json(args: &[&str]) -> serde_json::Value {
    serde_json::from_str(&run(args)).unwrap()
}

/// A run that must be refused with each of `words` on stderr, and no panic.
fn refused(args: &[&str], words: &[&str]) -> String {
    let (ok, _, stderr) = run_any(args);
    assert!(!ok, "{args:?} succeeded");
    assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
    for w in words {
        assert!(stderr.contains(w), "{args:?} does not say {w:?}: {stderr}");
    }
    stderr
}

/// The error lines of stderr.
fn error_text(stderr: &str) -> String {
    let errors = stderr.lines().filter(|l| l.starts_with("error: "));
    errors.collect::<Vec<_>>().join("\n")
}

fn s(path: &std::path::Path) -> &str {
    path.to_str().unwrap()
}

/// A fresh folder for a test's outputs.
fn out(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join("bench")
        .join(name);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn frames_out_of_range_are_refused_with_the_range() {
    refused(&["--frames", "0"], &["1..=100000"]);
}

/// `autostereo-bench --json` names the files `--report` wrote (before: no `written`).
#[test]
fn bench_json_names_the_report_files() {
    let dir = out("vocabulary_bench_report");
    let saved = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../docs/bench_quick.json");
    let json = bench_json(&[
        "--report",
        dir.to_str().unwrap(),
        "--from-json",
        saved.to_str().unwrap(),
        "--json",
    ]);
    let written: Vec<&str> = json["written"]
        .as_array()
        .unwrap()
        .iter()
        .map(|w| w.as_str().unwrap())
        .collect();
    assert!(
        written.iter().any(|w| w.ends_with("BENCHMARKS.md")),
        "{json}"
    );
    for file in &written {
        assert!(std::path::Path::new(file).is_file(), "{file}");
    }
}

#[test]
fn a_report_path_that_is_a_file_names_report_and_the_path() {
    // Said "Not a directory (os error 20)", no flag, no path.
    let dir = out("vocabulary_errors_report");
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("BENCHMARKS.md");
    std::fs::write(&file, "# Benchmarks\n").unwrap();
    let (ok, stderr) = bench(&["--report", file.to_str().unwrap()]);
    assert!(!ok);
    let text = error_text(&stderr);
    assert!(
        text.starts_with("error: --report ") && text.contains(file.to_str().unwrap()),
        "{text}"
    );
    assert!(text.contains("takes a folder"), "{text}");
}

#[test]
fn bench_from_json_takes_no_measuring_flags() {
    let saved = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../docs/bench_quick.json");
    let dir = out("names_bench");
    for flag in [
        &["--frames", "3"][..],
        &["--gaussians"][..],
        &["--quick"][..],
    ] {
        let mut args = vec!["--report", s(&dir), "--from-json", s(&saved)];
        args.extend_from_slice(flag);
        refused(&args, &[flag[0]]);
    }
}

/// `autostereo-bench --report dir --from-json json`; the report's text.
fn report_from(dir: &std::path::Path, json: &std::path::Path) -> String {
    run(&[
        "--report",
        dir.to_str().unwrap(),
        "--from-json",
        json.to_str().unwrap(),
    ]);
    std::fs::read_to_string(dir.join("BENCHMARKS.md")).unwrap()
}

/// The report is regenerated from saved results: every section and every renderer target.
#[test]
fn bench_report_regenerates_from_saved_results() {
    let dir = out("bench_report");
    let json = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../docs/bench_quick.json");
    let md = report_from(&dir, &json);
    for section in [
        "## The paper's charts",
        "## Time against the number of views",
        "## Targets of the renderer issues",
        "## Speed/accuracy trade-offs",
        "## Model only what a scene requires",
        "## Numerical stability",
    ] {
        assert!(md.contains(section), "missing {section}");
    }
    for target in [
        "N-pass / SP ≥ 5 at N = 8",
        "N-pass / SP ≥ 3 at N = 8",
        "N-pass / SP ≥ 2 at N = 8",
    ] {
        assert!(md.contains(target), "missing target {target}");
    }
    let (ok, _) = {
        let out = Command::new(env!("CARGO_BIN_EXE_autostereo-bench"))
            .args([
                "--report",
                dir.to_str().unwrap(),
                "--from-json",
                "Cargo.toml",
            ])
            .output()
            .unwrap();
        (out.status.success(), ())
    };
    assert!(!ok, "a file that is not bench output must be an error");
}

/// The targets table computes its ratios and verdicts from the rows: saved results edited so
/// that points at N = 8 are exactly 2× (target 3×: missed) and meshes 10× (target 2×: met).
#[test]
fn bench_report_targets_follow_the_measured_rows() {
    let saved = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../docs/bench_quick.json");
    let mut json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(saved).unwrap()).unwrap();
    let mut edited = 0;
    for row in json["rows"].as_array_mut().unwrap() {
        let n_pass_ms = match row["primitive"].as_str().unwrap() {
            "points" => 200.0,
            "mesh" => 1000.0,
            _ => continue,
        };
        if row["display"] != "hubner8" {
            continue;
        }
        let ms = match row["kind"].as_str().unwrap() {
            "single-pass" => 100.0,
            "n-pass" => n_pass_ms,
            _ => continue,
        };
        row["ms"] = ms.into();
        edited += 1;
    }
    assert!(edited >= 4, "the saved results lack the N = 8 rows");
    let dir = out("bench_report_edited");
    std::fs::create_dir_all(&dir).unwrap();
    let edited_json = dir.join("edited.json");
    std::fs::write(&edited_json, json.to_string()).unwrap();
    let md = report_from(&dir, &edited_json);
    let line = |start: &str, target: &str| {
        md.lines()
            .find(|l| l.starts_with(start) && l.contains(target))
            .unwrap_or_else(|| panic!("no {start} row for {target}"))
            .to_string()
    };
    let points = line("| points |", "N-pass / SP ≥ 3 at N = 8");
    assert!(points.ends_with("| 2.00× | **missed** |"), "{points}");
    let mesh = line("| mesh |", "N-pass / SP ≥ 2 at N = 8");
    assert!(mesh.ends_with("| 10.00× | met |"), "{mesh}");
}
