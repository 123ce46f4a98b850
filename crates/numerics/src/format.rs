//! The workspace's one number format: shortest round-trip, exactly as in JSON.
//!
//! Titles, report bodies, CSV comments and error messages all print numbers with [`number`], so
//! a value reads the same in a message as in the `--json` output that carries it.

/// `x` in the shortest form that reads back to the same `f64`, as `serde_json` writes it
/// (`0.00006`, `1e-9`, `60.0`, `1e+16`); `nan`, `inf` and `-inf` for the values JSON cannot hold.
///
/// ```
/// use numerics::format::number;
/// assert_eq!(number(60e-6), "0.00006");
/// assert_eq!(number(1e-9), "1e-9");
/// assert_eq!(number(0.04), "0.04");
/// assert_eq!(number(f64::NAN), "nan");
/// ```
pub fn number(x: f64) -> String {
    if x.is_nan() {
        "nan".into()
    } else if x.is_infinite() {
        if x > 0.0 { "inf" } else { "-inf" }.into()
    } else {
        // serde_json's own formatter, so that the two can never disagree
        serde_json::Value::from(x).to_string()
    }
}

/// Significant figures a derived value is rounded to before [`number`] prints it in a message.
const DERIVED_DIGITS: usize = 12;

/// `x`, a value computed from the inputs (a difference, a scaled length), in the form of
/// [`number`] after rounding to 12 significant figures, so that the arithmetic itself adds no
/// digits (0.04 - 0.03 = 0.010000000000000002 reads 0.01). For messages and titles only: the
/// JSON keeps every digit.
///
/// ```
/// use numerics::format::derived;
/// assert_eq!(derived(0.04 - 0.03), "0.01");
/// assert_eq!(derived(60e-6 / 1e-6), "60.0");
/// assert_eq!(derived(f64::NAN), "nan");
/// ```
pub fn derived(x: f64) -> String {
    let rounded = format!("{x:.prec$e}", prec = DERIVED_DIGITS - 1)
        .parse()
        .unwrap_or(x);
    number(rounded)
}

/// Plain decimals longer than this many characters in another library's message are written
/// again by [`shorten_numbers`]: `0.000123` stays, twenty zeros before the digits do not.
const LONG_NUMBER: usize = 20;

/// `text` (another library's message) with each plain decimal longer than 20 characters, as
/// some libraries print tiny or huge values, in the form of [`number`]; the rest unchanged.
///
/// ```
/// use numerics::format::shorten_numbers;
/// assert_eq!(
///     shorten_numbers("Step size is too small at time = 0.0000000000000000000001085628328344482"),
///     "Step size is too small at time = 1.085628328344482e-22"
/// );
/// assert_eq!(shorten_numbers("t = 0.5, h = 1e-9"), "t = 0.5, h = 1e-9");
/// ```
pub fn shorten_numbers(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut run = String::new();
    let flush = |run: &mut String, out: &mut String| {
        let plain = !run.contains(['e', 'E']) && run.len() > LONG_NUMBER;
        match run.parse::<f64>() {
            Ok(x) if plain => out.push_str(&number(x)),
            _ => out.push_str(run),
        }
        run.clear();
    };
    for c in text.chars() {
        if c.is_ascii_digit() || c == '.' || (c == '-' && run.is_empty()) {
            run.push(c);
        } else {
            flush(&mut run, &mut out);
            out.push(c);
        }
    }
    flush(&mut run, &mut out);
    out
}

/// A length (m) in the unit that suits it (nm, um, mm, cm, m), for titles: `60 um`, `10 nm`.
///
/// The scaled value is printed by [`derived`], so that the conversion itself (60e-6 / 1e-6 =
/// 60.00000000000001) adds no digits.
///
/// ```
/// use numerics::format::length;
/// assert_eq!(length(60e-6), "60 um");
/// assert_eq!(length(1.5e-6), "1.5 um");
/// assert_eq!(length(1e-7), "100 nm");
/// assert_eq!(length(0.003), "3 mm");
/// ```
pub fn length(metres: f64) -> String {
    const UNITS: [(f64, &str); 5] = [
        (1.0, "m"),
        (1e-2, "cm"),
        (1e-3, "mm"),
        (1e-6, "um"),
        (1e-9, "nm"),
    ];
    if !metres.is_finite() || metres <= 0.0 {
        return format!("{} m", number(metres));
    }
    let (scale, unit) = UNITS
        .iter()
        .copied()
        .find(|(s, _)| metres >= *s)
        .unwrap_or(UNITS[UNITS.len() - 1]);
    let text = derived(metres / scale);
    let text = text.strip_suffix(".0").unwrap_or(&text);
    format!("{text} {unit}")
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Round trip across the whole range: the text reads back to the same f64 (the property the
    /// format promises; the literal forms are in the doctest of [`number`]).
    #[test]
    fn reads_back_to_the_same_value() {
        for x in [
            6e-5,
            1e-5,
            1e-4,
            0.04,
            60.0,
            1e15,
            1e16,
            1e-300,
            123456.789,
            -2.5e-7,
            0.1 + 0.2,
        ] {
            assert_eq!(number(x).parse::<f64>(), Ok(x), "{x}");
        }
        assert_eq!(number(f64::INFINITY), "inf");
        assert_eq!(number(f64::NEG_INFINITY), "-inf");
    }

    #[test]
    fn lengths() {
        assert_eq!(length(30e-6), "30 um");
        assert_eq!(length(1e-8), "10 nm");
        assert_eq!(length(0.01), "1 cm");
        assert_eq!(length(60.0), "60 m");
        assert_eq!(length(1e-12), "0.001 nm");
    }
}
