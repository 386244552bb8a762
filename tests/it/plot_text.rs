//! Every plot's text stays inside its canvas: each `<text>` of an SVG the specs and fixtures write,
//! measured at 0.55 em a character (DejaVu Sans' mean advance over mixed text; plotters lays text
//! out without fonts, so a title too long for its canvas is cut at the viewer's edge), anchored as
//! written (start, middle, end), rotated a quarter turn where the SVG says so, lies within
//! [0, width] × [0, height] (a pixel's slack for rounding).

/// Mean advance of a character, in em.
const EM_PER_CHAR: f64 = 0.55;

fn attr(tag: &str, name: &str) -> Option<String> {
    let at = tag.find(&format!(" {name}=\""))? + name.len() + 3;
    Some(tag[at..].split('"').next()?.to_string())
}

fn number(tag: &str, name: &str) -> f64 {
    attr(tag, name).and_then(|v| v.parse().ok()).unwrap_or(0.0)
}

/// The texts of an SVG that run past its canvas: (text, its extent x0, x1, y0, y1).
pub(crate) fn outside(svg: &str) -> Vec<(String, [f64; 4])> {
    let head = &svg[..svg.find('>').unwrap_or(0)];
    let (width, height) = (number(head, "width"), number(head, "height"));
    let mut out = Vec::new();
    let mut rest = svg;
    while let Some(at) = rest.find("<text ") {
        rest = &rest[at..];
        let Some(close) = rest.find('>') else { break };
        let tag = &rest[..close];
        let Some(end) = rest.find("</text>") else { break };
        let text = rest[close + 1..end].trim().replace("&lt;", "<").replace("&gt;", ">").replace("&amp;", "&");
        rest = &rest[end..];
        let (x, y, size) = (number(tag, "x"), number(tag, "y"), number(tag, "font-size"));
        let long = text.chars().count() as f64 * EM_PER_CHAR * size;
        let (a, b) = match attr(tag, "text-anchor").as_deref() {
            Some("middle") => (-0.5 * long, 0.5 * long),
            Some("end") => (-long, 0.0),
            _ => (0.0, long),
        };
        let extent = if tag.contains("rotate(270") || tag.contains("rotate(90") {
            [x - size, x + size, y + a, y + b]
        } else {
            [x + a, x + b, y - 0.25 * size, y + size]
        };
        if extent[0] < -1.0 || extent[1] > width + 1.0 || extent[2] < -1.0 || extent[3] > height + 1.0 {
            out.push((text, extent));
        }
    }
    out
}

/// Asserts that every text of every plot in `files` stays inside its canvas.
pub(crate) fn assert_text_inside(scene: &str, files: &[(String, String)]) {
    for (name, svg) in files.iter().filter(|(n, _)| n.ends_with(".svg")) {
        let bad = outside(svg);
        assert!(bad.is_empty(), "{scene}: {name}: text outside the canvas: {bad:?}");
    }
}

/// The measure itself: a title centred on a 200 px canvas fits at 20 characters of 14 px
/// (154 px), and does not at 40 (308 px); a rotated label is measured along y.
#[test]
fn the_measure_finds_text_past_the_edge() {
    let svg = |text: &str, rotate: &str| {
        format!(
            "<svg width=\"200\" height=\"100\" viewBox=\"0 0 200 100\">\n<text x=\"100\" y=\"5\" text-anchor=\"middle\" font-size=\"14\"{rotate}>\n{text}\n</text>\n</svg>"
        )
    };
    assert!(outside(&svg(&"x".repeat(20), "")).is_empty());
    assert_eq!(outside(&svg(&"x".repeat(40), "")).len(), 1);
    assert_eq!(outside(&svg(&"x".repeat(20), " transform=\"rotate(270, 100, 5)\"")).len(), 1);
}
