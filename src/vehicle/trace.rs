//! A vehicle's speed trace read from a CSV file: a header naming the columns (time in seconds, the
//! speed with its unit, the grade optional), then one sample per line. The trace is piecewise
//! linear between the samples (README, "Vehicles and drive cycles").
//!
//! Headers read: NREL FASTSim's `cycSecs`, `cycMps`, `cycGrade` (its cycle files as they are: a
//! UTF-8 byte-order mark and CRLF line ends are accepted), or `time [s]` with `speed [m/s]`,
//! `speed [km/h]` or `speed [mph]` (also `(…)` or `_s`, `_mps`, `_kmh`, `_mph` forms, and `v` for
//! `speed`), and `grade` (rise over run). Other columns are ignored; `#` starts a comment line.
//!
//! ```
//! let trace = gearloss::vehicle::Trace::read("time [s], speed [km/h]\n0, 0\n10, 36\n").unwrap();
//! assert_eq!(trace.speed, vec![0.0, 10.0]);
//! assert_eq!(trace.distance(), 50.0);
//! ```

/// The samples of a trace, in SI.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Trace {
    /// t (s), strictly increasing.
    pub time: Vec<f64>,
    /// v (m/s), ≥ 0.
    pub speed: Vec<f64>,
    /// Grade (rise/run) at each sample; 0 without a grade column.
    pub grade: Vec<f64>,
}

/// What is wrong with a trace, and where (line and column in the file, from 1).
#[derive(Debug, Clone, PartialEq)]
pub struct TraceError {
    pub line: usize,
    pub column: usize,
    pub message: String,
    pub hint: String,
}

/// The speed units a header may name, with their factor to m/s.
/// (unit, multiplier, divisor): v (m/s) = value × multiplier / divisor (km/h divided by 3.6 exactly).
const SPEED_UNITS: &[(&str, f64, f64)] =
    &[("m/s", 1.0, 1.0), ("mps", 1.0, 1.0), ("km/h", 1.0, 3.6), ("kmh", 1.0, 3.6), ("mph", 0.44704, 1.0)];
/// An interval longer than this many times the median interval is a gap in the trace.
const GAP_FACTOR: f64 = 10.0;
/// Plausible traces, so that a typo in a unit, an exponent or a decimal mark is refused at its line
/// instead of giving a cycle of absurd energies: samples at least 1 ms apart, a trace of at most
/// 10⁶ s (11.6 days), speeds up to 150 m/s (540 km/h), accelerations up to 20 m/s² (2 g), grades
/// up to 50 % (rise over run 0.5).
const MIN_STEP: f64 = 1e-3;
const MAX_DURATION: f64 = 1e6;
const MAX_SPEED: f64 = 150.0;
const MAX_ACCELERATION: f64 = 20.0;
const MAX_GRADE: f64 = 0.5;
/// The most samples a trace may hold: what a cycle run does in seconds and a bounded memory (its
/// cost grows linearly with the samples: 36 000, ten hours at 1 Hz or one at 10 Hz; README gives
/// the measured figures).
pub const MAX_SAMPLES: usize = 36_000;

#[derive(Clone, Copy, PartialEq)]
enum Column {
    Time,
    /// (multiplier, divisor) to m/s.
    Speed(f64, f64),
    Grade,
    Other,
}

impl Column {
    fn is_time(&self) -> bool {
        *self == Column::Time
    }

    fn is_speed(&self) -> bool {
        matches!(self, Column::Speed(..))
    }
}

fn error(line: usize, column: usize, message: String, hint: &str) -> TraceError {
    TraceError { line, column, message, hint: hint.to_string() }
}

/// A header cell split into its name and unit: `speed [km/h]`, `speed (km/h)`, `speed_kmh`.
fn name_and_unit(cell: &str) -> (String, Option<String>) {
    let cell = cell.trim().to_ascii_lowercase();
    for (open, close) in [('[', ']'), ('(', ')')] {
        if let (Some(a), Some(b)) = (cell.find(open), cell.rfind(close)) {
            if a < b {
                return (cell[..a].trim().to_string(), Some(cell[a + 1..b].trim().to_string()));
            }
        }
    }
    match cell.rsplit_once('_') {
        Some((name, unit)) if ["s", "mps", "kmh", "mph", "m/s", "km/h"].contains(&unit) => {
            (name.to_string(), Some(unit.to_string()))
        }
        _ => (cell, None),
    }
}

/// What a header cell names; an error for a speed or time in an unknown unit.
fn column(cell: &str, at: usize) -> Result<Column, TraceError> {
    let bad_unit = |what: &str, units: &str| {
        error(1, at, format!("the column `{}` gives {what} in a unit this reader does not know", cell.trim()), units)
    };
    match cell.trim().to_ascii_lowercase().as_str() {
        "cycsecs" => return Ok(Column::Time),
        "cycmps" => return Ok(Column::Speed(1.0, 1.0)),
        "cycmph" => return Ok(Column::Speed(0.44704, 1.0)),
        "cycgrade" => return Ok(Column::Grade),
        _ => {}
    }
    let (name, unit) = name_and_unit(cell);
    match name.as_str() {
        "time" | "t" => match unit.as_deref() {
            None | Some("s") => Ok(Column::Time),
            Some(_) => Err(bad_unit("the time", "give the time in seconds: `time [s]`")),
        },
        "speed" | "v" | "velocity" => match unit.as_deref() {
            None => Err(error(
                1,
                at,
                format!("the column `{}` gives a speed without its unit", cell.trim()),
                "name the unit in the header: `speed [km/h]`, `speed [m/s]` or `speed [mph]`",
            )),
            Some(u) => SPEED_UNITS
                .iter()
                .find(|(name, _, _)| *name == u)
                .map(|(_, m, d)| Column::Speed(*m, *d))
                .ok_or_else(|| bad_unit("the speed", "the speed units read are m/s, km/h and mph: `speed [km/h]`")),
        },
        "grade" => Ok(Column::Grade),
        _ => Ok(Column::Other),
    }
}

impl Trace {
    /// Reads a trace from the text of its file.
    pub fn read(text: &str) -> Result<Trace, TraceError> {
        let text = text.strip_prefix('\u{feff}').unwrap_or(text);
        // Line ends as any editor writes them: LF, CRLF, a bare CR (old Mac), or a mix.
        let text = text.replace("\r\n", "\n").replace('\r', "\n");
        let mut lines = text.lines().enumerate().map(|(i, l)| (i + 1, l));
        let Some((header_line, header)) = lines.find(|(_, l)| !l.trim().is_empty() && !l.trim_start().starts_with('#'))
        else {
            return Err(error(
                1,
                1,
                "the trace file is empty".into(),
                "a header `time [s], speed [km/h]`, then one sample per line",
            ));
        };
        if let Some(c) = [';', '\t'].into_iter().find(|c| header.contains(*c) && !header.contains(',')) {
            return Err(error(
                header_line,
                1 + header.find(c).unwrap_or(0),
                format!("the header `{}` separates its columns by {c:?}", header.trim()),
                "this reader takes commas between the columns (`time [s], speed [km/h]`) and decimal points in the numbers",
            ));
        }
        let mut columns = Vec::new();
        let mut col = 1;
        for cell in header.split(',') {
            let unquoted = cell.trim().trim_matches('"');
            columns.push(column(unquoted, col).map_err(|e| TraceError { line: header_line, ..e })?);
            col += cell.len() + 1;
        }
        let find = |want: fn(&Column) -> bool| columns.iter().position(want);
        let (Some(t_col), Some(v_col)) = (find(|c| *c == Column::Time), find(|c| matches!(c, Column::Speed(..))))
        else {
            return Err(error(
                header_line,
                1,
                format!("the header `{}` names no time and speed columns", header.trim()),
                "start the file with a header such as `time [s], speed [km/h]`",
            ));
        };
        let header_cells: Vec<&str> = header.split(',').collect();
        for (what, is) in [("time", Column::is_time as fn(&Column) -> bool), ("speed", Column::is_speed)] {
            let named: Vec<usize> = (0..columns.len()).filter(|&k| is(&columns[k])).collect();
            if let [first, second, ..] = named[..] {
                return Err(error(
                    header_line,
                    1 + header_cells.iter().take(second).map(|c| c.len() + 1).sum::<usize>(),
                    format!(
                        "two {what} columns, `{}` and `{}`: which one the cycle follows would be a guess",
                        header_cells[first].trim(),
                        header_cells[second].trim()
                    ),
                    "keep one of them (or rename the other, which is then ignored)",
                ));
            }
        }
        let Column::Speed(multiplier, divisor) = columns[v_col] else { unreachable!("v_col is a speed column") };
        let g_col = find(|c| *c == Column::Grade);
        let mut trace = Trace { time: Vec::new(), speed: Vec::new(), grade: Vec::new() };
        let mut lines_of = Vec::new();
        for (line, text) in lines {
            if text.trim().is_empty() || text.trim_start().starts_with('#') {
                continue;
            }
            if trace.time.len() == MAX_SAMPLES {
                return Err(error(
                    line,
                    1,
                    format!("more than {MAX_SAMPLES} samples: a cycle this long is more than gearloss runs in reasonable time and memory"),
                    "resample the trace (the regulation cycles are 1 Hz: WLTC has 1801 samples) or cut it into traces of a few hours",
                ));
            }
            let cells: Vec<&str> = text.split(',').collect();
            if cells.len() != columns.len() {
                return Err(error(
                    line,
                    1,
                    format!("{} cells on this line, {} columns in the header", cells.len(), columns.len()),
                    "one cell per column, separated by commas, with decimal points (5.5, not 5,5)",
                ));
            }
            let cell = |k: usize, what: &str| -> Result<f64, TraceError> {
                let column = 1 + cells.iter().take(k).map(|c| c.len() + 1).sum::<usize>();
                let raw = cells.get(k).map(|c| c.trim()).unwrap_or("");
                if raw.is_empty() {
                    return Err(error(
                        line,
                        column,
                        format!("a gap: no {what} on this line"),
                        "every sample needs its time and speed",
                    ));
                }
                match raw.parse::<f64>() {
                    Ok(x) if x.is_finite() => Ok(x),
                    _ => Err(error(
                        line,
                        column,
                        format!("`{raw}` is not a number ({what})"),
                        "write plain decimal numbers",
                    )),
                }
            };
            let (t, v) = (cell(t_col, "time")?, cell(v_col, "speed")?);
            let g = g_col.map(|k| cell(k, "grade")).transpose()?.unwrap_or(0.0);
            if v < 0.0 {
                return Err(error(
                    line,
                    1,
                    format!("the speed {v} is negative"),
                    "a trace drives forwards: speeds ≥ 0",
                ));
            }
            if v * multiplier / divisor > MAX_SPEED || g.abs() > MAX_GRADE {
                return Err(error(
                    line,
                    1,
                    format!("the speed {v} or the grade {g} is outside the plausible range"),
                    "speeds up to 150 m/s (540 km/h), grades as rise over run up to 0.5 (50 %): check the unit in the header",
                ));
            }
            if let Some(&last) = trace.time.last() {
                if t <= last {
                    return Err(error(
                        line,
                        1,
                        format!("the time {t} s does not come after {last} s"),
                        "times must increase from line to line",
                    ));
                }
                let (dt, dv) = (t - last, v * multiplier / divisor - trace.speed[trace.speed.len() - 1]);
                if dt < MIN_STEP || (dv / dt).abs() > MAX_ACCELERATION || t - trace.time[0] > MAX_DURATION {
                    return Err(error(
                        line,
                        1,
                        format!("from {last} s to {t} s the trace is not plausible (step {dt:e} s, acceleration {:e} m/s²)", dv / dt),
                        "samples at least 1 ms apart, accelerations up to 20 m/s², a trace of at most 1e6 s: check the time column's unit",
                    ));
                }
            }
            trace.time.push(t);
            trace.speed.push(v * multiplier / divisor);
            trace.grade.push(g);
            lines_of.push(line);
        }
        if trace.time.len() < 2 {
            return Err(error(
                header_line,
                1,
                format!("the trace holds {} samples", trace.time.len()),
                "give at least two samples",
            ));
        }
        trace.check_gaps(&lines_of)?;
        Ok(trace)
    }

    /// An interval much longer than the trace's usual one (more than [`GAP_FACTOR`] × the median).
    fn check_gaps(&self, lines: &[usize]) -> Result<(), TraceError> {
        let mut steps: Vec<f64> = self.time.windows(2).map(|w| w[1] - w[0]).collect();
        let all = steps.clone();
        steps.sort_by(f64::total_cmp);
        let median = steps[steps.len() / 2];
        match all.iter().position(|&d| d > GAP_FACTOR * median) {
            Some(k) => Err(error(
                lines[k + 1],
                1,
                format!(
                    "a gap of {} s after {} s, where the trace's samples are {median} s apart",
                    all[k], self.time[k]
                ),
                "the trace is read as straight lines between samples: give the samples of the gap",
            )),
            None => Ok(()),
        }
    }

    /// The distance (m): the exact integral of the piecewise-linear speed.
    pub fn distance(&self) -> f64 {
        (1..self.time.len())
            .map(|k| 0.5 * (self.speed[k] + self.speed[k - 1]) * (self.time[k] - self.time[k - 1]))
            .sum()
    }

    /// The duration (s).
    pub fn duration(&self) -> f64 {
        self.time[self.time.len() - 1] - self.time[0]
    }
}
