//! A one-pair scene as the one-stage drive it is. A scene of one `gears` block that puts a vehicle on
//! a drive cycle (`vehicle`, `drive_cycle`) is rewritten, before lowering, into the syntax of a drive
//! and lowered as one; every span still points at what the user wrote. What the rewrite keeps is the
//! pair's meaning:
//!
//! | the pair writes | the one-stage drive reads |
//! |---|---|
//! | `gears { ... pinion { ... } wheel { ... } }` | `stage "pair" { gears { ... pinion { ...  shaft = pinion_shaft  at = 0 mm } wheel { ...  shaft = wheel_shaft  at = 0 mm } } }`: both gears at 0 on their shafts, so a bearing's `at` is measured from the mesh mid-plane as the pair measures it |
//! | `hand` (or none) | `hand = right` for a helical pair: the pinion's axial force points to +`at` at a positive pinion torque, the pair's reading (its README: a pair of the other hand mirrors its positions) |
//! | `gearbox { lubrication = ... }` | the stage's `lubrication` |
//! | `gearbox { pinion_shaft { ... }  wheel_shaft { ... } }` | `gearbox { shaft pinion_shaft { input ... }  shaft wheel_shaft { output ... } }` (a shaft block not written is an empty one) |
//! | bearings without `at` | places without positions: each bearing an equal share of the gear force, the pair's rule |
//! | `pinion_torque`, `pinion_speed` | `input_torque`, `input_speed` (the pinion's shaft is the input), in `operating`, in a `duty_cycle`'s steps and on an `efficiency_map`'s axes; the torque stays the pair's, at the pinion gear (into the mesh): the walk puts the input's torque at that plus the pinion shaft's own losses (`evaluate/drive_setup.rs`), and the report labels the points `T_pinion` |
//!
//! The housing, duty cycle, lubricant, friction laws, vehicle, drive cycle and analyses are taken
//! as written.

use super::ast::*;

/// The stage's name in the drive a one-pair scene is.
pub(crate) const STAGE: &str = "pair";
/// The pair's shaft blocks in `gearbox`, which become the drive's shafts of these names.
const SHAFTS: [&str; 2] = ["pinion_shaft", "wheel_shaft"];

/// Whether the scene is one pair (a `gears` block, no `stage`) that puts a vehicle on a drive cycle:
/// then it is lowered as the one-stage drive [`as_one_stage`] writes.
pub(super) fn is_pair_on_a_cycle(ast: &SceneAst) -> bool {
    let has = |kind: &str| ast.items.iter().any(|i| matches!(i, Item::Block(b) if b.kind.text == kind));
    has("gears") && !has("stage") && (has("vehicle") || has("drive_cycle"))
}

/// The scene rewritten as the one-stage drive of its pair (the table above).
pub(super) fn as_one_stage(ast: &SceneAst) -> SceneAst {
    let lubrication = ast.items.iter().find_map(|i| match i {
        Item::Block(b) if b.kind.text == "gearbox" => {
            b.items.iter().find(|i| matches!(i, Item::Assignment { key, .. } if key.text == "lubrication")).cloned()
        }
        _ => None,
    });
    let gears_span = ast.items.iter().find_map(|i| match i {
        Item::Block(b) if b.kind.text == "gears" => Some(b.kind.span),
        _ => None,
    });
    let mut items = Vec::with_capacity(ast.items.len() + 1);
    for item in &ast.items {
        items.push(match item {
            Item::Block(b) if b.kind.text == "gears" => Item::Block(stage(b, lubrication.clone())),
            Item::Block(b) if b.kind.text == "gearbox" => Item::Block(gearbox(b)),
            Item::Block(b) if b.kind.text == "operating" => Item::Block(operating(b)),
            Item::Block(b) if b.kind.text == "duty_cycle" => Item::Block(calls_at_input(b, "step")),
            Item::Block(b) if b.kind.text == "analyses" => Item::Block(calls_at_input(b, "efficiency_map")),
            other => other.clone(),
        });
    }
    if let (false, Some(span)) = (ast.items.iter().any(|i| i.head().text == "gearbox"), gears_span) {
        items.push(Item::Block(gearbox(&Block { kind: name("gearbox", span), label: None, items: Vec::new(), span })));
    }
    SceneAst { title: ast.title.clone(), title_span: ast.title_span, items }
}

fn name(text: &str, span: Span) -> Name {
    Name { text: text.into(), span }
}

/// `key = value-name` (a name is a call without arguments).
fn assign_name(key: &str, value: &str, span: Span) -> Item {
    let call = Call { name: name(value, span), arguments: Vec::new(), span };
    Item::Assignment { key: name(key, span), value: Value { kind: ValueKind::Call(call), span } }
}

/// `at = 0 mm`.
fn at_zero(span: Span) -> Item {
    let unit = UnitExpr { text: "mm".into(), span, factors: vec![("mm".into(), span, 1)] };
    Item::Assignment {
        key: name("at", span),
        value: Value { kind: ValueKind::Quantity { number: 0.0, unit: Some(unit) }, span },
    }
}

fn is_key(item: &Item, key: &str) -> bool {
    matches!(item, Item::Assignment { key: k, .. } if k.text == key)
}

/// `stage "pair" { gears { ... } lubrication = ... }`.
fn stage(gears: &Block, lubrication: Option<Item>) -> Block {
    let span = gears.kind.span;
    let mut pair = gears.clone();
    pair.items.retain(|i| !is_key(i, "hand"));
    if gears.items.iter().any(|i| is_key(i, "helix_angle")) {
        pair.items.push(assign_name("hand", "right", span));
    }
    for item in &mut pair.items {
        let Item::Block(gear) = item else { continue };
        let shaft = match gear.kind.text.as_str() {
            "pinion" => "pinion_shaft",
            "wheel" => "wheel_shaft",
            _ => continue,
        };
        gear.items.retain(|i| !is_key(i, "hand"));
        gear.items.push(assign_name("shaft", shaft, gear.kind.span));
        gear.items.push(at_zero(gear.kind.span));
    }
    let mut items = vec![Item::Block(pair)];
    items.extend(lubrication);
    Block { kind: name("stage", span), label: Some(name(STAGE, span)), items, span: gears.span }
}

/// `gearbox { shaft pinion_shaft { input ... }  shaft wheel_shaft { output ... }  housing { ... } }`.
fn gearbox(block: &Block) -> Block {
    let mut items: Vec<Item> = Vec::with_capacity(block.items.len() + 2);
    for (shaft, end) in SHAFTS.into_iter().zip(["input", "output"]) {
        let written = block.items.iter().find_map(|i| match i {
            Item::Block(b) if b.kind.text == shaft => Some(b),
            _ => None,
        });
        let (span, whole, mut inner) = match written {
            Some(b) => (b.kind.span, b.span, b.items.clone()),
            None => (block.kind.span, block.span, Vec::new()),
        };
        inner.insert(0, Item::Call(Call { name: name(end, span), arguments: Vec::new(), span }));
        items.push(Item::Block(Block {
            kind: name("shaft", span),
            label: Some(name(shaft, span)),
            items: inner,
            span: whole,
        }));
    }
    items.extend(
        block
            .items
            .iter()
            // (Any other block stays, for the drive's gearbox to refuse at its name.)
            .filter(|i| {
                !is_key(i, "lubrication") && !matches!(i, Item::Block(b) if SHAFTS.contains(&b.kind.text.as_str()))
            })
            .cloned(),
    );
    Block { items, ..block.clone() }
}

/// `pinion_torque` and `pinion_speed` as the input's.
fn operating(block: &Block) -> Block {
    let mut out = block.clone();
    for item in &mut out.items {
        if let Item::Assignment { key, .. } = item {
            at_input(key);
        }
    }
    out
}

/// The calls `call(...)` of a block (a duty cycle's `step`s, the `efficiency_map`) with their
/// `pinion_torque` and `pinion_speed` as the input's.
fn calls_at_input(block: &Block, call: &str) -> Block {
    let mut out = block.clone();
    for item in &mut out.items {
        if let Item::Call(c) = item {
            if c.name.text == call {
                c.arguments.iter_mut().for_each(|(key, _)| at_input(key));
            }
        }
    }
    out
}

/// A pinion's key as the input end's (the pinion's shaft is the input).
fn at_input(key: &mut Name) {
    match key.text.as_str() {
        "pinion_torque" => key.text = "input_torque".into(),
        "pinion_speed" => key.text = "input_speed".into(),
        _ => {}
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The rewrite of a pair written in full: the stage, the shafts with their ends, the input's
    /// keys; the parse of the rewritten scene's printed form is not needed (spans stay the user's).
    #[test]
    fn a_pair_on_a_cycle_becomes_its_one_stage_drive() {
        let text = r#"scene "p" {
            gears { module = 3 mm  helix_angle = 15 deg  hand = left  pinion { teeth = 20 } wheel { teeth = 40 } }
            gearbox { lubrication = dip(pinion_immersion = 0 mm, wheel_immersion = 25 mm, axis_height = 120 mm, housing_width = 120 mm)
                      pinion_shaft { seal(diameter = 30 mm) } }
            operating { pinion_torque = 100 N*m  oil_temperature = 60 degC }
            vehicle "v" { mass = 1500 kg }
            duty_cycle "d" { step(duration = 2 min, pinion_torque = 50 N*m, pinion_speed = 900 rpm) }
            analyses { efficiency_map(pinion_torque = 10..100 N*m count 3, pinion_speed = 100..900 rpm count 3)
                       transmission_error(pinion_torque = [100] N*m) }
        }"#;
        let ast = crate::parse("p.gear", text).unwrap();
        assert!(is_pair_on_a_cycle(&ast));
        let drive = as_one_stage(&ast);
        let heads: Vec<&str> = drive.items.iter().map(|i| i.head().text.as_str()).collect();
        assert_eq!(heads, ["stage", "gearbox", "operating", "vehicle", "duty_cycle", "analyses"]);
        let Item::Block(stage) = &drive.items[0] else { panic!() };
        assert_eq!(stage.label.as_ref().unwrap().text, STAGE);
        assert!(stage.items.iter().any(|i| is_key(i, "lubrication")));
        let Item::Block(gears) = &stage.items[0] else { panic!() };
        let hands: Vec<&Item> = gears.items.iter().filter(|i| is_key(i, "hand")).collect();
        assert!(
            matches!(hands[..], [Item::Assignment { value: Value { kind: ValueKind::Call(c), .. }, .. }] if c.name.text == "right")
        );
        let Item::Block(gearbox) = &drive.items[1] else { panic!() };
        let shafts: Vec<(String, String)> = gearbox
            .items
            .iter()
            .filter_map(|i| match i {
                Item::Block(b) => Some((b.label.as_ref()?.text.clone(), b.items[0].head().text.clone())),
                _ => None,
            })
            .collect();
        assert_eq!(shafts, [("pinion_shaft".into(), "input".into()), ("wheel_shaft".into(), "output".into())]);
        assert!(!gearbox.items.iter().any(|i| is_key(i, "lubrication")));
        let Item::Block(op) = &drive.items[2] else { panic!() };
        assert_eq!(op.items[0].head().text, "input_torque");
        // A step's and the map's pinion keys are the input's; an analysis of the pair keeps its own.
        let keys = |k: usize| -> Vec<Vec<String>> {
            let Item::Block(b) = &drive.items[k] else { panic!() };
            let call = |i: &Item| match i {
                Item::Call(c) => c.arguments.iter().map(|(n, _)| n.text.clone()).collect(),
                _ => Vec::new(),
            };
            b.items.iter().map(call).collect()
        };
        assert_eq!(keys(4), [["duration", "input_torque", "input_speed"]]);
        assert_eq!(keys(5), [vec!["input_torque", "input_speed"], vec!["pinion_torque"]]);
    }
}
