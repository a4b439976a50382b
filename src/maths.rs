//! The sines, cosines and arctangents the method takes. Most come from the `libm` crate: a
//! port of musl's library, the one Rust's standard library itself calls in the wasm build.
//! Every build computes them with the same code, so that a run gives the same bits natively
//! and in the browser (`tests/data/reports/` against the wasm tests, and the book's figures
//! against `dvf simulate --csv`). Natively it is inlined where the platform's library
//! (glibc's) is a call into the shared library with its error handling. Each is within an
//! ulp of the exact value (musl's bound).
//!
//! Two that a step takes for many robots are written here on musl's polynomials, without a
//! branch: the angle of the field a robot circling a virtual obstacle turns to ([`atan2`]),
//! and the raised cosine of the transition function ([`raised_cosine`]). musl's choose an
//! argument reduction by branches on the argument's range, which a crowd's robots take at
//! random; these choose it by selects and take at most one division. Within 2 ulps of the
//! exact value (`agrees_with_the_platform_library`, `raised_cosine_is_the_raised_cosine`).
//! The arctangent sums musl's polynomial by Estrin's scheme rather than Horner's (the same
//! coefficients, fewer operations in a row, as accurate): a circling robot's command waits on
//! it.

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
/// (`sin_cos_is_sin_and_cos`), in every build.
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

/// musl's polynomial for `atan z` on `|z| ≤ 7/16` (`atan z = z − z·(s₁ + s₂)`).
const AT: [f64; 11] = [
    0.333_333_333_333_329_3,
    -0.199_999_999_998_764_83,
    0.142_857_142_725_034_66,
    -0.111_111_104_054_623_56,
    0.090_908_871_334_365_07,
    -0.076_918_762_050_448_3,
    0.066_610_731_373_875_31,
    -0.058_335_701_337_905_735,
    0.049_768_779_946_159_324,
    -0.036_531_572_744_216_916,
    0.016_285_820_115_365_782,
];

/// `π/4` and `π/2`, each as the nearest double and the rest (musl's `atanhi`, `atanlo`).
const QUARTER_PI: (f64, f64) = (std::f64::consts::FRAC_PI_4, 3.061_616_997_868_383e-17);
const HALF_PI: (f64, f64) = (std::f64::consts::FRAC_PI_2, 6.123_233_995_736_766e-17);

/// `tan(π/8) = √2 − 1` and `tan(3π/8) = √2 + 1`: past the first, an angle is nearer `π/4`
/// than 0; past the second, nearer `π/2` than `π/4`.
const TAN_PI_8: f64 = 0.414_213_562_373_095_03;
const TAN_3PI_8: f64 = 2.414_213_562_373_095;

/// `atan2(a, b)` for `a, b ≥ 0`, an angle in `[0, π/2]`; 0 for `a = b = 0`. Taken from the
/// nearest of 0, `π/4` and `π/2`, by the tangent of what is left: `a/b`, `(a − b)/(a + b)` or
/// `−b/a`, at most `tan(π/8)` in magnitude, where musl's polynomial holds. One division,
/// its operands chosen by two comparisons. Finite arguments, or one of them infinite.
///
/// Not always without a branch: inlined into the controller, the choice may be compiled into
/// branches (selects of the values, and of their bits, alike), which the angle's octant can
/// mispredict in a jam. The choice stays in registers rather than indexing small arrays, which
/// would put the reduction through memory in the angle's chain.
#[inline]
#[must_use]
fn first_quadrant(a: f64, b: f64) -> f64 {
    let past_eighth = a > b * TAN_PI_8;
    let past_three_eighths = a > b * TAN_3PI_8;
    let pick = |near_half: f64, near_quarter: f64, near_zero: f64| {
        if past_three_eighths {
            near_half
        } else if past_eighth {
            near_quarter
        } else {
            near_zero
        }
    };
    let num = pick(-b, a - b, a);
    let den = pick(a, a + b, b);
    let z = num / den;
    let z = if den == 0.0 { 0.0 } else { z };
    let w = z * z;
    let w2 = w * w;
    // musl's two polynomials in `w² = z⁴` by Estrin's scheme, pairs of terms joined by the
    // powers `w⁴` and `w⁸`, rather than Horner's: six operations in a row after `w²` instead
    // of eleven. A circling robot's command waits on this angle (its turn rate, then the chord
    // the barrier clamps its speed along), and in a jam nearly every robot circles. musl's
    // coefficients summed in another order than musl's: within 2 ulps of the platform's
    // library, as `atan2_is_the_angle` checks.
    let w4 = w2 * w2;
    let w8 = w4 * w4;
    let s1 = w * ((AT[0] + w2 * AT[2]) + w4 * (AT[4] + w2 * AT[6]) + w8 * (AT[8] + w2 * AT[10]));
    let s2 = w2 * ((AT[1] + w2 * AT[3]) + w4 * (AT[5] + w2 * AT[7]) + w8 * AT[9]);
    let (hi, lo) = (
        pick(HALF_PI.0, QUARTER_PI.0, 0.0),
        pick(HALF_PI.1, QUARTER_PI.1, 0.0),
    );
    hi - ((z * (s1 + s2) - lo) - z)
}

/// `atan2(y, x)`, the angle of `(x, y)` in `[−π, π]`, with the signs of zeros as IEEE 754
/// gives them ([`first_quadrant`] folded into the quadrant of `(x, y)`). Finite arguments,
/// or one of them infinite.
#[inline]
#[must_use]
pub fn atan2(y: f64, x: f64) -> f64 {
    let a = first_quadrant(y.abs(), x.abs());
    let a = if x.is_sign_negative() {
        (HALF_PI.0 - a) + HALF_PI.0 + 2.0 * HALF_PI.1
    } else {
        a
    };
    a.copysign(y)
}

/// musl's polynomial for `sin x` on `|x| ≤ π/4` (`__sin`'s `S1` … `S6`).
const S: [f64; 6] = [
    -0.166_666_666_666_666_32,
    0.008_333_333_333_322_49,
    -0.000_198_412_698_298_579_5,
    2.755_731_370_707_006_8e-06,
    -2.505_076_025_340_686_3e-08,
    1.589_690_995_211_55e-10,
];

/// The raised cosine `(1 − cos πu)/2` of `u ∈ [0, 1]`: 0 at 0, 1 at 1, with a zero slope at
/// both ends. Taken as `sin²(πu/2)` up to `u = ½` and `1 − sin²(π(1 − u)/2)` above, the sine
/// of at most `π/4` from musl's polynomial without a reduction, the half chosen by a select.
/// Outside `[0, 1]` it is not the raised cosine.
#[inline]
#[must_use]
pub fn raised_cosine(u: f64) -> f64 {
    let upper = u > 0.5;
    let x = if upper { 1.0 - u } else { u } * std::f64::consts::FRAC_PI_2;
    let z = x * x;
    let w = z * z;
    let r = S[1] + z * (S[2] + z * S[3]) + z * w * (S[4] + z * S[5]);
    let sin = x + z * x * (S[0] + z * r);
    let s = sin * sin;
    if upper {
        1.0 - s
    } else {
        s
    }
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

    /// How many ulps of `b` lie between `a` and `b` (relative, for `b` down to 1e-300).
    fn ulps(a: f64, b: f64) -> f64 {
        (a - b).abs() / (f64::EPSILON * b.abs().max(1e-300))
    }

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

    /// [`atan2`] within 2 ulps of the platform's library (glibc's, correctly rounded in
    /// practice) over angles of every direction and pairs of every ratio of magnitudes from
    /// 1e-12 to 1e12, and exactly its value on the axes, the diagonals' signs and zeros of
    /// either sign.
    #[test]
    fn atan2_is_the_angle() {
        let mut rng = XorShift(0x1F2E_3D4C_5B6A_7988);
        for k in 0..200_000 {
            let (y, x) = (rng.range(-1.0, 1.0), rng.range(-1.0, 1.0));
            let x = if k % 2 == 0 {
                x
            } else {
                x * 10f64.powf(rng.range(-12.0, 12.0))
            };
            assert!(ulps(atan2(y, x), y.atan2(x)) <= 2.0, "atan2({y}, {x})");
        }
        for (y, x) in [
            (0.0, 0.0),
            (-0.0, 0.0),
            (0.0, -0.0),
            (-0.0, -0.0),
            (1.0, 0.0),
            (-1.0, 0.0),
            (0.0, -1.0),
            (-0.0, -1.0),
            (0.0, 3.0),
            (2.0, 2.0),
            (-2.0, -2.0),
            (1.0, f64::INFINITY),
            (f64::INFINITY, -1.0),
            (1e-300, 1e300),
            (1e300, 1e-300),
        ] {
            let (got, want) = (atan2(y, x), y.atan2(x));
            assert!(
                got == want || ulps(got, want) <= 1.0,
                "atan2({y}, {x}) = {got}, not {want}"
            );
            assert_eq!(
                got.is_sign_negative(),
                want.is_sign_negative(),
                "atan2({y}, {x})"
            );
        }
    }

    /// [`raised_cosine`] within 4 ulps of `sin²(πu/2)` taken with the platform's sine,
    /// relatively below `u = ½` and of 1 above (where `1 − s` rounds to ulps of 1): 2 ulps of
    /// its own (the product `πu/2`, the polynomial, the square), and up to 1.5 of the
    /// reference's (the sine's rounding, doubled by the square, and the square's). 0 and 1
    /// exactly at the ends, and non-decreasing across `u = ½`.
    #[test]
    fn raised_cosine_is_the_raised_cosine() {
        use std::f64::consts::FRAC_PI_2;
        let mut rng = XorShift(0x6A09_E667_F3BC_C908);
        for k in 0..200_000 {
            let u = if k % 4 == 0 {
                0.5 + rng.range(-1e-6, 1e-6)
            } else {
                rng.unit()
            };
            let exact = (FRAC_PI_2 * u).sin().powi(2);
            let scale = if u > 0.5 { 1.0 } else { exact.max(1e-300) };
            let err = (raised_cosine(u) - exact).abs() / (f64::EPSILON * scale);
            assert!(err <= 4.0, "u = {u}: {} against {exact}", raised_cosine(u));
        }
        assert_eq!(raised_cosine(0.0), 0.0);
        assert_eq!(raised_cosine(1.0), 1.0);
        let mut u = 0.5 - 1e-12;
        let mut prev = raised_cosine(u);
        while u < 0.5 + 1e-12 {
            u = u.next_up();
            let s = raised_cosine(u);
            assert!(s >= prev, "{u}: {s} after {prev}");
            prev = s;
        }
    }

    /// Within an ulp or two of the platform's library (natively glibc, correctly rounded in
    /// practice; in wasm the same code): a wrong binding would be off by far more.
    #[test]
    fn agrees_with_the_platform_library() {
        let mut rng = XorShift(0x2545_F491_4F6C_DD1D);
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
