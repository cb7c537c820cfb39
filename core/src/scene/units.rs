//! Parsing typed values with units, e.g. `1 µm`, `2000 Pa s`, `0.1 J/m^2`, `3 cm/s`.

use crate::error::{Error, Result};

/// SI prefixes accepted in front of a unit.
const PREFIXES: [(&str, f64); 10] = [
    ("p", 1e-12),
    ("n", 1e-9),
    ("u", 1e-6),
    ("µ", 1e-6),
    ("μ", 1e-6),
    ("m", 1e-3),
    ("c", 1e-2),
    ("k", 1e3),
    ("M", 1e6),
    ("G", 1e9),
];

/// Normalises spelling variants of a unit: `·`/`*`/spaces between factors, `^2`/`2`/`²`, `^3`/`³`.
fn normalise(unit: &str, out: &mut [u8; 32]) -> Option<usize> {
    let mut len = 0;
    let mut push = |b: &[u8], len: &mut usize| -> Option<()> {
        for &c in b {
            *out.get_mut(*len)? = c;
            *len += 1;
        }
        Some(())
    };
    let mut chars = unit.trim().chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            ' ' | '·' | '*' | '⋅' => {
                if chars.peek().is_some_and(|n| *n != ' ') && len > 0 {
                    push(b" ", &mut len)?;
                }
            }
            '^' => {}
            '²' => push(b"2", &mut len)?,
            '³' => push(b"3", &mut len)?,
            'μ' | 'µ' => push(b"u", &mut len)?,
            c if c.is_ascii() => push(&[c as u8], &mut len)?,
            _ => return None,
        }
    }
    Some(len)
}

/// What a number too small for a double reads as (issue 37: `1e-400` became 0 and was refused
/// as "speed 0").
pub const UNDERFLOW: &str =
    "a number a double can hold: it underflows to 0 (the smallest is about 4.9e-324)";

/// Whether the decimal text `number` names a nonzero value that parsed to `value` = 0: a mantissa
/// with a nonzero digit whose exponent is below a double's range.
pub fn underflows(number: &str, value: f64) -> bool {
    let mantissa = number.split(['e', 'E']).next().unwrap_or(number);
    value == 0.0 && mantissa.chars().any(|c| matches!(c, '1'..='9'))
}

/// Parses `text` as a number with an optional unit compatible with `unit` (the SI unit of the
/// field, as written in [`crate::scene::params::PARAMETERS`]); returns the value in that SI unit.
/// A nonzero number below a double's range is refused ([`UNDERFLOW`]), not read as 0.
pub fn parse_quantity(field: &'static str, text: &str, unit: &str) -> Result<f64> {
    let text = text.trim();
    let split = text
        .char_indices()
        .find(|&(i, c)| {
            !(c.is_ascii_digit()
                || c == '.'
                || c == '+'
                || c == '-'
                || ((c == 'e' || c == 'E')
                    && text[i + 1..]
                        .chars()
                        .next()
                        .is_some_and(|n| n.is_ascii_digit() || n == '-' || n == '+')))
        })
        .map(|(i, _)| i)
        .unwrap_or(text.len());
    let (number, suffix) = text.split_at(split);
    let value: f64 = number.trim().parse().map_err(|_| Error::InvalidValue {
        field,
        expected: "a number, optionally followed by a unit",
    })?;
    if !value.is_finite() {
        return Err(Error::OutOfRange {
            field,
            value,
            expected: "must be finite",
        });
    }
    if underflows(number, value) {
        return Err(Error::InvalidValue {
            field,
            expected: UNDERFLOW,
        });
    }
    let suffix = suffix.trim();
    if suffix.is_empty() {
        return Ok(value);
    }
    let mut a = [0u8; 32];
    let mut b = [0u8; 32];
    let (Some(la), Some(lb)) = (normalise(suffix, &mut a), normalise(unit, &mut b)) else {
        return Err(Error::InvalidValue {
            field,
            expected: unit_expectation(unit, None),
        });
    };
    let (given, si) = (&a[..la], &b[..lb]);
    match scaled(value, given, si) {
        Some(v) => Ok(v),
        // A unit of another kind is named (issue 37 E1: `2 um` for a time read only "expected a
        // time", as `5 parsecs` did).
        None => Err(Error::InvalidValue {
            field,
            expected: unit_expectation(unit, kind_of(given)),
        }),
    }
}

/// `value` in the normalised unit `given` expressed in the normalised SI unit `si`, when `given`
/// is `si` with an SI prefix (or a special spelling); `None` when it is another unit.
fn scaled(value: f64, given: &[u8], si: &[u8]) -> Option<f64> {
    if si.is_empty() {
        return None;
    }
    if given == si {
        return Some(value);
    }
    // Special spellings.
    if si == b"kg/m3" && given == b"g/cm3" {
        return Some(value * 1000.0);
    }
    for (prefix, factor) in PREFIXES {
        let p = if prefix == "µ" || prefix == "μ" {
            "u"
        } else {
            prefix
        };
        // Prefix on the unit's first symbol (e.g. "um" for "m", "kPa s" for "Pa s"), or on a leading
        // "kg" replaced by "g" (e.g. "g/m3" for "kg/m3").
        if given.len() == p.len() + si.len()
            && given.starts_with(p.as_bytes())
            && &given[p.len()..] == si
        {
            // Divide by the exact power of ten for sub-unit prefixes: 100 µs is then the double
            // nearest 1e-4, as typed (100 × 1e-6 is 9.999999999999999e-5).
            return Some(if factor < 1.0 {
                value / libm::round(1.0 / factor)
            } else {
                value * factor
            });
        }
    }
    None
}

/// What the fields' units measure, for naming a unit typed into a field of another kind.
const KINDS: [(&str, Kind); 9] = [
    ("m", Kind::Length),
    ("m/s", Kind::Speed),
    ("s", Kind::Time),
    ("Pa", Kind::Pressure),
    ("Pa s", Kind::Viscosity),
    ("J/m²", Kind::SurfaceEnergy),
    ("kg/m³", Kind::Density),
    ("kg", Kind::Mass),
    ("K", Kind::Temperature),
];

/// The kind of quantity a typed unit measures.
#[derive(Clone, Copy)]
enum Kind {
    Length,
    Speed,
    Time,
    Pressure,
    Viscosity,
    SurfaceEnergy,
    Density,
    Mass,
    Temperature,
}

/// The kind of the normalised unit `given` (`um` → a length), if it is one of the fields' units.
fn kind_of(given: &[u8]) -> Option<Kind> {
    KINDS.iter().find_map(|(unit, kind)| {
        let mut b = [0u8; 32];
        let n = normalise(unit, &mut b)?;
        scaled(1.0, given, &b[..n]).map(|_| *kind)
    })
}

/// What a field of SI unit `unit` expects, and what was typed when it was a unit of another kind
/// ("a time, not a length, e.g. …": the kinds before the examples, which a narrow status line
/// may cut): static text (the core has no allocator), every pair spelled out by `concat!`.
fn unit_expectation(unit: &str, got: Option<Kind>) -> &'static str {
    macro_rules! got {
        ($noun:literal, $examples:literal) => {
            match got {
                Some(Kind::Length) => concat!($noun, ", not a length", $examples),
                Some(Kind::Speed) => concat!($noun, ", not a speed", $examples),
                Some(Kind::Time) => concat!($noun, ", not a time", $examples),
                Some(Kind::Pressure) => concat!($noun, ", not a pressure", $examples),
                Some(Kind::Viscosity) => concat!($noun, ", not a viscosity", $examples),
                Some(Kind::SurfaceEnergy) => concat!($noun, ", not a surface energy", $examples),
                Some(Kind::Density) => concat!($noun, ", not a density", $examples),
                Some(Kind::Mass) => concat!($noun, ", not a mass", $examples),
                Some(Kind::Temperature) => concat!($noun, ", not a temperature", $examples),
                None => concat!($noun, $examples),
            }
        };
    }
    match unit {
        "m" => got!("a length", ", e.g. 1e-6, 1 um, 2 cm"),
        "m/s" => got!("a speed", ", e.g. 0.01, 1 cm/s, 5 mm/s"),
        "s" => got!("a time", ", e.g. 1e-4, 0.1 ms"),
        "Pa" => got!("a pressure", ", e.g. 1e10, 10 GPa"),
        "Pa s" => got!("a viscosity", ", e.g. 1000, 1 kPa s"),
        "J/m²" => got!("a surface energy", ", e.g. 0.1, 100 mJ/m^2"),
        "kg/m³" => got!("a density", ", e.g. 900, 0.9 g/cm^3"),
        "kg" => got!("a mass", ", e.g. 5.688e26"),
        "K" => got!("a temperature", ", e.g. 200, 200 K"),
        "" => got!("a plain number without unit", ""),
        _ => got!("a number in SI units", ""),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn units_scale_by_their_prefix() {
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-15 * b.abs();
        assert!(close(parse_quantity("x", "1 um", "m").unwrap(), 1e-6));
        assert!(close(parse_quantity("x", "1µm", "m").unwrap(), 1e-6));
        assert!(close(parse_quantity("x", "2 cm", "m").unwrap(), 0.02));
        assert!(close(parse_quantity("x", "1e-6", "m").unwrap(), 1e-6));
        assert!(close(parse_quantity("x", "3 cm/s", "m/s").unwrap(), 0.03));
        assert!(close(
            parse_quantity("x", "1 kPa s", "Pa s").unwrap(),
            1000.0
        ));
        assert!(close(
            parse_quantity("x", "1 kPa·s", "Pa s").unwrap(),
            1000.0
        ));
        assert!(close(parse_quantity("x", "10 GPa", "Pa").unwrap(), 1e10));
        assert!(close(
            parse_quantity("x", "100 mJ/m^2", "J/m²").unwrap(),
            0.1
        ));
        assert!(close(
            parse_quantity("x", "0.9 g/cm³", "kg/m³").unwrap(),
            900.0
        ));
        assert!(close(parse_quantity("x", "-2.5e-3", "").unwrap(), -2.5e-3));
    }

    #[test]
    fn sub_unit_prefixes_give_the_double_nearest_the_typed_value_issue_22() {
        // The decimal value typed, correctly rounded once: 100 µs is 1e-4, not 100 × 1e-6.
        for (text, unit, want) in [
            ("100 us", "s", 1e-4),
            ("3 cm/s", "m/s", 0.03),
            ("300 um", "m", 3e-4),
            ("7 nm", "m", 7e-9),
            ("30 mm/s", "m/s", 0.03),
            ("1 um", "m", 1e-6),
        ] {
            assert_eq!(parse_quantity("x", text, unit).unwrap(), want, "{text}");
        }
    }

    #[test]
    fn wrong_units_and_garbage_name_the_field() {
        for (text, unit) in [
            ("1 Pa", "m"),
            ("1 m", ""),
            ("abc", "m"),
            ("1 um/s", "m"),
            ("", "m"),
        ] {
            let e = parse_quantity("layer.thickness", text, unit).unwrap_err();
            let msg = alloc_free_message(&e);
            assert!(msg.contains("layer.thickness"), "{text}: {msg}");
        }
    }

    /// Issue 37 (review E1): a unit of another kind is named (`2 um` where a time is expected
    /// read "expected a time", as `5 parsecs` did); a unit of no known kind is not.
    #[test]
    fn issue_37_a_unit_of_another_kind_is_named() {
        for (text, unit, got) in [
            ("2 um", "s", "a length"),
            ("2um", "s", "a length"),
            ("3 ms", "m", "a time"),
            ("1 cm/s", "m", "a speed"),
            ("10 GPa", "Pa s", "a pressure"),
            ("1 kPa s", "Pa", "a viscosity"),
            ("0.9 g/cm^3", "kg", "a density"),
            ("5 kg", "kg/m³", "a mass"),
            ("200 K", "s", "a temperature"),
            ("100 mJ/m²", "m", "a surface energy"),
            ("1 m", "", "a length"),
        ] {
            let e = parse_quantity("bulk.damping.time", text, unit).unwrap_err();
            let msg = alloc_free_message(&e);
            let (want, not) = msg
                .strip_prefix("bulk.damping.time: expected ")
                .and_then(|m| m.split_once(", not "))
                .unwrap_or_else(|| panic!("{text}: {msg}"));
            assert!(!want.is_empty() && want != got, "{text}: {msg}");
            assert!(not.starts_with(got), "{text}: {msg}");
        }
        for text in ["5 parsecs", "2 furlongs/s"] {
            let msg =
                alloc_free_message(&parse_quantity("bulk.damping.time", text, "s").unwrap_err());
            assert_eq!(
                msg, "bulk.damping.time: expected a time, e.g. 1e-4, 0.1 ms",
                "{text}"
            );
        }
    }

    fn alloc_free_message(e: &Error) -> std::string::String {
        use std::string::ToString;
        e.to_string()
    }
}
