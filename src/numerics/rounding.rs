//! Numbers as reports keep them: ten significant digits, so that output does not change with the
//! last bit of a libm call.

/// Significant digits kept in report.json and the map's CSV.
pub const SIGNIFICANT_DIGITS: usize = 10;

/// Rounds to [`SIGNIFICANT_DIGITS`] significant digits (non-finite values pass through).
pub fn round_sig(x: f64) -> f64 {
    if !x.is_finite() || x == 0.0 {
        return if x == 0.0 { 0.0 } else { x };
    }
    // Written into a buffer on the stack (report.json rounds every number it holds: a heap string
    // each cost a large sweep's report a tenth of its writing time).
    let mut buf = StackText { bytes: [0; 48], len: 0 };
    use std::fmt::Write;
    if write!(buf, "{:.*e}", SIGNIFICANT_DIGITS - 1, x).is_err() {
        return x;
    }
    std::str::from_utf8(&buf.bytes[..buf.len]).ok().and_then(|t| t.parse().ok()).unwrap_or(x)
}

/// A short text written on the stack ([`round_sig`]'s `d.ddddddddde±x`, at most 24 bytes).
struct StackText {
    bytes: [u8; 48],
    len: usize,
}

impl std::fmt::Write for StackText {
    fn write_str(&mut self, s: &str) -> std::fmt::Result {
        let end = self.len + s.len();
        if end > self.bytes.len() {
            return Err(std::fmt::Error);
        }
        self.bytes[self.len..end].copy_from_slice(s.as_bytes());
        self.len = end;
        Ok(())
    }
}

/// Six significant digits, for the inputs table (as written and SI columns).
pub(crate) fn sig(x: f64) -> String {
    sig_digits(x, 6)
}

/// `digits` significant digits (1 or more), trailing zeros dropped; plain from 1e-3 to below 1e6,
/// else with an exponent (`1.5e-8`).
pub(crate) fn sig_digits(x: f64, digits: usize) -> String {
    if x == 0.0 {
        return "0".into();
    }
    let last = digits.max(1) - 1;
    let s = format!("{x:.last$e}");
    let v: f64 = s.parse().unwrap_or(x);
    if (1e-3..1e6).contains(&v.abs()) {
        let decimals = (last as i32 - v.abs().log10().floor() as i32).max(0) as usize;
        let t = format!("{v:.decimals$}");
        if t.contains('.') {
            t.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            t
        }
    } else {
        match s.split_once('e') {
            Some((mantissa, exp)) if mantissa.contains('.') => {
                format!("{}e{exp}", mantissa.trim_end_matches('0').trim_end_matches('.'))
            }
            _ => s,
        }
    }
}

/// Writes `x` with `d` decimals; non-finite values are written as `—` (and listed in the findings).
pub(crate) fn fixed(x: f64, d: usize) -> String {
    if x.is_finite() {
        let s = format!("{x:.d$}");
        if s.starts_with('-') && s[1..].chars().all(|c| c == '0' || c == '.') {
            s[1..].to_string()
        } else {
            s
        }
    } else {
        "—".into()
    }
}
