//! Elementary functions, always from `libm` — also with `std`. The platform's maths library differs
//! between targets in the last bit (glibc natively, a musl port on wasm32), and the terminal, the
//! command line and the web page must give bit-identical numbers for the same scene (issue 11), so
//! every target evaluates the same code.

macro_rules! unary {
    ($name:ident, $libm:ident) => {
        #[inline]
        pub(crate) fn $name(x: f64) -> f64 {
            libm::$libm(x)
        }
    };
}

unary!(sqrt, sqrt);
unary!(ln, log);
unary!(log10, log10);
unary!(exp, exp);
unary!(cbrt, cbrt);
unary!(atan, atan);

#[inline]
pub(crate) fn powf(x: f64, y: f64) -> f64 {
    libm::pow(x, y)
}

#[inline]
pub(crate) fn atan2(y: f64, x: f64) -> f64 {
    libm::atan2(y, x)
}

/// A Chebyshev series `Σ c_k T_k(t)` at `t ∈ [-1, 1]` by Clenshaw's recurrence (the master tables'
/// and brilliantov2007's tables' sum); `c` must not be empty.
#[inline]
pub(crate) fn clenshaw(c: &[f64], t: f64) -> f64 {
    let (mut b1, mut b2) = (0.0, 0.0);
    let t2 = 2.0 * t;
    for &ck in c[1..].iter().rev() {
        let b0 = ck + t2 * b1 - b2;
        b2 = b1;
        b1 = b0;
    }
    c[0] + t * b1 - b2
}
