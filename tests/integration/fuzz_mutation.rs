//! Grammar-aware mutation fuzzing of the real binary, for a bounded time (CI runs it on
//! every submission; `docs/fuzzing.md`).
//!
//! Each case takes a seed scene from `tests/`, applies one to four token-level mutations
//! (splice, delete, duplicate, insert a keyword, unbalance a bracket, deep nesting, huge
//! numbers, long lines, unclosed constructs, stray bytes) and runs `durer check` or
//! `durer render` at 8 x 6 in a subprocess with a timeout and a memory limit. A case fails
//! on a panic (exit code 101 or "panicked"), a signal (a stack overflow's SIGSEGV or
//! SIGABRT) or a timeout; the failing scene is written to
//! `target/tmp/fuzz-mutation/` with the command and its output.
//!
//! Cases come from fixed seeds first (the same every run), then from a fresh seed per run,
//! printed so a failure can be replayed. Environment:
//! - `DURER_FUZZ_SECONDS`: time budget (default 75 s; the fixed seeds always run);
//! - `DURER_FUZZ_SEED`: run this seed instead of a fresh one (as printed).
//!
//! The generators go past every limit of `docs/limits.md` (nesting 20,001 deep, 24
//! unclosed `/*`, `#macro`, `<` or `"` in one case, lines of 200,000 characters): each must
//! end in a diagnostic within the timeout.

use crate::{scratch, tests_folder};
use durer::syntax::tokens::{next_token, TokenKind};
use std::io::Read;
use std::os::unix::process::ExitStatusExt;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// SplitMix64: a fixed, documented generator, so a printed seed replays the same cases on
/// any machine and with any crate versions (a crate's generator may change its stream).
#[derive(Clone, Debug)]
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// A number in `0..n` (`n` > 0).
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }

    /// A number in `low..=high`.
    fn between(&mut self, low: usize, high: usize) -> usize {
        low + self.below(high - low + 1)
    }

    fn pick<'a, T>(&mut self, items: &'a [T]) -> &'a T {
        &items[self.below(items.len())]
    }

    fn chance(&mut self, one_in: usize) -> bool {
        self.below(one_in) == 0
    }
}

/// How far the generators go: past the nesting limit (20,000), more unclosed constructs
/// than a backtracking parser survives, lines past the report printer's old 65,535-column
/// panic.
#[derive(Clone, Copy, Debug)]
struct Caps {
    /// Deepest nesting a generator writes.
    nesting: usize,
    /// Most unclosed `/*`, `#macro` or `<` one case adds.
    unclosed: usize,
    /// Longest line a generator writes, in characters.
    line: usize,
}

const CAPS: Caps = Caps {
    nesting: 20_001,
    unclosed: 24,
    line: 200_000,
};

/// A scene cut into tokens, each with the text (whitespace, comments) that follows it.
struct Pieces {
    /// Text before the first token.
    head: String,
    pieces: Vec<String>,
}

impl Pieces {
    fn of(text: &str) -> Pieces {
        let mut tokens = Vec::new();
        let mut position = 0;
        while let Some(token) = next_token(text, position) {
            if token.end <= position || !text.is_char_boundary(token.end) {
                break;
            }
            tokens.push(token);
            position = token.end;
        }
        let head = text[..tokens.first().map_or(text.len(), |t| t.start)].to_string();
        let pieces = tokens
            .iter()
            .enumerate()
            .map(|(i, t)| {
                let end = tokens.get(i + 1).map_or(text.len(), |n| n.start);
                text[t.start..end].to_string()
            })
            .collect();
        Pieces { head, pieces }
    }

    fn text(&self) -> String {
        let mut text = self.head.clone();
        for piece in &self.pieces {
            text.push_str(piece);
        }
        text
    }

    /// A position to insert at (`0..=len`).
    fn position(&self, rng: &mut Rng) -> usize {
        rng.below(self.pieces.len() + 1)
    }

    /// A run of up to `most` pieces: start and end.
    fn run(&self, rng: &mut Rng, most: usize) -> Option<(usize, usize)> {
        if self.pieces.is_empty() {
            return None;
        }
        let start = rng.below(self.pieces.len());
        let end = (start + rng.between(1, most)).min(self.pieces.len());
        Some((start, end))
    }

    fn insert(&mut self, at: usize, text: String) {
        self.pieces.insert(at.min(self.pieces.len()), text);
    }
}

/// The mutations, by name (printed in the summary).
const MUTATIONS: &[&str] = &[
    "delete",
    "duplicate",
    "splice",
    "keyword",
    "bracket",
    "nesting",
    "number",
    "long-line",
    "unclosed",
    "bytes",
];

/// Directive words worth inserting (with `#`), besides the keyword table.
const DIRECTIVES: &[&str] = &[
    "#declare X = ",
    "#local X = ",
    "#undef X",
    "#if (1)",
    "#else",
    "#end",
    "#while (0)",
    "#for (I, 0, 3)",
    "#switch (1)",
    "#case (1)",
    "#break",
    "#ifdef (X)",
    "#version 3.5;",
    "#default { pigment { rgb 1 } }",
    "#debug \"x\"",
    "#warning \"x\"",
    "#error \"x\"",
    "#include \"colors.inc\"",
];

/// Numbers that stress arithmetic, sizes and counts.
const HUGE_NUMBERS: &[&str] = &[
    "1e308",
    "-1e308",
    "1e400",
    "1e-320",
    "0",
    "-0",
    "-1",
    "4294967296",
    "18446744073709551616",
    "2147483647",
    "1/0",
    "0/0",
    "-1e9",
    "1e9",
    "65536",
    "0.000000001",
];

/// Nested constructs: opening and closing text, repeated `depth` times around a core.
const NESTINGS: &[(&str, &str, &str)] = &[
    ("union { ", " }", "sphere { 0, 1 }"),
    ("object { ", " }", "box { -1, 1 }"),
    ("difference { sphere { 0, 1 } ", " }", "sphere { 0, 1 }"),
    ("(", ")", "1"),
    ("-", "", "1"),
    ("<", ",1,1>", "1"),
    ("array[1] { ", " }", "1"),
    ("pigment { ", " }", "rgb 1"),
    ("#if (1) ", " #end", "sphere { 0, 1 }"),
    ("/* ", " */", ""),
    ("function { ", " }", "x"),
];

/// Text that leaves a construct open.
const UNCLOSED: &[&str] = &[
    "/* ",
    "#macro M() ",
    "< ",
    "\"",
    "#if (1) ",
    "{ ",
    "#while (0) ",
];

/// A line of about `length` characters.
fn long_line(rng: &mut Rng, length: usize) -> String {
    let unit = *rng.pick(&["1+", "x", " ", "sphere{0,1}", "\"ab\"", "//", "é"]);
    let mut line = String::with_capacity(length + 16);
    match rng.below(4) {
        // A long string literal or identifier, then something wrong on the same line.
        0 => {
            line.push_str("#declare S = \"");
            while line.len() < length {
                line.push('a');
            }
            line.push_str("\"; sphere { 0, pigmnet }");
        }
        1 => {
            line.push_str("#declare ");
            while line.len() < length {
                line.push('a');
            }
            line.push_str(" = ;");
        }
        // Spaces, then an error far along the line.
        2 => {
            while line.len() < length {
                line.push(' ');
            }
            line.push_str("sphere { 0 pigment }");
        }
        _ => {
            while line.len() < length {
                line.push_str(unit);
            }
        }
    }
    line.push('\n');
    line
}

/// Applies one mutation; returns its name.
fn mutate(
    pieces: &mut Pieces,
    rng: &mut Rng,
    donors: &[String],
    caps: &Caps,
    unclosed: &mut usize,
) -> &'static str {
    let kind = *rng.pick(MUTATIONS);
    match kind {
        "delete" => {
            if let Some((start, end)) = pieces.run(rng, 4) {
                pieces.pieces.drain(start..end);
            }
        }
        "duplicate" => {
            if let Some((start, end)) = pieces.run(rng, 12) {
                let copy: Vec<String> = pieces.pieces[start..end].to_vec();
                // Many copies only of a run that leaves nothing open (so the copies stay
                // within the cap on unclosed constructs).
                let joined = copy.concat();
                let count = |s: &str| joined.matches(s).count();
                let balanced = count("#macro") == 0
                    && count("/*") == count("*/")
                    && count("<") == count(">")
                    && count("{") == count("}")
                    && count("(") == count(")")
                    && count("[") == count("]");
                let times = if balanced && rng.chance(8) {
                    rng.between(2, 50)
                } else {
                    1
                };
                let at = if rng.chance(2) {
                    end
                } else {
                    pieces.position(rng)
                };
                for _ in 0..times {
                    for (offset, piece) in copy.iter().enumerate() {
                        pieces.insert(at + offset, piece.clone());
                    }
                }
            }
        }
        "splice" => {
            let donor = Pieces::of(rng.pick(donors).as_str());
            if let Some((start, end)) = donor.run(rng, 40) {
                let at = pieces.position(rng);
                for (offset, piece) in donor.pieces[start..end].iter().enumerate() {
                    pieces.insert(at + offset, piece.clone());
                }
            }
        }
        "keyword" => {
            let word = if rng.chance(3) {
                rng.pick(DIRECTIVES).to_string()
            } else {
                rng.pick(durer::syntax::keywords::ALL).to_string()
            };
            let at = pieces.position(rng);
            pieces.insert(at, format!("{word} "));
        }
        "bracket" => {
            let brackets = ["{", "}", "<", ">", "(", ")", "[", "]", ",", ";"];
            let candidates: Vec<usize> = (0..pieces.pieces.len())
                .filter(|&i| brackets.iter().any(|b| pieces.pieces[i].starts_with(b)))
                .collect();
            if !candidates.is_empty() && rng.chance(2) {
                let i = *rng.pick(&candidates);
                pieces.pieces.remove(i);
            } else {
                let at = pieces.position(rng);
                pieces.insert(at, format!("{} ", rng.pick(&brackets)));
            }
        }
        "nesting" => {
            let (open, close, core) = *rng.pick(NESTINGS);
            let depth = rng.between(2, caps.nesting);
            let mut text = String::new();
            for _ in 0..depth {
                text.push_str(open);
            }
            text.push_str(core);
            for _ in 0..depth {
                text.push_str(close);
            }
            text.push('\n');
            let at = pieces.position(rng);
            pieces.insert(at, text);
        }
        "number" => {
            let numbers: Vec<usize> = (0..pieces.pieces.len())
                .filter(|&i| {
                    next_token(&pieces.pieces[i], 0).is_some_and(|t| t.kind == TokenKind::Number)
                })
                .collect();
            let number = rng.pick(HUGE_NUMBERS).to_string();
            if numbers.is_empty() {
                let at = pieces.position(rng);
                pieces.insert(at, format!("{number} "));
            } else {
                let i = *rng.pick(&numbers);
                let rest = next_token(&pieces.pieces[i], 0).map_or(0, |t| t.end);
                pieces.pieces[i] = format!("{number}{}", &pieces.pieces[i][rest..]);
            }
        }
        "long-line" => {
            let length = rng.between(1_000, caps.line.saturating_sub(64).max(1_000));
            let line = long_line(rng, length);
            let at = pieces.position(rng);
            pieces.insert(at, line);
        }
        "unclosed" => {
            if *unclosed < caps.unclosed {
                *unclosed += 1;
                let at = pieces.position(rng);
                pieces.insert(at, rng.pick(UNCLOSED).to_string());
            }
        }
        _ => {
            // Stray bytes: control characters, a NUL, a lone surrogate's replacement,
            // characters outside ASCII.
            let stray = *rng.pick(&["\0", "\u{1}", "\u{7f}", "\u{feff}", "\u{fffd}", "é", "\r"]);
            let at = pieces.position(rng);
            pieces.insert(at, stray.to_string());
        }
    }
    kind
}

/// How a case ended.
#[derive(Debug, PartialEq)]
enum Verdict {
    /// Exit 0, or a diagnostic with this non-zero exit code.
    Clean(i32),
    /// A failure, described.
    Failure(String),
}

/// The binary, under a memory limit (virtual memory: the evaluator's 1 GiB stack is
/// reserved, not used) through the shell's `ulimit`.
fn limited_command(args: &[&str], memory_kib: u64) -> Command {
    let mut command = Command::new("sh");
    command
        .arg("-c")
        .arg(format!("ulimit -v {memory_kib} && exec \"$0\" \"$@\""))
        .arg(env!("CARGO_BIN_EXE_durer"))
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::piped());
    command
}

/// Runs one command with a timeout; the verdict and the standard error.
fn run_case(args: &[&str], timeout: Duration) -> (Verdict, String) {
    let mut child = match limited_command(args, 6 << 20).spawn() {
        Ok(child) => child,
        Err(e) => {
            return (
                Verdict::Failure(format!("cannot start: {e}")),
                String::new(),
            )
        }
    };
    // Read standard error on a thread, so a chatty scene cannot block on a full pipe.
    let mut stderr = child.stderr.take().expect("piped stderr");
    let reader = std::thread::spawn(move || {
        let mut bytes = Vec::new();
        let _ = stderr.by_ref().take(1 << 20).read_to_end(&mut bytes);
        let _ = std::io::copy(&mut stderr, &mut std::io::sink());
        String::from_utf8_lossy(&bytes).into_owned()
    });
    let start = Instant::now();
    let status = loop {
        match child.try_wait() {
            Ok(Some(status)) => break Some(status),
            Ok(None) if start.elapsed() > timeout => {
                let _ = child.kill();
                let _ = child.wait();
                break None;
            }
            Ok(None) => std::thread::sleep(Duration::from_millis(3)),
            Err(_) => break None,
        }
    };
    let stderr = reader.join().unwrap_or_default();
    let verdict = match status {
        None => Verdict::Failure(format!("timeout after {} s", timeout.as_secs())),
        Some(status) => match (status.code(), status.signal()) {
            (_, Some(signal)) => Verdict::Failure(format!("killed by signal {signal}")),
            (Some(101), _) => Verdict::Failure("panic (exit code 101)".into()),
            _ if stderr.contains("panicked") => Verdict::Failure("panic message".into()),
            _ if stderr.contains("has overflowed its stack") => {
                Verdict::Failure("stack overflow".into())
            }
            (code, _) => Verdict::Clean(code.unwrap_or(0)),
        },
    };
    (verdict, stderr)
}

/// Seed scenes: the small `.pov` files of the test folders, sorted.
fn seed_scenes() -> Vec<(PathBuf, String)> {
    let mut scenes = Vec::new();
    for folder in ["reference", "language", "diagnostics", "stdlib", "cli"] {
        let Ok(entries) = std::fs::read_dir(tests_folder().join(folder)) else {
            continue;
        };
        for entry in entries.flatten() {
            let path = entry.path();
            let small = entry.metadata().is_ok_and(|m| m.len() < 6_000);
            if small && path.extension().is_some_and(|e| e == "pov") {
                if let Ok(text) = std::fs::read_to_string(&path) {
                    scenes.push((path, text));
                }
            }
        }
    }
    scenes.sort();
    scenes
}

/// Counts of a run, for the summary.
#[derive(Default)]
struct Tally {
    cases: usize,
    checks: usize,
    renders: usize,
    clean_exits: usize,
    error_exits: usize,
    slowest: Duration,
    failures: Vec<String>,
    mutations: std::collections::BTreeMap<&'static str, usize>,
}

/// Generates and runs case `index` of `seed`.
#[allow(clippy::too_many_arguments)]
fn run_one(
    seed: u64,
    index: u64,
    scenes: &[(PathBuf, String)],
    donors: &[String],
    caps: &Caps,
    dir: &Path,
    crashes: &Path,
    tally: &mut Tally,
) {
    let mut rng = Rng(seed ^ index.wrapping_mul(0xd1b5_4a32_d192_ed03));
    rng.next();
    let (origin, text) = rng.pick(scenes);
    let mut pieces = Pieces::of(text);
    let mut unclosed = 0;
    let mut applied = Vec::new();
    for _ in 0..rng.between(1, 4) {
        let kind = mutate(&mut pieces, &mut rng, donors, caps, &mut unclosed);
        *tally.mutations.entry(kind).or_default() += 1;
        applied.push(kind);
    }
    let scene = dir.join("case.pov");
    std::fs::write(&scene, pieces.text()).expect("write case");
    let scene_arg = scene.to_str().expect("utf-8 path");
    let library = origin.parent().and_then(Path::to_str).unwrap_or(".");
    let output = dir.join("case.png");
    let output_arg = output.to_str().expect("utf-8 path");
    let render = rng.chance(3);
    // Every case must end, within the limits: a tenth of the default object and iteration
    // limits keeps each one short (a loop turned endless by a mutated bound reached the
    // default 5,000,000 objects in 16 s on a loaded 2-core machine, past the 20 s budget
    // when tests share the machine).
    let limits = ["--limit", "objects=500000", "--limit", "iterations=1000000"];
    let mut args: Vec<&str> = if render {
        tally.renders += 1;
        vec![
            "render",
            scene_arg,
            "-L",
            library,
            "--width",
            "8",
            "--height",
            "6",
            "--threads",
            "1",
            "--quiet",
            "-o",
            output_arg,
        ]
    } else {
        tally.checks += 1;
        vec![
            "check", scene_arg, "-L", library, "--width", "8", "--height", "6",
        ]
    };
    args.extend(limits);
    let start = Instant::now();
    let (verdict, stderr) = run_case(&args, Duration::from_secs(20));
    tally.slowest = tally.slowest.max(start.elapsed());
    tally.cases += 1;
    match verdict {
        Verdict::Clean(0) => tally.clean_exits += 1,
        Verdict::Clean(_) => tally.error_exits += 1,
        Verdict::Failure(why) => {
            let name = format!("crash-{seed:016x}-{index}");
            let saved = crashes.join(format!("{name}.pov"));
            let _ = std::fs::copy(&scene, &saved);
            let report = format!(
                "{why}\nseed {seed:#018x} case {index} from {} with {applied:?}\ncommand: durer {}\n\
                 --- stderr ---\n{stderr}",
                origin.display(),
                args.join(" ")
            );
            let _ = std::fs::write(crashes.join(format!("{name}.txt")), &report);
            tally
                .failures
                .push(format!("{why}: {} ({})", saved.display(), origin.display()));
        }
    }
}

/// The fixed seeds every run starts with.
const FIXED_SEEDS: &[u64] = &[1, 2, 3, 0x5eed, 0xd0e4];
/// Cases run from each fixed seed.
const FIXED_CASES: u64 = 40;

#[test]
fn mutated_scenes_neither_crash_nor_hang() {
    let budget = std::env::var("DURER_FUZZ_SECONDS")
        .ok()
        .and_then(|s| s.parse().ok())
        .map_or(Duration::from_secs(75), Duration::from_secs);
    let fresh = std::env::var("DURER_FUZZ_SEED")
        .ok()
        .and_then(|s| u64::from_str_radix(s.trim_start_matches("0x"), 16).ok())
        .unwrap_or_else(|| {
            let now = std::time::SystemTime::now()
                .duration_since(std::time::UNIX_EPOCH)
                .unwrap_or_default();
            Rng(now.as_nanos() as u64 ^ u64::from(std::process::id())).next()
        });
    let caps = CAPS;
    println!(
        "fuzz_mutation: fresh seed {fresh:#018x} (replay: DURER_FUZZ_SEED={fresh:016x}), \
         budget {} s, caps {caps:?}",
        budget.as_secs()
    );
    let scenes = seed_scenes();
    assert!(scenes.len() > 50, "seed scenes found: {}", scenes.len());
    let donors: Vec<String> = scenes.iter().map(|(_, text)| text.clone()).collect();
    let dir = scratch("fuzz-mutation");
    let crashes = Path::new(env!("CARGO_TARGET_TMPDIR")).join("fuzz-mutation");
    std::fs::create_dir_all(&crashes).expect("crash folder");
    let mut tally = Tally::default();
    let start = Instant::now();
    for &seed in FIXED_SEEDS {
        for index in 0..FIXED_CASES {
            run_one(
                seed, index, &scenes, &donors, &caps, &dir, &crashes, &mut tally,
            );
        }
    }
    let fixed = tally.cases;
    let mut index = 0;
    while start.elapsed() < budget {
        run_one(
            fresh, index, &scenes, &donors, &caps, &dir, &crashes, &mut tally,
        );
        index += 1;
    }
    println!(
        "fuzz_mutation: {} cases ({fixed} from fixed seeds, {index} from seed {fresh:#x}) in \
         {:.1} s: {} check, {} render; {} ran clean, {} ended in a diagnostic; slowest {:.2} s; \
         {} failures",
        tally.cases,
        start.elapsed().as_secs_f64(),
        tally.checks,
        tally.renders,
        tally.clean_exits,
        tally.error_exits,
        tally.slowest.as_secs_f64(),
        tally.failures.len()
    );
    println!("fuzz_mutation: mutations applied {:?}", tally.mutations);
    assert!(
        tally.failures.is_empty(),
        "{} mutated scenes crashed or hung (each saved with a .txt of its command and \
         output):\n{}",
        tally.failures.len(),
        tally.failures.join("\n")
    );
}

#[test]
fn the_fuzz_dictionary_has_every_keyword() {
    let path = tests_folder().join("../fuzz/sdl.dict");
    let dict = std::fs::read_to_string(&path).expect("fuzz/sdl.dict");
    let missing: Vec<&str> = durer::syntax::keywords::ALL
        .iter()
        .copied()
        .filter(|word| !dict.contains(&format!("=\"{word}\"")))
        .collect();
    assert!(
        missing.is_empty(),
        "fuzz/sdl.dict lacks {missing:?}: run fuzz/make_dict.sh"
    );
}

#[test]
fn the_mutator_is_deterministic_and_respects_the_caps() {
    let scenes = seed_scenes();
    let donors: Vec<String> = scenes.iter().map(|(_, text)| text.clone()).collect();
    let generate = |seed: u64| {
        let mut rng = Rng(seed);
        let mut texts = Vec::new();
        for _ in 0..300 {
            let mut pieces = Pieces::of(&rng.pick(&scenes).1);
            let mut unclosed = 0;
            for _ in 0..4 {
                mutate(&mut pieces, &mut rng, &donors, &CAPS, &mut unclosed);
            }
            assert!(unclosed <= CAPS.unclosed);
            texts.push(pieces.text());
        }
        texts
    };
    let first = generate(7);
    assert_eq!(first, generate(7), "same seed, same scenes");
    assert_ne!(first, generate(8), "another seed, other scenes");
    for text in &first {
        let longest = text.lines().map(|l| l.chars().count()).max().unwrap_or(0);
        let seed_longest = scenes
            .iter()
            .map(|(_, t)| t.lines().map(|l| l.chars().count()).max().unwrap_or(0))
            .max()
            .unwrap_or(0);
        // Four mutations, each at most adding a line of the cap's length or doubling one.
        assert!(
            longest <= (CAPS.line + seed_longest.max(100)) * 16,
            "a line of {longest} characters"
        );
    }
    // The tokenizer's pieces give back the text they were cut from.
    for (_, text) in &scenes {
        assert_eq!(&Pieces::of(text).text(), text);
    }
}

/// One scene the fuzzers found, with what it must now do: its header lines say
/// `// command: check` (or `render`), `// expect: TEXT` (on standard error) and optionally
/// `// exit: N` (default 1).
struct Found {
    path: PathBuf,
    command: String,
    expect: String,
    exit: i32,
}

fn found_scenes() -> Vec<Found> {
    let mut found = Vec::new();
    let Ok(entries) = std::fs::read_dir(tests_folder().join("fuzz_found")) else {
        return found;
    };
    for path in entries.flatten().map(|e| e.path()) {
        if path.extension().is_none_or(|e| e != "pov") {
            continue;
        }
        let bytes = std::fs::read(&path).expect("read found scene");
        let text = String::from_utf8_lossy(&bytes);
        let header = |key: &str| {
            text.lines()
                .take_while(|l| l.starts_with("//"))
                .find_map(|l| l.strip_prefix(&format!("// {key}: ")).map(str::to_string))
        };
        found.push(Found {
            command: header("command").unwrap_or_else(|| "check".into()),
            expect: header("expect").unwrap_or_else(|| panic!("{}: no expect", path.display())),
            exit: header("exit").and_then(|e| e.parse().ok()).unwrap_or(1),
            path,
        });
    }
    found.sort_by(|a, b| a.path.cmp(&b.path));
    found
}

/// Every crash the fuzzers found (tests/fuzz_found/) now ends in its diagnostic.
#[test]
fn scenes_the_fuzzers_found_end_in_a_diagnostic() {
    let dir = scratch("fuzz-found");
    let output = dir.join("out.png");
    let mut wrong = Vec::new();
    let found = found_scenes();
    for scene in &found {
        let path = scene.path.to_str().expect("utf-8 path");
        let mut args = vec![
            scene.command.as_str(),
            path,
            "--width",
            "8",
            "--height",
            "6",
        ];
        if scene.command == "render" {
            args.extend(["--threads", "2", "--quiet", "-o"]);
            args.push(output.to_str().expect("utf-8 path"));
        }
        let (verdict, stderr) = run_case(&args, Duration::from_secs(30));
        if verdict != Verdict::Clean(scene.exit) || !stderr.contains(&scene.expect) {
            wrong.push(format!(
                "{}: {verdict:?} (want exit {} and {:?})\n{stderr}",
                scene.path.display(),
                scene.exit,
                scene.expect
            ));
        }
    }
    println!("fuzz_found: {} scenes", found.len());
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}
