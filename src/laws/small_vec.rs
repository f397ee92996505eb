//! The few fixed-size vector operations the laws need on `[f64; N]`, N = NFDIR ∈ {1, 2}.
//! With N = 1 the compiler folds them to scalar code, which is the "2-D runs scalar code"
//! promise of the contract without a second implementation.

/// Euclidean norm; for N = 1 exactly `|v₁|`. Correct over the whole f64 range: when `v·v`
/// overflows, underflows or is subnormal, the norm is taken of `v` scaled by its largest entry
/// (as `hypot` does), so entries near f64::MAX or among the subnormals keep their length.
#[inline(always)]
#[must_use]
pub(crate) fn norm<const N: usize>(v: &[f64; N]) -> f64 {
    if N == 1 {
        return v[0].abs();
    }
    let s = dot(v, v);
    if is_positive_normal(s) {
        s.sqrt()
    } else if *v == [0.0; N] {
        // The zero vector (a sticking point's slip): common, and exactly 0 without scaling.
        0.0
    } else {
        scaled_norm(*v)
    }
}

/// `None` when |v| ≤ bound, else `Some(|v|)` (`Some(NaN)` for a NaN entry). For N = 2 the test
/// is first made on the squares, v·v ≤ bound², which needs no square root and is exact to
/// rounding whenever bound² is a normal number (v·v ≤ bound² then bounds |v| by bound·(1 + 2ε),
/// and an underflowed v·v means |v| below the smallest such bound); otherwise, or when the
/// squares say no, on [`norm`], which is then returned.
#[inline(always)]
#[must_use]
pub(crate) fn length_beyond<const N: usize>(v: &[f64; N], bound: f64) -> Option<f64> {
    if N > 1 {
        let bound_sq = bound * bound;
        if is_positive_normal(bound_sq) && dot(v, v) <= bound_sq {
            return None;
        }
    }
    let length = norm(v);
    if length <= bound { None } else { Some(length) }
}

/// `f64::MIN_POSITIVE ≤ x < ∞`, in one integer comparison of the bits (negative values, NaN,
/// zero and subnormals all fall outside): the range test of the per-call path.
#[inline(always)]
pub(crate) fn is_positive_normal(x: f64) -> bool {
    x.to_bits().wrapping_sub(f64::MIN_POSITIVE.to_bits())
        < f64::INFINITY.to_bits() - f64::MIN_POSITIVE.to_bits()
}

/// `m·|v/m|` with m the largest |entry|: no overflow or underflow in the squares. NaN in, NaN
/// out; ∞ in, ∞ out.
#[cold]
#[inline(never)]
#[allow(clippy::needless_pass_by_value)] // by value: a reference would keep `v` in memory at every caller
fn scaled_norm<const N: usize>(v: [f64; N]) -> f64 {
    let mut m = 0.0f64;
    for x in &v {
        if x.is_nan() {
            return f64::NAN;
        }
        m = m.max(x.abs());
    }
    if m == 0.0 || m == f64::INFINITY {
        return m;
    }
    let mut s = 0.0;
    for x in &v {
        let r = x / m;
        s += r * r;
    }
    m * s.sqrt()
}

#[inline(always)]
#[must_use]
pub(crate) fn dot<const N: usize>(a: &[f64; N], b: &[f64; N]) -> f64 {
    let mut s = 0.0;
    for i in 0..N {
        s += a[i] * b[i];
    }
    s
}

#[inline(always)]
#[must_use]
pub(crate) fn scale<const N: usize>(v: &[f64; N], s: f64) -> [f64; N] {
    let mut out = *v;
    for x in &mut out {
        *x *= s;
    }
    out
}

/// `v/len`, dividing each entry (not multiplying by `1/len`), so that in 1-D the direction is
/// exactly ±1 and τ = τ_crit·n lands exactly on μp. `len` is `norm(v)`; when it is subnormal
/// its rounding is coarse (up to 41 % for two entries of the smallest subnormal), and when it
/// overflows every entry divides to 0, so then the direction is taken of `v` scaled exactly by
/// a power of two instead.
#[inline(always)]
#[must_use]
pub(crate) fn unit<const N: usize>(v: &[f64; N], len: f64) -> [f64; N] {
    if N > 1 && !is_positive_normal(len) {
        return unit_of_extreme(*v, len);
    }
    divided(v, len)
}

/// The unit vector along `v`, or 0 when `v` = 0 (a direction that the motion does not give:
/// exact stick's slip out of a held point that did not move).
#[inline(always)]
#[must_use]
pub(crate) fn unit_or_zero<const N: usize>(v: &[f64; N]) -> [f64; N] {
    let len = norm(v);
    if len > 0.0 { unit(v, len) } else { [0.0; N] }
}

/// [`unit()`] for a caller that refuses its results when `len` is infinite (the elastic-stick
/// slip, whose slip increment is then infinite): one comparison instead of the range test.
#[inline(always)]
#[must_use]
pub(crate) fn unit_unless_infinite<const N: usize>(v: &[f64; N], len: f64) -> [f64; N] {
    if N > 1 && len < f64::MIN_POSITIVE {
        return unit_of_extreme(*v, len);
    }
    divided(v, len)
}

/// Σ v_i, from the first entry (so that N = 1 is exactly v₁).
#[inline(always)]
#[must_use]
pub(crate) fn sum<const N: usize>(v: &[f64; N]) -> f64 {
    v[1..].iter().fold(v[0], |s, x| s + x)
}

/// `v/len` entry by entry.
#[inline(always)]
pub(crate) fn divided<const N: usize>(v: &[f64; N], len: f64) -> [f64; N] {
    let mut out = *v;
    for x in &mut out {
        *x /= len;
    }
    out
}

/// The direction of a vector whose norm `len` is subnormal or overflows (zero or NaN entries
/// give NaN, as `v/len` would).
#[cold]
#[inline(never)]
#[allow(clippy::needless_pass_by_value)] // by value, as `scaled_norm`
fn unit_of_extreme<const N: usize>(v: [f64; N], len: f64) -> [f64; N] {
    // 2^±600: exact on entries below f64::MIN_POSITIVE (up) or near f64::MAX (down), and takes
    // them far from both ends of the range.
    const UP: f64 = f64::from_bits((1023 + 600) << 52);
    const DOWN: f64 = f64::from_bits((1023 - 600) << 52);
    let w = scale(&v, if len < 1.0 { UP } else { DOWN });
    divided(&w, norm(&w))
}

#[inline(always)]
#[must_use]
pub(crate) fn add<const N: usize>(a: &[f64; N], b: &[f64; N]) -> [f64; N] {
    let mut out = *a;
    for i in 0..N {
        out[i] += b[i];
    }
    out
}

/// `s·I` as an N×N matrix, `m[a][b]`.
#[inline(always)]
#[must_use]
pub(crate) fn diagonal<const N: usize>(s: f64) -> [[f64; N]; N] {
    let mut m = [[0.0; N]; N];
    for (a, row) in m.iter_mut().enumerate() {
        row[a] = s;
    }
    m
}

/// `s·(I − n nᵀ)`: the projection onto the plane normal to the unit vector `n`, scaled. For
/// N = 1 it is exactly zero (seed 000: "for two-dimensional problems the term involving
/// (δ_ij − n_i n_j) vanishes").
#[inline(always)]
#[must_use]
pub(crate) fn transverse_projection<const N: usize>(n: &[f64; N], s: f64) -> [[f64; N]; N] {
    let mut m = [[0.0; N]; N];
    if N == 1 {
        return m;
    }
    for a in 0..N {
        for b in 0..N {
            let delta = if a == b { 1.0 } else { 0.0 };
            m[a][b] = s * (delta - n[a] * n[b]);
        }
    }
    m
}

/// `r·n nᵀ + t·(I − n nᵀ)`: the tangent of τ = τ_eq(|γ|)·n with respect to γ along a unit
/// vector `n` (seed 000, Eq. 5.2.3-3: r = ∂τ_eq/∂|γ|, t = τ_eq/|γ|). Evaluated as written for
/// every N (for N = 1, n = ±1 and the projection is exactly 0).
#[inline(always)]
#[must_use]
pub(crate) fn radial_transverse<const N: usize>(
    n: &[f64; N],
    radial: f64,
    transverse: f64,
) -> [[f64; N]; N] {
    let mut m = [[0.0; N]; N];
    for (i, row) in m.iter_mut().enumerate() {
        for (j, x) in row.iter_mut().enumerate() {
            let delta = if i == j { 1.0 } else { 0.0 };
            *x = radial * n[i] * n[j] + transverse * (delta - n[i] * n[j]);
        }
    }
    m
}

/// True when every entry is finite.
#[inline]
#[must_use]
pub(crate) fn all_finite<const N: usize>(v: &[f64; N]) -> bool {
    v.iter().all(|x| x.is_finite())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn norm_over_the_whole_range() {
        // 3-4-5 at every scale: the squares overflow above ~1e154 and underflow below ~1e-154.
        for scale_by in [1.0, 1e300, 1e-300, 1e-320, f64::MAX / 5.0] {
            let v = [3.0 * scale_by, 4.0 * scale_by];
            let expected = 5.0 * scale_by;
            let n = norm(&v);
            assert!(
                (n - expected).abs() <= expected * 1e-15 + 1e-323,
                "{scale_by}: {n} vs {expected}"
            );
        }
        assert_eq!(norm(&[0.0, 0.0]), 0.0);
        assert_eq!(norm(&[-5e-324, 0.0]), 5e-324);
        assert_eq!(norm(&[f64::MAX, 0.0]), f64::MAX);
        assert_eq!(norm(&[f64::INFINITY, 1.0]), f64::INFINITY);
        assert!(norm(&[f64::NAN, f64::INFINITY]).is_nan());
        assert!(norm(&[f64::NAN, 1.0]).is_nan());
    }

    #[test]
    fn unit_vectors_of_tiny_and_huge_vectors_have_length_one() {
        for v in [
            [5e-324, 5e-324],
            [-5e-324, 1.5e-323],
            [3e-320, -4e-320],
            [1e-300, 1e-300],
            [1e300, -1e300],
            [f64::MAX, f64::MAX],
        ] {
            let n = unit(&v, norm(&v));
            let len = (n[0] * n[0] + n[1] * n[1]).sqrt();
            assert!((len - 1.0).abs() < 1e-15, "{v:?}: {n:?}");
            // Same direction: the cross product vanishes and the dot product is positive.
            assert!((n[0] * v[1].signum() - n[1] * v[0].signum()).abs() < 1.0 + 1e-15);
            assert!(n[0] * v[0] + n[1] * v[1] > 0.0);
        }
        // 1-D stays exactly ±1.
        assert_eq!(unit(&[-5e-324], 5e-324), [-1.0]);
    }

    /// `length_beyond` against the exactly rounded length (`hypot`): the same answer except in
    /// a band of a few ε about |v| = bound, and never "within" for |v| beyond bound·(1 + 4ε) —
    /// the margin the Coulomb law's stick stress relies on. Vectors and bounds over the whole
    /// f64 range, with bounds put near |v| on purpose.
    #[test]
    fn length_beyond_agrees_with_the_norm_up_to_rounding() {
        let mut rng = crate::testing::XorShift(0x2545_f491_4f6c_dd1d);
        let mut wide = || {
            let bits = rng.bits();
            let exponent = (bits >> 53) % 2046 + 1;
            f64::from_bits((exponent << 52) | (bits & ((1 << 52) - 1)))
                * if bits & (1 << 52) == 0 { 1.0 } else { -1.0 }
        };
        let band = 4.0 * f64::EPSILON;
        for i in 0..200_000 {
            let v = [wide(), wide()];
            let length = v[0].hypot(v[1]);
            let bound = match i % 4 {
                0 => wide().abs(),
                1 => length,
                2 => length * (1.0 + band * 2.0),
                _ => length * (1.0 - band * 2.0),
            };
            if !(bound > 0.0 && bound < f64::INFINITY && length < f64::INFINITY) {
                continue;
            }
            let within = length_beyond(&v, bound).is_none();
            if let Some(l) = length_beyond(&v, bound) {
                assert!(l == norm(&v), "{v:?}: {l} is not the norm");
            }
            if length > bound * (1.0 + band) {
                assert!(!within, "{v:?} within {bound}");
            }
            if length < bound * (1.0 - band) {
                assert!(within, "{v:?} not within {bound}");
            }
        }
        assert!(length_beyond(&[3.0, 4.0], 5.0).is_none());
        assert!(length_beyond(&[3.0, 4.0], 4.999_999).is_some());
        assert!(length_beyond(&[f64::NAN, 0.0], 1.0).is_some());
        assert!(length_beyond(&[f64::MAX, f64::MAX], 1e200).is_some());
        assert!(length_beyond(&[1e-170, 1e-170], 1e-160).is_none());
        assert!(length_beyond(&[-2.0], 1.5).is_some());
    }
}
