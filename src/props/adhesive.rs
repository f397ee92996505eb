//! `PROPS` layout of the adhesive friction law (`PROPS(1) = 2`, seed 004), shared by `fric_`
//! (tangential part) and `uinter_` (the whole interface). The table in `docs/props.md`
//! documents the same layout for users.

use crate::LawError;
use crate::laws::adhesive::{Adhesive, AdhesiveParameters};
use crate::laws::adhesive_interface::AdhesiveInterface;
use crate::laws::coulomb::{Coulomb, StickMode};

use super::FrictionLaw;
use super::range_flag;

/// `PROPS(1)` code of the adhesive friction law.
pub const LAW_ADHESIVE: i32 = 2;

/// Number of `PROPS` entries the adhesive law reads (`PROPS(1..13)`).
pub const ADHESIVE_NPROPS: usize = 13;

/// How the interface exchanges heat (`uinter_` only).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HeatExchange {
    /// `PROPS(11) = 1`: conductance across the interface from the `INTERFACIAL_CONFIG` file
    /// (the GAPCON laws, keyed by the interaction name).
    pub conductance: bool,
    /// η, the fraction of the frictional dissipation converted into heat (`PROPS(12)`).
    pub heat_fraction: f64,
    /// f, the part of that heat that flows into the slave surface (`PROPS(13)`, 0 → ½).
    pub slave_fraction: f64,
}

/// The adhesive law and the entries only `uinter_` reads.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AdhesiveProps {
    /// The tangential law (and adhesive strengths).
    pub law: Adhesive,
    /// Penalty normal stiffness K_n (`PROPS(10)`; 0 = not given, which `uinter_` refuses).
    pub normal_stiffness: f64,
    /// Heat exchange across the interface.
    pub heat: HeatExchange,
}

impl AdhesiveProps {
    /// The law as `fric_` runs it: the Coulomb law itself in the special case S_a = k_μ =
    /// v_½ = 0, μ_s = μ_d (so the special case costs what the Coulomb law costs).
    #[inline(always)]
    #[must_use]
    pub fn into_friction_law(self) -> FrictionLaw {
        match self.law.coulomb_special_case() {
            Some(c) => FrictionLaw::Coulomb(c),
            None => FrictionLaw::Adhesive(self),
        }
    }

    /// The interface law for `uinter_`, which needs K_n.
    pub fn interface(&self) -> Result<AdhesiveInterface, LawError> {
        if self.normal_stiffness == 0.0 {
            return Err(LawError::Parameter(
                "PROPS(10) = 0: UINTER needs the penalty normal stiffness K_n > 0 of the \
                 adhesive law (PROPS(10))"
                    .into(),
            ));
        }
        AdhesiveInterface::new(self.law, self.normal_stiffness).map_err(|e| in_props(10, e))
    }
}

/// The common case of the adhesive layout: valid `PROPS`, or `None` (then the checked path
/// [`adhesive`] says what is wrong). Branch-light, like the Coulomb fast path; a property test
/// checks that both agree.
#[inline(always)]
pub(crate) fn adhesive_fast(props: &[f64]) -> Option<FrictionLaw> {
    adhesive_props_fast(props).map(AdhesiveProps::into_friction_law)
}

/// The Coulomb law of a valid adhesive `PROPS` in its Coulomb special case, else `None` (any
/// other adhesive `PROPS`, or not the adhesive law at all). Inlined into the out-of-line
/// `other_plain_layouts` (props.rs), which `fric_`'s plain path calls only when `PROPS` is not
/// the plain Coulomb layout.
///
/// Decides with plain comparisons, like [`adhesive_props_fast`] (a property test checks that
/// it agrees with that function followed by [`Adhesive::coulomb_special_case`]).
#[inline]
pub(crate) fn adhesive_coulomb_special_case(props: &[f64]) -> Option<Coulomb> {
    // The layouts a friction-only host passes (up to γ_crit, or up to the slip tolerance):
    // read as one array, no padding.
    if let Ok(first_eight) = <&[f64; 8]>::try_from(props) {
        return special_case_of_friction_entries(*first_eight, 0.0);
    }
    if let Ok(&[e0, e1, e2, e3, e4, e5, e6, e7, tolerance]) = <&[f64; 9]>::try_from(props) {
        return special_case_of_friction_entries([e0, e1, e2, e3, e4, e5, e6, e7], tolerance);
    }
    if props.len() < 2 || props.len() > ADHESIVE_NPROPS {
        return None;
    }
    // Absent entries read as 0 (an absent PROPS(3) means "no μ_s", as 0 does); entry by entry
    // rather than a copy of the given ones (a call to memcpy for ≤ 13 values).
    let e: [f64; ADHESIVE_NPROPS] = std::array::from_fn(|i| props.get(i).copied().unwrap_or(0.0));
    let [
        code,
        mu_d,
        mu_s,
        sa,
        na,
        kmu,
        vhalf,
        gamma_crit,
        tolerance,
        kn,
        conductance,
        eta,
        f,
    ] = e;
    // 0 ≤ v < ∞ for μ_d, N_a, γ_crit, the tolerance and K_n, in one test of the top bit
    // (`range_flag`).
    let flags = range_flag(mu_d)
        | range_flag(na)
        | range_flag(gamma_crit)
        | range_flag(tolerance)
        | range_flag(kn);
    // The special case: S_a = k_μ = v_½ = 0 and μ_s = μ_d (no static coefficient: PROPS(3)
    // finite and ≤ 0, or equal to μ_d).
    let special = code == f64::from(LAW_ADHESIVE)
        && flags >> 63 == 0
        && sa == 0.0
        && kmu == 0.0
        && vhalf == 0.0
        && ((mu_s <= 0.0 && mu_s > f64::NEG_INFINITY) || mu_s == mu_d)
        && (conductance == 0.0 || conductance == 1.0)
        && (0.0..=1.0).contains(&eta)
        && (0.0..=1.0).contains(&f);
    special.then(|| Coulomb::from_validated(mu_d, 0.0, gamma_crit, tolerance, StickMode::Elastic))
}

/// [`adhesive_coulomb_special_case`] for `NPROPS` = 8 or 9: the absent entries (the slip
/// tolerance when `NPROPS = 8`, K_n, the conductance flag, η, f) read as 0, which is each one's
/// valid default, so only the given ones are tested.
#[inline(always)]
fn special_case_of_friction_entries(e: [f64; 8], tolerance: f64) -> Option<Coulomb> {
    let [code, mu_d, mu_s, sa, na, kmu, vhalf, gamma_crit] = e;
    // 0 ≤ v < ∞ for μ_d, N_a and γ_crit in one test of the top bit, as in the general case.
    // No static coefficient: μ_s = μ_d, or −∞ < μ_s ≤ 0, which is −μ_s in range (same test).
    let static_flag = if mu_s == mu_d { 0 } else { range_flag(-mu_s) };
    let flags = range_flag(mu_d)
        | range_flag(na)
        | range_flag(gamma_crit)
        | range_flag(tolerance)
        | static_flag;
    // S_a = k_μ = v_½ = 0 (either sign of zero): no bit but the sign bits set.
    let zeros = (sa.to_bits() | kmu.to_bits() | vhalf.to_bits()) << 1 == 0;
    let special = code == f64::from(LAW_ADHESIVE) && flags >> 63 == 0 && zeros;
    special.then(|| Coulomb::from_validated(mu_d, 0.0, gamma_crit, tolerance, StickMode::Elastic))
}

/// [`adhesive_fast`] before the special case is recognised.
#[inline(always)]
fn adhesive_props_fast(props: &[f64]) -> Option<AdhesiveProps> {
    if props.len() < 2 || props.len() > ADHESIVE_NPROPS || props[0] != f64::from(LAW_ADHESIVE) {
        return None;
    }
    // Zero-padded copy: absent trailing entries read as 0 without a branch per entry.
    let mut e = [0.0; ADHESIVE_NPROPS];
    e[..props.len()].copy_from_slice(props);
    let mu_s_entry = if props.len() >= 3 { e[2] } else { -1.0 };
    // μ_d, S_a, N_a, k_μ, v_½ finite and ≥ 0; γ_crit, tolerance, K_n 0 or finite > 0 (the same
    // test); PROPS(11) 0 or 1; η and f in [0, 1] (f = 0 meaning ½).
    // x·0 is ±0 for finite x and NaN otherwise; with all finite, the minimum decides the sign.
    let (mut probe, mut low) = (0.0, 0.0f64);
    for v in [e[1], e[3], e[4], e[5], e[6], e[7], e[8], e[9]] {
        probe += v * 0.0;
        low = low.min(v);
    }
    let mut valid = probe == 0.0 && low >= 0.0;
    valid &= mu_s_entry.is_finite() && (mu_s_entry <= 0.0 || mu_s_entry >= e[1]);
    valid &= e[10] == 0.0 || e[10] == 1.0;
    valid &= (0.0..=1.0).contains(&e[11]) && (0.0..=1.0).contains(&e[12]);
    valid.then(|| AdhesiveProps {
        law: Adhesive::from_validated(
            e[1],
            if mu_s_entry > 0.0 { mu_s_entry } else { e[1] },
            e[3],
            e[4],
            e[5],
            e[6],
            e[7],
            e[8],
        ),
        normal_stiffness: e[9],
        heat: HeatExchange {
            conductance: e[10] == 1.0,
            heat_fraction: e[11],
            slave_fraction: if e[12] == 0.0 { 0.5 } else { e[12] },
        },
    })
}

/// The adhesive `PROPS` as `uinter_` needs them (also in the Coulomb special case): the fast
/// path, else the checked one, which names what is wrong.
pub(crate) fn adhesive_props(props: &[f64]) -> Result<AdhesiveProps, LawError> {
    match adhesive_props_fast(props) {
        Some(a) => Ok(a),
        None => adhesive(props),
    }
}

/// Adhesive layout: `PROPS(2)` coeff μ_d, `PROPS(3)` coeffStatic μ_s (≤ 0 → none),
/// `PROPS(4)` Sa, `PROPS(5)` Na, `PROPS(6)` kmu, `PROPS(7)` vhalf, `PROPS(8)` γ_crit
/// (0 → tolerance × CHRLNGTH), `PROPS(9)` slip tolerance (0 → 0.005), `PROPS(10)` K_n,
/// `PROPS(11)` conductance from the configuration file (0 no, 1 yes), `PROPS(12)` η,
/// `PROPS(13)` f.
pub(crate) fn adhesive(props: &[f64]) -> Result<AdhesiveProps, LawError> {
    if props.len() < 2 {
        return Err(LawError::Parameter(format!(
            "NPROPS = {} but the adhesive law needs at least 2 (PROPS(1) = 2, PROPS(2) = coeff)",
            props.len()
        )));
    }
    if let Some((i, v)) = props
        .iter()
        .enumerate()
        .skip(ADHESIVE_NPROPS)
        .find(|(_, v)| **v != 0.0)
    {
        return Err(LawError::Parameter(format!(
            "PROPS({}) = {v} is not used by the adhesive law (PROPS(1..{ADHESIVE_NPROPS})); \
             refusing to ignore it",
            i + 1
        )));
    }
    let get = |i: usize| props.get(i - 1).copied().unwrap_or(0.0);
    let coeff_static = if props.len() >= 3 { get(3) } else { -1.0 };
    let parameters = AdhesiveParameters {
        coeff: get(2),
        coeff_static,
        sa: get(4),
        na: get(5),
        kmu: get(6),
        vhalf: get(7),
    };
    let mut law = Adhesive::new(&parameters).map_err(|e| {
        // Name the entry: the core names the seed's parameter.
        let entry = match &e {
            LawError::Parameter(m) if m.starts_with("coeffStatic") => 3,
            LawError::Parameter(m) if m.starts_with("coeff") => 2,
            LawError::Parameter(m) if m.starts_with("Sa") => 4,
            LawError::Parameter(m) if m.starts_with("Na") => 5,
            LawError::Parameter(m) if m.starts_with("kmu") => 6,
            _ => 7,
        };
        in_props(entry, e)
    })?;
    let tolerance = get(9);
    if tolerance != 0.0 {
        law = law
            .with_slip_tolerance(tolerance)
            .map_err(|e| in_props(9, e))?;
    }
    let gamma_crit = get(8);
    if gamma_crit != 0.0 {
        law = law
            .with_critical_slip_absolute(gamma_crit)
            .map_err(|e| in_props(8, e))?;
    }
    let normal_stiffness = get(10);
    if !(normal_stiffness == 0.0 || (normal_stiffness > 0.0 && normal_stiffness.is_finite())) {
        return Err(LawError::Parameter(format!(
            "PROPS(10) = {normal_stiffness}: the penalty normal stiffness K_n must be finite and \
             > 0 (0 when only FRIC is used)"
        )));
    }
    let conductance = match get(11) {
        0.0 => false,
        1.0 => true,
        other => {
            return Err(LawError::Parameter(format!(
                "PROPS(11) = {other} must be 0 (no heat conduction) or 1 (conductance from the \
                 INTERFACIAL_CONFIG file)"
            )));
        }
    };
    let heat_fraction = get(12);
    if !(0.0..=1.0).contains(&heat_fraction) {
        return Err(LawError::Parameter(format!(
            "PROPS(12) = {heat_fraction}: the fraction η of frictional dissipation converted \
             into heat must be in [0, 1]"
        )));
    }
    let slave_fraction = match get(13) {
        0.0 => 0.5,
        f if f > 0.0 && f <= 1.0 => f,
        other => {
            return Err(LawError::Parameter(format!(
                "PROPS(13) = {other}: the part f of the frictional heat that goes to the slave \
                 surface must be in (0, 1] (0 → ½)"
            )));
        }
    };
    Ok(AdhesiveProps {
        law,
        normal_stiffness,
        heat: HeatExchange {
            conductance,
            heat_fraction,
            slave_fraction,
        },
    })
}

fn in_props(index: usize, e: LawError) -> LawError {
    match e {
        LawError::Parameter(m) => LawError::Parameter(format!("PROPS({index}): {m}")),
        other => other,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn entry() -> impl Strategy<Value = f64> {
        prop_oneof![
            Just(0.0),
            Just(1.0),
            Just(-1.0),
            Just(0.5),
            Just(f64::NAN),
            Just(f64::INFINITY),
            0.0..2.0f64,
        ]
    }

    proptest! {
        /// The fast path accepts exactly what the checked path accepts, with the same result.
        #[test]
        fn fast_and_checked_paths_agree(mut props in prop::collection::vec(entry(), 0..15)) {
            if !props.is_empty() {
                props[0] = 2.0;
            }
            match (adhesive_props_fast(&props), adhesive(&props)) {
                (Some(f), Ok(c)) => prop_assert_eq!(f, c),
                (None, Err(_)) => {}
                // Longer PROPS with trailing zeros are valid but left to the checked path.
                (None, Ok(_)) => prop_assert!(props.len() > ADHESIVE_NPROPS),
                (Some(_), Err(e)) => prop_assert!(false, "fast path accepted {props:?}: {e}"),
            }
        }
    }

    fn special_case_entry() -> impl Strategy<Value = f64> {
        prop_oneof![
            6 => Just(0.0),
            1 => Just(-0.0),
            2 => Just(0.3),
            1 => Just(1.0),
            1 => Just(-1.0),
            1 => Just(f64::NAN),
            1 => Just(f64::INFINITY),
            1 => Just(f64::NEG_INFINITY),
            1 => Just(f64::MAX),
            1 => Just(5e-324),
            1 => 0.0..2.0f64,
        ]
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 5000, failure_persistence: None, ..ProptestConfig::default() })]
        /// The Coulomb special case recognised by `fric_`'s plain path is exactly the one the
        /// full adhesive parse finds.
        #[test]
        fn special_case_agrees_with_the_full_parse(
            mut props in prop_oneof![
                prop::collection::vec(special_case_entry(), 0..15),
                // NPROPS = 8 and 9 have their own route.
                prop::collection::vec(special_case_entry(), 8..=9),
            ],
            lead in prop::bool::ANY,
        ) {
            if lead && !props.is_empty() {
                props[0] = 2.0;
            }
            let full = adhesive_props_fast(&props).and_then(|a| a.law.coulomb_special_case());
            prop_assert_eq!(adhesive_coulomb_special_case(&props), full, "{:?}", props);
        }
    }

    #[test]
    fn layout_and_defaults() {
        let a = adhesive(&[2.0, 0.3]).unwrap();
        assert_eq!(a.law.mu_static(), 0.3);
        assert!(a.law.coulomb_special_case().is_some());
        assert_eq!(a.heat.slave_fraction, 0.5);
        let a = adhesive(&[
            2.0, 0.3, 0.5, 1.0, 2.0, 0.1, 0.2, 1e-3, 0.0, 1e5, 1.0, 0.9, 0.25,
        ])
        .unwrap();
        assert_eq!(
            (
                a.law.mu_static(),
                a.law.shear_adhesion(),
                a.law.normal_adhesion()
            ),
            (0.5, 1.0, 2.0)
        );
        assert_eq!((a.law.k_mu(), a.law.v_half()), (0.1, 0.2));
        assert_eq!(a.normal_stiffness, 1e5);
        assert!(a.heat.conductance);
        assert_eq!((a.heat.heat_fraction, a.heat.slave_fraction), (0.9, 0.25));
    }

    #[test]
    fn bad_entries_are_named() {
        for (props, needle) in [
            (&[2.0][..], "NPROPS = 1"),
            (&[2.0, -0.3][..], "PROPS(2)"),
            (
                &[2.0, 0.3, 0.2][..],
                "PROPS(3): coeffStatic = 0.2 is below coeff",
            ),
            (&[2.0, 0.3, f64::NAN][..], "PROPS(3)"),
            (&[2.0, 0.3, 0.0, -1.0][..], "PROPS(4): Sa"),
            (&[2.0, 0.3, 0.0, 0.0, -1.0][..], "PROPS(5): Na"),
            (&[2.0, 0.3, 0.0, 0.0, 0.0, f64::NAN][..], "PROPS(6): kmu"),
            (&[2.0, 0.3, 0.0, 0.0, 0.0, 0.0, -1.0][..], "PROPS(7): vhalf"),
            (&[2.0, 0.3, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0][..], "PROPS(8)"),
            (
                &[2.0, 0.3, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0][..],
                "PROPS(9)",
            ),
            (
                &[2.0, 0.3, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0][..],
                "PROPS(10)",
            ),
            (
                &[2.0, 0.3, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 2.0][..],
                "PROPS(11)",
            ),
            (
                &[2.0, 0.3, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.5][..],
                "PROPS(12)",
            ),
            (
                &[
                    2.0, 0.3, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0,
                ][..],
                "PROPS(13)",
            ),
            (
                &[
                    2.0, 0.3, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0,
                ][..],
                "PROPS(14)",
            ),
        ] {
            let e = adhesive(props).unwrap_err().to_string();
            assert!(e.contains(needle), "{props:?}: {e}");
        }
    }
}
