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

use std::sync::atomic::{AtomicU64, AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::Instant;

use crate::fuzz_mutations::{mutate, seeds, unit_names, Rng};

/// Seconds a case may take before the watchdog calls it a hang.
const CASE_SECONDS: u64 = 120;
/// Largest sweep run whole in the campaign (larger valid scenes are checked only, and counted).
const MAX_RUN_POINTS: usize = 20_000;
const MAX_RUN_DYNAMICS_POINTS: usize = 100;

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
