//! The elastic constant of a contact.

/// E' = 2 / [(1 − ν1²)/E1 + (1 − ν2²)/E2] (physics notes; He–Cho–Singh print a misplaced parenthesis).
pub fn reduced_modulus(e: [f64; 2], nu: [f64; 2]) -> f64 {
    2.0 / ((1.0 - nu[0] * nu[0]) / e[0] + (1.0 - nu[1] * nu[1]) / e[1])
}
