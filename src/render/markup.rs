//! The Markdown writer of report.md: lines appended to a `String`, which cannot fail, so no
//! renderer discards a `fmt::Result` (`let _ = writeln!(...)` at every line before). [`md!`] writes
//! one line (or an empty one); [`put!`] writes text without ending the line; tables are
//! [`super::table::header`] and [`super::table::row`].
//!
//! ```text
//! let mut out = String::new();
//! md!(out, "## {}\n", "Loss budget");
//! md!(out);
//! assert_eq!(out, "## Loss budget\n\n\n");
//! ```

/// Text appended to a report being written.
pub(crate) trait Markup {
    /// `args` and a line end.
    fn line(&mut self, args: std::fmt::Arguments);
    /// `args`, the line left open.
    fn put(&mut self, args: std::fmt::Arguments);
}

impl Markup for String {
    fn line(&mut self, args: std::fmt::Arguments) {
        self.put(args);
        self.push('\n');
    }

    fn put(&mut self, args: std::fmt::Arguments) {
        match args.as_str() {
            Some(text) => self.push_str(text),
            // Formatting into a String fails only when a value's own `Display` does, which no
            // value of a report does (its numbers and words format into text unconditionally).
            None => self.push_str(&std::fmt::format(args)),
        }
    }
}

/// `md!(out, "format", args…)`: one line of report.md; `md!(out)`: an empty line.
macro_rules! md {
    ($out:expr) => {
        $out.push('\n')
    };
    ($out:expr, $($arg:tt)*) => {{
        use $crate::render::markup::Markup as _;
        $out.line(format_args!($($arg)*))
    }};
}

/// `put!(out, "format", args…)`: text without a line end.
macro_rules! put {
    ($out:expr, $($arg:tt)*) => {{
        use $crate::render::markup::Markup as _;
        $out.put(format_args!($($arg)*))
    }};
}

pub(crate) use {md, put};

/// `n` things in words, singular or plural: `counted(1, "stage", "stages")` is "1 stage",
/// `counted(0, "note", "notes")` "0 notes".
pub(crate) fn counted(n: usize, one: &str, many: &str) -> String {
    format!("{n} {}", if n == 1 { one } else { many })
}

#[cfg(test)]
mod counted_tests {
    #[test]
    fn one_is_singular_every_other_count_plural() {
        assert_eq!(super::counted(1, "stage", "stages"), "1 stage");
        assert_eq!(super::counted(0, "note", "notes"), "0 notes");
        assert_eq!(super::counted(2, "operating point", "operating points"), "2 operating points");
    }
}

#[cfg(test)]
mod tests {
    /// A line, an empty line and open text append exactly what `writeln!`/`write!` would.
    #[test]
    fn lines_as_writeln_writes_them() {
        let mut out = String::new();
        let title = "Loss budget";
        md!(out, "## {title}\n");
        md!(out);
        put!(out, "a {}", 1);
        md!(out, " b");
        let mut by_hand = String::new();
        use std::fmt::Write;
        writeln!(by_hand, "## {title}\n").unwrap();
        writeln!(by_hand).unwrap();
        write!(by_hand, "a {}", 1).unwrap();
        writeln!(by_hand, " b").unwrap();
        assert_eq!(out, by_hand);
        let r: &mut String = &mut out;
        md!(r, "x");
        assert!(out.ends_with(" b\nx\n"));
    }
}
