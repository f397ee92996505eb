//! The few fixed-size vector operations the laws need on `[f64; N]`, N = NFDIR ∈ {1, 2}.
//! With N = 1 the compiler folds them to scalar code, which is the "2-D runs scalar code"
//! promise of the contract without a second implementation.

/// Euclidean norm; for N = 1 exactly `|v₁|`.
#[inline]
#[must_use]
pub(crate) fn norm<const N: usize>(v: &[f64; N]) -> f64 {
    if N == 1 { v[0].abs() } else { dot(v, v).sqrt() }
}

#[inline]
#[must_use]
pub(crate) fn dot<const N: usize>(a: &[f64; N], b: &[f64; N]) -> f64 {
    let mut s = 0.0;
    for i in 0..N {
        s += a[i] * b[i];
    }
    s
}

#[inline]
#[must_use]
pub(crate) fn scale<const N: usize>(v: &[f64; N], s: f64) -> [f64; N] {
    let mut out = *v;
    for x in &mut out {
        *x *= s;
    }
    out
}

/// `v/len`, dividing each entry (not multiplying by `1/len`), so that in 1-D the direction is
/// exactly ±1 and τ = τ_crit·n lands exactly on μp.
#[inline]
#[must_use]
pub(crate) fn unit<const N: usize>(v: &[f64; N], len: f64) -> [f64; N] {
    let mut out = *v;
    for x in &mut out {
        *x /= len;
    }
    out
}

#[inline]
#[must_use]
pub(crate) fn add<const N: usize>(a: &[f64; N], b: &[f64; N]) -> [f64; N] {
    let mut out = *a;
    for i in 0..N {
        out[i] += b[i];
    }
    out
}

/// `s·I` as an N×N matrix, `m[a][b]`.
#[inline]
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
#[inline]
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

/// True when every entry is finite.
#[inline]
#[must_use]
pub(crate) fn all_finite<const N: usize>(v: &[f64; N]) -> bool {
    v.iter().all(|x| x.is_finite())
}
