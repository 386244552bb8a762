//! report.json's text: serde_json's pretty output with each array of plain values (numbers,
//! strings, `null`) joined onto the line that opens it, so that a plot's series stays readable.
//!
//! The joining is done in place in the serialised bytes: a joined array is never longer than its
//! pretty lines (each element loses its indentation, at least two spaces, and its line break, and
//! gains `, `), so the text is written behind the point it is read from and a large report is held
//! once, not three times (the pretty text, its lines and the joined copy).

use serde::Serialize;

/// `value` as report.json writes it: pretty, plain arrays on one line, ending in a line break.
pub(crate) fn json_text<T: Serialize + ?Sized>(value: &T, what: &str) -> String {
    let mut bytes = serde_json::to_vec_pretty(value).unwrap_or_else(|e| panic!("{what} serialises: {e}"));
    join_plain_arrays(&mut bytes);
    bytes.push(b'\n');
    String::from_utf8(bytes).expect("joining whole lines and elements keeps the text UTF-8")
}

/// Joins, in place, every array of serde_json's pretty output (`pretty`) whose elements are all
/// plain values onto the line that opens it: `[\n  1.0,\n  2.0\n]` → `[1.0, 2.0]`. Nested arrays
/// and objects keep their lines.
pub(crate) fn join_plain_arrays(pretty: &mut Vec<u8>) {
    let n = pretty.len();
    let (mut read, mut write) = (0, 0);
    while read < n {
        if read > 0 {
            // The previous line's break, written back behind it.
            pretty[write] = b'\n';
            write += 1;
        }
        let end = line_end(pretty, read);
        if pretty[read..end].ends_with(b"[") {
            if let Some((close, after)) = plain_elements_end(pretty, end) {
                write = copy(pretty, read..end, write);
                let mut item = end + 1;
                let mut first = true;
                while item < close {
                    let item_end = line_end(pretty, item);
                    if !first {
                        write = put(pretty, b", ", write);
                    }
                    first = false;
                    let (from, to) = trimmed(pretty, item, item_end);
                    write = copy(pretty, from..to, write);
                    item = item_end + 1;
                }
                let (from, to) = (first_non_space(pretty, close), line_end(pretty, close));
                write = copy(pretty, from..to, write);
                read = after;
                continue;
            }
        }
        write = copy(pretty, read..end, write);
        read = end + 1;
    }
    pretty.truncate(write);
}

/// Where the elements of the array opened on the line ending at `open_end` end, if each is a
/// plain value on a line of its own: the start of the closing `]` line and the start of the line
/// after it.
fn plain_elements_end(text: &[u8], open_end: usize) -> Option<(usize, usize)> {
    let mut line = open_end + 1;
    while line < text.len() {
        let end = line_end(text, line);
        let t = &text[first_non_space(text, line)..end];
        if t == b"]" || t == b"]," {
            return Some((line, end + 1));
        }
        let nested = t.ends_with(b"[") || t.ends_with(b"{") || t.starts_with(b"]") || t.starts_with(b"}");
        if nested {
            return None;
        }
        line = end + 1;
    }
    None
}

/// The end of the line starting at `start` (its `\n`, or the end of the text).
fn line_end(text: &[u8], start: usize) -> usize {
    text[start..].iter().position(|&b| b == b'\n').map_or(text.len(), |k| start + k)
}

/// The first byte of the line at `start` that is not indentation.
fn first_non_space(text: &[u8], start: usize) -> usize {
    start + text[start..].iter().take_while(|&&b| b == b' ').count()
}

/// An element's line without its indentation and its trailing comma.
fn trimmed(text: &[u8], start: usize, end: usize) -> (usize, usize) {
    let from = first_non_space(text, start);
    let to = from + text[from..end].iter().rposition(|&b| b != b',').map_or(0, |k| k + 1);
    (from, to)
}

/// Copies `range` to `write` (never ahead of it) and returns the write position after it.
fn copy(text: &mut [u8], range: std::ops::Range<usize>, write: usize) -> usize {
    debug_assert!(write <= range.start);
    let len = range.len();
    text.copy_within(range, write);
    write + len
}

/// Writes `bytes` at `write` and returns the write position after them.
fn put(text: &mut [u8], bytes: &[u8], write: usize) -> usize {
    text[write..write + bytes.len()].copy_from_slice(bytes);
    write + bytes.len()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The reference reading, as report.json was joined before it was done in place: the pretty
    /// text's lines collected, each plain array joined into a new string.
    fn joined_by_lines(pretty: &str) -> String {
        // Written into one string as it goes: no line or joined array is allocated on its own.
        let lines: Vec<&str> = pretty.lines().collect();
        let mut out = String::with_capacity(pretty.len());
        let mut i = 0;
        while i < lines.len() {
            if i > 0 {
                out.push('\n');
            }
            let line = lines[i];
            if line.ends_with('[') {
                // The elements up to the matching `]`, if each is a plain value on a line of its own.
                let mut j = i + 1;
                let closed = loop {
                    let Some(next) = lines.get(j) else { break None };
                    let t = next.trim_start();
                    if t == "]" || t == "]," {
                        break Some(t);
                    }
                    let plain = !(t.ends_with('[') || t.ends_with('{') || t.starts_with(']') || t.starts_with('}'));
                    if !plain {
                        break None;
                    }
                    j += 1;
                };
                if let Some(close) = closed {
                    out.push_str(line);
                    for (k, item) in lines[i + 1..j].iter().enumerate() {
                        if k > 0 {
                            out.push_str(", ");
                        }
                        out.push_str(item.trim_start().trim_end_matches(','));
                    }
                    out.push_str(close);
                    i = j + 1;
                    continue;
                }
            }
            out.push_str(line);
            i += 1;
        }
        out
    }

    /// Nested arrays, objects in arrays, empty arrays, strings with brackets, commas and non-ASCII
    /// text, and arrays at the end of the text: the in-place joining gives the reference's bytes.
    #[test]
    fn in_place_joining_is_the_line_by_line_reading() {
        let value = serde_json::json!({
            "x": [1.5, null, "a, b [c]", "µ ≥ 0"],
            "y": [[1, 2], [], [3]],
            "z": [{"a": [1]}, {"b": []}],
            "empty": [],
            "s": "[",
            "t": {"u": [true, false], "v": {"w": [-1e-300, 2]}},
            "last": [[["deep"]]]
        });
        let pretty = serde_json::to_string_pretty(&value).unwrap();
        let mut bytes = pretty.clone().into_bytes();
        join_plain_arrays(&mut bytes);
        let joined = String::from_utf8(bytes).unwrap();
        assert_eq!(joined, joined_by_lines(&pretty));
        assert!(joined.contains("\"x\": [1.5, null, \"a, b [c]\", \"µ ≥ 0\"]"), "{joined}");
        assert!(joined.contains("[1, 2],"), "{joined}");
        // Text serde_json does not write (an empty line, an array left open) reads as the reference reads it.
        for text in ["{\n  \"a\": [\n    1\n  ],\n\n  \"b\": [\n\n    2\n  ]\n}", "[\n  1,\n  2"] {
            let mut bytes = text.as_bytes().to_vec();
            join_plain_arrays(&mut bytes);
            assert_eq!(String::from_utf8(bytes).unwrap(), joined_by_lines(text), "{text:?}");
        }
        let array = serde_json::to_string_pretty(&serde_json::json!([1, [2, 3]])).unwrap();
        let mut bytes = array.clone().into_bytes();
        join_plain_arrays(&mut bytes);
        assert_eq!(String::from_utf8(bytes).unwrap(), joined_by_lines(&array));
    }
}
