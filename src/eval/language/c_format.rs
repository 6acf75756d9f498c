//! Numbers as C's `printf` writes them, for the texts POV-Ray makes with it.
//!
//! In: a float and a count of significant digits. Out: C's `%.Pg` text. Holds: nothing.
//! Used by `#write` (six digits) and by `str`/`vstr` when their fixed text is too long.

/// C's `%.Pg`: `digits` significant digits (at least 1), in fixed notation when the decimal
/// exponent after rounding is from -4 to below `digits`, else as `1.5e+300`; trailing zeros
/// of the fraction dropped; `nan`, `inf`, `-inf` and `-0` as C writes them.
pub(crate) fn general_format(value: f64, digits: usize) -> String {
    let digits = digits.max(1);
    if !value.is_finite() {
        return match (value.is_nan(), value < 0.0) {
            (true, _) => "nan".into(),
            (false, true) => "-inf".into(),
            (false, false) => "inf".into(),
        };
    }
    if value == 0.0 {
        return if value.is_sign_negative() { "-0" } else { "0" }.into();
    }
    // The exponent after rounding to the digits decides the form, as in C.
    let scientific = format!("{:.*e}", digits - 1, value);
    let (mantissa, exponent) = scientific.split_once('e').unwrap_or((&scientific, "0"));
    let exponent: i64 = exponent.parse().unwrap_or(0);
    if exponent < -4 || exponent >= digits as i64 {
        let sign = if exponent < 0 { '-' } else { '+' };
        format!(
            "{}e{sign}{:02}",
            without_trailing_zeros(mantissa),
            exponent.abs()
        )
    } else {
        let decimals = (digits as i64 - 1 - exponent) as usize;
        without_trailing_zeros(&format!("{value:.decimals$}")).to_string()
    }
}

/// A decimal text without the trailing zeros of its fraction (and without a bare `.`).
fn without_trailing_zeros(text: &str) -> &str {
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.')
    } else {
        text
    }
}

#[cfg(test)]
mod tests {
    use super::general_format;

    #[test]
    fn general_format_is_c_percent_g() {
        assert_eq!(general_format(1.5, 6), "1.5");
        assert_eq!(general_format(1e-5, 6), "1e-05");
        assert_eq!(general_format(1234567.0, 6), "1.23457e+06");
        assert_eq!(general_format(999999.5, 6), "1e+06");
        assert_eq!(general_format(0.0001, 6), "0.0001");
        assert_eq!(general_format(-0.0, 6), "-0");
        assert_eq!(general_format(f64::NAN, 6), "nan");
        assert_eq!(general_format(f64::NEG_INFINITY, 6), "-inf");
        assert_eq!(general_format(1e300, 2), "1e+300");
        assert_eq!(general_format(2.5, 0), "2");
    }
}
