//! Selects meant to compile to no branch: `a` when `take`, else `b`.
//!
//! A plain `if take { a } else { b }` is a select to LLVM, which may still turn it into a branch.
//! Where the condition is a coin toss, as whether a neighbour in a crowd is ahead or behind, a
//! branch is mispredicted about half the time. These say so to the compiler
//! (`std::hint::select_unpredictable`). On x86-64 that is enough for an integer and for a
//! scalar whose condition is a comparison of floats; a scalar `f64` on another condition may
//! still be compiled into a branch, so `swarm::cluster` makes its condition such a comparison
//! and keeps its nearest neighbour by place, an integer.

/// `a` when `take`, else `b`, the same bits.
#[inline]
#[must_use]
pub(crate) fn pick(take: bool, a: f64, b: f64) -> f64 {
    std::hint::select_unpredictable(take, a, b)
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
    }
}
