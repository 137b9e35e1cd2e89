//! The docs against today's command line (issue 31): every command their code shows parses, the
//! flags of every command line they show are its command's, and every `--flag` they name at all
//! is some command's (or another tool's, listed below). Parsing only: nothing runs, so the
//! commands' runtime checks (files, GPU) are not part of this. Shell words are split by `shlex`.

use crate::Cli;
use clap::CommandFactory;
use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// Flags of other tools that the docs name, and whose they are.
const OTHER_TOOLS: &[(&str, &str)] = &[
    ("--release", "cargo build/run: the optimised build"),
    ("--features", "cargo: autostereo-bench/plots"),
    ("--bench", "cargo bench --bench NAME"),
    ("--test", "cargo test --test NAME"),
    ("--nocapture", "the test harness's"),
    ("--example", "cargo run --example NAME"),
    ("--workspace", "cargo build/test: every package"),
    ("--quiet", "cargo build: no progress lines"),
    ("--suffix", "mktemp's"),
    ("--bin-dir", "docs/tools/peer_vtk.py's"),
    ("--no-build", "docs/tools/peer_vtk.py's"),
    ("--write", "docs/tools/auto_fit.py's"),
    ("--measurements", "docs/tools/auto_fit.py's"),
];

/// Shell words that end a command (`a | b`, `a && b`, `a > file`).
const ENDS: &[&str] = &["|", "||", "&&", ";", "&", "<", ">", ">>", "2>", "2>&1"];

/// The CLI with the bench harness as its `bench` subcommand: the docs name both binaries.
fn command() -> clap::Command {
    use clap::Args;
    let bench = autostereo_bench::BenchArgs::augment_args(clap::Command::new("bench"));
    let mut cli = Cli::command().subcommand(bench);
    cli.build(); // adds --help and --version
    cli
}

/// Subcommand → its long flags and aliases, with `--help`; "" → every command's.
fn flags(cli: &clap::Command) -> BTreeMap<String, BTreeSet<String>> {
    let longs = |cmd: &clap::Command| -> BTreeSet<String> {
        let args = cmd.get_arguments();
        let names = args.flat_map(|a| {
            let aliases = a.get_all_aliases().unwrap_or_default();
            a.get_long().into_iter().chain(aliases)
        });
        names.map(|l| format!("--{l}")).collect()
    };
    let mut map: BTreeMap<_, _> = cli
        .get_subcommands()
        .map(|s| (s.get_name().to_string(), longs(s)))
        .collect();
    let all = map.values().flatten().cloned().chain(longs(cli)).collect();
    map.insert(String::new(), all);
    map
}

/// README.md, docs/**/*.md and docs/tools/*.sh, as (path from the repository root, text).
fn files() -> Vec<(String, String)> {
    fn walk(root: &Path, dir: &str, out: &mut Vec<(String, String)>) {
        let mut paths: Vec<_> = std::fs::read_dir(root.join(dir)).unwrap().collect();
        paths.sort_by_key(|e| e.as_ref().unwrap().path());
        for path in paths.into_iter().map(|e| e.unwrap().path()) {
            let rel = path.strip_prefix(root).unwrap().display().to_string();
            if path.is_dir() {
                walk(root, &rel, out);
            } else if rel.ends_with(".md") || rel.ends_with(".sh") {
                out.push((rel, std::fs::read_to_string(&path).unwrap()));
            }
        }
    }
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut out = vec![(
        "README.md".into(),
        std::fs::read_to_string(root.join("README.md")).unwrap(),
    )];
    walk(&root, "docs", &mut out);
    out
}

/// The lines of `text` that may hold commands, `\` continuations joined, with their numbers: a
/// script's every line; Markdown's fenced code (not Rust or Python: `autostereo` there is the
/// crate or the Python module) and code spans, wrapped ones joined.
fn code_lines(path: &str, text: &str) -> Vec<(usize, String)> {
    let (mut out, mut fence, mut other_language) = (Vec::new(), false, false);
    let mut pending: Option<(usize, String)> = None;
    let mut open: Option<(usize, String)> = None;
    for (n, line) in text.lines().enumerate().map(|(n, l)| (n + 1, l)) {
        let t = line.trim_start();
        if path.ends_with(".md") && t.starts_with("```") {
            (fence, other_language) = (!fence, t.contains("rust") || t.contains("python"));
            continue;
        }
        if path.ends_with(".sh") || (fence && !other_language) {
            let (first, mut joined) = pending.take().unwrap_or((n, String::new()));
            joined += line;
            match joined.strip_suffix('\\') {
                Some(rest) => pending = Some((first, rest.to_string())),
                None => out.push((first, joined)),
            }
        } else if !fence {
            // A code span may wrap onto the next line of its paragraph: an odd count of
            // backticks leaves the last one open.
            let (first, text) = match open.take() {
                Some((first, start)) if !t.is_empty() => (first, format!("{start} {line}")),
                _ => (n, line.to_string()),
            };
            let parts: Vec<&str> = text.split('`').collect();
            let closed = parts.len() % 2 == 1;
            for (i, span) in parts.iter().enumerate().skip(1).step_by(2) {
                if closed || i + 1 < parts.len() {
                    out.push((if i == 1 { first } else { n }, span.to_string()));
                } else {
                    open = Some((if i == 1 { first } else { n }, format!("`{span}")));
                }
            }
        }
    }
    out
}

/// The CLI's arguments in `words`, where they run it (`autostereo …`, `…/autostereo …`, the
/// bench binary as the `bench` subcommand, `cargo run … -- …`), up to what ends the command.
fn cli_args(words: &[String]) -> Option<Vec<String>> {
    let is = |w: &str, bin: &str| w == bin || w.ends_with(&format!("/{bin}"));
    let package = |i: usize| i > 0 && ["-p", "--package", "--bin"].contains(&&*words[i - 1]);
    let cargo_run = words.windows(2).any(|w| w[0] == "cargo" && w[1] == "run");
    let (at, bench) = if cargo_run && !words.iter().any(|w| w == "--example") {
        let bench = words.iter().any(|w| w == "autostereo-bench");
        (words.iter().position(|w| w == "--")?, bench)
    } else {
        let at = (0..words.len()).find(|&i| {
            !package(i) && (is(&words[i], "autostereo") || is(&words[i], "autostereo-bench"))
        })?;
        (at, is(&words[at], "autostereo-bench"))
    };
    let rest = words[at + 1..].iter().map(|w| w.trim_end_matches(';'));
    let rest = rest.take_while(|w| !ENDS.contains(w) && !w.starts_with(['>', '<']));
    let args: Vec<String> = bench
        .then(|| "bench".to_string())
        .into_iter()
        .chain(rest.map(str::to_string))
        .collect();
    (!args.is_empty()).then_some(args)
}

/// A synopsis, not a command: `[--x]`, `a|b`, `…`, or a placeholder word (`FILE`, `WxH`).
fn is_synopsis(args: &[String]) -> bool {
    let placeholder = |w: &str| {
        let upper = |c: char| c.is_ascii_uppercase();
        w.chars().any(upper) && w.chars().all(|c| upper(c) || "_x,:.".contains(c))
    };
    args.iter()
        .any(|w| w.contains(['[', '|', '…']) || placeholder(w))
}

/// Every `--flag` a line names (lower-case names: `--FLAG` is prose).
fn flags_named(line: &str) -> impl Iterator<Item = String> + '_ {
    let word_char = |c: char| c.is_alphanumeric() || "-_".contains(c);
    let starts = line.match_indices("--").map(|(i, _)| i);
    let starts = starts.filter(move |&i| !line[..i].ends_with(word_char));
    let flag_char = |c: char| c.is_ascii_alphanumeric() || c == '-';
    let names = starts.map(move |i| line[i + 2..].split(|c| !flag_char(c)).next().unwrap());
    let names = names.map(|n| n.trim_end_matches('-'));
    let names = names.filter(|n| n.starts_with(|c: char| c.is_ascii_lowercase()));
    names.map(|n| format!("--{n}"))
}

#[test]
fn doc_examples_parse_and_name_existing_flags() {
    let cli = command();
    let flags = flags(&cli);
    let (mut parsed, mut problems, mut used) = (0, Vec::new(), BTreeSet::new());
    for (path, text) in files() {
        // Every flag named anywhere is some command's, or another tool's.
        for (n, line) in text.lines().enumerate() {
            for flag in flags_named(line).filter(|f| !flags[""].contains(f)) {
                match OTHER_TOOLS.iter().find(|o| o.0 == flag) {
                    Some(other) => drop(used.insert(other.0)),
                    None => problems.push(format!("{path}:{}: {flag} is no flag", n + 1)),
                }
            }
        }
        // Every command line shown: its flags are its command's; it parses, unless it is a
        // synopsis or a script's words stand for values only the shell knows (`$out`).
        for (n, line) in code_lines(&path, &text) {
            let Some(args) = shlex::split(&line).and_then(|words| cli_args(&words)) else {
                continue;
            };
            let own = flags.get(&args[0]).unwrap_or(&flags[""]);
            let named = args.iter().filter_map(|w| w.split('=').next());
            for flag in named.filter(|w| w.starts_with("--") && !own.contains(*w)) {
                problems.push(format!("{path}:{n}: {flag} is not a flag of `{}`", args[0]));
            }
            if is_synopsis(&args) || args.iter().any(|w| w.contains('$')) {
                continue;
            }
            let argv = std::iter::once("autostereo".to_string()).chain(args);
            match cli.clone().try_get_matches_from(argv) {
                Ok(_) => parsed += 1,
                // A code span may name a command without its arguments (`autostereo rgbd`).
                Err(e) if e.kind() == clap::error::ErrorKind::MissingRequiredArgument => {}
                Err(e) => {
                    let e = e.to_string().lines().next().unwrap_or_default().to_string();
                    problems.push(format!("{path}:{n}: `{}`: {e}", line.trim()));
                }
            }
        }
    }
    for (flag, whose) in OTHER_TOOLS.iter().filter(|o| !used.contains(o.0)) {
        problems.push(format!("{flag} ({whose}): allow-listed, named nowhere"));
    }
    // Guards the extraction itself: one that finds nothing passes vacuously.
    println!("{parsed} commands parsed");
    if parsed < 90 {
        problems.push(format!("only {parsed} commands found"));
    }
    assert!(problems.is_empty(), "docs vs CLI:\n{}", problems.join("\n"));
}
