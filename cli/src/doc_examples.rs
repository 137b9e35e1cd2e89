//! The docs against today's command line (issue 31): every command they show parses, and every
//! `--flag` they name exists (on the command the line names, where it names one). Parsing only:
//! nothing runs, so the commands' runtime checks (files, GPU) are not part of this.

use crate::Cli;
use clap::CommandFactory;
use std::collections::{BTreeMap, BTreeSet, HashMap};
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
    ("--bin-dir", "docs/tools/peer_vtk.py's"),
    ("--no-build", "docs/tools/peer_vtk.py's"),
];

/// Script lines whose arguments only a running shell knows (`"$1"` after `set -- $mode`, `"$@"`
/// in a function): listed on failure, their flags still checked against their command.
const MAX_SKIPPED: usize = 4;

/// Programs that run the CLI as their argument (`xvfb-run -a autostereo view …`).
const WRAPPERS: &[&str] = &["xvfb-run", "/usr/bin/time", "env"];

/// Stands for an expansion only a running shell knows; `x` where part of a word
/// (`"$out/x.png"` → `x/x.png`, a plausible path), the line skipped where the whole word.
const UNKNOWN: &str = "\u{1}";

/// Subcommand → its long flags and aliases (nested subcommands' too); "" → every command's.
type Flags = BTreeMap<String, BTreeSet<String>>;
/// A script's variables by this line, as text to substitute (arrays: their words, quoted).
type Env = HashMap<String, String>;

/// The CLI with the bench harness as its `bench` subcommand: the docs name both binaries.
fn command() -> clap::Command {
    use clap::Args;
    let bench = autostereo_bench::BenchArgs::augment_args(clap::Command::new("bench"));
    Cli::command().subcommand(bench)
}

/// `line` with `autostereo-bench …` (and `cargo run -p autostereo-bench -- …`) written as the
/// `bench` subcommand of [`command`].
fn bench_as_subcommand(line: &str) -> String {
    line.replace(
        "-p autostereo-bench --features plots -- ",
        "--features plots -- bench ",
    )
    .replace("-p autostereo-bench -- ", "-- bench ")
    .replace("autostereo-bench", "autostereo bench")
}

fn flags() -> Flags {
    fn collect(cmd: &clap::Command, set: &mut BTreeSet<String>) {
        let mut longs = Vec::new();
        for arg in cmd.get_arguments() {
            longs.extend(arg.get_long());
            longs.extend(arg.get_all_aliases().unwrap_or_default());
        }
        for sub in cmd.get_subcommands() {
            longs.extend(sub.get_long_flag());
            longs.extend(sub.get_all_long_flag_aliases());
            collect(sub, set);
        }
        set.extend(longs.iter().map(|l| format!("--{l}")));
    }
    let mut cli = command();
    cli.build(); // adds --help and --version
    let mut flags = Flags::new();
    collect(&cli, flags.entry(String::new()).or_default());
    for sub in cli.get_subcommands() {
        collect(sub, flags.entry(sub.get_name().into()).or_default());
    }
    flags
}

/// (path from the repository root, text) of the files under `dir` whose names end in `ext`.
fn files(dir: &str, ext: &str, out: &mut Vec<(String, String)>) {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let entries = std::fs::read_dir(root.join(dir)).unwrap();
    let mut paths: Vec<_> = entries.map(|e| e.unwrap().path()).collect();
    paths.sort();
    for path in paths {
        let rel = path.strip_prefix(&root).unwrap().display().to_string();
        if path.is_dir() {
            files(&rel, ext, out);
        } else if rel.ends_with(ext) {
            out.push((rel, std::fs::read_to_string(&path).unwrap()));
        }
    }
}

/// `$VAR`, `${VAR}`, `${VAR:-default}` and `"${ARRAY[@]}"` substituted from `env`.
fn expand(line: &str, env: &Env) -> String {
    let (mut out, mut rest) = (String::new(), line);
    while let Some(i) = rest.find('$') {
        out += &rest[..i];
        rest = &rest[i + 1..];
        let brace = rest
            .strip_prefix('{')
            .map(|b| b.find('}').unwrap_or(b.len()));
        let end = rest.find(|c: char| !(c.is_alphanumeric() || c == '_'));
        // (the name and any `:-default`, the expansion's length after the `$`)
        let (inner, len) = match (brace, end.unwrap_or(rest.len())) {
            (Some(b), _) => (&rest[1..b + 1], b + 2),
            (None, 0) if rest.starts_with('@') => ("@", 1),
            (None, end) => (&rest[..end], end),
        };
        if inner.is_empty() {
            out.push('$'); // `$(…)`: left to `tokens`
            continue;
        }
        let (name, default) = inner.split_once(":-").unwrap_or((inner, ""));
        let name = name.trim_end_matches(":?");
        let array = name.strip_suffix("[@]");
        let value = env.get(array.unwrap_or(name)).map(String::as_str);
        let value = value.or((!default.is_empty()).then_some(default));
        rest = &rest[len..];
        if let (Some(_), Some(r), true) = (array, rest.strip_prefix('"'), out.ends_with('"')) {
            // "${a[@]}": each element its own word, as stored
            out.pop();
            rest = r;
        }
        out += value.unwrap_or(UNKNOWN);
    }
    out + rest
}

/// `line` in shell words (quotes removed), None for what ends a command (`|`, `;`, `&`, `>`,
/// `<`, `(`, `)`, `$(`); a `#` comment dropped.
fn tokens(line: &str) -> Vec<Option<String>> {
    let (mut out, mut word, mut quote) = (Vec::new(), None::<String>, None);
    let mut chars = line.chars().peekable();
    while let Some(ch) = chars.next() {
        match (quote, ch) {
            (Some(q), _) if ch == q => quote = None,
            (Some('\''), _) => word.get_or_insert_default().push(ch),
            (None, '\'' | '"') => (quote, word) = (Some(ch), word.or(Some(String::new()))),
            (None, ' ' | '\t') => out.extend(word.take().map(Some)),
            (None, '#') if word.is_none() => break,
            (_, '$') if chars.next_if_eq(&'(').is_some() => out.extend([word.take(), None]),
            (None, '|' | ';' | '&' | '>' | '<' | '(' | ')') => {
                // the 2 of 2>/dev/null is no argument
                let fd = |w: &String| ch == '>' && w.chars().all(|d| d.is_ascii_digit());
                out.extend([word.take().filter(|w| !fd(w)), None]);
            }
            (_, '\\') => word.get_or_insert_default().extend(chars.next()),
            _ => word.get_or_insert_default().push(ch),
        }
    }
    out.extend(word.map(Some));
    out
}

/// A script line's effect on its variables: `NAME=VALUE`, `NAME=(…)`, `NAME+=(…)`, and a
/// `for NAME in FIRST …` loop's first value.
fn assign(line: &str, env: &mut Env) {
    let t = line.trim_start();
    let first = |s: &str| tokens(&expand(s, env)).into_iter().next().flatten();
    if let Some((name, list)) = t.strip_prefix("for ").and_then(|r| r.split_once(" in ")) {
        let value = first(list).unwrap_or_default();
        env.insert(name.trim().into(), value);
        return;
    }
    let n = t.find(|c: char| !(c.is_alphanumeric() || c == '_'));
    let (name, rest) = t.split_at(n.unwrap_or(0));
    let (append, value) = match (rest.strip_prefix("+="), rest.strip_prefix('=')) {
        (Some(v), _) => (true, v),
        (None, Some(v)) if !name.is_empty() => (false, v),
        _ => return,
    };
    let value = match value.strip_prefix('(').and_then(|v| v.rsplit_once(')')) {
        Some((inner, _)) => Some(expand(inner, env)),
        None if value.contains("$(") => None,
        None => first(value),
    };
    match value.filter(|v| v != UNKNOWN) {
        None => drop(env.remove(name)),
        Some(v) if append => *env.entry(name.into()).or_default() += &format!(" {v}"),
        Some(v) => drop(env.insert(name.into(), v)),
    }
}

/// The CLI's arguments in one command of `toks`: after `autostereo`, `…/autostereo` (`$bin`)
/// first on the command (after `VAR=value`s and keywords; anywhere after a wrapper), or
/// `cargo run … --`.
fn cli_args(toks: &[Option<String>]) -> Option<Vec<String>> {
    toks.split(Option::is_none).find_map(|cmd| {
        let w: Vec<&str> = cmd.iter().flatten().map(String::as_str).collect();
        let keyword = |s: &&str| ["{", "!", "if", "then", "do", "else"].contains(s);
        let k = w.iter().position(|s| !s.contains('=') && !keyword(s))?;
        let bin = |s: &&str| *s == "autostereo" || s.ends_with("/autostereo");
        let dashes = w.iter().position(|s| *s == "--");
        let start = match (w[k], w.get(k + 1)) {
            ("cargo", Some(&"run")) if !w.contains(&"--example") => dashes?,
            (p, _) if WRAPPERS.contains(&p) => k + 1 + w[k + 1..].iter().position(bin)?,
            (p, _) => (bin(&p)).then_some(k)?,
        };
        let args: Vec<String> = w[start + 1..].iter().map(|s| s.to_string()).collect();
        (!args.is_empty()).then_some(args)
    })
}

/// Physical lines joined over trailing `\`: (first line's number, text) once a line ends.
fn join(lines: &mut (usize, String), n: usize, line: &str) -> Option<(usize, String)> {
    if lines.1.ends_with('\\') {
        lines.1.pop();
        lines.1 += line;
    } else {
        *lines = (n, line.into());
    }
    (!line.ends_with('\\')).then(|| lines.clone())
}

/// Where a line comes from: what counts as a command there.
#[derive(Clone, Copy, PartialEq)]
enum Src {
    /// A fenced or indented code block: commands, and usage synopses (`[--x]`, `a|b`, `SPEC`).
    Code,
    /// An inline code span: as a code block's line, and fragments that name a command without
    /// its required arguments (`autostereo mask --gpu`).
    Span,
    /// A docs/tools script line, its variables substituted.
    Script,
}

/// What the checks found.
#[derive(Default)]
struct Report {
    parsed: usize,
    synopses: usize,
    skipped: Vec<String>,
    failures: Vec<String>,
    /// OTHER_TOOLS' flags the docs name: an entry they no longer name is stale.
    used: BTreeSet<String>,
}

impl Report {
    /// `raw` (a logical line) parses, if it runs the CLI.
    fn check(&mut self, loc: String, raw: &str, src: Src, env: &Env, flags: &Flags) {
        let toks = tokens(&expand(raw, env));
        let Some(args) = cli_args(&toks) else { return };
        let code = raw.split(" #").next().unwrap_or(raw);
        let placeholder = |w: &str| {
            let upper = |c: char| c.is_ascii_uppercase();
            w.chars().any(upper) && w.chars().all(|c| upper(c) || "_x,:".contains(c))
        };
        let marks = code.contains(['[', '(', '|', '…']);
        let synopsis = marks || code.split_whitespace().any(placeholder);
        if src != Src::Script && synopsis {
            self.synopses += 1; // its flags are check 2's
        } else if args.iter().any(|w| w == UNKNOWN) {
            self.skipped.push(format!("{loc}: {}", raw.trim()));
            let (sub, own) = (&args[0], flags.get(&args[0]).unwrap_or(&flags[""]));
            let args = args.iter().filter_map(|w| w.split('=').next());
            for flag in args.filter(|f| f.starts_with("--") && !own.contains(*f)) {
                self.failures
                    .push(format!("{loc}: {flag} is not a flag of `{sub}`"));
            }
        } else {
            let argv = ["autostereo".to_string()].into_iter();
            let missing = clap::error::ErrorKind::MissingRequiredArgument;
            let argv = argv.chain(args.iter().map(|w| w.replace(UNKNOWN, "x")));
            match command().try_get_matches_from(argv) {
                Ok(_) => self.parsed += 1,
                Err(e) if src == Src::Span && e.kind() == missing => self.synopses += 1,
                Err(e) => {
                    let e = e.to_string().lines().next().unwrap_or_default().to_string();
                    self.failures.push(format!("{loc}: `{}`: {e}", raw.trim()))
                }
            }
        }
    }

    /// Check 1 on a Markdown file's code, check 2 on all its lines.
    fn markdown(&mut self, path: &str, text: &str, flags: &Flags) {
        let (mut fence, mut rust, mut indented, mut in_span) = (false, false, false, false);
        let (mut blank, mut carried, mut lines, none) =
            (true, None, (0, String::new()), Env::new());
        for (n, line) in text.lines().enumerate().map(|(n, l)| (n + 1, l)) {
            let line = &bench_as_subcommand(line);
            let t = line.trim_start();
            let blank_before = std::mem::replace(&mut blank, t.is_empty());
            if t.starts_with("```") {
                (fence, rust, in_span, carried) = (!fence, t.contains("rust"), false, None);
                continue;
            }
            // Markdown's indented code: after a blank line, not a list item's continuation.
            indented = line.starts_with("    ") && (indented || blank_before);
            // (offset, subcommand): from there on the line's flags are that subcommand's (None: any).
            let mut ranges: Vec<(usize, Option<&str>)> = vec![(0, None)];
            if fence || indented {
                let mut hash = line.match_indices('#').map(|(i, _)| i);
                let comment = hash.find(|&i| i == 0 || line[..i].ends_with(' '));
                let comment = comment.unwrap_or(line.len());
                // A synopsis's `[…]` lines and `\` continuations are the line above's command.
                let continued = t.starts_with('[') || lines.1.ends_with('\\');
                let above = carried.filter(|_| continued).map(|s| (0, s));
                let own = owner(&line[..comment], flags).or(above);
                ranges.extend([(own.map_or(0, |o| o.0), own.map(|o| o.1)), (comment, None)]);
                carried = own.map(|o| o.1);
                if let Some((first, cmd)) = join(&mut lines, n, line).filter(|_| !rust) {
                    self.check(format!("{path}:{first}"), &cmd, Src::Code, &none, flags);
                }
            } else {
                (in_span, lines) = (in_span && !t.is_empty(), (n, String::new()));
                let (mut at, segments) = (0, line.split('`').collect::<Vec<_>>());
                for (k, seg) in segments.iter().enumerate() {
                    let span = in_span ^ (k % 2 == 1);
                    if let Some((end, s)) = owner(seg, flags).filter(|_| span) {
                        ranges.extend([(at + end, Some(s)), (at + seg.len(), None)]);
                    }
                    // Only spans that open and close on this line are whole commands.
                    if span && k > 0 && k + 1 < segments.len() {
                        self.check(format!("{path}:{n}"), seg, Src::Span, &none, flags);
                    }
                    at += seg.len() + 1;
                }
                in_span ^= segments.len() % 2 == 0;
            }
            for (at, flag) in flag_tokens(line) {
                let own = ranges.iter().rev().find(|r| r.0 <= at).and_then(|r| r.1);
                if own.is_none() && OTHER_TOOLS.iter().any(|o| o.0 == flag) {
                    self.used.insert(flag);
                } else if !flags[own.unwrap_or("")].contains(&flag) {
                    let whose = own.map_or("any command".into(), |s| format!("`autostereo {s}`"));
                    self.failures
                        .push(format!("{path}:{n}: {flag} is not a flag of {whose}"));
                }
            }
        }
    }

    /// Check 1 on a shell script, its variables followed line by line.
    fn script(&mut self, path: &str, text: &str, flags: &Flags) {
        let (mut env, mut lines) = (Env::new(), (0, String::new()));
        for (n, line) in text.lines().enumerate() {
            if let Some((first, cmd)) = join(&mut lines, n + 1, &bench_as_subcommand(line)) {
                assign(&cmd, &mut env);
                self.check(format!("{path}:{first}"), &cmd, Src::Script, &env, flags);
            }
        }
    }
}

/// The subcommand a doc text names (`autostereo SUB`, `cargo run … -- SUB`): where its
/// arguments start, and which it is.
fn owner<'a>(text: &str, flags: &'a Flags) -> Option<(usize, &'a str)> {
    let subs = flags.keys().filter(|s| !s.is_empty());
    let found = subs.flat_map(|s| ["autostereo ", "-- "].map(|p| (format!("{p}{s}"), s)));
    let ends_word = |rest: &str| rest.chars().next().is_none_or(|c| " `\\".contains(c));
    let found = found.filter_map(|(pat, s)| {
        let mut hits = text.match_indices(&pat).map(|(i, _)| i);
        let i = hits.find(|i| ends_word(&text[i + pat.len()..]))?;
        Some((i, i + pat.len(), s.as_str()))
    });
    found.min_by_key(|m| m.0).map(|(_, end, s)| (end, s))
}

/// Every `--flag` in a line, at its byte offset.
fn flag_tokens(line: &str) -> Vec<(usize, String)> {
    let word_char = |c: char| c.is_alphanumeric() || "-_".contains(c);
    let starts = line.match_indices("--").map(|(i, _)| i);
    let starts = starts.filter(|&i| !line[..i].ends_with(word_char));
    let flag_char = |c: char| c.is_ascii_alphanumeric() || c == '-';
    let name = |i: usize| line[i + 2..].split(|c| !flag_char(c)).next();
    let names = starts.map(|i| (i, name(i).unwrap_or_default().trim_end_matches('-')));
    let names = names.filter(|(_, n)| n.starts_with(|c: char| c.is_ascii_lowercase()));
    names.map(|(i, n)| (i, format!("--{n}"))).collect()
}

#[test]
fn doc_examples_parse_and_name_existing_flags() {
    let (flags, mut md, mut sh, mut r) = (flags(), vec![], vec![], Report::default());
    files("docs", ".md", &mut md);
    files("docs/tools", ".sh", &mut sh);
    let readme = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../README.md"));
    md.insert(0, ("README.md".into(), readme.unwrap()));
    md.iter().for_each(|(p, t)| r.markdown(p, t, &flags));
    sh.iter().for_each(|(p, t)| r.script(p, t, &flags));
    let (parsed, synopses, skipped) = (r.parsed, r.synopses, r.skipped.len());
    println!("{parsed} commands parsed, {synopses} synopses/fragments, {skipped} skipped");
    let mut problems = r.failures;
    if skipped > MAX_SKIPPED {
        problems.push(format!("{skipped} lines unchecked, over {MAX_SKIPPED}:"));
        problems.extend(r.skipped);
    }
    for (flag, whose) in OTHER_TOOLS.iter().filter(|o| !r.used.contains(o.0)) {
        problems.push(format!("{flag} ({whose}): allow-listed, named nowhere"));
    }
    // Guards the extraction itself: one that finds nothing passes vacuously.
    if parsed < 90 {
        problems.push(format!("only {parsed} commands found"));
    }
    assert!(problems.is_empty(), "docs vs CLI:\n{}", problems.join("\n"));
}
