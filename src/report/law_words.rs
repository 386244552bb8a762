//! A law's label in the words of its catalogue title, for legends and tables.

/// A law's label in words for legends: `coulomb(mu = 0.04)` → "Coulomb μ = 0.04",
/// `iso_14179_2(x_l = 0.846)` → "ISO/TR 14179-2 X_L = 0.846"; `benedict_kelley` and
/// `benedict_kelley_bernard` keep their parentheses ("Benedict–Kelley (Bernard Table 1)").
/// Whatever follows the closing parenthesis (`iso_14179_2(x_l = 0.846), external`) is kept as it is.
pub(crate) fn law_words(label: &str) -> String {
    let (law, rest) = match label.rfind(')') {
        Some(end) => label.split_at(end + 1),
        None => label.split_once(", ").map_or((label, ""), |(l, _)| (l, &label[l.len()..])),
    };
    format!("{}{rest}", law_words_of(law))
}

fn law_words_of(label: &str) -> String {
    let (name, args) = match label.split_once('(') {
        Some((n, a)) => (n, a.trim_end_matches(')')),
        None => (label, ""),
    };
    let short = |t: &'static str| t.split(" (").next().unwrap_or(t);
    let laws = crate::friction::catalog::LAWS;
    // The title without its parenthesis, unless another law shares that short title (the two
    // Benedict–Kelley forms): then the whole title, so that distinct laws read differently.
    let title = laws.iter().find(|l| l.id.name() == name).map_or(name.to_string(), |l| {
        let twin = laws.iter().any(|o| o.id != l.id && short(o.title) == short(l.title));
        if twin {
            l.title.to_string()
        } else {
            short(l.title).to_string()
        }
    });
    let args: Vec<String> = args
        .split(", ")
        .filter(|a| !a.is_empty())
        .map(|a| {
            let (k, v) = a.split_once(" = ").unwrap_or((a, ""));
            let k = match k {
                "mu" => "μ",
                "x_l" => "X_L",
                "mu_boundary" => "μ_bl",
                "mu_ehl" => "μ_EHL",
                other => other,
            };
            format!("{k} = {v}")
        })
        .collect();
    if args.is_empty() {
        title
    } else {
        format!("{title} {}", args.join(", "))
    }
}

#[cfg(test)]
mod tests {
    use super::law_words;

    /// Arguments in words, and what follows the law (a formulation) kept: the duty cycle's label
    /// once read "X_L = 0.846), external = ".
    #[test]
    fn labels_in_words() {
        assert_eq!(law_words("coulomb(mu = 0.04)"), "Coulomb μ = 0.04");
        assert_eq!(law_words("iso_14179_2(x_l = 0.846), external"), "ISO/TR 14179-2 X_L = 0.846, external");
        assert_eq!(law_words("coulomb, internal"), "Coulomb, internal");
    }
}
