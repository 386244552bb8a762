//! Every fenced `gear` block of README.md, ARCHITECTURE.md and DEVELOPING.md that is a complete
//! scene checks and runs; every `gear-fragment` block names, on its first line (`# in full: …`),
//! complete scenes that check and use every key and call the fragment writes.

use std::collections::BTreeSet;

/// (info string, first line number, text) of every fenced block of a Markdown file.
fn blocks(text: &str) -> Vec<(String, usize, String)> {
    let mut out = Vec::new();
    let mut open: Option<(String, usize, Vec<&str>)> = None;
    for (i, line) in text.lines().enumerate() {
        match (&mut open, line.strip_prefix("```")) {
            (None, Some(info)) => open = Some((info.trim().to_string(), i + 1, Vec::new())),
            (Some(_), Some(_)) => {
                let (info, at, body) = open.take().unwrap();
                out.push((info, at, body.join("\n")));
            }
            (Some((_, _, body)), None) => body.push(line),
            (None, None) => {}
        }
    }
    out
}

/// The names a fragment writes as keys (`name =`), blocks (`name {`) or calls (`name(`), comments
/// and elisions (`...`) left out.
fn names(fragment: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    for line in fragment.lines() {
        let code = line.split('#').next().unwrap_or("");
        let chars: Vec<char> = code.chars().collect();
        let mut i = 0;
        while i < chars.len() {
            if chars[i].is_ascii_alphabetic() || chars[i] == '_' {
                let start = i;
                while i < chars.len() && (chars[i].is_ascii_alphanumeric() || chars[i] == '_') {
                    i += 1;
                }
                let word: String = chars[start..i].iter().collect();
                let next = chars[i..].iter().find(|c| !c.is_whitespace());
                let before_ok = start == 0 || !chars[start - 1].is_ascii_digit();
                if before_ok && matches!(next, Some('=') | Some('{') | Some('(')) {
                    out.insert(word);
                }
            } else {
                i += 1;
            }
        }
    }
    out
}

#[test]
fn documentation_scenes_run() {
    let mut complete = 0;
    let mut fragments = 0;
    for doc in ["README.md", "ARCHITECTURE.md", "DEVELOPING.md"] {
        let text = std::fs::read_to_string(crate::root().join(doc)).unwrap();
        for (info, at, body) in blocks(&text) {
            let place = format!("{doc}:{at}");
            match info.as_str() {
                "gear" => {
                    let first = body.lines().find(|l| !l.trim().is_empty() && !l.trim_start().starts_with('#'));
                    assert!(first.is_some_and(|l| l.starts_with("scene")), "{place}: a `gear` block is a whole scene");
                    let files = gearloss::run_to_files(&place, &body).unwrap_or_else(|e| panic!("{place}: {e}"));
                    assert!(files.files.iter().any(|(f, _)| f == "report.md"), "{place}");
                    complete += 1;
                }
                "gear-fragment" => {
                    let first = body.lines().next().unwrap_or("");
                    let list =
                        first.strip_prefix("# in full: ").unwrap_or_else(|| panic!("{place}: starts `# in full: …`"));
                    let mut scenes = String::new();
                    for path in list.split(", ") {
                        let text = std::fs::read_to_string(crate::root().join(path))
                            .unwrap_or_else(|e| panic!("{place}: {path}: {e}"));
                        gearloss::check(path, &text).unwrap_or_else(|e| panic!("{place}: {path} does not check: {e}"));
                        scenes.push_str(&text);
                    }
                    for name in names(&body) {
                        assert!(scenes.contains(&name), "{place}: `{name}` is not in {list}");
                    }
                    fragments += 1;
                }
                "" if body.trim_start().starts_with("scene ") => panic!("{place}: a scene fenced without `gear`"),
                _ => {}
            }
        }
    }
    assert!(complete >= 1 && fragments >= 10, "{complete} scenes, {fragments} fragments");
}
