//! Four f64 lanes and the few operations the Taylor engine's series need, written once for any
//! processor (arrays, what the browser runs) and once for AVX's registers (intrinsics).
//!
//! Every operation rounds each lane as one f64 operation does (no fused multiply-add, no
//! reordering), so the two give the same bits: the engine is written once over [`Lanes`] and
//! compiled for each. Written out rather than left to the compiler's vectorizer, which paired
//! the same arithmetic differently from one change of the code to the next.

#[cfg(target_arch = "x86_64")]
use std::arch::x86_64::*;

/// Four f64 in a row, as the engine's rows hold them.
pub type Quad = [f64; 4];

/// Four f64 lanes: a register where the processor has one, an array where it has not.
pub trait Lanes {
    type Four: Copy;

    /// Returns `x` in every lane.
    fn splat(x: f64) -> Self::Four;

    /// Returns the four values of `quad`.
    fn load(quad: &Quad) -> Self::Four;

    /// Returns the lanes as an array.
    fn store(lanes: Self::Four) -> Quad;

    /// Returns the first lane.
    fn first(lanes: Self::Four) -> f64;

    /// Returns a + b, lane by lane.
    fn add(a: Self::Four, b: Self::Four) -> Self::Four;

    /// Returns a·b, lane by lane.
    fn mul(a: Self::Four, b: Self::Four) -> Self::Four;

    /// Returns [a1, a0, a3, a2]: each pair swapped.
    fn swap_pairs(a: Self::Four) -> Self::Four;

    /// Returns [a2, a3, a0, a1]: the halves swapped.
    fn swap_halves(a: Self::Four) -> Self::Four;

    /// Returns [a0, a1, a0, a1]: the low half in both.
    fn low_half_twice(a: Self::Four) -> Self::Four;
}

/// Arrays: compiled for any processor, one lane at a time where it has no vectors.
pub struct Portable;

impl Lanes for Portable {
    type Four = Quad;

    #[inline(always)]
    fn splat(x: f64) -> Quad {
        [x; 4]
    }

    #[inline(always)]
    fn load(quad: &Quad) -> Quad {
        *quad
    }

    #[inline(always)]
    fn store(lanes: Quad) -> Quad {
        lanes
    }

    #[inline(always)]
    fn first(lanes: Quad) -> f64 {
        lanes[0]
    }

    #[inline(always)]
    fn add(a: Quad, b: Quad) -> Quad {
        std::array::from_fn(|i| a[i] + b[i])
    }

    #[inline(always)]
    fn mul(a: Quad, b: Quad) -> Quad {
        std::array::from_fn(|i| a[i] * b[i])
    }

    #[inline(always)]
    fn swap_pairs([a0, a1, a2, a3]: Quad) -> Quad {
        [a1, a0, a3, a2]
    }

    #[inline(always)]
    fn swap_halves([a0, a1, a2, a3]: Quad) -> Quad {
        [a2, a3, a0, a1]
    }

    #[inline(always)]
    fn low_half_twice([a0, a1, ..]: Quad) -> Quad {
        [a0, a1, a0, a1]
    }
}

/// AVX's four-lane registers.
///
/// Only code compiled for AVX, on a processor that has it, may use these (the engine's
/// `integrate_on_avx`): each operation is one AVX instruction.
#[cfg(target_arch = "x86_64")]
pub struct Avx;

// SAFETY (every function here): AVX is present, which is the condition of using `Avx`
// at all; the loads and stores read and write whole `Quad`s.
#[cfg(target_arch = "x86_64")]
impl Lanes for Avx {
    type Four = __m256d;

    #[inline(always)]
    fn splat(x: f64) -> __m256d {
        unsafe { _mm256_set1_pd(x) }
    }

    #[inline(always)]
    fn load(quad: &Quad) -> __m256d {
        unsafe { _mm256_loadu_pd(quad.as_ptr()) }
    }

    #[inline(always)]
    fn store(lanes: __m256d) -> Quad {
        let mut quad = [0.0; 4];
        unsafe { _mm256_storeu_pd(quad.as_mut_ptr(), lanes) };
        quad
    }

    #[inline(always)]
    fn first(lanes: __m256d) -> f64 {
        unsafe { _mm256_cvtsd_f64(lanes) }
    }

    #[inline(always)]
    fn add(a: __m256d, b: __m256d) -> __m256d {
        unsafe { _mm256_add_pd(a, b) }
    }

    #[inline(always)]
    fn mul(a: __m256d, b: __m256d) -> __m256d {
        unsafe { _mm256_mul_pd(a, b) }
    }

    #[inline(always)]
    fn swap_pairs(a: __m256d) -> __m256d {
        unsafe { _mm256_permute_pd::<0b0101>(a) }
    }

    #[inline(always)]
    fn swap_halves(a: __m256d) -> __m256d {
        unsafe { _mm256_permute2f128_pd::<0x01>(a, a) }
    }

    #[inline(always)]
    fn low_half_twice(a: __m256d) -> __m256d {
        unsafe { _mm256_permute2f128_pd::<0x00>(a, a) }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    // AVX's lanes do what the arrays do, bit for bit, on every operation.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn the_registers_do_what_the_arrays_do() {
        if !std::is_x86_feature_detected!("avx") {
            return;
        }
        let a: Quad = [1.5, -0.1, 3e-300, f64::MAX];
        let b: Quad = [0.3, 7.0, 1e-20, 2.0];
        let same = |x: Quad, y: Quad| x.map(f64::to_bits) == y.map(f64::to_bits);
        let (va, vb) = (Avx::load(&a), Avx::load(&b));
        assert!(same(Avx::store(Avx::add(va, vb)), Portable::add(a, b)));
        assert!(same(Avx::store(Avx::mul(va, vb)), Portable::mul(a, b)));
        assert!(same(
            Avx::store(Avx::swap_pairs(va)),
            Portable::swap_pairs(a)
        ));
        assert!(same(
            Avx::store(Avx::swap_halves(va)),
            Portable::swap_halves(a)
        ));
        assert!(same(
            Avx::store(Avx::low_half_twice(va)),
            Portable::low_half_twice(a)
        ));
        assert!(same(Avx::store(Avx::splat(0.7)), Portable::splat(0.7)));
        assert_eq!(Avx::first(va).to_bits(), Portable::first(a).to_bits());
        assert_eq!(Portable::swap_pairs(a), [-0.1, 1.5, f64::MAX, 3e-300]);
        assert_eq!(Portable::swap_halves(a), [3e-300, f64::MAX, 1.5, -0.1]);
    }
}
