//! The lowered form as text: what stage 2 (`lower`) hands the evaluation, printed by
//! `gearloss check --emit lowered` so that lowering is read and snapshot-tested on its own.
//!
//! It is the checked [`Scene`] as JSON: every quantity in SI base units (m, kg, s, N, Pa, K, rad,
//! rad/s: uom's own serialisation of its values), each next to the text the user `written` where
//! the scene keeps it; the drive of every scene (a scene of one pair's is its one-stage drive,
//! `one_pair`: stage `pair` from `pinion_shaft` to `wheel_shaft`) with its shafts, bearing places
//! and stages; the friction laws, analyses and,
//! for a cycle, the vehicle and its trace. Source spans are left out (they change with every
//! comment above them, and the diagnostics already carry them); a value that is not a finite
//! number prints as `null`.

use crate::model::Scene;

/// The scene's lowered form as pretty-printed JSON (keys in alphabetical order, numbers in
/// serde_json's shortest round-trip form: the same scene always prints the same text).
///
/// ```
/// let scene = gearloss::check("s.gear", r#"scene "s" {
///     gears { module = 2 mm  pressure_angle = 20 deg  face_width = 20 mm
///             pinion { teeth = 20  material = steel }  wheel { teeth = 40  material = steel } }
///     material steel { youngs_modulus = 210 GPa  poisson_ratio = 0.3 }
///     operating { pinion_torque = 100 N*m  pinion_speed = 1000 rpm }
/// }"#).unwrap();
/// let text = gearloss::lowered(&scene);
/// let json: serde_json::Value = serde_json::from_str(&text).unwrap();
/// // SI: the module in metres, the speed in rad/s, the modulus in pascals; what was written beside.
/// assert_eq!(json["gears"]["module"]["value"], 0.002);
/// assert_eq!(json["gears"]["module"]["written"], "2 mm");
/// let omega = json["operating"]["pinion_speed"]["values"][0].as_f64().unwrap();
/// assert!((omega - 1000.0 * std::f64::consts::PI / 30.0).abs() < 1e-12);
/// assert_eq!(json["gears"]["pinion"]["material"]["youngs_modulus"]["value"], 210e9);
/// assert!(!text.contains("\"span\""));
/// ```
pub(crate) fn lowered(scene: &Scene) -> String {
    let mut value = serde_json::to_value(scene).unwrap_or(serde_json::Value::Null);
    drop_spans(&mut value);
    let mut text = serde_json::to_string_pretty(&value).unwrap_or_default();
    text.push('\n');
    text
}

/// Removes every `span` and `…_span` key (source positions) at any depth.
fn drop_spans(value: &mut serde_json::Value) {
    match value {
        serde_json::Value::Object(map) => {
            map.retain(|k, _| k != "span" && !k.ends_with("_span"));
            map.values_mut().for_each(drop_spans);
        }
        serde_json::Value::Array(items) => items.iter_mut().for_each(drop_spans),
        _ => {}
    }
}
