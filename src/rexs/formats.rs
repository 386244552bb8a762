//! A REXS file's bytes into a [`RexsModel`]: XML (`.rexs`), JSON (`.rexsj`, `.rexs.json`) or a zip
//! holding one of them (`.rexsz`, `.rexs.zip`), told apart by their content; a UTF-8 byte-order
//! mark is skipped.

use std::collections::BTreeMap;

use super::error::RexsError;
use super::model::{Attribute, AttributeValue, Component, LoadCase, Reference, Relation, RexsModel};

/// The model in `bytes` (a file's content).
pub(crate) fn read_model(bytes: &[u8]) -> Result<RexsModel, RexsError> {
    if bytes.starts_with(b"PK\x03\x04") {
        return read_model(&unzip(bytes)?);
    }
    let text = std::str::from_utf8(bytes).map_err(|e| {
        RexsError::new(
            format!("the file is not UTF-8 text ({e})"),
            "give a REXS model: XML (.rexs), JSON (.rexsj) or a zip of one (.rexsz)",
        )
    })?;
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    match text.trim_start().chars().next() {
        Some('<') => read_xml(text),
        Some('{') => read_json(text),
        _ => Err(RexsError::new(
            "the file is neither XML nor JSON",
            "give a REXS model: XML (.rexs), JSON (.rexsj) or a zip of one (.rexsz)",
        )),
    }
}

/// The largest REXS model read, as a file and as the model inflated from a `.rexsz` (the largest
/// real gear-unit models are a few MiB): a zip that inflates past it is refused, never inflated whole.
pub(crate) const MAX_MODEL_BYTES: u64 = 64 << 20;

/// The one model file inside a zip: a `.rexs`, `.rexsj` or `.rexs.json` member, else the one
/// `.json` member that holds a REXS model (a tool's manifest beside it is passed over). Two models
/// in one archive are refused by name: which one was meant is not the importer's to guess.
fn unzip(bytes: &[u8]) -> Result<Vec<u8>, RexsError> {
    let mut archive = zip::ZipArchive::new(std::io::Cursor::new(bytes)).map_err(|e| zip_error(e.to_string()))?;
    let names: Vec<String> = archive.file_names().filter_map(|n| n.ok().map(|n| n.to_string())).collect();
    let named = |n: &&String| n.ends_with(".rexs") || n.ends_with(".rexsj") || n.ends_with(".rexs.json");
    let mut models: Vec<(String, Vec<u8>)> = Vec::new();
    for name in names.iter().filter(named) {
        models.push((name.clone(), member(&mut archive, name)?));
    }
    if models.is_empty() {
        for name in names.iter().filter(|n| n.ends_with(".json")) {
            let text = member(&mut archive, name)?;
            let holds_model =
                serde_json::from_slice::<serde_json::Value>(&text).is_ok_and(|v| v.get("model").is_some());
            if holds_model {
                models.push((name.clone(), text));
            }
        }
    }
    match models.len() {
        1 => Ok(models.pop().expect("one model").1),
        0 => Err(zip_error(format!("it holds no REXS model (it holds: {})", names.join(", ")))),
        _ => Err(RexsError::new(
            format!(
                "the zip archive holds {} models: {}",
                models.len(),
                models.iter().map(|(n, _)| format!("`{n}`")).collect::<Vec<_>>().join(", ")
            ),
            "unpack the archive and import the model meant",
        )),
    }
}

/// A zip archive that cannot be read, and why.
fn zip_error(why: String) -> RexsError {
    RexsError::new(format!("the zip archive cannot be read: {why}"), "give a .rexsz holding one .rexs or .rexsj file")
}

/// A zip member's bytes, inflated to at most [`MAX_MODEL_BYTES`].
fn member(archive: &mut zip::ZipArchive<std::io::Cursor<&[u8]>>, name: &str) -> Result<Vec<u8>, RexsError> {
    use std::io::Read;
    let mut out = Vec::new();
    let member = archive.by_name(name).map_err(|e| zip_error(e.to_string()))?;
    member.take(MAX_MODEL_BYTES + 1).read_to_end(&mut out).map_err(|e| zip_error(e.to_string()))?;
    if out.len() as u64 > MAX_MODEL_BYTES {
        return Err(RexsError::new(
            format!("`{name}` inflates to more than {} MiB", MAX_MODEL_BYTES >> 20),
            "a REXS model of a gear unit is a few MiB; give the model itself, not an archive that only claims to be one",
        ));
    }
    Ok(out)
}

/// Adds `c` to the model; two components of one id are refused naming both (the second silently
/// replaced the first, and the relations to it were then reported missing or wrong).
fn add_component(model: &mut RexsModel, c: Component) -> Result<(), RexsError> {
    if let Some(first) = model.components.get(&c.id) {
        return Err(RexsError::new(
            format!(
                "two components share the id {}: {} and {}",
                c.id,
                super::error::describe(first),
                super::error::describe(&c)
            ),
            "every component of a REXS model has an id of its own; export the model again from its tool",
        ));
    }
    model.components.insert(c.id, c);
    Ok(())
}

fn number(text: &str) -> Option<f64> {
    text.trim().parse::<f64>().ok().filter(|x| x.is_finite())
}

/// An XML attribute's value: an `<array>` of `<c>`, or the element's text (a number, a boolean or text).
fn xml_value(node: roxmltree::Node) -> AttributeValue {
    if let Some(array) = node.children().find(|c| c.has_tag_name("array")) {
        if array.attribute("code").is_some() {
            return AttributeValue::Other;
        }
        let cells: Vec<&str> =
            array.children().filter(|c| c.has_tag_name("c")).map(|c| c.text().unwrap_or("").trim()).collect();
        if !cells.is_empty() && cells.iter().all(|c| *c == "true" || *c == "false") {
            return AttributeValue::Bools(cells.iter().map(|c| *c == "true").collect());
        }
        let values: Option<Vec<f64>> = cells.into_iter().map(number).collect();
        return values.map_or(AttributeValue::Other, AttributeValue::Numbers);
    }
    if node.children().any(|c| c.is_element()) {
        return AttributeValue::Other;
    }
    let text = node.text().unwrap_or("").trim();
    match (text, number(text)) {
        ("true", _) => AttributeValue::Bool(true),
        ("false", _) => AttributeValue::Bool(false),
        (_, Some(x)) => AttributeValue::Number(x),
        _ => AttributeValue::Text(text.to_string()),
    }
}

fn id_of(text: Option<&str>, what: &str) -> Result<u64, RexsError> {
    text.and_then(|t| t.trim().parse().ok()).ok_or_else(|| {
        RexsError::new(format!("{what} has no numeric id"), "every component and reference carries an integer `id`")
    })
}

fn xml_attributes(node: roxmltree::Node) -> Vec<Attribute> {
    node.children()
        .filter(|a| a.has_tag_name("attribute"))
        .map(|a| Attribute {
            id: a.attribute("id").unwrap_or("").to_string(),
            unit: a.attribute("unit").map(str::to_string),
            value: xml_value(a),
        })
        .collect()
}

fn read_xml(text: &str) -> Result<RexsModel, RexsError> {
    use super::xml_depth::{depth, MAX_XML_DEPTH};
    if depth(text, MAX_XML_DEPTH) > MAX_XML_DEPTH {
        return Err(RexsError::new(
            format!("the XML nests elements more than {MAX_XML_DEPTH} deep"),
            "a REXS model nests six deep (model, components, component, attribute, array, c); give the model as its tool exported it",
        ));
    }
    let doc = roxmltree::Document::parse(text).map_err(|e| {
        RexsError::new(format!("the file is not well-formed XML: {e}"), "give a REXS model as its tool exported it")
    })?;
    let root = doc.root_element();
    if !root.has_tag_name("model") {
        return Err(not_rexs(root.tag_name().name()));
    }
    let mut model = RexsModel {
        version: root.attribute("version").unwrap_or("").to_string(),
        application: format!(
            "{} {}",
            root.attribute("applicationId").unwrap_or(""),
            root.attribute("applicationVersion").unwrap_or("")
        )
        .trim()
        .to_string(),
        ..Default::default()
    };
    for part in root.children().filter(|n| n.is_element()) {
        match part.tag_name().name() {
            "relations" => {
                for r in part.children().filter(|n| n.has_tag_name("relation")) {
                    let refs = r
                        .children()
                        .filter(|n| n.has_tag_name("ref"))
                        .map(|x| {
                            Ok(Reference {
                                id: id_of(x.attribute("id"), "a relation's reference")?,
                                role: x.attribute("role").unwrap_or("").to_string(),
                                hint: x.attribute("hint").map(str::to_string),
                            })
                        })
                        .collect::<Result<_, RexsError>>()?;
                    model.relations.push(Relation { kind: r.attribute("type").unwrap_or("").to_string(), refs });
                }
            }
            "components" => {
                for c in part.children().filter(|n| n.has_tag_name("component")) {
                    let id = id_of(c.attribute("id"), "a component")?;
                    add_component(
                        &mut model,
                        Component {
                            id,
                            kind: c.attribute("type").unwrap_or("").to_string(),
                            name: c.attribute("name").unwrap_or("").to_string(),
                            attributes: xml_attributes(c),
                        },
                    )?;
                }
            }
            "load_spectrum" => {
                for case in part.children().filter(|n| n.has_tag_name("load_case")) {
                    let mut components = BTreeMap::new();
                    for c in case.children().filter(|n| n.has_tag_name("component")) {
                        components.insert(id_of(c.attribute("id"), "a load case's component")?, xml_attributes(c));
                    }
                    model.load_cases.push(LoadCase { id: id_of(case.attribute("id"), "a load case")?, components });
                }
            }
            _ => {}
        }
    }
    Ok(model)
}

fn not_rexs(root: &str) -> RexsError {
    RexsError::new(
        format!("the file's root is `{root}`, not a REXS `model`"),
        "give a REXS model: its root element (XML) or key (JSON) is `model`",
    )
}

/// A JSON attribute: its value under the key naming its type.
fn json_attribute(a: &serde_json::Value) -> Attribute {
    let value = if let Some(x) = a.get("floating_point").or_else(|| a.get("integer")).and_then(|v| v.as_f64()) {
        AttributeValue::Number(x)
    } else if let Some(b) = a.get("boolean").and_then(|v| v.as_bool()) {
        AttributeValue::Bool(b)
    } else if let Some(s) = a.get("string").or_else(|| a.get("enum")).and_then(|v| v.as_str()) {
        AttributeValue::Text(s.to_string())
    } else if let Some(x) = a.get("reference_component").and_then(|v| v.as_f64()) {
        AttributeValue::Number(x)
    } else if let Some(v) = a.get("floating_point_array").or_else(|| a.get("integer_array")).and_then(|v| v.as_array())
    {
        v.iter().map(|x| x.as_f64()).collect::<Option<Vec<_>>>().map_or(AttributeValue::Other, AttributeValue::Numbers)
    } else if let Some(v) = a.get("boolean_array").and_then(|v| v.as_array()) {
        v.iter().map(|x| x.as_bool()).collect::<Option<Vec<_>>>().map_or(AttributeValue::Other, AttributeValue::Bools)
    } else {
        AttributeValue::Other
    };
    Attribute {
        id: a.get("id").and_then(|v| v.as_str()).unwrap_or("").to_string(),
        unit: a.get("unit").and_then(|v| v.as_str()).map(str::to_string),
        value,
    }
}

fn json_id(v: &serde_json::Value, what: &str) -> Result<u64, RexsError> {
    v.get("id")
        .and_then(|i| i.as_u64().or_else(|| i.as_f64().filter(|x| x.fract() == 0.0 && *x >= 0.0).map(|x| x as u64)))
        .ok_or_else(|| {
            RexsError::new(format!("{what} has no numeric id"), "every component and reference carries an integer `id`")
        })
}

fn json_attributes(c: &serde_json::Value) -> Vec<Attribute> {
    c.get("attributes").and_then(|a| a.as_array()).map_or_else(Vec::new, |a| a.iter().map(json_attribute).collect())
}

fn read_json(text: &str) -> Result<RexsModel, RexsError> {
    let doc: serde_json::Value = serde_json::from_str(text).map_err(|e| {
        RexsError::new(format!("the file is not valid JSON: {e}"), "give a REXS model as its tool exported it")
    })?;
    let Some(root) = doc.get("model") else {
        let key = doc.as_object().and_then(|o| o.keys().next().cloned()).unwrap_or_default();
        return Err(not_rexs(&key));
    };
    let text_of = |k: &str| root.get(k).and_then(|v| v.as_str()).unwrap_or("").to_string();
    let mut model = RexsModel {
        version: text_of("version"),
        application: format!("{} {}", text_of("applicationId"), text_of("applicationVersion")).trim().to_string(),
        ..Default::default()
    };
    for r in root.get("relations").and_then(|v| v.as_array()).into_iter().flatten() {
        let refs = r
            .get("refs")
            .and_then(|v| v.as_array())
            .into_iter()
            .flatten()
            .map(|x| {
                Ok(Reference {
                    id: json_id(x, "a relation's reference")?,
                    role: x.get("role").and_then(|v| v.as_str()).unwrap_or("").to_string(),
                    hint: x.get("hint").and_then(|v| v.as_str()).map(str::to_string),
                })
            })
            .collect::<Result<_, RexsError>>()?;
        model.relations.push(Relation { kind: r.get("type").and_then(|v| v.as_str()).unwrap_or("").to_string(), refs });
    }
    for c in root.get("components").and_then(|v| v.as_array()).into_iter().flatten() {
        let id = json_id(c, "a component")?;
        add_component(
            &mut model,
            Component {
                id,
                kind: c.get("type").and_then(|v| v.as_str()).unwrap_or("").to_string(),
                name: c.get("name").and_then(|v| v.as_str()).unwrap_or("").to_string(),
                attributes: json_attributes(c),
            },
        )?;
    }
    let spectrum = root.get("load_spectrum");
    for case in spectrum.and_then(|s| s.get("load_cases")).and_then(|v| v.as_array()).into_iter().flatten() {
        let mut components = BTreeMap::new();
        for c in case.get("components").and_then(|v| v.as_array()).into_iter().flatten() {
            components.insert(json_id(c, "a load case's component")?, json_attributes(c));
        }
        model.load_cases.push(LoadCase { id: json_id(case, "a load case")?, components });
    }
    Ok(model)
}
