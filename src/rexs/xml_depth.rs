//! A guard run on XML text before it is parsed: how deep its elements nest. The XML parser
//! descends one call per level, so a file nested 100 000 deep would overflow the stack; a REXS
//! model nests six deep (model, components, component, attribute, array, c), so anything past
//! [`MAX_XML_DEPTH`] is refused without building the tree.

/// The deepest nesting read (a REXS model has six levels; extensions a few more).
pub(crate) const MAX_XML_DEPTH: usize = 64;

/// The deepest element nesting in `text` up to `limit + 1` (the scan stops there), counting start
/// tags against end tags; comments, CDATA sections, processing instructions, declarations and
/// quoted attribute values are skipped, and an empty-element tag (`<a/>`) opens nothing.
///
/// ```ignore
/// assert_eq!(depth("<a><b/><c><d></d></c></a>", 64), 3);
/// ```
pub(crate) fn depth(text: &str, limit: usize) -> usize {
    let bytes = text.as_bytes();
    let (mut i, mut depth, mut deepest) = (0usize, 0usize, 0usize);
    let skip_to = |from: usize, end: &[u8]| -> usize {
        bytes[from..].windows(end.len()).position(|w| w == end).map_or(bytes.len(), |p| from + p + end.len())
    };
    while i < bytes.len() {
        if bytes[i] != b'<' {
            i += 1;
            continue;
        }
        let rest = &bytes[i..];
        if rest.starts_with(b"<!--") {
            i = skip_to(i + 4, b"-->");
        } else if rest.starts_with(b"<![CDATA[") {
            i = skip_to(i + 9, b"]]>");
        } else if rest.starts_with(b"<?") {
            i = skip_to(i + 2, b"?>");
        } else if rest.starts_with(b"<!") {
            i = skip_to(i + 2, b">");
        } else if rest.starts_with(b"</") {
            depth = depth.saturating_sub(1);
            i = skip_to(i + 2, b">");
        } else {
            // A start tag: find its '>' outside quotes; '/>' closes it at once.
            let (mut j, mut quote) = (i + 1, None::<u8>);
            while j < bytes.len() {
                match (quote, bytes[j]) {
                    (None, b'"' | b'\'') => quote = Some(bytes[j]),
                    (Some(q), c) if c == q => quote = None,
                    (None, b'>') => break,
                    _ => {}
                }
                j += 1;
            }
            if j >= bytes.len() || bytes[j - 1] != b'/' {
                depth += 1;
                deepest = deepest.max(depth);
                if deepest > limit {
                    return deepest;
                }
            }
            i = j + 1;
        }
    }
    deepest
}

#[cfg(test)]
mod tests {
    use super::depth;

    #[test]
    fn counts_elements_not_comments_quotes_or_empty_tags() {
        assert_eq!(depth("<a><b/><c><d></d></c></a>", 64), 3);
        assert_eq!(depth("<?xml version=\"1.0\"?><!-- <x><y><z> --><a t=\"<b>\" u='/>'><![CDATA[<c><d>]]></a>", 64), 1);
        assert_eq!(depth("<!DOCTYPE model><model><components><component id=\"1\"/></components></model>", 64), 2);
        // The scan stops one past the limit, whatever the length.
        let deep = "<a>".repeat(100_000);
        assert_eq!(depth(&deep, 64), 65);
        assert_eq!(depth("", 64), 0);
    }
}
