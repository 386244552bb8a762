//! How an imported scene writes the model's numbers and names.

/// A number as the scene writes it: the shortest text that reads back exactly, −0 as 0.
pub(super) fn n(x: f64) -> String {
    format!("{}", x + 0.0)
}

/// A name from the model as the scene may write it, in a comment or a string: on one line (a line
/// break would end the comment and let the rest be read as scene), no `"` (it would end the
/// string), no other control characters.
pub(super) fn clean(name: &str) -> String {
    name.chars()
        .map(|c| {
            if c.is_control() {
                ' '
            } else if c == '"' {
                '\''
            } else {
                c
            }
        })
        .collect()
}

pub(super) fn shaft_name(id: u64) -> String {
    format!("shaft_{id}")
}
