//! Speed grids: evenly spaced in log10 (decades exact) or linearly.

/// The double nearest to `10^k`: exact products for |k| ≤ 22 (every power of ten up to 1e22 is a
/// double, and one correctly rounded division gives the nearest double to 10^-k), `pow` beyond.
pub fn exact_decade(k: i32) -> f64 {
    if k.unsigned_abs() <= 22 {
        let mut p = 1.0;
        for _ in 0..k.unsigned_abs() {
            p *= 10.0;
        }
        if k < 0 { 1.0 / p } else { p }
    } else {
        libm::pow(10.0, k as f64)
    }
}

/// Fills `out` with speeds spaced evenly in log10 from `from` to `to`, both ends kept exactly.
/// The exponents are interpolated from the ends' decimal exponents; a point whose exponent is a
/// whole number k is [`exact_decade`]`(k)`, so decades print as `1e-5`, never
/// `9.999999999999999e-6`. Every surface (the explorer, `rime curve`, the figures) spaces speeds
/// with this one function, so the same range gives bit-identical speeds everywhere.
pub fn log_space(from: f64, to: f64, out: &mut [f64]) {
    let n = out.len();
    if n == 0 {
        return;
    }
    if n == 1 {
        out[0] = from;
        return;
    }
    let (a, b) = (libm::log10(from), libm::log10(to));
    let m = (n - 1) as f64;
    for (i, g) in out.iter_mut().enumerate() {
        let i = i as f64;
        let e = (a * (m - i) + b * i) / m;
        let k = libm::round(e);
        *g = if libm::fabs(e - k) < 1e-12 && libm::fabs(k) < 400.0 {
            exact_decade(k as i32)
        } else {
            libm::pow(10.0, e)
        };
    }
    out[0] = from;
    out[n - 1] = to;
}

/// Fills `out` with speeds spaced evenly from 0 to `max` inclusive, both ends exact.
pub fn linear_space(max: f64, out: &mut [f64]) {
    let n = out.len();
    for (i, g) in out.iter_mut().enumerate() {
        *g = if n == 1 {
            max
        } else {
            max * i as f64 / (n - 1) as f64
        };
    }
    // The last speed is `max` itself (max·(n−1)/(n−1) can miss it by an ulp), so the printed grid
    // names its range exactly.
    if let Some(last) = out.last_mut() {
        *last = max;
    }
}
