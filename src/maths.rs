//! The sines, cosines and arctangents the method takes, from the `libm` crate: a port of
//! musl's library, the one Rust's standard library itself calls in the wasm build. Every
//! build computes them with the same code, so that a run gives the same bits natively and in
//! the browser (`tests/data/reports/` against the wasm tests, and the book's figures against
//! `dvf simulate --csv`). Natively it is also faster than the platform's library (glibc's,
//! reached through a call into the shared library with its error handling): a step of the
//! crowd of 1,000 takes fewer instructions (README, Performance).
//!
//! Each is within an ulp of the exact value (musl's bound).

/// `sin x`.
#[inline]
#[must_use]
pub fn sin(x: f64) -> f64 {
    libm::sin(x)
}

/// `cos x`: the method takes it with the sine (`sin_cos`); the tests compare the two.
#[cfg(test)]
#[inline]
#[must_use]
pub fn cos(x: f64) -> f64 {
    libm::cos(x)
}

/// `(sin x, cos x)`, with one argument reduction: the very bits of `sin` and `cos` apart
/// (`sin_cos_is_sin_and_cos`). In the wasm build too, where it takes 618 bytes more than the
/// two apart and a quarter less of the step's time in the sine and cosine (README,
/// Performance).
#[inline]
#[must_use]
pub fn sin_cos(x: f64) -> (f64, f64) {
    libm::sincos(x)
}

/// The unit vector `(cos a, sin a)`: glam's `DVec2::from_angle` with this module's sine and
/// cosine.
#[inline]
#[must_use]
pub fn from_angle(a: f64) -> glam::DVec2 {
    let (s, c) = sin_cos(a);
    glam::DVec2::new(c, s)
}

/// `atan x`, in `[−π/2, π/2]`.
#[inline]
#[must_use]
pub fn atan(x: f64) -> f64 {
    libm::atan(x)
}

/// `atan2(y, x)`, the angle of `(x, y)` in `[−π, π]`.
#[inline]
#[must_use]
pub fn atan2(y: f64, x: f64) -> f64 {
    libm::atan2(y, x)
}

/// `acos x`, in `[0, π]` (NaN outside `[−1, 1]`).
#[inline]
#[must_use]
pub fn acos(x: f64) -> f64 {
    libm::acos(x)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::{test, XorShift};

    /// In every build `sin_cos` and `sin`, `cos` agree to the bit, over
    /// every range the method uses (headings, half-angles, turns) and beyond.
    #[test]
    fn sin_cos_is_sin_and_cos() {
        let mut rng = XorShift(0x9E37_79B9_7F4A_7C15);
        for _ in 0..20_000 {
            let x = rng.range(-20.0, 20.0);
            let (s, c) = sin_cos(x);
            assert_eq!(s.to_bits(), sin(x).to_bits(), "sin {x}");
            assert_eq!(c.to_bits(), cos(x).to_bits(), "cos {x}");
        }
    }

    /// Within an ulp or two of the platform's library (natively glibc, correctly rounded in
    /// practice; in wasm the same code): a wrong binding would be off by far more.
    #[test]
    fn agrees_with_the_platform_library() {
        let mut rng = XorShift(0x2545_F491_4F6C_DD1D);
        let ulps = |a: f64, b: f64| (a - b).abs() / (f64::EPSILON * b.abs().max(1e-300));
        for _ in 0..20_000 {
            let (x, y) = (rng.range(-4.0, 4.0), rng.range(-4.0, 4.0));
            assert!(ulps(sin(x), x.sin()) <= 2.0);
            assert!(ulps(cos(x), x.cos()) <= 2.0);
            assert!(ulps(atan(x), x.atan()) <= 2.0);
            assert!(ulps(atan2(y, x), y.atan2(x)) <= 2.0);
            let u = rng.range(-1.0, 1.0);
            assert!(ulps(acos(u), u.acos()) <= 2.0);
            assert_eq!(from_angle(x), glam::DVec2::new(cos(x), sin(x)));
        }
    }
}
