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
    let wrong_unit = Error::InvalidValue {
        field,
        expected: unit_expectation(unit),
    };
    let (Some(la), Some(lb)) = (normalise(suffix, &mut a), normalise(unit, &mut b)) else {
        return Err(wrong_unit);
    };
    let (given, si) = (&a[..la], &b[..lb]);
    if si.is_empty() {
        return Err(wrong_unit);
    }
    if given == si {
        return Ok(value);
    }
    // Special spellings.
    if si == b"kg/m3" && given == b"g/cm3" {
        return Ok(value * 1000.0);
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
            return Ok(if factor < 1.0 {
                value / libm::round(1.0 / factor)
            } else {
                value * factor
            });
        }
    }
    Err(wrong_unit)
}

fn unit_expectation(unit: &str) -> &'static str {
    match unit {
        "m" => "a length, e.g. 1e-6, 1 um, 2 cm",
        "m/s" => "a speed, e.g. 0.01, 1 cm/s, 5 mm/s",
        "s" => "a time, e.g. 1e-4, 0.1 ms",
        "Pa" => "a pressure, e.g. 1e10, 10 GPa",
        "Pa s" => "a viscosity, e.g. 1000, 1 kPa s",
        "J/m²" => "a surface energy, e.g. 0.1, 100 mJ/m^2",
        "kg/m³" => "a density, e.g. 900, 0.9 g/cm^3",
        "kg" => "a mass, e.g. 5.688e26",
        "K" => "a temperature, e.g. 200, 200 K",
        "" => "a plain number without unit",
        _ => "a number in SI units",
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

    fn alloc_free_message(e: &Error) -> std::string::String {
        use std::string::ToString;
        e.to_string()
    }
}
