//! The fuzz campaign's mutations ([`crate::fuzz_campaign`]): a seedable generator, the seeds
//! (every scene in specs/ and tests/specs/) and the grammar-aware mutation of a scene's text.

use std::path::PathBuf;

/// splitmix64: a small, seedable generator (the campaign is reproducible from its seed).
pub(crate) struct Rng(pub(crate) u64);
impl Rng {
    pub(crate) fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    pub(crate) fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
    pub(crate) fn pick<'a, T>(&mut self, v: &'a [T]) -> &'a T {
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
pub(crate) fn seeds() -> (Vec<String>, Vec<String>) {
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

pub(crate) fn unit_names() -> Vec<&'static str> {
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
pub(crate) fn mutate(text: &str, rng: &mut Rng, units: &[&str]) -> String {
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
