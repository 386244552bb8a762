//! The fuzz campaign (not run in CI; README gives the command and its last result):
//!
//! ```text
//! GEARLOSS_FUZZ_CASES=100000 cargo test --release --test it -- --ignored --exact fuzz_campaign::fuzz_campaign --nocapture
//! ```
//!
//! Every case is a grammar-aware mutation of a seed (every scene in specs/ and tests/specs/): numbers
//! swapped for extreme ones (0, ±1e308, 5e-324, NaN, inf, huge counts), units swapped for others of
//! the unit table, lines deleted, duplicated or swapped, blocks nested up to 60 deep, names swapped,
//! invisible and look-alike characters inserted, the text cut short. Each goes through `check` and,
//! when valid, the whole run in memory (evaluate, report, render, record files). A case fails on a
//! panic, on a hang (a watchdog aborts the campaign after [`CASE_SECONDS`] and leaves the case in
//! `target/fuzz/hang.gear`), on a diagnostic without hint or with a raw control character, and on a
//! non-finite number reaching a report. Memory per case is bounded by running the command under
//! `ulimit -v`; an abort leaves the case in `target/fuzz/current-*.gear`. Failing cases are written
//! to `target/fuzz/failures/` and become fixtures in tests/specs/err.

use std::path::PathBuf;
use std::sync::atomic::{AtomicU64, AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::Instant;

/// Seconds a case may take before the watchdog calls it a hang.
const CASE_SECONDS: u64 = 120;
/// Largest sweep run whole in the campaign (larger valid scenes are checked only, and counted).
const MAX_RUN_POINTS: usize = 20_000;
const MAX_RUN_DYNAMICS_POINTS: usize = 100;

/// splitmix64: a small, seedable generator (the campaign is reproducible from its seed).
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
    fn pick<'a, T>(&mut self, v: &'a [T]) -> &'a T {
        &v[self.below(v.len())]
    }
}

const EXTREME_NUMBERS: &[&str] = &[
    "0",
    "-0",
    "-1",
    "1e308",
    "-1e308",
    "1e-308",
    "5e-324",
    "1e400",
    "NaN",
    "inf",
    "-inf",
    "1e6",
    "1e-6",
    "0.5",
    "123456789",
    "2",
    "3",
    "100000",
    "1e-12",
    "7",
];
const COMPOUND_UNITS: &[&str] =
    &["N*m", "lbf*in", "kg*m^2", "1/Pa", "mm^2/s", "m^6*m^6*m^6*m^6*m^6", "rpm", "degC", "1/in"];
const INSERTS: &[&str] = &[
    "\u{00A0}",
    "\u{2212}",
    "\u{FEFF}",
    "\u{200B}",
    ",",
    "{",
    "}",
    "[",
    "]",
    "(",
    ")",
    "\"",
    "#",
    "\r",
    "\u{7}",
    "=",
    "..",
    " step 0",
    " count 100000",
    "ï",
    "µ",
    "\n",
];
const NAMES: &[&str] = &[
    "module",
    "teeth",
    "profile_shift",
    "tip_diameter",
    "face_width",
    "center_distance",
    "pinion_torque",
    "pinion_speed",
    "coulomb",
    "xu",
    "composite",
    "benedict_kelley",
    "efficiency",
    "dynamics",
    "stability_map",
    "film",
    "friction_along_loa",
    "mesh_stiffness",
    "iso_6336",
    "equal",
    "none",
    "external",
    "internal",
    "base",
    "detail_points",
    "pressure_viscosity",
    "dynamic_viscosity",
    "load_sharing",
    "inertia",
    "numerics",
];

/// Every seed scene, made quick to run: the numerics study (seconds of timing runs) is dropped,
/// stability maps cut to two speeds, operating lists to their first value and ranges to two values
/// (mutations still write large counts and long lists); the 100 001-value list fixture is left out.
/// Seeds in two sets: valid scenes (specs/, tests/specs/ok) and invalid ones (tests/specs/err).
fn seeds() -> (Vec<String>, Vec<String>) {
    (seeds_in(&["specs", "tests/specs/ok"]), seeds_in(&["tests/specs/err"]))
}

fn seeds_in(dirs: &[&str]) -> Vec<String> {
    let mut out = Vec::new();
    for dir in dirs {
        let mut paths: Vec<PathBuf> =
            std::fs::read_dir(crate::root().join(dir)).unwrap().map(|e| e.unwrap().path()).collect();
        paths.sort();
        for p in paths.into_iter().filter(|p| p.extension().is_some_and(|e| e == "gear")) {
            let Ok(text) = std::fs::read_to_string(&p) else { continue };
            if text.len() > 100_000 {
                continue;
            }
            let text = text
                .lines()
                .filter(|l| l.trim() != "numerics")
                .map(|l| {
                    if l.contains("stability_map(") {
                        "        stability_map(pinion_speed = [1000, 20000] rpm)".to_string()
                    } else {
                        shorten_sweeps(l)
                    }
                })
                .collect::<Vec<_>>()
                .join("\n");
            out.push(text);
        }
    }
    out
}

/// A line with its operating lists cut to the first value and its ranges to `count 2`.
fn shorten_sweeps(line: &str) -> String {
    let mut l = line.to_string();
    if l.contains("pinion_torque") || l.contains("pinion_speed") {
        if let (Some(a), Some(b)) = (l.find('['), l.find(']')) {
            if let Some(c) = l[a..b].find(',') {
                l.replace_range(a + c..b, "");
            }
        }
    }
    for word in ["count ", "step "] {
        if let Some(at) = l.find(word) {
            let end = l[at + word.len()..]
                .find(|c: char| !(c.is_ascii_alphanumeric() || c == '.'))
                .map_or(l.len(), |e| at + word.len() + e);
            l.replace_range(at..end, "count 2");
        }
    }
    l
}

fn unit_names() -> Vec<&'static str> {
    gearloss::scene::units::UNITS.iter().map(|u| u.name).collect()
}

/// Byte ranges of the numbers and of the words in `text`.
fn tokens(text: &str, number: bool) -> Vec<(usize, usize)> {
    let b = text.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        let is_start = if number { b[i].is_ascii_digit() } else { b[i].is_ascii_alphabetic() };
        if is_start && (i == 0 || !(b[i - 1].is_ascii_alphanumeric() || b[i - 1] == b'_' || b[i - 1] == b'.')) {
            let mut j = i;
            while j < b.len()
                && (b[j].is_ascii_alphanumeric() || b[j] == b'_' || (number && (b[j] == b'.' || b[j] == b'-')))
            {
                j += 1;
            }
            out.push((i, j));
            i = j;
        } else {
            i += 1;
        }
    }
    out
}

/// One mutation of `text`.
fn mutate(text: &str, rng: &mut Rng, units: &[&str]) -> String {
    let lines: Vec<&str> = text.lines().collect();
    let boundary = |t: &str, mut at: usize| {
        at = at.min(t.len());
        while !t.is_char_boundary(at) {
            at -= 1;
        }
        at
    };
    match rng.below(12) {
        10 | 11 => {
            // A plausible neighbour: the number scaled by a factor from 0.5 to 2.
            let nums = tokens(text, true);
            if nums.is_empty() {
                return text.to_string();
            }
            let (a, b) = *rng.pick(&nums);
            let Ok(x) = text[a..b].parse::<f64>() else { return text.to_string() };
            let f = 0.5 + 1.5 * (rng.below(1000) as f64 / 1000.0);
            format!("{}{}{}", &text[..a], x * f, &text[b..])
        }
        0 | 1 => {
            let nums = tokens(text, true);
            if nums.is_empty() {
                return text.to_string();
            }
            let (a, b) = *rng.pick(&nums);
            format!("{}{}{}", &text[..a], rng.pick(EXTREME_NUMBERS), &text[b..])
        }
        2 => {
            let words: Vec<(usize, usize)> =
                tokens(text, false).into_iter().filter(|(a, b)| units.contains(&&text[*a..*b])).collect();
            if words.is_empty() {
                return text.to_string();
            }
            let (a, b) = *rng.pick(&words);
            let unit = if rng.below(3) == 0 { *rng.pick(COMPOUND_UNITS) } else { *rng.pick(units) };
            format!("{}{}{}", &text[..a], unit, &text[b..])
        }
        3 if !lines.is_empty() => {
            let k = rng.below(lines.len());
            lines.iter().enumerate().filter(|(i, _)| *i != k).map(|(_, l)| *l).collect::<Vec<_>>().join("\n")
        }
        4 if !lines.is_empty() => {
            let k = rng.below(lines.len());
            let mut v = lines.clone();
            v.insert(k, lines[k]);
            v.join("\n")
        }
        5 if lines.len() > 1 => {
            let (i, j) = (rng.below(lines.len()), rng.below(lines.len()));
            let mut v = lines.clone();
            v.swap(i, j);
            v.join("\n")
        }
        6 => {
            let depth = 1 + rng.below(60);
            let at = boundary(text, rng.below(text.len() + 1));
            format!("{}{}{}{}", &text[..at], "x {".repeat(depth), "}".repeat(depth), &text[at..])
        }
        7 => {
            let words = tokens(text, false);
            if words.is_empty() {
                return text.to_string();
            }
            let (a, b) = *rng.pick(&words);
            format!("{}{}{}", &text[..a], rng.pick(NAMES), &text[b..])
        }
        8 => {
            let at = boundary(text, rng.below(text.len() + 1));
            format!("{}{}{}", &text[..at], rng.pick(INSERTS), &text[at..])
        }
        _ => text[..boundary(text, rng.below(text.len() + 1))].to_string(),
    }
}

/// What one case did.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Outcome {
    Diagnostic,
    Report,
    CheckedOnly,
    Panic,
    BadDiagnostic,
    NonFinite,
}

fn case(text: &str) -> Outcome {
    let result = std::panic::catch_unwind(|| match gearloss::check("fuzz.gear", text) {
        Err(e) => {
            let ok = !e.diagnostics.is_empty()
                && e.diagnostics.iter().all(|d| {
                    !d.hints.is_empty()
                        && std::iter::once(&d.reason).chain(&d.hints).all(|t| !t.chars().any(char::is_control))
                        && d.span.end <= text.len()
                });
            let _ = e.render(false);
            if ok {
                Outcome::Diagnostic
            } else {
                Outcome::BadDiagnostic
            }
        }
        Ok(scene) => {
            let dynamics = scene.dynamics.is_some() && scene.analyses.dynamics;
            let n = scene.operating.count();
            if n > MAX_RUN_POINTS || (dynamics && n > MAX_RUN_DYNAMICS_POINTS) {
                return Outcome::CheckedOnly;
            }
            match gearloss::run_to_files("fuzz.gear", text) {
                Err(_) => Outcome::BadDiagnostic,
                Ok(r) => {
                    let json = &r.files.iter().find(|(f, _)| f == "report.json").expect("report.json").1;
                    let v: serde_json::Value = serde_json::from_str(json).expect("report.json parses");
                    let flagged = v["findings"].as_array().is_some_and(|f| {
                        f.iter().any(|x| x["message"].as_str().is_some_and(|m| m.contains("not a finite number")))
                    });
                    let records = v["records"]["non_finite_values"].as_u64().unwrap_or(0);
                    if flagged || records > 0 {
                        Outcome::NonFinite
                    } else {
                        Outcome::Report
                    }
                }
            }
        }
    });
    result.unwrap_or(Outcome::Panic)
}

#[test]
#[ignore = "the fuzz campaign: minutes; run on demand (module docs)"]
fn fuzz_campaign() {
    let cases: usize = std::env::var("GEARLOSS_FUZZ_CASES").ok().and_then(|s| s.parse().ok()).unwrap_or(100_000);
    let seed: u64 = std::env::var("GEARLOSS_FUZZ_SEED").ok().and_then(|s| s.parse().ok()).unwrap_or(1);
    let dir = crate::root().join("target/fuzz");
    std::fs::create_dir_all(dir.join("failures")).unwrap();
    let seeds = seeds();
    let units = unit_names();
    std::panic::set_hook(Box::new(|_| {}));
    let started = Instant::now();
    // Watchdog: the start time of each worker's case (ms since start; 0 = idle).
    let workers = 2;
    let busy: Vec<AtomicU64> = (0..workers).map(|_| AtomicU64::new(0)).collect();
    let current: Vec<Mutex<(usize, String)>> = (0..workers).map(|_| Mutex::new((0, String::new()))).collect();
    let next = AtomicUsize::new(0);
    let counts: Mutex<Vec<(Outcome, usize)>> = Mutex::new(Vec::new());
    let failures = AtomicUsize::new(0);
    std::thread::scope(|s| {
        s.spawn(|| loop {
            std::thread::sleep(std::time::Duration::from_secs(1));
            if next.load(Ordering::Relaxed) >= cases + workers {
                return;
            }
            let now = started.elapsed().as_millis() as u64;
            for (w, b) in busy.iter().enumerate() {
                let t = b.load(Ordering::Relaxed);
                if t > 0 && now.saturating_sub(t) > CASE_SECONDS * 1000 {
                    let (k, text) = current[w].lock().unwrap().clone();
                    std::fs::write(dir.join("hang.gear"), text).unwrap();
                    eprintln!("hang: case {k} ran over {CASE_SECONDS} s; it is in target/fuzz/hang.gear");
                    std::process::abort();
                }
            }
        });
        for w in 0..workers {
            let (busy, current, next, counts, failures, seeds, units, dir) =
                (&busy, &current, &next, &counts, &failures, &seeds, &units, &dir);
            // One single-threaded rayon pool per worker: cases never compete for one shared pool.
            let pool = rayon::ThreadPoolBuilder::new().num_threads(1).build().expect("a rayon pool");
            s.spawn(move || loop {
                let k = next.fetch_add(1, Ordering::Relaxed);
                if k > 0 && k % 10_000 == 0 && k < cases {
                    eprintln!("{k} cases in {:.0} s", started.elapsed().as_secs_f64());
                }
                if k >= cases {
                    next.fetch_add(1, Ordering::Relaxed);
                    return;
                }
                let mut rng = Rng(seed.wrapping_mul(0x1000_0000_0001).wrapping_add(k as u64));
                // Four in five cases start from a valid scene, so that most reach the run.
                let mut text = if rng.below(5) < 4 { rng.pick(&seeds.0) } else { rng.pick(&seeds.1) }.clone();
                for _ in 0..[1, 1, 1, 2, 2, 3][rng.below(6)] {
                    text = mutate(&text, &mut rng, units);
                }
                *current[w].lock().unwrap() = (k, text.clone());
                // Kept on disk while it runs: an abort (stack overflow, out of memory) leaves it here.
                std::fs::write(dir.join(format!("current-{w}.gear")), &text).unwrap();
                busy[w].store(started.elapsed().as_millis() as u64 + 1, Ordering::Relaxed);
                let outcome = pool.install(|| case(&text));
                busy[w].store(0, Ordering::Relaxed);
                if matches!(outcome, Outcome::Panic | Outcome::BadDiagnostic | Outcome::NonFinite) {
                    let n = failures.fetch_add(1, Ordering::Relaxed);
                    std::fs::write(dir.join(format!("failures/{outcome:?}-{n}.gear")), &text).unwrap();
                }
                let mut c = counts.lock().unwrap();
                match c.iter_mut().find(|(o, _)| *o == outcome) {
                    Some((_, n)) => *n += 1,
                    None => c.push((outcome, 1)),
                }
            });
        }
    });
    let _ = std::panic::take_hook();
    let counts = counts.into_inner().unwrap();
    let seconds = started.elapsed().as_secs_f64();
    println!(
        "fuzz campaign: {cases} cases from {} seeds (seed {seed}) in {seconds:.1} s",
        seeds.0.len() + seeds.1.len()
    );
    for (o, n) in &counts {
        println!("  {o:?}: {n}");
    }
    let failed = failures.load(Ordering::Relaxed);
    println!("  failures: {failed} (target/fuzz/failures/)");
    for w in 0..workers {
        let _ = std::fs::remove_file(dir.join(format!("current-{w}.gear")));
    }
    assert_eq!(failed, 0, "failing cases are in target/fuzz/failures/");
}

/// Reruns one case of the campaign: `GEARLOSS_FUZZ_FILE=target/fuzz/hang.gear cargo test --release --test it
/// -- --ignored --exact fuzz_campaign::fuzz_case --nocapture` prints its outcome and time.
#[test]
#[ignore = "reruns one fuzz case, on demand"]
fn fuzz_case() {
    let path = std::env::var("GEARLOSS_FUZZ_FILE").expect("GEARLOSS_FUZZ_FILE names the case");
    let text = String::from_utf8_lossy(&std::fs::read(path).unwrap()).into_owned();
    let started = Instant::now();
    let outcome = case(&text);
    println!("{outcome:?} in {:.2} s", started.elapsed().as_secs_f64());
}

/// A quick share of the campaign in every test run: 300 cases, so that the mutator itself stays tested.
#[test]
fn a_few_mutated_seeds_pass() {
    let seeds = seeds();
    let units = unit_names();
    let mut rng = Rng(7);
    for _ in 0..300 {
        let mut text = if rng.below(2) == 0 { rng.pick(&seeds.0) } else { rng.pick(&seeds.1) }.clone();
        text = mutate(&text, &mut rng, &units);
        let o = case(&text);
        assert!(matches!(o, Outcome::Diagnostic | Outcome::Report | Outcome::CheckedOnly), "{o:?}:\n{text}");
    }
}
