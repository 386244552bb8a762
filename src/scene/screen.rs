//! Screening of the scene text before the parser: what a parser would report badly or not survive.
//! Invisible and look-alike characters (a no-break space, the minus sign U+2212, a byte-order mark,
//! a letter with an accent in a key) are named with their code point, outside comments and strings;
//! blocks, lists and calls nested deeper than [`MAX_NESTING`] are refused before the recursive
//! descent could overflow the stack.

use crate::diagnostics::{Diagnostic, DiagnosticKind, Span};

/// Deepest nesting of `{`, `[` and `(` a scene may have (a real scene needs 4).
pub(crate) const MAX_NESTING: usize = 32;
/// Characters flagged before the screen stops looking.
const MAX_FLAGGED: usize = 10;

/// Non-ASCII characters the language uses: the micro sign, the Greek mu and the degree sign in units.
const ALLOWED: [char; 3] = ['µ', 'μ', '°'];

/// Names and the fix of the characters people paste without seeing them.
fn look_alike(c: char) -> Option<(&'static str, &'static str)> {
    Some(match c {
        '\u{00A0}' => ("NO-BREAK SPACE", "replace it with a plain space"),
        '\u{2007}' | '\u{202F}' => ("NARROW OR FIGURE SPACE", "replace it with a plain space"),
        '\u{2000}'..='\u{200A}' => ("TYPOGRAPHIC SPACE", "replace it with a plain space"),
        '\u{200B}' => ("ZERO WIDTH SPACE", "delete it (it is invisible)"),
        '\u{200C}' | '\u{200D}' | '\u{2060}' => ("ZERO WIDTH JOINER OR NON-JOINER", "delete it (it is invisible)"),
        '\u{FEFF}' => ("BYTE ORDER MARK", "delete it: save the file as UTF-8 without a byte-order mark"),
        '\u{00AD}' => ("SOFT HYPHEN", "delete it (it is invisible)"),
        '\u{2212}' => ("MINUS SIGN", "write the ASCII hyphen-minus `-`"),
        '\u{2010}'..='\u{2015}' => ("DASH OR HYPHEN", "write the ASCII hyphen-minus `-` (or `..` for a range)"),
        '\u{00D7}' | '\u{22C5}' | '\u{00B7}' | '\u{2219}' => ("MULTIPLICATION SIGN OR DOT", "write `*` between units"),
        '\u{2044}' | '\u{2215}' => ("FRACTION SLASH", "write the ASCII slash `/`"),
        '\u{201C}' | '\u{201D}' | '\u{201E}' | '\u{00AB}' | '\u{00BB}' => {
            ("TYPOGRAPHIC QUOTE", "write the ASCII quote `\"`")
        }
        '\u{2018}' | '\u{2019}' => ("TYPOGRAPHIC APOSTROPHE", "the language has no apostrophes; names are ASCII"),
        '\u{FF0C}' | '\u{201A}' => ("FULLWIDTH OR LOW COMMA", "write the ASCII comma `,`"),
        '\u{FF1D}' => ("FULLWIDTH EQUALS SIGN", "write the ASCII `=`"),
        '\u{2026}' => ("HORIZONTAL ELLIPSIS", "write two ASCII dots `..` for a range"),
        _ => return None,
    })
}

fn flag(c: char, at: usize) -> Diagnostic {
    let span = Span::new(at, at + c.len_utf8());
    let code = format!("U+{:04X}", c as u32);
    match look_alike(c) {
        Some((name, fix)) => Diagnostic::new(
            DiagnosticKind::Syntax,
            span,
            format!("invisible or look-alike character {code} {name} outside a string or comment"),
        )
        .hint(fix),
        None if c.is_control() => {
            Diagnostic::new(DiagnosticKind::Syntax, span, format!("control character {code} in the scene"))
                .hint("delete it; a scene is plain text (tabs and line ends are fine)")
        }
        None => Diagnostic::new(
            DiagnosticKind::Syntax,
            span,
            format!("non-ASCII character `{c}` ({code}) outside a string or comment"),
        )
        .hint("keys, names and numbers are ASCII (units may use µ and °); text in \"quotes\" or after `#` may be anything"),
    }
}

/// Problems the parser must not see; empty when the text may be parsed.
pub(crate) fn screen(source: &str) -> Vec<Diagnostic> {
    let mut out = Vec::new();
    let (mut in_comment, mut in_string) = (false, false);
    let mut openers: Vec<usize> = Vec::new();
    let mut too_deep = false;
    for (at, c) in source.char_indices() {
        if out.len() >= MAX_FLAGGED {
            break;
        }
        if c == '\u{FEFF}' {
            out.push(flag(c, at));
            continue;
        }
        if in_comment {
            in_comment = c != '\n';
            continue;
        }
        if in_string {
            in_string = c != '"' && c != '\n';
            if c.is_control() && c != '\t' && c != '\n' {
                out.push(flag(c, at));
            }
            continue;
        }
        match c {
            '#' => in_comment = true,
            '"' => in_string = true,
            '{' | '[' | '(' => {
                openers.push(at);
                if openers.len() > MAX_NESTING && !too_deep {
                    too_deep = true;
                    out.push(
                        Diagnostic::new(
                            DiagnosticKind::Syntax,
                            Span::new(at, at + 1),
                            format!("blocks, lists and calls nested more than {MAX_NESTING} deep"),
                        )
                        .hint("a scene needs a few levels (scene, gears, pinion); close the blocks that are open"),
                    );
                }
            }
            '}' | ']' | ')' => {
                openers.pop();
            }
            '\t' | '\n' | '\r' => {}
            c if ALLOWED.contains(&c) => {}
            c if !c.is_ascii() || c.is_ascii_control() => out.push(flag(c, at)),
            _ => {}
        }
    }
    out
}
