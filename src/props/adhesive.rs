//! `PROPS` layout of the adhesive friction law (`PROPS(1) = 2`, seed 004), shared by `fric_`
//! (tangential part) and `uinter_` (the whole interface), described once in [`ADHESIVE`]:
//! the fast paths, the checked parser, the defaults, [`AdhesiveBuilder`] and the docs/props.md
//! table all come from that table (src/props/schema.rs).

use crate::LawError;
use crate::laws::adhesive::Adhesive;
use crate::laws::adhesive_interface::AdhesiveInterface;
use crate::laws::coulomb::{Coulomb, DEFAULT_SLIP_TOLERANCE, StickMode};

use super::FrictionLaw;
use super::builder::{LawBuilder, entry_setters};
use super::schema::Default::{self, Described, Required};
use super::schema::{
    Class, Entry, FastLayout, Fix, Fixed, Layout, Plan, PropsError, Rule, admits_fixed,
};

/// `PROPS(1)` code of the adhesive friction law.
pub const LAW_ADHESIVE: i32 = 2;

/// Number of `PROPS` entries the adhesive law reads (`PROPS(1..13)`).
pub const ADHESIVE_NPROPS: usize = ADHESIVE.entries.len();

/// The adhesive layout (seed 004's parameter names where it has them).
#[rustfmt::skip]
pub const ADHESIVE: Layout = Layout {
    law: "adhesive law",
    code: LAW_ADHESIVE,
    entries: &[
        Entry::law_code(LAW_ADHESIVE),
        Entry::new(2, "coeff", "dynamic friction coefficient", Class::NonNegative)
            .seed_name().symbol("μ_d").when_absent(Required),
        Entry::new(3, "coeffStatic", "static friction coefficient", Class::FiniteOrNone)
            .seed_name().symbol("μ_s").when_absent(Default::Entry(2))
            .note("the seed's −1; any value ≤ 0 means none"),
        Entry::new(4, "Sa", "shear adhesive strength", Class::NonNegative)
            .seed_name().symbol("S_a").unit("stress"),
        Entry::new(5, "Na", "normal adhesive strength", Class::NonNegative)
            .seed_name().symbol("N_a").unit("stress"),
        Entry::new(6, "kmu", "slope of μ against the slip rate", Class::NonNegative)
            .seed_name().symbol("k_μ").unit("1/velocity"),
        Entry::new(7, "vhalf", "slip rate at which μ_s → μ_d is half done", Class::NonNegative)
            .seed_name().symbol("v_½").unit("velocity").note("0: instantaneous drop"),
        Entry::new(8, "gamma_crit", "allowable elastic slip", Class::OffOrPositive)
            .symbol("γ_crit").unit("length")
            .when_absent(Described("`PROPS(9)` × `CHRLNGTH`")).note("absolute"),
        Entry::new(9, "slip_tolerance", "slip tolerance", Class::OffOrPositive)
            .when_absent(Default::Value(DEFAULT_SLIP_TOLERANCE))
            .note("γ_crit = tolerance × `CHRLNGTH`"),
        Entry::new(10, "normal_stiffness", "penalty normal stiffness", Class::OffOrPositive)
            .symbol("K_n").unit("stress/length")
            .when_absent(Described("none: `uinter_` refuses 0"))
            .note("`uinter_` only; `fric_` ignores it"),
        Entry::new(11, "conductance", "heat conduction across the interface", CONDUCTANCE)
            .note("`uinter_` only"),
        Entry::new(12, "heat_fraction", HEAT_FRACTION, Class::UnitInterval)
            .symbol("η").note("`uinter_` only"),
        Entry::new(13, "slave_fraction", SLAVE_FRACTION, Class::OffOrFraction)
            .symbol("f").when_absent(Default::Value(0.5)).note("`uinter_` only"),
    ],
    rules: &[Rule::AtLeastWhenGiven {
        entry: 3,
        floor: 2,
        why: "the static coefficient μ_s must be ≥ the dynamic one (or ≤ 0 for none)",
    }],
    variants: &[],
};

/// The Coulomb special case (seed 004: "the simple Coulomb friction contact law is a special
/// case of this law"): S_a = k_μ = v_½ = 0 and no static coefficient (μ_s none or = μ_d). N_a
/// plays no part in the tangential law in contact. `fric_` runs it as the Coulomb law itself.
pub const COULOMB_SPECIAL_CASE: Fixed = Fixed {
    name: "Coulomb special case",
    fixed: &[
        (3, Fix::NoneOrEqual(2)),
        (4, Fix::Zero),
        (6, Fix::Zero),
        (7, Fix::Zero),
    ],
};

/// The validator of [`COULOMB_SPECIAL_CASE`] for the first `N` entries (a host that leaves
/// out trailing ones), worked out when the crate compiles.
struct SpecialCase<const N: usize>;

impl<const N: usize> FastLayout for SpecialCase<N> {
    const PLAN: Plan = Plan::of(&ADHESIVE, &COULOMB_SPECIAL_CASE, N);
}

/// The validator of the whole layout, nothing pinned.
pub(crate) struct Whole;

impl FastLayout for Whole {
    const PLAN: Plan = Plan::of(&ADHESIVE, &Fixed::NONE, ADHESIVE_NPROPS);
}

/// `PROPS(11)`: 0 or 1.
const CONDUCTANCE: Class = Class::Switch {
    off: "none",
    on: "the GAPCON law of this interaction from `INTERFACIAL_CONFIG`",
};

/// `PROPS(12)`'s meaning.
const HEAT_FRACTION: &str = "fraction of the frictional dissipation converted into heat";

/// `PROPS(13)`'s meaning.
const SLAVE_FRACTION: &str =
    "part of that heat flowing into the slave surface, 1 − f into the master";

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
        AdhesiveInterface::new(self.law, self.normal_stiffness)
            .map_err(|e| PropsError::law(&ADHESIVE, 10, e).into())
    }

    /// The parameters of valid entries `e` (`e[i - 1] = PROPS(i)`), defaults applied as
    /// [`ADHESIVE`] says.
    #[inline(always)]
    fn from_entries(e: &[f64; ADHESIVE_NPROPS]) -> Self {
        let get = |i| ADHESIVE.resolved(e, i);
        AdhesiveProps {
            law: Adhesive::from_validated(
                get(2),
                get(3),
                get(4),
                get(5),
                get(6),
                get(7),
                get(8),
                get(9),
            ),
            normal_stiffness: get(10),
            heat: HeatExchange {
                conductance: get(11) == 1.0,
                heat_fraction: get(12),
                slave_fraction: get(13),
            },
        }
    }
}

/// The common case of the adhesive layout: valid `PROPS`, or `None` (then the checked path
/// [`adhesive`] says what is wrong). Branch-light (`admits_fixed`); a property test checks
/// that it agrees with the checked path.
#[inline(always)]
pub(crate) fn adhesive_fast(props: &[f64]) -> Option<FrictionLaw> {
    adhesive_props_fast(props).map(AdhesiveProps::into_friction_law)
}

/// The Coulomb law of a valid adhesive `PROPS` in its [`COULOMB_SPECIAL_CASE`], else `None`
/// (any other adhesive `PROPS`, or not the adhesive law at all). Inlined into the out-of-line
/// `plain_coulomb_other_lengths` (props.rs), which `fric_`'s plain path calls only when `PROPS` is not
/// the plain Coulomb layout. A property test checks that it agrees with the full parse
/// followed by [`Adhesive::coulomb_special_case`].
#[inline]
pub(crate) fn adhesive_coulomb_special_case(props: &[f64]) -> Option<Coulomb> {
    // The layouts a friction-only host passes (up to γ_crit, or up to the slip tolerance):
    // read as one array, no padding; the absent entries are each one's valid default, so only
    // the given ones are tested.
    if let Ok(first_eight) = <&[f64; 8]>::try_from(props) {
        return special_case(first_eight);
    }
    if let Ok(first_nine) = <&[f64; 9]>::try_from(props) {
        return special_case(first_nine);
    }
    if props.len() < ADHESIVE.required_len() || props.len() > ADHESIVE_NPROPS {
        return None;
    }
    // Absent entries read as 0; entry by entry rather than a copy of the given ones (a call
    // to memcpy for ≤ 13 values).
    let e: [f64; ADHESIVE_NPROPS] = std::array::from_fn(|i| props.get(i).copied().unwrap_or(0.0));
    special_case(&e)
}

/// [`adhesive_coulomb_special_case`] of the first `N` entries.
#[inline(always)]
fn special_case<const N: usize>(e: &[f64; N]) -> Option<Coulomb> {
    admits_fixed::<SpecialCase<N>, N>(e).then(|| {
        let get = |i| ADHESIVE.resolved(e, i);
        Coulomb::from_validated(get(2), 0.0, get(8), get(9), StickMode::Elastic)
    })
}

/// [`adhesive_fast`] before the special case is recognised.
#[inline(always)]
fn adhesive_props_fast(props: &[f64]) -> Option<AdhesiveProps> {
    if props.len() < ADHESIVE.required_len()
        || props.len() > ADHESIVE_NPROPS
        || props[0] != f64::from(LAW_ADHESIVE)
    {
        return None;
    }
    // Zero-padded copy: absent trailing entries read as 0 without a branch per entry.
    let mut e = [0.0; ADHESIVE_NPROPS];
    e[..props.len()].copy_from_slice(props);
    admits_fixed::<Whole, ADHESIVE_NPROPS>(&e).then(|| AdhesiveProps::from_entries(&e))
}

/// The adhesive `PROPS` as `uinter_` needs them (also in the Coulomb special case): the fast
/// path, else the checked one, which names what is wrong.
pub(crate) fn adhesive_props(props: &[f64]) -> Result<AdhesiveProps, LawError> {
    if super::careful_path_only() {
        return adhesive(props);
    }
    match adhesive_props_fast(props) {
        Some(a) => Ok(a),
        None => adhesive(props),
    }
}

/// The checked parser of the adhesive layout ([`ADHESIVE`]): the parameters, or the first
/// entry that is wrong, named. Cold and out of line: inlined into `uinter_` it made that
/// function large enough that the compiler stopped inlining the interface law into it.
#[cold]
#[inline(never)]
pub(crate) fn adhesive(props: &[f64]) -> Result<AdhesiveProps, LawError> {
    let e = ADHESIVE.check::<ADHESIVE_NPROPS>(props)?;
    Ok(AdhesiveProps::from_entries(&e))
}

/// A law-2 `PROPS` array built by entry name (tests, scenes, fuzz decoders): every entry
/// starts at its "0 / absent" value, `PROPS(1) = 2`.
pub type AdhesiveBuilder = LawBuilder<LAW_ADHESIVE>;

impl AdhesiveBuilder {
    entry_setters!("law 2", {
        coeff => "coeff",
        coeff_static => "coeffStatic",
        sa => "Sa",
        na => "Na",
        kmu => "kmu",
        vhalf => "vhalf",
        gamma_crit => "gamma_crit",
        slip_tolerance => "slip_tolerance",
        normal_stiffness => "normal_stiffness",
        heat_fraction => "heat_fraction",
        slave_fraction => "slave_fraction",
    });

    /// Sets the conductance switch (`PROPS(11)`).
    #[must_use]
    pub fn conductance(self, on: bool) -> Self {
        self.set(
            const { ADHESIVE.index_of("conductance") },
            if on { 1.0 } else { 0.0 },
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::laws::adhesive::AdhesiveParameters;
    use proptest::prelude::*;

    /// The checked reader before the schema (kept as the oracle): the law's own constructors
    /// (`Adhesive::new`, `with_*`) validate.
    /// Adhesive layout: `PROPS(2)` coeff μ_d, `PROPS(3)` coeffStatic μ_s (≤ 0 → none),
    /// `PROPS(4)` Sa, `PROPS(5)` Na, `PROPS(6)` kmu, `PROPS(7)` vhalf, `PROPS(8)` γ_crit
    /// (0 → tolerance × CHRLNGTH), `PROPS(9)` slip tolerance (0 → 0.005), `PROPS(10)` K_n,
    /// `PROPS(11)` conductance from the configuration file (0 no, 1 yes), `PROPS(12)` η,
    /// `PROPS(13)` f.
    fn constructors_reference(props: &[f64]) -> Result<AdhesiveProps, LawError> {
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
        // The constructor's message names the seed's parameter (its key), not the entry.
        let mut law = Adhesive::new(&parameters)?;
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

    /// A `PROPS` array that is valid but for at most two entries: a valid base (each entry
    /// 0 or a value inside its class) with one or two entries replaced by any `entry()` or
    /// edge value, so that each entry's test is reached with the others passing (random
    /// arrays almost always fail an earlier entry).
    fn nearly_valid() -> impl Strategy<Value = Vec<f64>> {
        let base = prop::collection::vec(prop_oneof![3 => Just(0.0), 1 => 0.0..1.0f64], 15);
        let bad = prop_oneof![
            entry(),
            Just(-0.0),
            Just(f64::NEG_INFINITY),
            Just(5e-324),
            Just(f64::MAX),
            Just(1.5),
            Just(2.0),
        ];
        (base, 0..15usize, bad.clone(), 0..15usize, bad, 1..=15usize).prop_map(
            |(mut p, i, v, j, w, len)| {
                p[0] = 2.0;
                // μ_s (PROPS(3)) from the base is below μ_d half the time: none instead.
                p[2] = -p[2];
                p[i] = v;
                if j % 3 == 0 {
                    p[j] = w;
                }
                p.truncate(len);
                p
            },
        )
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

    proptest! {
        #![proptest_config(ProptestConfig { cases: 3000, failure_persistence: None, ..ProptestConfig::default() })]
        /// The fast path accepts exactly what the checked path accepts, with the same result;
        /// and the schema's checked parser accepts exactly what the law's own constructors
        /// accept (the reader before the schema), with the same law; refusals name the same
        /// entry except when both γ_crit and the tolerance are bad (the constructors looked at
        /// the tolerance first, the schema goes in entry order).
        #[test]
        fn fast_checked_and_constructors_agree(
            mut props in prop_oneof![prop::collection::vec(entry(), 0..15), nearly_valid()],
        ) {
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
            match (adhesive(&props), constructors_reference(&props)) {
                (Ok(a), Ok(b)) => prop_assert_eq!(a, b),
                (Err(_), Err(b)) => {
                    let typed = ADHESIVE.check::<ADHESIVE_NPROPS>(&props).unwrap_err();
                    if let Some(i) = typed.index() {
                        // The constructors name PROPS(2..7) by the seed's name, the rest by
                        // index.
                        let b = b.to_string();
                        let by_key = ADHESIVE.entries.get(i - 1).is_some_and(|e| {
                            b.starts_with(&format!("bad parameter: {} ", e.key))
                        });
                        let named = b.contains(&format!("PROPS({i})")) || by_key;
                        prop_assert!(named || i == 8, "{props:?}: {typed} / {b}");
                    }
                }
                (a, b) => prop_assert!(false, "{props:?}: {a:?} / {b:?}"),
            }
        }
    }

    /// The table is well formed (`Layout::assert_well_formed`), and the pins of the special
    /// case lie inside each entry's class.
    #[test]
    fn the_schema_is_consistent() {
        ADHESIVE.assert_well_formed();
        assert_eq!(ADHESIVE.required_len(), 2);
        for (index, fix) in COULOMB_SPECIAL_CASE.fixed {
            let class = ADHESIVE.entry(*index).class;
            match fix {
                Fix::Zero => assert!(class.admits(0.0)),
                Fix::NoneOrEqual(_) => assert!(class.admits(-1.0) && class.is_off(-1.0)),
                Fix::ZeroOrEqual(_) | Fix::Is(_) | Fix::MappedBy(_) => {
                    panic!("not a pin of the special case: {fix:?}")
                }
            }
        }
        // Absent entries past NPROPS = 2 are valid: the smallest valid layout.
        let mut smallest = [0.0; ADHESIVE_NPROPS];
        smallest[..2].copy_from_slice(&[2.0, 0.3]);
        assert!(admits_fixed::<Whole, ADHESIVE_NPROPS>(&smallest));
    }

    /// The special case pins μ_s to "none or μ_d", which satisfies the layout's one rule
    /// (μ_s ≥ μ_d when given): its plans test no rule per call; the whole layout's tests it.
    #[test]
    fn the_plans_keep_only_the_rules_that_can_fail() {
        assert!(SpecialCase::<8>::PLAN.live_rules().is_empty());
        assert!(SpecialCase::<ADHESIVE_NPROPS>::PLAN.live_rules().is_empty());
        assert_eq!(Whole::PLAN.live_rules(), [&ADHESIVE.rules[0]]);
    }

    /// Each named setter writes its own entry: the parsed law reports the value set.
    #[test]
    fn builder_setters_reach_their_entries() {
        let props = AdhesiveBuilder::new()
            .coeff(0.3)
            .coeff_static(0.5)
            .sa(1.0)
            .na(2.0)
            .kmu(0.1)
            .vhalf(0.2)
            .gamma_crit(1e-3)
            .slip_tolerance(0.02)
            .normal_stiffness(1e5)
            .conductance(true)
            .heat_fraction(0.9)
            .slave_fraction(0.25)
            .build();
        let a = adhesive(&props).unwrap();
        assert_eq!(props.len(), ADHESIVE_NPROPS);
        assert_eq!((a.law.mu_dynamic(), a.law.mu_static()), (0.3, 0.5));
        assert_eq!(
            (a.law.shear_adhesion(), a.law.normal_adhesion()),
            (1.0, 2.0)
        );
        assert_eq!((a.law.k_mu(), a.law.v_half()), (0.1, 0.2));
        assert_eq!(
            a.law.critical_slip(),
            crate::laws::coulomb::CriticalSlip::Absolute(1e-3)
        );
        let without_gamma = AdhesiveBuilder::new().coeff(0.3).slip_tolerance(0.02);
        assert_eq!(
            adhesive(&without_gamma.build())
                .unwrap()
                .law
                .critical_slip(),
            crate::laws::coulomb::CriticalSlip::Tolerance(0.02)
        );
        assert_eq!(without_gamma.build_first(9).len(), 9);
        assert_eq!(a.normal_stiffness, 1e5);
        assert_eq!(
            a.heat,
            HeatExchange {
                conductance: true,
                heat_fraction: 0.9,
                slave_fraction: 0.25
            }
        );
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
            // The typed cause carries the index the message names.
            let typed = ADHESIVE.check::<ADHESIVE_NPROPS>(props).unwrap_err();
            match typed.index() {
                Some(i) => assert!(needle.starts_with(&format!("PROPS({i})")), "{typed:?}"),
                None => assert_eq!(
                    typed.cause(),
                    &super::super::schema::Cause::TooFew { given: 1 }
                ),
            }
        }
    }
}
