//! Number formatting for the explorer: short, unit-aware, never `NaN` or `inf` on screen.

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
        let d = (digits - 1 - a.log10().floor() as i32).clamp(0, 8) as usize;
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
/// `15.08 g`). Units that do not take prefixes well (`kg/m³`, `J/m²`, dimensionless) are printed
/// as plain numbers. Non-finite values become `—`.
pub fn qty(v: f64, unit: &str) -> String {
    qty_sig(v, unit, 4)
}

/// Like [`qty`] with 3 significant digits.
pub fn qty3(v: f64, unit: &str) -> String {
    qty_sig(v, unit, 3)
}

fn qty_sig(v: f64, unit: &str, digits: i32) -> String {
    if !v.is_finite() {
        return "—".into();
    }
    let (v, unit) = if unit == "kg" {
        (v * 1e3, "g")
    } else {
        (v, unit)
    };
    let prefixable = matches!(unit, "m" | "s" | "m/s" | "Pa" | "Pa s" | "g" | "J" | "N");
    if !prefixable || v == 0.0 {
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

/// `YYYYMMDD-HHMMSS` (UTC) for a time in seconds since the Unix epoch.
pub fn timestamp(unix_seconds: u64) -> String {
    let days = (unix_seconds / 86_400) as i64;
    let rem = unix_seconds % 86_400;
    // Civil-from-days (Howard Hinnant's algorithm).
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = doy - (153 * mp + 2) / 5 + 1;
    let m = if mp < 10 { mp + 3 } else { mp - 9 };
    let y = yoe + era * 400 + i64::from(m <= 2);
    format!(
        "{y:04}{m:02}{d:02}-{:02}{:02}{:02}",
        rem / 3600,
        (rem / 60) % 60,
        rem % 60
    )
}

#[cfg(test)]
mod tests {
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
    fn timestamps_are_utc_civil_dates() {
        assert_eq!(timestamp(0), "19700101-000000");
        assert_eq!(timestamp(1_700_000_000), "20231114-221320");
    }
}
