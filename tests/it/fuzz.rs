//! Random and mutated scene text never panics: it gives a diagnostic or a report.

use proptest::prelude::*;

const FZG: &str = include_str!("../../specs/fzg_type_c.gear");

fn run(text: &str) {
    match gearloss::check("fuzz.gear", text) {
        Ok(scene) => {
            let report = gearloss::report_of(&scene);
            gearloss::render(&report).expect("a checked scene renders");
        }
        Err(e) => {
            assert!(!e.diagnostics.is_empty());
            let rendered = e.render(false);
            assert!(rendered.contains("fuzz.gear:"));
        }
    }
}

/// Pieces that make mutations meaningful: numbers at the edges, units, punctuation, names.
fn token() -> impl Strategy<Value = String> {
    prop_oneof![
        Just("0".to_string()),
        Just("-1".to_string()),
        Just("1e400".to_string()),
        Just("1e-300".to_string()),
        Just("NaN".to_string()),
        Just("mm".to_string()),
        Just("1/Pa".to_string()),
        Just("{".to_string()),
        Just("}".to_string()),
        Just("[".to_string()),
        Just("]".to_string()),
        Just("=".to_string()),
        Just(",".to_string()),
        Just("..".to_string()),
        Just("\"".to_string()),
        Just("#".to_string()),
        Just("\n".to_string()),
        Just("µ".to_string()),
        Just("step 0".to_string()),
        Just("teeth = 5".to_string()),
        Just("profile_shift = 2.4".to_string()),
        "[a-z_]{1,8}",
        "[0-9.e+-]{1,6}",
    ]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn mutated_scenes_never_panic(at in 0usize..FZG.len(), cut in 0usize..12, insert in token()) {
        let mut at = at;
        while !FZG.is_char_boundary(at) { at -= 1; }
        let mut end = (at + cut).min(FZG.len());
        while !FZG.is_char_boundary(end) { end -= 1; }
        let text = format!("{}{}{}", &FZG[..at], insert, &FZG[end..]);
        run(&text);
    }

    #[test]
    fn random_text_never_panics(text in "\\PC{0,200}") {
        run(&text);
    }

    #[test]
    fn random_values_never_panic(z1 in 0u32..60, z2 in 0u32..200, x1 in -2.0f64..3.0, x2 in -2.0f64..3.0, tip in 0.0f64..400.0, m in 0.1f64..20.0) {
        let text = format!(
            "scene \"p\" {{ gears {{ module = {m} mm pressure_angle = 20 deg face_width = 10 mm \
             pinion {{ teeth = {z1} profile_shift = {x1} tip_diameter = {tip} mm material = s }} \
             wheel {{ teeth = {z2} profile_shift = {x2} material = s }} }} \
             material s {{ youngs_modulus = 200 GPa poisson_ratio = 0.3 }} \
             operating {{ pinion_torque = 100 N*m pinion_speed = 1000 rpm }} }}"
        );
        run(&text);
    }
}
