//! Drive cycles under hostile input (issue 56): a trace's line ends as any editor writes them, and
//! a trace, a vehicle or a phase that cannot be meant refused at its line with the way out — never
//! a cycle of absurd energies.

use gearloss::vehicle::Trace;

/// The trace's error (line, column, message, hint), or its sample count.
fn read(text: &str) -> Result<usize, (usize, usize, String, String)> {
    Trace::read(text).map(|t| t.time.len()).map_err(|e| (e.line, e.column, e.message, e.hint))
}

#[test]
fn traces_are_read_whatever_their_line_ends_and_quotes() {
    assert_eq!(read("time [s], speed [km/h]\r0, 0\r10, 36\r"), Ok(2), "bare CR (old Mac)");
    assert_eq!(read("time [s], speed [km/h]\r\n0, 0\r10, 36\n20, 0"), Ok(3), "mixed line ends");
    assert_eq!(read("\"time [s]\",\"speed [km/h]\"\n0,0\n10,36\n"), Ok(2), "quoted header");
}

#[test]
fn implausible_traces_are_refused_at_their_line() {
    let refused = |text: &str, line: usize, words: &str| {
        let (at, _, message, hint) = read(text).expect_err(text);
        assert_eq!(at, line, "{text}: {message}");
        assert!(message.contains(words) || hint.contains(words), "{text}: {message} / {hint}");
    };
    refused("time [s], speed [km/h]\n0, 0\n10, 5,5\n", 3, "decimal points (5.5, not 5,5)");
    refused("time [s], speed [km/h], v [m/s]\n0, 0, 0\n1, 3.6, 1\n", 1, "two speed columns");
    refused("t [s], time [s], speed [km/h]\n0, 0, 0\n1, 1, 3.6\n", 1, "two time columns");
    refused("time [s], speed [km/h]\n0, 0\n1e-9, 0\n", 3, "at least 1 ms apart");
    refused("time [s], speed [km/h]\n0, 0\n1e300, 0\n", 3, "at most 1e6 s");
    refused("time [s], speed [km/h]\n0, 0\n1, 100\n", 3, "accelerations up to 20 m/s²");
    refused("time [s], speed [km/h]\n0, 0\n100, 1e6\n", 3, "up to 150 m/s");
    refused("time [s], speed [km/h], grade\n0, 0, 0\n10, 36, 2\n", 3, "up to 0.5");
    refused("time [s];speed [km/h]\n0;0\n", 1, "separates its columns by ';'");
    // The column of the second speed column is named.
    assert_eq!(read("time [s], speed [km/h], v [m/s]\n0, 0, 0\n").unwrap_err().1, 24);
}

/// A trace holds at most `MAX_SAMPLES` (36 000) samples, what a cycle run does in seconds (a 4 MiB
/// trace inside the file limit held 300 000 and took 98 s and 798 MiB): the next sample is refused
/// at its line, with the way out.
#[test]
fn a_trace_longer_than_the_tool_runs_is_refused_at_its_line() {
    use gearloss::vehicle::MAX_SAMPLES;
    let samples = |n: usize| {
        let mut text = String::from("time [s], speed [km/h]\n");
        for k in 0..n {
            text.push_str(&format!("{k}, {}\n", if k % 60 < 30 { 36 } else { 0 }));
        }
        text
    };
    assert_eq!(read(&samples(MAX_SAMPLES)), Ok(MAX_SAMPLES));
    let (line, _, message, hint) = read(&samples(MAX_SAMPLES + 1)).unwrap_err();
    assert_eq!(line, MAX_SAMPLES + 2, "{message}");
    assert!(message.contains("more than 36000 samples") && hint.contains("resample"), "{message} / {hint}");
}

/// The WLTC scene with `edits`; the error messages and hints when it is refused.
fn refused(edits: &[(&str, &str)]) -> String {
    let path = crate::root().join("specs/ev_reducer_wltc.gear");
    let mut text = std::fs::read_to_string(&path).unwrap();
    for (a, b) in edits {
        assert!(text.contains(a), "{a}");
        text = text.replacen(a, b, 1);
    }
    match gearloss::check(&path.display().to_string(), &text) {
        Ok(_) => panic!("{edits:?} is accepted"),
        Err(e) => e.diagnostics.iter().map(|d| format!("{} / {}", d.reason, d.hints.join(" "))).collect(),
    }
}

#[test]
fn implausible_vehicles_and_phases_are_refused() {
    let said = refused(&[("mass = 1976 kg", "mass = 1e-6 kg")]);
    assert!(said.contains("vehicle's mass of 1e-6 kg is outside the plausible range, 10 kg to 1000 t"), "{said}");
    let said = refused(&[("wheel_radius = 0.335 m", "wheel_radius = 335 m")]);
    assert!(said.contains("wheel_radius of 335 m"), "{said}");
    let said = refused(&[("start_temperature = 25 degC", "start_temperature = 399 degC")]);
    assert!(said.contains("start temperature of 399 degC"), "{said}");
    let said = refused(&[("from = 589 s, to = 1022 s", "from = 500 s, to = 1022 s")]);
    assert!(said.contains("the phase `medium` (500 s to 1022 s) overlaps: `low`"), "{said}");
    let said = refused(&[("name = \"medium\"", "name = \"low\"")]);
    assert!(said.contains("is named twice"), "{said}");
    let said = refused(&[
        (
            "drag(coefficient = 0.267, frontal_area = 2.3903615 m^2, air_density = 1.225 kg/m^3)",
            "road_load(f0 = -165 N, f1 = 0.47 N*s/m, f2 = 0.32 N*s^2/m^2)",
        ),
        ("rolling_resistance = 0.009", ""),
    ]);
    assert!(said.contains("coastdown coefficient f0 = -165 N is negative"), "{said}");
}
