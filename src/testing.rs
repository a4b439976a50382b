//! Test support, outside the public API: compiled into the library's unit tests
//! (`#[cfg(test)]`) and included by the integration tests (`#[path]`), one file for both.
//!
//! - [`assert_close!`]: an approximate comparison whose message prints both values, the
//!   tolerance and the actual difference;
//! - [`XorShift`]: a tiny deterministic generator, so that random inputs are the same on every
//!   run and platform (the product's own randomness, `dvf sweep`, uses `rand_pcg`);
//! - [`test`]: the test attribute, `#[wasm_bindgen_test]` under wasm and the built-in one
//!   natively, so that one `use crate::testing::test;` runs a module's tests natively, in Node
//!   and in Chromium.
#![allow(dead_code, unused_imports, unused_macros)]

#[cfg(not(target_arch = "wasm32"))]
pub use core::prelude::v1::test;
#[cfg(target_arch = "wasm32")]
pub use wasm_bindgen_test::wasm_bindgen_test as test;

/// `assert_close!(actual, expected, tol)`: `|actual − expected| ≤ tol`, NaN always fails.
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
pub(crate) use assert_close;

/// xorshift64* (Vigna); its state is the seed, any value but 0.
#[derive(Clone, Debug)]
pub struct XorShift(pub u64);

impl XorShift {
    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }

    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }

    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }

    /// Uniform in (−π, π].
    pub fn heading(&mut self) -> f64 {
        std::f64::consts::PI - 2.0 * std::f64::consts::PI * self.unit()
    }
}
