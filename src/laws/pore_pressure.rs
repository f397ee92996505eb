//! Interface pore pressure (seed 000, the interface pore-pressure section that opens the seed):
//! the contribution of one interface integration point to the virtual work of a coupled
//! pore-fluid/stress analysis,
//!
//! δΠ^ipp = −∫_A [ Δh δp̄ + p̄ δh + Δt (q̂ δp̂ + p̂ δq̂) ] dA,
//! p̄ = (p₁ + p₂)/2, p̂ = (p₁ − p₂)/2,
//!
//! its consistent linearization, and the simplified forms the seed derives from it: closed
//! contact (Δh = 0, dh = 0), steady state (transient terms dropped, flow in rate form) and small
//! sliding (the terms in dδp̄, dδh, dδp̂ and dδq̂ vanish).
//!
//! # What the kernel returns
//!
//! Per unit area, with the leading minus sign of δΠ^ipp included, in the basis
//! x = (h, p̄, p̂, q̂) of [`Basis::MeanJump`] (or (h, p₁, p₂, q̂) of [`Basis::PerSide`]):
//! - `residual[i]`: the coefficient of δx_i in δΠ^ipp;
//! - `tangent[i][j]`: ∂`residual[i]`/∂x_j, the coefficient of δx_i·dx_j in dδΠ^ipp (the column
//!   of h is taken with the start-of-increment opening fixed, so dΔh = dh);
//! - `geometric[i]`: the coefficient of dδx_i in dδΠ^ipp, which the host multiplies by the
//!   change of the variation that its own contact geometry gives (zero in small sliding).
//!
//! The integrand is bilinear in the unknowns and their variations, so the geometric
//! coefficients of finite sliding equal the residual coefficients, and the tangent holds only
//! the constants −1 and −Δt: the kernel's value lies in stating each variant exactly, validating
//! the point and handing the host one layout for all of them.
//!
//! # Conventions (decided here; see docs/pore-pressure.md)
//!
//! - h is the normal opening of the interface (positive when the faces separate), Δh its
//!   increment in this time increment; p₁, p₂ the pore pressures on side 1 and side 2.
//! - q̂ is the work conjugate of p̂ = (p₁ − p₂)/2, half the pressure jump: the fluid volume
//!   flux per unit area from side 1 to side 2 is q̂/2 (q̂ is the difference of the fluxes
//!   leaving the two faces). Stationarity in q̂ gives p̂ = 0: pressure continuity.
//! - The residual coefficients carry the sign of δΠ^ipp, the same sign as the continuum's
//!   −∫p δε_v in the virtual work: the host adds them to its internal virtual work unchanged.

use crate::LawError;

/// Whether the two faces touch at the point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Contact {
    /// The faces are apart: the opening changes (Δh ≠ 0) and the fluid volume Δh of the gap
    /// enters the mass balance of both sides.
    Open,
    /// The faces touch: Δh = 0 and dh = 0 (seed 000, "Closed contact").
    Closed,
}

/// Whether the analysis is transient or steady.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Regime {
    /// Transient: fluxes integrated over Δt (the seed's form multiplied by Δt).
    Transient,
    /// Steady state: transient terms omitted, flow in rate form, interface displacements
    /// assumed to vanish (seed 000, "The steady-state equations"). The contact flag has no
    /// effect and Δt is not read.
    Steady,
}

/// Contact formulation of the host.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Sliding {
    /// Small sliding: the geometric terms dδp̄, p̄dδh, dδp̂ and p̂dδq̂ vanish (seed 000, "Small
    /// sliding").
    Small,
    /// Finite sliding: the variations change with the geometry; the geometric coefficients are
    /// returned for the host to combine with its own dδ(·).
    Finite,
}

/// The unknowns in which the residual and the tangent are written.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Basis {
    /// (h, p̄, p̂, q̂), the seed's variables.
    MeanJump,
    /// (h, p₁, p₂, q̂), one pressure per side, as a host's nodes carry them.
    PerSide,
}

/// One variant of the kernel.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Variant {
    /// Open or closed contact.
    pub contact: Contact,
    /// Transient or steady state.
    pub regime: Regime,
    /// Small or finite sliding.
    pub sliding: Sliding,
}

impl Variant {
    /// The general form: open contact, transient, finite sliding.
    pub const GENERAL: Variant = Variant {
        contact: Contact::Open,
        regime: Regime::Transient,
        sliding: Sliding::Finite,
    };
}

/// The state of one interface integration point at the end of the increment.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct InterfacePoint {
    /// Pore pressure on side 1.
    pub p1: f64,
    /// Pore pressure on side 2.
    pub p2: f64,
    /// Flux variable q̂ (the flux from side 1 to side 2 is q̂/2).
    pub q_hat: f64,
    /// Normal opening h (positive apart).
    pub h: f64,
    /// Increment Δh of the opening in this increment.
    pub dh: f64,
    /// Time increment Δt (transient only; > 0).
    pub dt: f64,
}

/// Why a point was refused; each names the offending input.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PointFault {
    /// An input is NaN or infinite.
    NotFinite {
        /// The input's name as documented (`p1`, `p2`, `q_hat`, `h`, `dh`, `dt`).
        name: &'static str,
        /// Its value.
        value: f64,
    },
    /// A transient point needs Δt > 0: with Δt = 0 the flux terms vanish and the rows of p̂
    /// and q̂ are empty.
    TimeIncrementNotPositive(f64),
    /// A finite input whose products overflow (|q̂|·Δt or a pressure beyond f64).
    Overflow,
}

impl std::fmt::Display for PointFault {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            PointFault::NotFinite { name, value } => write!(f, "{name} = {value} is not finite"),
            PointFault::TimeIncrementNotPositive(dt) => write!(
                f,
                "dt = {dt}: a transient point needs a time increment > 0 (use the steady \
                 regime for a step without time)"
            ),
            PointFault::Overflow => write!(
                f,
                "the interface terms overflow f64 (|q_hat|*dt, |p1|, |p2| too large)"
            ),
        }
    }
}

impl From<PointFault> for LawError {
    fn from(f: PointFault) -> Self {
        match f {
            PointFault::Overflow => LawError::Numerical(f.to_string()),
            _ => LawError::Input(f.to_string()),
        }
    }
}

/// Residual coefficients, consistent tangent and geometric coefficients of one point.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PorePressureTerms {
    /// Coefficients of δx_i in δΠ^ipp.
    pub residual: [f64; 4],
    /// `tangent[i][j]` = ∂`residual[i]`/∂x_j.
    pub tangent: [[f64; 4]; 4],
    /// Coefficients of dδx_i in dδΠ^ipp (zero in small sliding).
    pub geometric: [f64; 4],
}

/// Index of h in the basis.
pub const H: usize = 0;
/// Index of p̄ (mean–jump basis) or p₁ (per-side basis).
pub const P_MEAN: usize = 1;
/// Index of p̂ (mean–jump basis) or p₂ (per-side basis).
pub const P_JUMP: usize = 2;
/// Index of q̂.
pub const Q_HAT: usize = 3;

#[inline]
fn finite(name: &'static str, value: f64) -> Result<(), PointFault> {
    if value.is_finite() {
        Ok(())
    } else {
        Err(PointFault::NotFinite { name, value })
    }
}

/// Checks the inputs a variant reads (Δt only in transient analysis).
#[inline]
pub fn validate(point: &InterfacePoint, variant: Variant) -> Result<(), PointFault> {
    finite("p1", point.p1)?;
    finite("p2", point.p2)?;
    finite("q_hat", point.q_hat)?;
    finite("h", point.h)?;
    finite("dh", point.dh)?;
    if variant.regime == Regime::Transient {
        finite("dt", point.dt)?;
        if point.dt <= 0.0 {
            return Err(PointFault::TimeIncrementNotPositive(point.dt));
        }
    }
    Ok(())
}

/// The interface terms of one point in the mean–jump basis (h, p̄, p̂, q̂), after validation.
///
/// # Errors
/// [`PointFault`] for a non-finite input, Δt ≤ 0 in a transient analysis, or an overflow.
#[inline]
pub fn interface_terms(
    point: &InterfacePoint,
    variant: Variant,
) -> Result<PorePressureTerms, PointFault> {
    validate(point, variant)?;
    let t = interface_terms_unchecked(point, variant);
    if t.residual.iter().all(|r| r.is_finite()) {
        Ok(t)
    } else {
        Err(PointFault::Overflow)
    }
}

/// ±0 for a finite `x`, NaN for NaN or ±∞.
#[inline(always)]
fn zero_if_finite(x: f64) -> f64 {
    x * 0.0
}

/// `x > 0 && x.is_finite()` in one integer comparison: the bit patterns of the positive finite
/// doubles are exactly 1 ..= 0x7FEF_FFFF_FFFF_FFFF (+0 is 0; −0, the negatives and negative NaNs
/// have the sign bit set; +∞ is 0x7FF0_0000_0000_0000 and positive NaNs lie above it).
#[inline(always)]
fn positive_finite(x: f64) -> bool {
    x.to_bits().wrapping_sub(1) < 0x7FEF_FFFF_FFFF_FFFF
}

/// [`interface_terms`] for valid inputs in one pass, `None` otherwise (the caller then asks
/// [`interface_terms`] for the cause). Same results bit for bit, and `None` exactly when
/// [`interface_terms`] refuses: the checks fold into one integer comparison (Δt) and one
/// floating-point comparison on the results.
///
/// Why checking the results suffices (Δt > 0 and finite, or 1 in steady state): the residual
/// of h is −(p₁/2 + p₂/2), non-finite exactly when p₁ or p₂ is (∞ + finite = ∞, ∞ − ∞ = NaN,
/// NaN propagates; finite halves cannot overflow); the residual of p̂ is −Δt·q̂, non-finite
/// when q̂ is or when it overflows; the residual of q̂ is −Δt·p̂, non-finite only by overflow.
/// h and Δh enter no product that the others cover, so they are checked themselves.
#[inline(always)]
#[must_use]
pub fn interface_terms_lean(point: &InterfacePoint, variant: Variant) -> Option<PorePressureTerms> {
    let time_ok = match variant.regime {
        Regime::Transient => positive_finite(point.dt),
        Regime::Steady => true,
    };
    if !time_ok {
        return None;
    }
    let t = interface_terms_unchecked(point, variant);
    // One sum, one branch: x·0 is ±0 exactly when x is finite (NaN otherwise).
    let finite_sum = zero_if_finite(t.residual[H])
        + zero_if_finite(t.residual[P_JUMP])
        + zero_if_finite(t.residual[Q_HAT])
        + zero_if_finite(point.h)
        + zero_if_finite(point.dh);
    (finite_sum == 0.0).then_some(t)
}

/// [`interface_terms`] without validation: finite inputs in range give finite outputs; the
/// caller has checked them.
#[inline(always)]
#[must_use]
pub fn interface_terms_unchecked(point: &InterfacePoint, variant: Variant) -> PorePressureTerms {
    // p̄ = (p₁ + p₂)/2, p̂ = (p₁ − p₂)/2, halved first so that finite pressures never overflow.
    let p_mean = 0.5 * point.p1 + 0.5 * point.p2;
    let p_jump = 0.5 * point.p1 - 0.5 * point.p2;
    // The transient form carries the fluxes integrated over Δt; the steady form writes them in
    // rate form, which is the same expression with the factor Δt replaced by 1.
    let flux_time = match variant.regime {
        Regime::Transient => point.dt,
        Regime::Steady => 1.0,
    };
    // Δh δp̄ is present only with open contact in a transient analysis: closed contact has
    // Δh = 0, dh = 0, and the steady form assumes the interface displacements vanish.
    let opening = variant.contact == Contact::Open && variant.regime == Regime::Transient;

    let mut residual = [0.0; 4];
    // δΠ^ipp = −[Δh δp̄ + p̄ δh + Δt (q̂ δp̂ + p̂ δq̂)]: the coefficient of each variation.
    residual[H] = -p_mean;
    residual[P_MEAN] = if opening { -point.dh } else { 0.0 };
    residual[P_JUMP] = -flux_time * point.q_hat;
    residual[Q_HAT] = -flux_time * p_jump;

    // dδΠ^ipp = −[dh δp̄ + dp̄ δh + Δt (dq̂ δp̂ + dp̂ δq̂) + geometric terms]: the coefficient of
    // δx_i·dx_j.
    let mut tangent = [[0.0; 4]; 4];
    tangent[H][P_MEAN] = -1.0; // dp̄ δh
    if opening {
        tangent[P_MEAN][H] = -1.0; // dh δp̄
    }
    tangent[P_JUMP][Q_HAT] = -flux_time; // Δt dq̂ δp̂
    tangent[Q_HAT][P_JUMP] = -flux_time; // Δt dp̂ δq̂

    // −[Δh dδp̄ + p̄ dδh + Δt (q̂ dδp̂ + p̂ dδq̂)]: these multiply the change of the variations
    // and vanish with small sliding.
    let geometric = match variant.sliding {
        Sliding::Finite => residual,
        Sliding::Small => [0.0; 4],
    };
    PorePressureTerms {
        residual,
        tangent,
        geometric,
    }
}

impl PorePressureTerms {
    /// The same terms in the per-side basis (h, p₁, p₂, q̂). With δp̄ = (δp₁ + δp₂)/2 and
    /// δp̂ = (δp₁ − δp₂)/2, i.e. x_mean-jump = T·x_per-side, the coefficients transform with Tᵀ
    /// (residual, geometric) and the tangent as Tᵀ·K·T.
    #[inline(always)]
    #[must_use]
    pub fn per_side(&self) -> PorePressureTerms {
        let side = |v: &[f64; 4]| {
            [
                v[H],
                0.5 * v[P_MEAN] + 0.5 * v[P_JUMP],
                0.5 * v[P_MEAN] - 0.5 * v[P_JUMP],
                v[Q_HAT],
            ]
        };
        // T is symmetric: K·T has rows side(row of K); Tᵀ·(K·T) transposed has rows
        // side(column of K·T).
        let transpose = |m: &[[f64; 4]; 4]| -> [[f64; 4]; 4] {
            std::array::from_fn(|i| std::array::from_fn(|j| m[j][i]))
        };
        let k_t: [[f64; 4]; 4] = std::array::from_fn(|i| side(&self.tangent[i]));
        let k_t_transposed = transpose(&k_t);
        let tangent = transpose(&std::array::from_fn(|j| side(&k_t_transposed[j])));
        PorePressureTerms {
            residual: side(&self.residual),
            tangent,
            geometric: side(&self.geometric),
        }
    }

    /// The terms in `basis`.
    #[inline(always)]
    #[must_use]
    pub fn in_basis(&self, basis: Basis) -> PorePressureTerms {
        match basis {
            Basis::MeanJump => *self,
            Basis::PerSide => self.per_side(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const POINT: InterfacePoint = InterfacePoint {
        p1: 3.0,
        p2: 1.0,
        q_hat: 0.5,
        h: 0.2,
        dh: 0.05,
        dt: 0.1,
    };

    #[test]
    fn general_form_is_the_seed_integrand() {
        let t = interface_terms(&POINT, Variant::GENERAL).unwrap();
        // p̄ = 2, p̂ = 1: −(Δh, p̄, Δt q̂, Δt p̂) as coefficients of (δp̄, δh, δp̂, δq̂).
        assert_eq!(t.residual, [-2.0, -0.05, -0.05, -0.1]);
        assert_eq!(t.geometric, t.residual);
    }

    #[test]
    fn per_side_coefficients_follow_the_chain_rule() {
        let t = interface_terms(&POINT, Variant::GENERAL).unwrap();
        let s = t.per_side();
        // δΠ = r_p̄ (δp₁ + δp₂)/2 + r_p̂ (δp₁ − δp₂)/2.
        assert_eq!(s.residual[1], 0.5 * (-0.05) + 0.5 * (-0.05));
        assert_eq!(s.residual[2], 0.5 * (-0.05) - 0.5 * (-0.05));
        // ∂r_h/∂p₁ = ∂r_h/∂p̄ · ∂p̄/∂p₁ = −1/2.
        assert_eq!(s.tangent[H][1], -0.5);
        assert_eq!(s.tangent[H][2], -0.5);
    }

    #[test]
    fn positive_finite_is_the_two_comparisons() {
        for x in crate::testing::EDGE_VALUES {
            assert_eq!(positive_finite(x), x > 0.0 && x.is_finite(), "{x:e}");
        }
    }

    #[test]
    fn faults_name_the_input() {
        let mut p = POINT;
        p.q_hat = f64::NAN;
        let e = interface_terms(&p, Variant::GENERAL).unwrap_err();
        assert!(e.to_string().starts_with("q_hat = NaN"), "{e}");
        let mut p = POINT;
        p.dt = 0.0;
        assert_eq!(
            interface_terms(&p, Variant::GENERAL).unwrap_err(),
            PointFault::TimeIncrementNotPositive(0.0)
        );
        let steady = Variant {
            regime: Regime::Steady,
            ..Variant::GENERAL
        };
        assert!(interface_terms(&p, steady).is_ok());
        let mut p = POINT;
        p.q_hat = 1e300;
        p.dt = 1e300;
        assert_eq!(
            interface_terms(&p, Variant::GENERAL).unwrap_err(),
            PointFault::Overflow
        );
    }
}
