//! Law 1's `PROPS` readers (the Coulomb family, layout and rules in `coulomb.rs`): the fast
//! readers `fric_` and the dispatcher try first (the plain seven-entry layout, the extended
//! layouts' compile-time plans, the decay law's lean layout), and the checked reader that
//! names the entry in force. The dispatcher over every law is `src/props.rs`.

use super::coulomb::{self, COULOMB};
use super::schema::admits_fixed;
use super::{FrictionLaw, LAW_ADHESIVE, adhesive, careful_path_only};
use crate::LawError;
use crate::laws::coulomb::{Coulomb, StickMode};
use crate::laws::coulomb_extended::ExtendedCoulomb;
use crate::laws::friction_coefficient::CoefficientLaw;
use crate::laws::friction_table::FrictionTable;

/// `PROPS(1)` code of the Coulomb family.
pub const LAW_COULOMB: i32 = 1;

/// Number of `PROPS` entries the Coulomb law reads (`PROPS(1..7)`); fewer may be given, the
/// missing trailing entries take their documented defaults.
pub const COULOMB_NPROPS: usize = 7;

/// Number of `PROPS` entries the extended Coulomb law reads (`PROPS(1..20)`, docs/props.md).
pub const COULOMB_EXTENDED_NPROPS: usize = COULOMB.entries.len();

/// The plain law-1 `PROPS` (isotropic, constant μ, `PROPS(1..7)`) as the small [`Coulomb`]
/// (not the whole [`FrictionLaw`], whose extended variant is large to move around), and also
/// the adhesive law's Coulomb special case (`PROPS(1) = 2` with
/// S_a = k_μ = v_½ = 0 and μ_s = μ_d, which `fric_` runs as the Coulomb law itself): the hot
/// path of `fric_`. The adhesive layout is only looked at when the plain one did not match,
/// out of line, so the plain law costs the same.
#[inline(always)]
#[must_use]
pub fn fast_plain_coulomb(props: &[f64]) -> Option<Coulomb> {
    if careful_path_only() {
        return None;
    }
    match <&[f64; COULOMB_NPROPS]>::try_from(props) {
        Ok(all) => coulomb_from_entries(*all),
        // Law 1 with more than 7 entries is the extended layout: no call to find that out
        // (the rate laws' path starts here too).
        Err(_) if props.len() > COULOMB_NPROPS && props[0] == f64::from(LAW_COULOMB) => None,
        Err(_) => plain_coulomb_other_lengths(props),
    }
}

/// [`fast_plain_coulomb`] for every `NPROPS` but 7: a shorter Coulomb `PROPS`, or
/// the adhesive law's special case. One call out of line, chosen by `PROPS(1)`.
#[inline(never)]
fn plain_coulomb_other_lengths(props: &[f64]) -> Option<Coulomb> {
    match props.first() {
        Some(&code) if code == f64::from(LAW_COULOMB) => coulomb_from_entries(padded(props)?),
        Some(&code) if code == f64::from(LAW_ADHESIVE) => {
            adhesive::adhesive_coulomb_special_case(props)
        }
        _ => None,
    }
}

/// A valid extended law-1 `PROPS` (anisotropy or `PROPS(8..20)`), else `None` (the plain law
/// and invalid `PROPS` included): the second hot path of `fric_`.
#[inline(always)]
#[must_use]
pub fn fast_extended_coulomb(props: &[f64]) -> Option<ExtendedCoulomb> {
    if careful_path_only() {
        return None;
    }
    with_admitted_extended(props, coulomb::extended_from_entries)
}

/// The common case of [`friction_law`]: a valid Coulomb `PROPS`, or `None`.
///
/// The full layout (`NPROPS = 7`, what hosts pass) is read straight from the array; a shorter
/// one is padded with zeros (the documented defaults) out of line.
#[inline(always)]
pub(super) fn coulomb_fast(props: &[f64]) -> Option<Coulomb> {
    let e = match <&[f64; COULOMB_NPROPS]>::try_from(props) {
        Ok(all) => *all,
        Err(_) => padded(props)?,
    };
    coulomb_from_entries(e)
}

/// The plain Coulomb law of the seven `PROPS` entries (absent ones already zero), or `None`.
/// Validity is the schema's: [`PLAIN`] over [`COULOMB`], worked out at compile
/// time (one top-bit test for μ, τ_max, γ_crit and the tolerance, μ₂ = 0 or μ); the stick
/// mode is tested once, by the match that maps it.
#[inline(always)]
fn coulomb_from_entries(e: [f64; COULOMB_NPROPS]) -> Option<Coulomb> {
    if !admits_fixed::<coulomb::Plain, COULOMB_NPROPS>(&e) {
        return None;
    }
    let [_, mu, _, tau_max, gamma_crit, tolerance, stick] = e;
    let stick = match stick {
        0.0 => StickMode::Elastic,
        1.0 => StickMode::Exact,
        2.0 => StickMode::Rough,
        _ => return None,
    };
    Some(Coulomb::from_validated(
        mu, tau_max, gamma_crit, tolerance, stick,
    ))
}

/// `PROPS(1..NPROPS)` with 2 ≤ NPROPS ≤ N padded with zeros (the absent entries' value) to
/// the `N` entries a fast reader reads (the plain layout's 7, the extended one's 20); `None`
/// for other lengths (the checked path then names the problem). Out of line: hosts pass the
/// whole layout, which the readers take as it is.
#[inline(never)]
fn padded<const N: usize>(props: &[f64]) -> Option<[f64; N]> {
    if props.len() < 2 || props.len() > N {
        return None;
    }
    let mut e = [0.0; N];
    e[..props.len()].copy_from_slice(props);
    Some(e)
}

/// The extended law-1 layout (`PROPS(3)`, `PROPS(8..20)`) when valid, else `None` (the
/// checked path then says what is wrong). Validity is the schema's, worked out at compile time:
/// [`EXTENDED_CONSTANT`] and [`EXTENDED_DECAY`] (stick modes 0, 1, 2 with constant μ or the
/// decay law) or [`TRANSPORT`] (`PROPS(7) = 3`) over [`COULOMB`]; the law is
/// [`coulomb::law_from_entries`]'s, as on the checked path. Declines the μ table
/// (`PROPS(8) = 2`), which needs the interaction's table.
#[inline(always)]
pub(super) fn fast_extended_friction_law(props: &[f64]) -> Option<FrictionLaw> {
    with_admitted_extended(props, coulomb::fast_law_from_entries)
}

/// `build` of the 20 law-1 entries of `props` (absent ones 0) when an extended fast plan
/// admits them ([`admits_extended`]), else `None`. The full layout (`NPROPS = 20`) is read in
/// place, a shorter one padded out of line; the adhesive layout leaves with one test.
#[inline(always)]
fn with_admitted_extended<T>(
    props: &[f64],
    build: impl FnOnce(&[f64; COULOMB_EXTENDED_NPROPS]) -> Option<T>,
) -> Option<T> {
    if props.first() != Some(&f64::from(LAW_COULOMB)) {
        return None;
    }
    let storage;
    let e = match <&[f64; COULOMB_EXTENDED_NPROPS]>::try_from(props) {
        Ok(all) => all,
        Err(_) => {
            storage = padded(props)?;
            &storage
        }
    };
    if !admits_extended(e) {
        return None;
    }
    build(e)
}

/// Whether the 20 law-1 entries `e` (absent ones 0) pass an extended fast plan: the plan of
/// their stick mode, μ law and dynamics (a value no plan takes fails the last one).
#[inline(always)]
fn admits_extended(e: &[f64; COULOMB_EXTENDED_NPROPS]) -> bool {
    if e[6] == 3.0 {
        admits_fixed::<coulomb::Transport, COULOMB_EXTENDED_NPROPS>(e)
    } else if e[7] != 0.0 {
        admits_fixed::<coulomb::ExtendedDecay, COULOMB_EXTENDED_NPROPS>(e)
    } else if e[13..19].iter().fold(0, |bits, v| bits | v.to_bits()) << 1 == 0 {
        // HHT and damping off: PROPS(14..19) all ±0, one test of their bits.
        admits_fixed::<coulomb::QuasiStatic, COULOMB_EXTENDED_NPROPS>(e)
    } else {
        admits_fixed::<coulomb::ExtendedConstant, COULOMB_EXTENDED_NPROPS>(e)
    }
}

/// The decay law's lean layout (`NPROPS = 20`: isotropic, elastic stick, exponential decay,
/// `PROPS(14..19)` all ±0, so no HHT, damping or steady transport; p_ref, b_θ, θ_ref and
/// frozen μ as they come) when valid, else `None`, whatever the reason (another layout, or a
/// bad one: the checked path sorts that out). The law is the one [`coulomb::law_from_entries`]
/// builds from the same entries (a test checks it), with fewer tests: the entries this layout
/// fixes are compared with their one accepted value. For the rate law's fast path in `fric_`.
#[inline(always)]
#[must_use]
pub(crate) fn fast_decay_lean(props: &[f64; COULOMB_EXTENDED_NPROPS]) -> Option<ExtendedCoulomb> {
    // PROPS(8) first: the other extended layouts (constant μ with HHT, damping, anisotropy,
    // the μ table) leave here with one test.
    if props[7] != 1.0 || careful_path_only() {
        return None;
    }
    // The rest of the layout's tests, from the schema: DECAY_LEAN over COULOMB, worked out at
    // compile time (the rules of other modes dropped, μ_s and d_c "> 0 with the decay law").
    if !admits_fixed::<coulomb::DecayLean, COULOMB_EXTENDED_NPROPS>(props) {
        return None;
    }
    let [
        _,
        mu,
        _,
        tau_max,
        gamma_crit,
        tolerance,
        _,
        _,
        mu_k,
        d_c,
        p_ref,
        b_theta,
        theta_ref,
        ..,
        frozen,
    ] = *props;
    // μ_k/μ_s must stay finite (a subnormal μ_s overflows it; the checked path refuses).
    let ratio = mu_k / mu;
    if ratio == f64::INFINITY {
        return None;
    }
    Some(
        ExtendedCoulomb::new(Coulomb::from_validated(
            mu,
            tau_max,
            gamma_crit,
            tolerance,
            StickMode::Elastic,
        ))
        .with_coefficient_law(CoefficientLaw::from_validated(
            Some((ratio, d_c)),
            p_ref,
            b_theta,
            theta_ref,
        ))
        .with_frozen_coefficient(frozen == 1.0),
    )
}

/// The whole law-1 layout (`PROPS(1..20)`, docs/props.md): the base entries, then anisotropy
/// (`PROPS(3)`), the μ law (`PROPS(8..13)`), HHT (`PROPS(14..16)`), damping (`PROPS(17..19)`)
/// and the frozen-μ switch (`PROPS(20)`). Returns the plain [`Coulomb`] when nothing beyond it
/// is switched on (the cheapest path).
pub fn coulomb_extended(props: &[f64]) -> Result<FrictionLaw, LawError> {
    coulomb_extended_with_table(props, None)
}

/// [`coulomb_extended`] with the μ table `PROPS(8) = 2` selects (the interaction's
/// `[interactions.NAME.friction]` of the configuration file, looked up by the caller); without
/// one, `PROPS(8) = 2` is refused. The schema's checked parser ([`COULOMB`]`.check`: classes,
/// rules, steady transport's variant, messages naming the entry) and the one builder
/// `law_from_entries` (src/props/coulomb.rs).
pub fn coulomb_extended_with_table(
    props: &[f64],
    table: Option<&'static FrictionTable>,
) -> Result<FrictionLaw, LawError> {
    let e = COULOMB.check::<COULOMB_EXTENDED_NPROPS>(props)?;
    Ok(coulomb::law_from_entries(&e, table)?)
}
