//! Number formatting, defined once for every surface: short, unit-aware values for screens
//! ([`qty`], [`sig`]), decade labels for log axes ([`decade`]), shortest round-trip numbers for
//! files ([`shortest`]) and values a user edits ([`editable`]). Never `NaN` or `inf`: non-finite
//! values read `—`. Needs `alloc`.

use crate::numerics::math::log10;
use alloc::format;
use alloc::string::{String, ToString};

/// A short number with 3 significant digits, plain between 1e-3 and 1e4, else `1.5e-7`.
/// Non-finite values become `—`.
pub fn num3(v: f64) -> String {
    sig(v, 3)
}

/// `v` with `digits` significant digits (trailing zeros removed); `—` when not finite.
pub fn sig(v: f64, digits: i32) -> String {
    if !v.is_finite() {
        return "—".into();
    }
    if v == 0.0 {
        return "0".into();
    }
    let a = v.abs();
    if (1e-3..1e4).contains(&a) {
        let d = (digits - 1 - libm::floor(log10(a)) as i32).clamp(0, 16) as usize;
        trim(&format!("{v:.d$}"))
    } else {
        let d = (digits - 1).max(0) as usize;
        let s = format!("{v:.d$e}");
        match s.split_once('e') {
            Some((m, e)) => format!("{}e{e}", trim(m)),
            None => s,
        }
    }
}

/// `v` rounded to `digits` significant decimal digits, as the nearest double (`3.0000000000000003e-4`
/// → `3e-4` at 12 digits); non-finite values and 0 unchanged.
pub fn round_sig(v: f64, digits: usize) -> f64 {
    if !v.is_finite() || v == 0.0 {
        return v;
    }
    let d = digits.clamp(1, 17) - 1;
    format!("{v:.d$e}").parse().unwrap_or(v)
}

/// Removes trailing zeros (and a trailing point) from a decimal string.
fn trim(s: &str) -> String {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s.to_string()
    }
}

const PREFIXES: [(f64, &str); 9] = [
    (1e12, "T"),
    (1e9, "G"),
    (1e6, "M"),
    (1e3, "k"),
    (1.0, ""),
    (1e-3, "m"),
    (1e-6, "µ"),
    (1e-9, "n"),
    (1e-12, "p"),
];

/// A quantity with its SI unit, using an SI prefix where that reads better (`6.6 µm/s`, `10 GPa`,
/// `15.08 g`), 4 significant digits. Units that do not take prefixes well (`kg/m³`, `J/m²`,
/// dimensionless) are printed as plain numbers. Non-finite values become `—`.
pub fn qty(v: f64, unit: &str) -> String {
    qty_sig(v, unit, 4)
}

/// The unit a kinematic viscosity (or any area per time) of size `x` \[m²/s\] is written in, with
/// its scale: m²/s, cm²/s, mm²/s or µm²/s, the largest that keeps `x` at or above 0.01 of it. A
/// ring's ν and its parts are written in the unit of the total, so that they add up as printed.
pub fn area_per_time_unit(x: f64) -> (f64, &'static str) {
    for (scale, unit) in [(1.0, "m²/s"), (1e-4, "cm²/s"), (1e-6, "mm²/s")] {
        if x.abs() >= 0.01 * scale {
            return (scale, unit);
        }
    }
    (1e-12, "µm²/s")
}

/// Like [`qty`] with 3 significant digits.
pub fn qty3(v: f64, unit: &str) -> String {
    qty_sig(v, unit, 3)
}

/// Like [`qty`] with `digits` significant digits.
pub fn qty_sig(v: f64, unit: &str, digits: i32) -> String {
    if !v.is_finite() {
        return "—".into();
    }
    let (v, unit) = if unit == "kg" {
        (v * 1e3, "g")
    } else {
        (v, unit)
    };
    if !prefixable(unit) || v == 0.0 {
        return join(sig(v, digits), unit);
    }
    let a = v.abs();
    for (scale, p) in PREFIXES {
        if a >= scale * 0.999_95 {
            if a / scale >= 1e4 {
                break;
            }
            return join(sig(v / scale, digits), &format!("{p}{unit}"));
        }
    }
    join(sig(v, digits), unit)
}

fn join(n: String, unit: &str) -> String {
    if unit.is_empty() {
        n
    } else {
        format!("{n} {unit}")
    }
}

/// The value a user edits: 12 significant digits with an SI prefix, so that float noise
/// (`0.000199999999999999982`) reads `200 µs` and typing it back gives the same number to 1e-12.
/// Units without SI prefixes (`kg/m³`, `J/m²`) are left off: the parameter's unit is implied.
pub fn editable(v: f64, unit: &str) -> String {
    if prefixable(unit) {
        qty_sig(v, unit, 12)
    } else {
        sig(v, 12)
    }
}

/// Whether [`qty`] writes `unit` with an SI prefix (a table keeps any other unit in its header
/// and prints plain numbers).
pub fn prefixable(unit: &str) -> bool {
    matches!(
        unit,
        "m" | "s" | "m/s" | "Pa" | "Pa s" | "g" | "kg" | "J" | "N"
    )
}

/// The shortest text that reads back as exactly `v` (`0.0002`, `1e-7`, `6.6e-6`), plain between
/// 1e-4 and 1e6, else with an exponent; `NaN`, `inf`, `-inf` for non-finite values (files only).
pub fn shortest(v: f64) -> String {
    let a = v.abs();
    if v == 0.0 || !v.is_finite() || (1e-4..1e6).contains(&a) {
        format!("{v}")
    } else {
        format!("{v:e}")
    }
}

/// A label for a decade `10^k` on a log axis: `1e-6`, `0.01`, `0.1`, `1`, `10`, `100`, `1e3`.
pub fn decade(k: i32) -> String {
    match k {
        -2 => "0.01".into(),
        -1 => "0.1".into(),
        0 => "1".into(),
        1 => "10".into(),
        2 => "100".into(),
        _ => format!("1e{k}"),
    }
}

/// The significant digits of `v` as printed in its shortest form (`3.84e-11` → 3, `1.341e8` → 4,
/// `37.6` → 3); 1 for zero or non-finite values.
pub fn printed_digits(v: f64) -> i32 {
    if !v.is_finite() || v == 0.0 {
        return 1;
    }
    let s = format!("{:e}", v.abs());
    let mantissa = s.split('e').next().unwrap_or("");
    let digits = mantissa.chars().filter(char::is_ascii_digit).count() as i32;
    digits.max(1)
}

/// Whether `computed` reproduces a `printed` value to the digits it is printed with: rounded to
/// [`printed_digits`] significant digits it reads the same. The one agree/disagree rule for
/// comparisons with numbers a paper prints.
pub fn agrees_to_printed(computed: f64, printed: f64) -> bool {
    if !(computed.is_finite() && printed.is_finite()) {
        return false;
    }
    let d = printed_digits(printed);
    sig(computed, d).parse::<f64>().ok() == sig(printed, d).parse::<f64>().ok()
}

#[cfg(test)]
mod tests {

    #[test]
    fn area_per_time_units_keep_the_value_at_or_above_a_hundredth() {
        assert_eq!(area_per_time_unit(0.01), (1.0, "m²/s"));
        assert_eq!(area_per_time_unit(0.0099), (1e-4, "cm²/s"));
        assert_eq!(area_per_time_unit(1.01e-6), (1e-4, "cm²/s"));
        assert_eq!(area_per_time_unit(9.9e-7), (1e-6, "mm²/s"));
        assert_eq!(area_per_time_unit(1.01e-8), (1e-6, "mm²/s"));
        assert_eq!(area_per_time_unit(9.9e-9), (1e-12, "µm²/s"));
        assert_eq!(area_per_time_unit(-0.5), (1.0, "m²/s"));
    }
    use super::*;

    #[test]
    fn numbers_are_short_and_finite() {
        let num = |v| sig(v, 4);
        assert_eq!(num(0.02), "0.02");
        assert_eq!(num(900.0), "900");
        assert_eq!(num(1e10), "1e10");
        assert_eq!(num(1.5e-7), "1.5e-7");
        assert_eq!(num(f64::NAN), "—");
        assert_eq!(num(f64::INFINITY), "—");
        assert_eq!(num(0.36019), "0.3602");
        assert_eq!(num3(0.36019), "0.36");
        assert_eq!(num3(1.5e-7), "1.5e-7");
        assert_eq!(qty3(4.618e-4, "s"), "462 µs");
    }

    #[test]
    fn quantities_use_si_prefixes() {
        assert_eq!(qty(6.6e-6, "m/s"), "6.6 µm/s");
        assert_eq!(qty(1e10, "Pa"), "10 GPa");
        assert_eq!(qty(0.015, "kg"), "15 g");
        assert_eq!(qty(1000.0, "Pa s"), "1 kPa s");
        assert_eq!(qty(1e-4, "s"), "100 µs");
        assert_eq!(qty(900.0, "kg/m³"), "900 kg/m³");
        assert_eq!(qty(0.3, ""), "0.3");
        assert_eq!(qty(f64::INFINITY, "s"), "—");
    }

    #[test]
    fn editable_values_have_no_float_noise_and_read_back() {
        // 2e-4 s computed the way a damping time from viscosities is: with a rounding error.
        let noisy = 2e-4 * (1.0 - f64::EPSILON);
        assert_ne!(noisy, 2e-4);
        assert_eq!(editable(noisy, "s"), "200 µs");
        assert_eq!(editable(1.0 / 3.0, ""), "0.333333333333");
        assert_eq!(editable(2000.0, "Pa s"), "2 kPa s");
        assert_eq!(editable(900.0, "kg/m³"), "900");
        for (v, unit) in [(noisy, "s"), (6.62e-6, "m/s"), (9.1e9, "Pa")] {
            let text = editable(v, unit);
            let back = crate::scene::units::parse_quantity("x", &text, unit).unwrap();
            assert!(((back - v) / v).abs() < 1e-11, "{v} → {text} → {back}");
        }
    }

    #[test]
    fn printed_values_compare_to_their_digits() {
        assert_eq!(printed_digits(3.84e-11), 3);
        assert_eq!(printed_digits(1.341e8), 4);
        assert_eq!(printed_digits(37.6), 3);
        assert_eq!(printed_digits(5.43e4), 3);
        // 1.3408e8 rounds to 1.341e8; 1.3404e8 does not.
        assert!(agrees_to_printed(1.3408e8, 1.341e8));
        assert!(!agrees_to_printed(1.3404e8, 1.341e8));
        assert!(!agrees_to_printed(37.72, 37.6));
        assert!(!agrees_to_printed(3.077e5, 5.43e4));
        assert!(!agrees_to_printed(f64::NAN, 1.0));
    }

    #[test]
    fn shortest_round_trips() {
        assert_eq!(round_sig(3.0 * 1e-4, 12), 3e-4);
        assert_eq!(round_sig(0.1 * 1e-4, 12), 1e-5);
        assert_eq!(round_sig(1.0 / 3.0, 3), 0.333);
        assert_eq!(round_sig(0.0, 3), 0.0);
        assert_eq!(shortest(2e-4), "0.0002");
        assert_eq!(shortest(1e-7), "1e-7");
        assert_eq!(shortest(6.6e-6), "6.6e-6");
        assert_eq!(shortest(1e6), "1e6");
        assert_eq!(shortest(0.0), "0");
        assert_eq!(shortest(1.0 / 3.0), "0.3333333333333333");
        for v in [1.0 / 3.0, 0.1 * 0.002, 1e-300, 123456.789] {
            assert_eq!(shortest(v).parse::<f64>().unwrap(), v);
        }
    }
}
