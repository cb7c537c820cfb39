//! Elementary functions: the platform's (via `std`) when available, `libm` otherwise.

macro_rules! unary {
    ($name:ident, $std:ident, $libm:ident) => {
        #[inline]
        pub(crate) fn $name(x: f64) -> f64 {
            #[cfg(feature = "std")]
            {
                x.$std()
            }
            #[cfg(not(feature = "std"))]
            {
                libm::$libm(x)
            }
        }
    };
}

unary!(sqrt, sqrt, sqrt);
unary!(ln, ln, log);
unary!(log10, log10, log10);
unary!(exp, exp, exp);
unary!(cbrt, cbrt, cbrt);
unary!(atan, atan, atan);

#[inline]
pub(crate) fn powf(x: f64, y: f64) -> f64 {
    #[cfg(feature = "std")]
    {
        x.powf(y)
    }
    #[cfg(not(feature = "std"))]
    {
        libm::pow(x, y)
    }
}

#[inline]
pub(crate) fn atan2(y: f64, x: f64) -> f64 {
    #[cfg(feature = "std")]
    {
        y.atan2(x)
    }
    #[cfg(not(feature = "std"))]
    {
        libm::atan2(y, x)
    }
}
