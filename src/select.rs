//! Selects that compile to no branch: `a` when `take`, else `b`, by masking their bits.
//!
//! A plain `if take { a } else { b }` is a select to LLVM, which may still turn it into a branch
//! (it did for several selects on one condition in `swarm::cluster`, and for one on an index test
//! in the simulation's sensing loop). Where the condition is a coin toss, as whether a neighbour
//! in a crowd is ahead or behind, a branch is mispredicted about half the time. The standard
//! library's `std::hint::select_unpredictable` says the same, but only from Rust 1.88, above the
//! crate's minimum supported version.

use glam::DVec2;

/// `a` when `take`, else `b`, the same bits, without a branch.
#[inline]
#[must_use]
pub(crate) fn pick(take: bool, a: f64, b: f64) -> f64 {
    let mask = u64::from(take).wrapping_neg();
    f64::from_bits((a.to_bits() & mask) | (b.to_bits() & !mask))
}

/// [`pick`] for both components of a vector.
#[inline]
#[must_use]
pub(crate) fn pick2(take: bool, a: DVec2, b: DVec2) -> DVec2 {
    DVec2::new(pick(take, a.x, b.x), pick(take, a.y, b.y))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::test;

    /// Either side, bit for bit: signed zeros, infinities and a NaN's payload included.
    #[test]
    fn pick_is_the_select_bit_for_bit() {
        let values = [
            0.0,
            -0.0,
            1.5,
            -2.25e-300,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
        ];
        let nan = f64::from_bits(0x7ff8_0000_dead_beef);
        for &a in values.iter().chain([nan].iter()) {
            for &b in &values {
                assert_eq!(pick(true, a, b).to_bits(), a.to_bits());
                assert_eq!(pick(false, a, b).to_bits(), b.to_bits());
            }
        }
        let (a, b) = (DVec2::new(1.0, -0.0), DVec2::new(f64::NAN, 3.0));
        assert_eq!(
            pick2(true, a, b).to_array().map(f64::to_bits),
            a.to_array().map(f64::to_bits)
        );
        assert_eq!(
            pick2(false, a, b).to_array().map(f64::to_bits),
            b.to_array().map(f64::to_bits)
        );
    }
}
