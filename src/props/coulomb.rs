//! `PROPS` layout of law 1, Coulomb friction, plain and extended (`PROPS(1) = 1`, seeds 000 and
//! 003, section 5.2.3), described once in [`COULOMB`]: the docs/props.md table,
//! [`CoulombBuilder`], the checked parser ([`COULOMB`]`.check`, whose messages name the entry),
//! the defaults (μ₂ = μ, HHT β(α) and γ(α) as the law's own functions, the slip tolerance) and
//! the validators of `fric_`'s fixed layouts, worked out at compile time: [`PLAIN`] and
//! [`DECAY_LEAN`], and [`EXTENDED_CONSTANT`], [`QUASI_STATIC`], [`EXTENDED_DECAY`] and
//! [`TRANSPORT`] behind the extended fast reader.
//!
//! The checked parser and the extended fast reader end in [`law_from_entries`], the one builder
//! of the law from validated entries; it holds only the refusals the layout cannot say
//! ([`Refusal`]: the decay law's μ_k/μ_s overflowing, the μ table where none is at hand) and
//! maps the stick mode and the μ law, which some fast plans leave to it (`Fix::MappedBy`). The
//! plain and decay-lean readers (src/props.rs) build their fixed layout's law directly.

use std::fmt;

use crate::laws::coulomb::{Coulomb, DEFAULT_SLIP_TOLERANCE, StickMode};
use crate::laws::coulomb_extended::{
    Damping, ExtendedCoulomb, Hht, SteadyTransport, ViscousSlipReference,
};
use crate::laws::friction_coefficient::CoefficientLaw;
use crate::laws::friction_table::FrictionTable;

use super::builder::{LawBuilder, entry_setters};
use super::schema::Default::{Derived, Described, Entry as SameAs, Required, Value};
use super::schema::{
    Class, Entry, FastLayout, Fix, Fixed, LawFn, Layout, Plan, PropsError, Rule, Variant,
};
use super::{COULOMB_EXTENDED_NPROPS, COULOMB_NPROPS, FrictionLaw, LAW_COULOMB};

/// `PROPS(7)`: the stick modes.
const STICK: Class = Class::Choice(&[
    (0, "elastic stick (penalty)"),
    (1, "exact stick (`LM = 1`)"),
    (2, "rough"),
    (3, "viscous stick for steady-state transport"),
    (
        4,
        "elastic stick with a constant stick stiffness k_s = `PROPS(5)`",
    ),
]);

/// `PROPS(8)`: the μ laws.
const MU_LAW: Class = Class::Choice(&[
    (0, "constant"),
    (1, "exponential decay μ = μ_k + (μ_s − μ_k)·exp(−d_c·γ̇_eq)"),
    (
        2,
        "table μ(γ̇_eq, p, θ̄) of the interaction (`CINAME`) from `INTERFACIAL_CONFIG`",
    ),
]);

/// `PROPS(7) = 3`, steady-state transport.
const VISCOUS: i32 = 3;

/// `PROPS(7) = 4`, elastic stick with a constant stick stiffness (`PROPS(5)`).
const CONSTANT_STICK: i32 = 4;

/// The whole law-1 layout: the plain entries `PROPS(1..7)`, then anisotropy (`PROPS(3)`), the
/// μ law (`PROPS(8..13)`), HHT (`PROPS(14..16)`, or steady transport's ω, axis and γ̇_crit
/// variant when `PROPS(7) = 3`), damping (`PROPS(17..19)`) and frozen μ (`PROPS(20)`).
#[rustfmt::skip]
pub const COULOMB: Layout = Layout {
    law: "Coulomb law",
    code: LAW_COULOMB,
    entries: &[
        Entry::law_code(LAW_COULOMB),
        Entry::new(2, "mu", "friction coefficient", Class::NonNegative)
            .symbol("μ").when_absent(Required),
        Entry::new(3, "mu2", "second-direction coefficient", Class::OffOrPositive)
            .symbol("μ₂").when_absent(SameAs(2))
            .note("anisotropy; μ = `PROPS(2)` is μ₁, which must then be > 0 unless μ₂ = μ₁"),
        Entry::new(4, "tau_max", "shear stress limit", Class::OffOrPositive)
            .symbol("τ_max").unit("stress").when_absent(Described("no limit"))
            .note("τ_crit = min(μp, τ_max)"),
        Entry::new(5, "gamma_crit", "allowable elastic slip", Class::OffOrPositive)
            .symbol("γ_crit").unit("length").when_absent(Described("`PROPS(6)` × `CHRLNGTH`"))
            .note("absolute; wins over `PROPS(6)`"),
        Entry::new(6, "slip_tolerance", "slip tolerance", Class::OffOrPositive)
            .when_absent(Value(DEFAULT_SLIP_TOLERANCE))
            .note("γ_crit = tolerance × `CHRLNGTH`; F_f of steady transport"),
        Entry::new(7, "stick", "stick mode", STICK),
        Entry::new(8, "mu_law", "μ law", MU_LAW)
            .note("decay: μ_s = `PROPS(2)`; table: see [config.md](config.md#friction-tables-interactionsnamefriction), \
                   `PROPS(2)` > 0 is then only the reference of the anisotropy ratio μ₂/μ₁ = `PROPS(3)`/`PROPS(2)`"),
        Entry::new(9, "mu_k", "kinetic coefficient (direction 1) of the decay law", Class::NonNegative)
            .symbol("μ_k").note("0 is a valid μ_k"),
        Entry::new(10, "decay", "decay coefficient", Class::OffOrPositive)
            .symbol("d_c").unit("time/length").when_absent(Described("— (required by the decay law)")),
        Entry::new(11, "p_ref", "reference pressure of μ", Class::OffOrPositive)
            .symbol("p_ref").unit("stress").when_absent(Described("none"))
            .note("μ ← μ/(1 + p/p_ref): μp saturates at μ·p_ref"),
        Entry::new(12, "b_theta", "temperature coefficient of μ", Class::Finite)
            .symbol("b_θ").unit("1/temperature").when_absent(Described("none (`TEMP` not read)"))
            .note("μ ← μ·exp(−b_θ(θ̄ − θ_ref)), θ̄ = (`TEMP(1)`+`TEMP(2)`)/2"),
        Entry::new(13, "theta_ref", "reference temperature of `PROPS(12)`", Class::Finite)
            .symbol("θ_ref").unit("temperature"),
        Entry::new(14, "hht_alpha", "HHT α", HHT_ALPHA)
            .symbol("α").when_absent(Described("static (Δt_rate = Δt)"))
            .note("dynamics: slip rates use Δt_rate = β·Δt/γ; HHT is on when any of `PROPS(14..16)` is non-zero"),
        Entry::new(15, "hht_beta", "HHT β", Class::OffOrPositive)
            .symbol("β").when_absent(Derived { of: 14, value: LawFn(Hht::default_beta), text: "(1 − α)²/4" }),
        Entry::new(16, "hht_gamma", "HHT γ", Class::OffOrPositive)
            .symbol("γ").when_absent(Derived { of: 14, value: LawFn(Hht::default_gamma), text: "1/2 − α" }),
        Entry::new(17, "damping", "tangential damping coefficient at zero overclosure", Class::OffOrPositive)
            .symbol("c₀").unit("stress·time/length").when_absent(Described("no damping"))
            .note("τ_v = c·γ̇ added to the friction stress"),
        Entry::new(18, "damping_clearance", "clearance at which the damping coefficient vanishes", Class::NonNegative)
            .symbol("g₀").unit("length"),
        Entry::new(19, "damping_fraction", "damping plateau fraction", FRACTION_BELOW_ONE)
            .symbol("f").note("c = c₀ over the fraction f of [0, g₀]"),
        Entry::new(20, "frozen", "slip rate of μ", FROZEN),
    ],
    rules: &[
        Rule::ZeroWhen { entry: 3, on: 2, value: 0,
            why: "no friction in direction 1: anisotropy needs μ₁ > 0" },
        Rule::ZeroWhen { entry: 5, on: 7, value: VISCOUS,
            why: "viscous stick uses the slip tolerance F_f = PROPS(6), not γ_crit" },
        Rule::PositiveWhen { entry: 2, on: 8, value: 1, why: "the exponential decay law" },
        Rule::PositiveWhen { entry: 2, on: 8, value: 2, why: "the reference of a μ table" },
        Rule::ZeroWhen { entry: 9, on: 8, value: 0, why: "constant μ" },
        Rule::ZeroWhen { entry: 9, on: 8, value: 2, why: "the μ table carries the rate dependence" },
        Rule::ZeroWhen { entry: 10, on: 8, value: 0, why: "constant μ" },
        Rule::PositiveWhen { entry: 10, on: 8, value: 1, why: "the exponential decay law" },
        Rule::ZeroWhen { entry: 10, on: 8, value: 2, why: "the μ table carries the rate dependence" },
        Rule::ZeroWhen { entry: 11, on: 8, value: 2, why: "the μ table carries the pressure dependence" },
        Rule::ZeroWhen { entry: 12, on: 8, value: 2, why: "the μ table carries the temperature dependence" },
        Rule::ZeroWhen { entry: 13, on: 8, value: 2, why: "the μ table carries the temperature dependence" },
        Rule::ZeroWhen { entry: 13, on: 12, value: 0, why: "no temperature law" },
        Rule::ZeroWhen { entry: 18, on: 17, value: 0, why: "no damping" },
        Rule::ZeroWhen { entry: 19, on: 17, value: 0, why: "no damping" },
        Rule::ZeroWhen { entry: 20, on: 8, value: 0, why: "μ does not depend on the slip rate" },
    ],
    variants: &[STEADY_TRANSPORT, STICK_STIFFNESS],
};

/// Elastic stick with a constant stick stiffness (`PROPS(7) = 4`): `PROPS(5)` is k_s instead
/// of γ_crit (CalculiX's `*FRICTION` stick slope λ, stress per length); the plain law only.
#[rustfmt::skip]
pub const STICK_STIFFNESS: Variant = Variant {
    name: "constant stick stiffness",
    on: 7,
    value: CONSTANT_STICK,
    entries: &[
        Entry::new(5, "stick_stiffness", "constant stick stiffness", Class::Positive)
            .symbol("k_s").unit("stress/length").when_absent(Described("— (required)"))
            .note("τ = τ̄ + k_s·Δγ in stick, CalculiX's stick slope λ; the plain law: `PROPS(3)` 0 or μ, `PROPS(8..20)` 0"),
    ],
};

/// `PROPS(14)`: HHT α.
const HHT_ALPHA: Class = Class::Interval {
    lo: -0.5,
    hi: 0.0,
    open_hi: false,
};

/// `PROPS(19)`: [0, 1).
const FRACTION_BELOW_ONE: Class = Class::Interval {
    lo: 0.0,
    hi: 1.0,
    open_hi: true,
};

/// `PROPS(20)`.
const FROZEN: Class = Class::Switch {
    off: "end-of-increment rate (implicit)",
    on: "frozen at its start-of-increment rate (`STATEV(2)`), explicit in the rate; needs a rate law",
};

/// Steady-state transport (`PROPS(7) = 3`, seed 000): `PROPS(14..16)` are ω, the spinning axis
/// and the allowable viscous slip rate's variant instead of HHT (off then).
#[rustfmt::skip]
pub const STEADY_TRANSPORT: Variant = Variant {
    name: "steady-state transport",
    on: 7,
    value: VISCOUS,
    entries: &[
        Entry::new(14, "omega", "angular spinning velocity of steady-state transport", Class::Positive)
            .symbol("ω").unit("1/time").when_absent(Described("— (required)"))
            .note("HHT is then off"),
        Entry::new(15, "axis", "spinning axis through the origin", AXIS)
            .when_absent(Described("3 (z)")),
        Entry::new(16, "viscous_reference", "allowable viscous slip rate", VISCOUS_REFERENCE),
    ],
};

/// `PROPS(15)` under steady transport.
const AXIS: Class = Class::Choice(&[(0, "z (the default)"), (1, "x"), (2, "y"), (3, "z")]);

/// `PROPS(16)` under steady transport.
const VISCOUS_REFERENCE: Class = Class::Switch {
    off: "γ̇_crit = 2·F_f·ω·R (seed 000)",
    on: "γ̇_crit = F_f·ω·R (seed 003, \"a fraction of the relative tangential velocity\")",
};

/// `fric_`'s plain layout, the hot path: `NPROPS = 7`, isotropic (μ₂ absent or equal to μ),
/// the stick mode 0, 1 or 2 (tested by [`fast_plain_coulomb`](super::fast_plain_coulomb)'s
/// match that maps it); constant μ, as `PROPS(8..20)` are absent.
pub const PLAIN: Fixed = Fixed {
    name: "plain Coulomb (NPROPS = 7)",
    fixed: &[(3, Fix::ZeroOrEqual(2)), (7, Fix::MappedBy(&[0, 1, 2]))],
};

/// The validator of [`PLAIN`], worked out when the crate compiles.
pub(crate) struct Plain;

impl FastLayout for Plain {
    const PLAN: Plan = Plan::of(&COULOMB, &PLAIN, COULOMB_NPROPS);
}

/// `PROPS(14..19)` pinned to ±0: no HHT (nor steady transport's ω) and no damping.
const NO_HHT_OR_DAMPING: [(usize, Fix); 6] = [
    (14, Fix::Zero),
    (15, Fix::Zero),
    (16, Fix::Zero),
    (17, Fix::Zero),
    (18, Fix::Zero),
    (19, Fix::Zero),
];

/// The decay law's lean layout, the rate law's fast path in `fric_`: `NPROPS = 20`,
/// isotropic, elastic stick, exponential decay, `PROPS(14..19)` all ±0 (no HHT, damping or
/// steady transport); τ_max, p_ref, b_θ, θ_ref and frozen μ as they come.
pub const DECAY_LEAN: Fixed = Fixed {
    name: "decay law, lean (NPROPS = 20)",
    fixed: &Fixed::joined::<9>(
        &[(3, Fix::ZeroOrEqual(2)), (7, Fix::Is(0)), (8, Fix::Is(1))],
        &NO_HHT_OR_DAMPING,
    ),
};

/// The validator of [`DECAY_LEAN`], worked out when the crate compiles.
pub(crate) struct DecayLean;

impl FastLayout for DecayLean {
    const PLAN: Plan = Plan::of(&COULOMB, &DECAY_LEAN, COULOMB_EXTENDED_NPROPS);
}

/// The extended fast reader's layout for the frictional stick modes with constant μ: any
/// valid law-1 layout with `PROPS(7)` 0, 1 or 2 (mapped by `law_from_entries`'s match) and
/// `PROPS(8) = 0`, so that the rules of the μ law turn into tests of single entries (μ_k, d_c
/// and frozen μ 0). [`QUASI_STATIC`] when `PROPS(14..19)` are all 0.
pub const EXTENDED_CONSTANT: Fixed = Fixed {
    name: "extended, frictional stick, constant μ (NPROPS ≤ 20)",
    fixed: &[(7, Fix::MappedBy(&[0, 1, 2])), (8, Fix::Is(0))],
};

/// [`EXTENDED_CONSTANT`] without HHT and damping (`PROPS(14..19)` ±0: anisotropy, τ_max, the
/// pressure and temperature factors as they come), so that their entries are one test of their
/// bits and their rules drop out.
pub const QUASI_STATIC: Fixed = Fixed {
    name: "extended, frictional stick, constant μ, no HHT or damping (NPROPS ≤ 20)",
    fixed: &Fixed::joined::<8>(EXTENDED_CONSTANT.fixed, &NO_HHT_OR_DAMPING),
};

/// The validator of [`QUASI_STATIC`], worked out when the crate compiles.
pub(crate) struct QuasiStatic;

impl FastLayout for QuasiStatic {
    const PLAN: Plan = Plan::of(&COULOMB, &QUASI_STATIC, COULOMB_EXTENDED_NPROPS);
}

/// The validator of [`EXTENDED_CONSTANT`], worked out when the crate compiles.
pub(crate) struct ExtendedConstant;

impl FastLayout for ExtendedConstant {
    const PLAN: Plan = Plan::of(&COULOMB, &EXTENDED_CONSTANT, COULOMB_EXTENDED_NPROPS);
}

/// [`EXTENDED_CONSTANT`] with the exponential decay law, `PROPS(8) = 1` (μ_s and d_c > 0).
/// The μ table, `PROPS(8) = 2`, has no fast plan: it needs the interaction's table, which
/// the fast path does not have (the checked path reads it).
pub const EXTENDED_DECAY: Fixed = Fixed {
    name: "extended, frictional stick, decay law (NPROPS ≤ 20)",
    fixed: &[(7, Fix::MappedBy(&[0, 1, 2])), (8, Fix::Is(1))],
};

/// The validator of [`EXTENDED_DECAY`], worked out when the crate compiles.
pub(crate) struct ExtendedDecay;

impl FastLayout for ExtendedDecay {
    const PLAN: Plan = Plan::of(&COULOMB, &EXTENDED_DECAY, COULOMB_EXTENDED_NPROPS);
}

/// The extended fast reader's layout for steady-state transport: `PROPS(7) = 3`, which
/// selects [`STEADY_TRANSPORT`]'s meaning of `PROPS(14..16)`, `PROPS(8)` 0 or 1 (mapped by
/// `law_from_entries`'s match; one plan for both, steady transport being rarer).
pub const TRANSPORT: Fixed = Fixed {
    name: "steady-state transport (NPROPS ≤ 20)",
    fixed: &[(7, Fix::Is(VISCOUS)), (8, Fix::MappedBy(&[0, 1]))],
};

/// The validator of [`TRANSPORT`], worked out when the crate compiles.
pub(crate) struct Transport;

impl FastLayout for Transport {
    const PLAN: Plan = Plan::of(&COULOMB, &TRANSPORT, COULOMB_EXTENDED_NPROPS);
}

/// Whether law-1 `PROPS` select the interaction's μ table (`PROPS(8)`, the μ law, = 2): the
/// one law-1 setting that needs something beyond `PROPS` (a table looked up by `CINAME` in the
/// configuration file). Said of law 1 only: the caller has matched `PROPS(1)` first.
pub(crate) fn selects_mu_table(props: &[f64]) -> bool {
    props.get(7) == Some(&2.0)
}

/// The law of valid law-1 entries (`e[i - 1] = PROPS(i)`, absent ones 0): those
/// [`COULOMB`]`.check` returns, or those a fast plan admitted (which leaves `PROPS(7)` and
/// `PROPS(8)` to the matches here). The one builder of every law-1 reader but the plain and
/// decay-lean ones, which build their fixed layout's law directly. Refuses, naming the entry,
/// only what the layout cannot say ([`Refusal`]); `table` is the interaction's μ table for
/// `PROPS(8) = 2` (`fric_`, `fric_coef_`). The plain [`Coulomb`] when nothing beyond it is on.
pub(crate) fn law_from_entries(
    e: &[f64; COULOMB_EXTENDED_NPROPS],
    table: Option<&'static FrictionTable>,
) -> Result<FrictionLaw, PropsError> {
    let law = if e[6] == f64::from(CONSTANT_STICK) {
        constant_stick_law(e)
    } else {
        build(e, table)
    };
    law.map_err(|no| match no {
        NoLaw::OutOfClass(index) => PropsError::out_of_class(&COULOMB, e, index),
        NoLaw::Refused(refusal) => refusal.into_props_error(),
    })
}

/// [`law_from_entries`] for the extended fast reader: the extended law of entries a fast plan
/// admitted, else `None` (the plain law, the μ table, a refusal: the other paths say which).
#[inline(always)]
pub(crate) fn extended_from_entries(e: &[f64; COULOMB_EXTENDED_NPROPS]) -> Option<ExtendedCoulomb> {
    match build(e, None) {
        Ok(FrictionLaw::CoulombExtended(law)) => Some(law),
        _ => None,
    }
}

/// [`law_from_entries`] for a fast reader without a μ table: the law, or `None` (the checked
/// path then says why).
#[inline(always)]
pub(crate) fn fast_law_from_entries(e: &[f64; COULOMB_EXTENDED_NPROPS]) -> Option<FrictionLaw> {
    build(e, None).ok()
}

/// What a law's builder refuses in entries the layout admits: conditions that need more than
/// one entry's class or a rule between two entries, or more than the `PROPS` array.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Refusal {
    /// Law 1's decay law: μ_k/μ_s = `PROPS(9)`/`PROPS(2)` overflows (μ_s too small), both
    /// entries valid on their own.
    KineticRatioOverflows {
        /// μ_k = `PROPS(9)`.
        mu_k: f64,
        /// μ_s = `PROPS(2)`.
        mu_s: f64,
    },
    /// Law 1's `PROPS(8) = 2` where no μ table is at hand: only `fric_` and `fric_coef_` look
    /// the interaction's table up.
    NoTable,
    /// Law 1's constant stick stiffness (`PROPS(7) = 4`) with anisotropy or any of
    /// `PROPS(8..20)`: the plain law only.
    StickStiffnessPlainOnly,
}

impl Refusal {
    /// The refusal as the schema's error of law 1's layout.
    #[cold]
    #[inline(never)]
    #[must_use]
    pub fn into_props_error(self) -> PropsError {
        PropsError::refused(&COULOMB, self.index(), self.to_string())
    }

    /// The `PROPS` index the refusal is said of.
    #[must_use]
    pub const fn index(self) -> usize {
        match self {
            Refusal::KineticRatioOverflows { .. } => 9,
            Refusal::NoTable => 8,
            Refusal::StickStiffnessPlainOnly => 7,
        }
    }
}

impl fmt::Display for Refusal {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Refusal::KineticRatioOverflows { mu_k, mu_s } => write!(
                f,
                "PROPS(9) = μ_k = {mu_k} over PROPS(2) = μ_s = {mu_s:e}: μ_k/μ_s = {} \
                 overflows; μ_s is too small for the decay law",
                mu_k / mu_s
            ),
            Refusal::NoTable => write!(
                f,
                "PROPS(8) = 2 (μ table from INTERFACIAL_CONFIG) is read by fric_ and fric_coef_ \
                 only, which look the table up by interaction name"
            ),
            Refusal::StickStiffnessPlainOnly => write!(
                f,
                "PROPS(7) = 4 (constant stick stiffness) is the plain isotropic law with constant \
                 μ: PROPS(3) must be 0 or μ and PROPS(8..20) 0"
            ),
        }
    }
}

/// Why [`build`] gives no law: small and `Copy`, so that a fast reader's `None` costs nothing;
/// [`law_from_entries`] makes it a [`PropsError`].
#[derive(Clone, Copy)]
enum NoLaw {
    /// `PROPS(index)`, left to the builder's match, is none of its values.
    OutOfClass(usize),
    /// What the layout cannot say.
    Refused(Refusal),
}

/// The body of [`law_from_entries`].
#[inline(always)]
fn build(
    e: &[f64; COULOMB_EXTENDED_NPROPS],
    table: Option<&'static FrictionTable>,
) -> Result<FrictionLaw, NoLaw> {
    let viscous = e[6] == f64::from(VISCOUS);
    let stick = match e[6] {
        0.0 | 3.0 => StickMode::Elastic,
        1.0 => StickMode::Exact,
        2.0 => StickMode::Rough,
        // PROPS(7) = 4 is built by `law_from_entries` alone (`constant_stick_law`): the fast
        // readers decline it here and the checked path answers.
        _ => return Err(NoLaw::OutOfClass(7)),
    };
    let mu = e[1];
    let base = Coulomb::from_validated(mu, e[3], e[4], e[5], stick);
    let mu2 = COULOMB.resolved(e, 3);
    // PROPS(8..20) all ±0 in one test of their bits.
    let rest_off = e[7..].iter().fold(0, |bits, v| bits | v.to_bits()) << 1 == 0;
    if !viscous && mu2 == mu && rest_off {
        return Ok(FrictionLaw::Coulomb(base));
    }
    let coefficient = match e[7] {
        0.0 => CoefficientLaw::from_validated(None, e[10], e[11], e[12]),
        1.0 => {
            // μ_k/μ_s must stay finite (a subnormal μ_s overflows it).
            let (mu_k, decay) = (e[8], e[9]);
            let ratio = mu_k / mu;
            if ratio == f64::INFINITY {
                return Err(NoLaw::Refused(Refusal::KineticRatioOverflows {
                    mu_k,
                    mu_s: mu,
                }));
            }
            CoefficientLaw::from_validated(Some((ratio, decay)), e[10], e[11], e[12])
        }
        2.0 => match table {
            Some(table) => CoefficientLaw::table_from_validated(table, mu),
            None => return Err(NoLaw::Refused(Refusal::NoTable)),
        },
        _ => return Err(NoLaw::OutOfClass(8)),
    };
    let hht = if !viscous && (e[13] != 0.0 || e[14] != 0.0 || e[15] != 0.0) {
        Some(Hht {
            alpha: e[13],
            beta: COULOMB.resolved(e, 15),
            gamma: COULOMB.resolved(e, 16),
        })
    } else {
        None
    };
    let damping = (e[16] != 0.0).then_some(Damping {
        c0: e[16],
        clearance: e[17],
        fraction: e[18],
    });
    let transport = viscous.then(|| SteadyTransport {
        // F_f: PROPS(6) or its default (γ_crit is not read then, a rule of the layout).
        tolerance: COULOMB.resolved(e, 6),
        omega: e[13],
        axis: match e[14] {
            1.0 => 0,
            2.0 => 1,
            _ => 2,
        },
        reference: if e[15] == 1.0 {
            ViscousSlipReference::RelativeVelocity
        } else {
            ViscousSlipReference::Circumferential
        },
    });
    Ok(FrictionLaw::CoulombExtended(
        ExtendedCoulomb::new(base)
            .with_validated_mu2(mu2)
            .with_coefficient_law(coefficient)
            .with_frozen_coefficient(e[19] == 1.0)
            .with_hht(hht)
            .with_damping(damping)
            .with_steady_transport(transport),
    ))
}

/// The law of valid entries with `PROPS(7) = 4`: the plain law with the constant stick
/// stiffness k_s = `PROPS(5)`, refused with anisotropy or any of `PROPS(8..20)`. Only
/// [`law_from_entries`] (the checked path) builds it, [`build`] declines it: so the fast readers
/// of the other stick modes do not pay for it (docs/performance.md's counts).
#[cold]
#[inline(never)]
fn constant_stick_law(e: &[f64; COULOMB_EXTENDED_NPROPS]) -> Result<FrictionLaw, NoLaw> {
    let mu = e[1];
    // k_s = PROPS(5) (a fast plan may have admitted it as γ_crit, which may be 0).
    let base = Coulomb::from_validated(mu, e[3], 0.0, e[5], StickMode::Elastic)
        .with_stick_stiffness(e[4])
        .map_err(|_| NoLaw::OutOfClass(5))?;
    let rest_off = e[7..].iter().fold(0, |bits, v| bits | v.to_bits()) << 1 == 0;
    if COULOMB.resolved(e, 3) != mu || !rest_off {
        return Err(NoLaw::Refused(Refusal::StickStiffnessPlainOnly));
    }
    Ok(FrictionLaw::Coulomb(base))
}

/// A law-1 `PROPS` array built by entry name (tests, scenes, fuzz decoders): every entry
/// starts at its "0 / absent" value, `PROPS(1) = 1`.
pub type CoulombBuilder = LawBuilder<LAW_COULOMB>;

impl CoulombBuilder {
    entry_setters!("law 1", {
        mu => "mu",
        mu2 => "mu2",
        tau_max => "tau_max",
        gamma_crit => "gamma_crit",
        stick_stiffness => "stick_stiffness",
        slip_tolerance => "slip_tolerance",
        stick => "stick",
        mu_law => "mu_law",
        mu_k => "mu_k",
        decay => "decay",
        p_ref => "p_ref",
        b_theta => "b_theta",
        theta_ref => "theta_ref",
        hht_alpha => "hht_alpha",
        hht_beta => "hht_beta",
        hht_gamma => "hht_gamma",
        omega => "omega",
        axis => "axis",
        viscous_reference => "viscous_reference",
        damping => "damping",
        damping_clearance => "damping_clearance",
        damping_fraction => "damping_fraction",
        frozen => "frozen",
    });
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use crate::props::coulomb_extended;
    use crate::props::schema::{Cause, FastLayout, Plan};
    use proptest::prelude::*;
    use proptest::test_runner::TestCaseError;

    /// `PROPS` values around the classes' edges, mostly 0 so that many arrays are valid (also
    /// the extended fast reader's agreement tests, src/props.rs).
    pub(in crate::props) fn entry() -> impl Strategy<Value = f64> {
        prop_oneof![
            8 => Just(0.0),
            1 => Just(-0.0),
            2 => Just(1.0),
            1 => Just(2.0),
            1 => Just(3.0),
            1 => Just(4.0),
            1 => Just(0.5),
            1 => Just(-0.5),
            1 => Just(-0.2),
            1 => Just(-1.0),
            1 => Just(f64::NAN),
            1 => Just(f64::INFINITY),
            1 => Just(f64::NEG_INFINITY),
            1 => 0.0..3.0f64,
        ]
    }

    /// What the builder refuses beyond the layout ([`Refusal`]: the law's own conditions, not
    /// a single entry's class or a rule between two entries), written out here: the μ table
    /// (`PROPS(8) = 2`) needs the interaction's table, which only `fric_` and `fric_coef_`
    /// look up (never passed here); and the decay law's ratio μ_k/μ_s must be finite (both
    /// entries valid, their ratio overflowing).
    fn refused_beyond_the_layout(e: &[f64; COULOMB_EXTENDED_NPROPS]) -> Option<Refusal> {
        // The constant stick stiffness (PROPS(7) = 4) is the plain law only: μ₂ absent (0) or
        // μ, and PROPS(8..20) all ±0; decided before the μ law's own refusals.
        if e[6] == 4.0 {
            let isotropic = e[2] == 0.0 || e[2] == e[1];
            let rest_off = e[7..].iter().all(|v| *v == 0.0);
            return (!isotropic || !rest_off).then_some(Refusal::StickStiffnessPlainOnly);
        }
        match e[7] {
            2.0 => Some(Refusal::NoTable),
            1.0 if !(e[8] / e[1]).is_finite() => Some(Refusal::KineticRatioOverflows {
                mu_k: e[8],
                mu_s: e[1],
            }),
            _ => None,
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 20000, failure_persistence: None, ..ProptestConfig::default() })]

        /// The checked parser `coulomb_extended` (the schema's check, then the builder) refuses
        /// what the schema refuses, with the schema's message, and of what the schema accepts
        /// exactly [`refused_beyond_the_layout`], with that typed cause (0 to 22 entries).
        #[test]
        fn schema_and_checked_parser_accept_the_same_arrays(
            mut props in prop::collection::vec(entry(), 0..23),
            live in prop::collection::vec(0usize..20, 0..4),
            stick in prop::sample::select(vec![0.0, 0.0, 1.0, 2.0, 3.0, 3.0]),
            mu_law in prop::sample::select(vec![0.0, 0.0, 1.0, 1.0, 2.0]),
        ) {
            // Most entries 0 but a few live ones, and the mode switches mostly valid, so that
            // both outcomes are common.
            for (i, v) in props.iter_mut().enumerate() {
                if i >= 2 && !live.contains(&i) && i != 6 && i != 7 {
                    *v = 0.0;
                }
            }
            if let Some(v) = props.first_mut() {
                *v = 1.0;
            }
            if props.len() > 6 && !live.contains(&6) {
                props[6] = stick;
            }
            if props.len() > 7 && !live.contains(&7) {
                props[7] = mu_law;
            }
            let parsed = coulomb_extended(&props);
            let checked = COULOMB.check::<COULOMB_EXTENDED_NPROPS>(&props);
            match (&parsed, checked) {
                (Ok(law), Ok(e)) => prop_assert!(
                    refused_beyond_the_layout(&e).is_none(),
                    "{props:?}: {law:?}"
                ),
                (Err(m), Err(e)) => prop_assert_eq!(m, &crate::LawError::from(e)),
                (Ok(law), Err(e)) => prop_assert!(false, "{props:?}: parser {law:?}, schema {e}"),
                (Err(m), Ok(e)) => {
                    let Some(refusal) = refused_beyond_the_layout(&e) else {
                        return Err(TestCaseError::fail(format!("{props:?}: {m}, schema accepts")));
                    };
                    let typed = law_from_entries(&e, None).unwrap_err();
                    let expected = refusal.into_props_error();
                    prop_assert_eq!(typed.cause(), expected.cause());
                    prop_assert_eq!(typed.index(), Some(refusal.index()));
                    prop_assert_eq!(m, &crate::LawError::from(typed));
                }
            }
        }
    }

    /// The classes' edges, one entry at a time on a valid base: the checked parser refuses
    /// exactly what the schema refuses and [`refused_beyond_the_layout`].
    #[test]
    fn edges_agree_entry_by_entry() {
        let edges = [
            0.0,
            -0.0,
            1e-300,
            -1e-300,
            0.5,
            -0.5,
            -0.5000001,
            0.9999999,
            1.0,
            2.0,
            3.0,
            4.0,
            -1.0,
            f64::MAX,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
        ];
        let bases = [
            CoulombBuilder::new().mu(0.3).build(),
            CoulombBuilder::new()
                .mu(0.3)
                .mu_law(1.0)
                .mu_k(0.1)
                .decay(2.0)
                .damping(1.0)
                .build(),
            CoulombBuilder::new().mu(0.3).stick(3.0).omega(10.0).build(),
            CoulombBuilder::new()
                .mu(0.3)
                .b_theta(0.01)
                .hht_alpha(-0.1)
                .build(),
        ];
        let (mut refused, mut accepted) = (0, 0);
        for base in &bases {
            assert!(
                COULOMB.check::<COULOMB_EXTENDED_NPROPS>(base).is_ok(),
                "{base:?}"
            );
            for i in 1..COULOMB_EXTENDED_NPROPS {
                for v in edges {
                    let mut props = base.clone();
                    props[i] = v;
                    let old = coulomb_extended(&props);
                    let new = COULOMB.check::<COULOMB_EXTENDED_NPROPS>(&props);
                    let beyond = new
                        .as_ref()
                        .is_ok_and(|e| refused_beyond_the_layout(e).is_some());
                    assert_eq!(
                        old.is_ok(),
                        new.is_ok() && !beyond,
                        "{props:?}: {old:?} / {new:?}"
                    );
                    refused += usize::from(new.is_err());
                    accepted += usize::from(old.is_ok());
                }
            }
        }
        // The sweep reaches both answers (it is not comparing two "yes" or two "no").
        assert!(refused > 100 && accepted > 100, "{refused} {accepted}");
    }

    /// The entries' positions are those of docs/props.md's law-1 table, written out by hand
    /// here; distinct values catch a setter wired to a neighbour.
    #[test]
    fn builder_setters_reach_their_entries() {
        let props = CoulombBuilder::new()
            .mu(0.3)
            .mu2(0.4)
            .tau_max(5.0)
            .gamma_crit(1e-3)
            .slip_tolerance(0.02)
            .stick(1.0)
            .mu_law(1.0)
            .mu_k(0.1)
            .decay(7.0)
            .p_ref(8.0)
            .b_theta(0.009)
            .theta_ref(300.0)
            .hht_alpha(-0.1)
            .hht_beta(0.3)
            .hht_gamma(0.6)
            .damping(11.0)
            .damping_clearance(0.12)
            .damping_fraction(0.13)
            .frozen(1.0)
            .build();
        let by_hand = [
            1.0, 0.3, 0.4, 5.0, 1e-3, 0.02, 1.0, 1.0, 0.1, 7.0, 8.0, 0.009, 300.0, -0.1, 0.3, 0.6,
            11.0, 0.12, 0.13, 1.0,
        ];
        assert_eq!(props, by_hand);
        assert!(matches!(
            coulomb_extended(&props),
            Ok(FrictionLaw::CoulombExtended(_))
        ));
        let viscous = CoulombBuilder::new()
            .mu(0.3)
            .stick(3.0)
            .omega(14.0)
            .axis(1.0)
            .viscous_reference(1.0)
            .build_first(16);
        assert_eq!(
            viscous,
            [
                1.0, 0.3, 0.0, 0.0, 0.0, 0.0, 3.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 14.0, 1.0, 1.0
            ]
        );
        assert!(coulomb_extended(&viscous).is_ok());
        assert_eq!(CoulombBuilder::new().mu(0.3).build_first(2), [1.0, 0.3]);
    }

    /// The table is well formed (`Layout::assert_well_formed`: entries, rules, variants), with
    /// two required entries and twenty in all.
    #[test]
    fn the_schema_is_consistent() {
        COULOMB.assert_well_formed();
        assert_eq!(COULOMB.required_len(), 2);
        assert_eq!(COULOMB.entries.len(), 20);
    }

    /// Each law-1 default is written once and every reader takes it from there: the HHT β(α)
    /// and γ(α) (`Hht::default_beta` / `default_gamma`, named by the schema), μ₂ = μ and the
    /// slip tolerance, through the extended fast reader, the checked parser and the law
    /// constructors, against the closed forms written out here. Changing the default in any
    /// one place fails this test: the schema's entry, the builder (`law_from_entries`, which
    /// both readers end in), the law's function (the closed form) or `Hht::new`.
    #[test]
    fn the_defaults_are_said_once() {
        use crate::laws::coulomb::{Coulomb, CriticalSlip};
        use crate::laws::coulomb_extended::ExtendedCoulomb;
        use crate::props::fast_extended_friction_law;
        for alpha in [-0.5f64, -0.3, -0.1, -1e-300, -0.0, 0.0] {
            // The closed forms of Abaqus's HHT relations.
            let (beta, gamma) = (0.25 * (1.0 - alpha).powi(2), 0.5 - alpha);
            let hht = Hht::new(alpha, 0.0, 0.0).unwrap();
            assert_eq!((hht.alpha, hht.beta, hht.gamma), (alpha, beta, gamma));
            let props = CoulombBuilder::new()
                .mu(0.3)
                .hht_alpha(alpha)
                .damping(if alpha == 0.0 { 1.0 } else { 0.0 })
                .build();
            assert_eq!(COULOMB.resolved_in(&props, 15), beta);
            assert_eq!(COULOMB.resolved_in(&props, 16), gamma);
            let by_hand = ExtendedCoulomb::new(Coulomb::new(0.3).unwrap());
            let by_hand = if alpha == 0.0 {
                // α = ±0 with β = γ = 0: HHT is off; damping makes the law extended.
                by_hand.with_damping(Some(Damping::new(1.0, 0.0, 0.0).unwrap()))
            } else {
                by_hand.with_hht(Some(Hht { alpha, beta, gamma }))
            };
            let expected = Some(FrictionLaw::CoulombExtended(by_hand));
            assert_eq!(fast_extended_friction_law(&props), expected, "α = {alpha}");
            assert_eq!(coulomb_extended(&props).ok(), expected, "α = {alpha}");
        }
        // μ₂ absent is μ₂ = μ (isotropic), with any extended entry on.
        let props = CoulombBuilder::new().mu(0.3).hht_alpha(-0.1).build();
        assert_eq!(COULOMB.resolved_in(&props, 3), 0.3);
        for law in [
            fast_extended_friction_law(&props),
            coulomb_extended(&props).ok(),
        ] {
            let Some(FrictionLaw::CoulombExtended(law)) = law else {
                panic!("{law:?}")
            };
            assert_eq!(law.mu2(), 0.3);
        }
        // The slip tolerance 0.005 (seed 000, "0.5%"): the schema, the constructor, the plain
        // and the steady-transport readers.
        let props = CoulombBuilder::new().mu(0.3).build_first(7);
        assert_eq!(COULOMB.resolved_in(&props, 6), 0.005);
        assert_eq!(
            Coulomb::new(0.3).unwrap().critical_slip(),
            CriticalSlip::Tolerance(0.005)
        );
        assert_eq!(
            crate::props::fast_plain_coulomb(&props).map(|c| c.critical_slip()),
            Some(CriticalSlip::Tolerance(0.005))
        );
        let props = CoulombBuilder::new().mu(0.3).stick(3.0).omega(2.0).build();
        for law in [
            fast_extended_friction_law(&props),
            coulomb_extended(&props).ok(),
        ] {
            let Some(FrictionLaw::CoulombExtended(law)) = law else {
                panic!("{law:?}")
            };
            assert_eq!(law.steady_transport().map(|t| t.tolerance), Some(0.005));
        }
    }

    /// The fast validators' plans drop at compile time every rule their fixed layout
    /// satisfies: none is left for the plain layout (anisotropy's "μ₂ = 0 when μ = 0" holds for
    /// μ₂ = 0 or μ), only "θ_ref needs b_θ" (the one rule between two free entries) for the
    /// decay law's lean layout; the extended reader's plans keep the rules of the modes they
    /// leave open (anisotropy, the temperature law, damping; the μ law under steady transport)
    /// and drop those their pins rule out or turn into single-entry tests (the μ table; μ_k, d_c
    /// and frozen μ 0 with constant μ; μ_s, d_c > 0 with the decay law; γ_crit 0 under steady
    /// transport; damping's with PROPS(17..19) pinned to 0).
    #[test]
    fn the_plans_keep_only_the_rules_that_can_fail() {
        let live = |plan: Plan| -> Vec<(usize, usize)> {
            plan.live_rules()
                .iter()
                .map(|r| (r.entry(), r.other()))
                .collect()
        };
        // Anisotropy, θ_ref needs b_θ, damping's g₀ and f need c₀.
        let free = [(3, 2), (13, 12), (18, 17), (19, 17)];
        assert_eq!(live(ExtendedConstant::PLAN), free);
        assert_eq!(live(ExtendedDecay::PLAN), free);
        assert_eq!(live(QuasiStatic::PLAN), free[..2]);
        // Steady transport leaves the μ law open (0 or 1): its five rules stay.
        assert_eq!(
            live(Transport::PLAN),
            [
                (3, 2),
                (2, 8),
                (9, 8),
                (10, 8),
                (10, 8),
                (13, 12),
                (18, 17),
                (19, 17),
                (20, 8)
            ]
        );
        // No plan tests a rule of the μ table.
        for plan in [
            ExtendedConstant::PLAN,
            ExtendedDecay::PLAN,
            QuasiStatic::PLAN,
            Transport::PLAN,
        ] {
            assert!(plan.live_rules().iter().all(|r| !matches!(
                r,
                Rule::ZeroWhen {
                    on: 8,
                    value: 2,
                    ..
                } | Rule::PositiveWhen {
                    on: 8,
                    value: 2,
                    ..
                }
            )));
        }
        assert!(Plain::PLAN.live_rules().is_empty());
        assert_eq!(
            DecayLean::PLAN.live_rules(),
            [&Rule::ZeroWhen {
                entry: 13,
                on: 12,
                value: 0,
                why: "no temperature law"
            }]
        );
        // A fixed layout that leaves steady transport (PROPS(7) = 3) possible has no plan:
        // the variant's entries mean something else.
        let open = Fixed {
            name: "open",
            fixed: &[(3, Fix::ZeroOrEqual(2))],
        };
        assert!(std::panic::catch_unwind(|| Plan::of(&COULOMB, &open, 7)).is_err());
        // Nor one pinning an entry past its NPROPS.
        assert!(std::panic::catch_unwind(|| Plan::of(&COULOMB, &DECAY_LEAN, 7)).is_err());
    }

    /// A plan whose pin selects a variant tests the variant's entries: [`TRANSPORT`] reads
    /// `PROPS(14..16)` as ω (> 0), the axis (0 to 3) and the γ̇_crit variant (0 or 1), not HHT;
    /// [`EXTENDED_CONSTANT`] as HHT's α, β and γ. The same arrays through the fast reader and the
    /// checked parser.
    #[test]
    fn the_transport_plan_takes_the_variants_entries() {
        assert_eq!(Transport::PLAN.class_of(14), Class::Positive);
        assert_eq!(
            Transport::PLAN.class_of(15),
            STEADY_TRANSPORT.entries[1].class
        );
        assert_eq!(
            Transport::PLAN.class_of(16),
            STEADY_TRANSPORT.entries[2].class
        );
        for index in 14..=16 {
            assert_eq!(
                ExtendedConstant::PLAN.class_of(index),
                COULOMB.entry(index).class
            );
        }
        let spinning = |omega: f64, axis: f64, reference: f64| {
            CoulombBuilder::new()
                .mu(0.3)
                .stick(3.0)
                .omega(omega)
                .axis(axis)
                .viscous_reference(reference)
                .build()
        };
        // ω = 2 is no HHT α, axis 3 no HHT β; ω = 0, axis 4 and variant 2 are refused.
        let props = spinning(2.0, 3.0, 1.0);
        let fast = crate::props::fast_extended_coulomb(&props);
        // Built by hand: no HHT, the transport of ω = 2 about z (axis 3), seed 003's γ̇_crit.
        let transport = SteadyTransport::new(DEFAULT_SLIP_TOLERANCE, 2.0, 2)
            .unwrap()
            .with_reference(ViscousSlipReference::RelativeVelocity);
        let by_hand =
            ExtendedCoulomb::new(Coulomb::new(0.3).unwrap()).with_steady_transport(Some(transport));
        assert_eq!(fast, Some(by_hand));
        assert_eq!(
            coulomb_extended(&props),
            Ok(FrictionLaw::CoulombExtended(by_hand))
        );
        for bad in [
            spinning(0.0, 0.0, 0.0),
            spinning(2.0, 4.0, 0.0),
            spinning(2.0, 0.0, 2.0),
        ] {
            assert_eq!(crate::props::fast_extended_coulomb(&bad), None);
            assert!(coulomb_extended(&bad).is_err());
        }
    }

    /// The builder's refusals are typed causes naming the entry, with the messages the tests
    /// of the entry points pin.
    #[test]
    fn the_builders_refusals_are_typed() {
        let table = CoulombBuilder::new().mu(0.3).mu_law(2.0).build();
        let e = COULOMB.check::<20>(&table).unwrap();
        let refused = law_from_entries(&e, None).unwrap_err();
        assert_eq!(refused.cause(), Refusal::NoTable.into_props_error().cause());
        assert_eq!(refused.index(), Some(8));
        assert!(
            refused.to_string().starts_with("PROPS(8) = 2 (μ table"),
            "{refused}"
        );
        let tiny = CoulombBuilder::new()
            .mu(1e-310)
            .mu_law(1.0)
            .mu_k(0.1)
            .decay(1.0)
            .build();
        let e = COULOMB.check::<20>(&tiny).unwrap();
        let refused = law_from_entries(&e, None).unwrap_err();
        assert_eq!(
            refused.cause(),
            Refusal::KineticRatioOverflows {
                mu_k: 0.1,
                mu_s: 1e-310
            }
            .into_props_error()
            .cause()
        );
        assert_eq!(refused.index(), Some(9));
        // Anisotropy with μ₁ = 0 is the layout's rule now, named by PROPS(3).
        let anisotropic = CoulombBuilder::new().mu(0.0).mu2(0.4).build();
        let e = COULOMB.check::<20>(&anisotropic).unwrap_err();
        assert_eq!(e.index(), Some(3));
        assert!(e.to_string().contains("anisotropy needs μ₁ > 0"), "{e}");
    }

    /// `PLAIN` leaves the stick mode to the plain reader's match: the match accepts exactly
    /// the modes the pin lists, each as the checked parser reads it, and refuses the others
    /// (steady transport's 3 included, which the plan ruled out).
    #[test]
    fn the_plain_readers_match_takes_the_modes_the_pin_lists() {
        let Some(&(7, Fix::MappedBy(listed))) = PLAIN.fixed.iter().find(|(i, _)| *i == 7) else {
            panic!("PROPS(7) is not MappedBy in PLAIN")
        };
        let mut accepted = Vec::new();
        for stick in [-1.0, -0.0, 0.0, 0.5, 1.0, 2.0, 3.0, 4.0, f64::NAN] {
            let props = CoulombBuilder::new().mu(0.3).stick(stick).build_first(7);
            let fast = crate::props::fast_plain_coulomb(&props);
            if let Some(law) = fast {
                assert_eq!(
                    coulomb_extended(&props),
                    Ok(FrictionLaw::Coulomb(law)),
                    "{stick}"
                );
                accepted.push(stick);
            }
        }
        let listed: Vec<f64> = listed.iter().map(|&c| f64::from(c)).collect();
        // −0 is 0 to the match, as to the checked parser.
        assert_eq!(accepted, [&[-0.0][..], &listed].concat());
    }

    /// The refusals name the entry in force: HHT α or steady transport's ω for `PROPS(14)`,
    /// and the rule that ties an entry to a switch.
    #[test]
    fn refusals_name_the_entry_in_force() {
        let hht = CoulombBuilder::new().mu(0.3).hht_alpha(0.5).build();
        let e = COULOMB.check::<20>(&hht).unwrap_err();
        assert_eq!(
            e.cause(),
            &Cause::OutOfClass {
                index: 14,
                value: 0.5
            }
        );
        assert_eq!(e.to_string(), "PROPS(14): HHT α = 0.5 must be in [−1/2, 0]");
        let viscous = CoulombBuilder::new().mu(0.3).stick(3.0).build();
        let e = COULOMB.check::<20>(&viscous).unwrap_err();
        assert_eq!(
            e.cause(),
            &Cause::OutOfClass {
                index: 14,
                value: 0.0
            }
        );
        assert!(
            e.to_string().contains("ω = 0 must be finite and > 0"),
            "{e}"
        );
        let unread = CoulombBuilder::new().mu(0.3).mu_k(0.1).build();
        let e = COULOMB.check::<20>(&unread).unwrap_err();
        assert_eq!(e.index(), Some(9));
        assert_eq!(
            e.to_string(),
            "PROPS(9) = 0.1 is not read when PROPS(8) = 0 (constant μ); refusing to ignore it"
        );
        let decay = CoulombBuilder::new().mu(0.3).mu_law(1.0).mu_k(0.1).build();
        let e = COULOMB.check::<20>(&decay).unwrap_err();
        assert_eq!(e.index(), Some(10));
        assert!(
            e.to_string().contains("must be > 0 when PROPS(8) = 1"),
            "{e}"
        );
        let stick = CoulombBuilder::new().mu(0.3).stick(5.0).build();
        let e = COULOMB.check::<20>(&stick).unwrap_err();
        assert!(
            e.to_string()
                .ends_with("must be 0 (elastic stick (penalty)), 1 (exact stick (`LM = 1`)), 2 (rough), 3 (viscous stick for steady-state transport) or 4 (elastic stick with a constant stick stiffness k_s = `PROPS(5)`)"),
            "{e}"
        );
        // PROPS(7) = 4 reads PROPS(5) as k_s, required.
        let stick = CoulombBuilder::new().mu(0.3).stick(4.0).build();
        let e = COULOMB.check::<20>(&stick).unwrap_err();
        assert_eq!(e.index(), Some(5));
        assert!(
            e.to_string()
                .contains("stick stiffness k_s = 0 must be finite and > 0"),
            "{e}"
        );
    }

    /// The checked parser takes its "not read" and "needed" refusals from the schema's rules:
    /// each names the entry, the switch and why (the texts written out here).
    #[test]
    fn the_checked_parser_refuses_by_the_schema_rules() {
        let refusal = |b: CoulombBuilder| match coulomb_extended(&b.build()) {
            Err(crate::LawError::Parameter(m)) => m,
            other => panic!("{other:?}"),
        };
        let base = || CoulombBuilder::new().mu(0.3);
        assert_eq!(
            refusal(base().mu_k(0.1)),
            "PROPS(9) = 0.1 is not read when PROPS(8) = 0 (constant μ); refusing to ignore it"
        );
        assert_eq!(
            refusal(base().stick(3.0).omega(1.0).gamma_crit(1e-3)),
            "PROPS(5) = 0.001 is not read when PROPS(7) = 3 (viscous stick uses the slip \
             tolerance F_f = PROPS(6), not γ_crit); refusing to ignore it"
        );
        assert_eq!(
            refusal(base().theta_ref(300.0)),
            "PROPS(13) = 300 is not read when PROPS(12) = 0 (no temperature law); refusing to \
             ignore it"
        );
        assert_eq!(
            refusal(base().damping_fraction(0.5)),
            "PROPS(19) = 0.5 is not read when PROPS(17) = 0 (no damping); refusing to ignore it"
        );
        assert_eq!(
            refusal(base().frozen(1.0)),
            "PROPS(20) = 1 is not read when PROPS(8) = 0 (μ does not depend on the slip rate); \
             refusing to ignore it"
        );
        assert_eq!(
            refusal(CoulombBuilder::new().mu_law(1.0).decay(2.0)),
            "PROPS(2): friction coefficient μ = 0 must be > 0 when PROPS(8) = 1 (the \
             exponential decay law)"
        );
    }
}
