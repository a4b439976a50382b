//! Approximate comparison for tests: the failure message prints both values, the tolerance
//! and the actual difference.

/// `assert_close!(actual, expected, tol)`: `|actual − expected| ≤ tol`, NaN always fails.
#[macro_export]
#[doc(hidden)]
macro_rules! assert_close {
    ($a:expr, $b:expr, $tol:expr $(,)?) => {{
        let (a, b, tol): (f64, f64, f64) = ($a, $b, $tol);
        let diff = (a - b).abs();
        assert!(
            diff <= tol,
            "assert_close!({}, {}): {} vs {}, difference {:e} exceeds tolerance {:e}",
            stringify!($a),
            stringify!($b),
            a,
            b,
            diff,
            tol
        );
    }};
}

#[doc(hidden)]
pub use assert_close;
