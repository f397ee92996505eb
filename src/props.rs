//! The `PROPS` dispatcher of the Abaqus-style entry points: `PROPS(1)` selects the law, whose
//! own files say what each entry means (`props/coulomb.rs` with its readers in
//! `props/coulomb_fast.rs`, `props/adhesive.rs`, `props/rate_state.rs`; the generic schema in
//! `props/schema.rs`). This is the one place that turns the host's flat `PROPS(NPROPS)` array
//! into a typed, validated law; `docs/props.md` is generated from the same layouts.

use crate::LawError;
use crate::laws::coulomb::Coulomb;
use crate::laws::coulomb_extended::ExtendedCoulomb;
use crate::laws::friction_table::FrictionTable;
use crate::laws::point_law::{Needs, PointInput, PointLaw, PointLawTask, PointResult};
use crate::laws::rate_state::RateState;
use crate::switch::Path;

mod adhesive;
mod builder;
mod coulomb;
mod coulomb_fast;
mod rate_state;
pub mod schema;
pub(crate) use adhesive::adhesive_props;
pub use adhesive::{
    ADHESIVE, ADHESIVE_NPROPS, AdhesiveBuilder, AdhesiveProps, COULOMB_SPECIAL_CASE, HeatExchange,
    LAW_ADHESIVE,
};
pub use builder::LawBuilder;
pub use coulomb::{
    COULOMB, CoulombBuilder, DECAY_LEAN, EXTENDED_CONSTANT, EXTENDED_DECAY, PLAIN, QUASI_STATIC,
    STEADY_TRANSPORT, TRANSPORT,
};
pub(crate) use coulomb_fast::fast_decay_lean;
pub use coulomb_fast::{
    COULOMB_EXTENDED_NPROPS, COULOMB_NPROPS, LAW_COULOMB, coulomb_extended,
    coulomb_extended_with_table, fast_extended_coulomb, fast_plain_coulomb,
};
use coulomb_fast::{coulomb_fast, fast_extended_friction_law};
pub use rate_state::{LAW_RATE_STATE, RATE_STATE, RATE_STATE_NPROPS, RateStateBuilder, rate_state};

/// Every law's `PROPS` layout, in law-code order (`PROPS(1)` = 1, 2, 3): the laws a tool can ask
/// about (`ifl_props_*`, numbered as `ifl_props_law_code` numbers them) and what
/// [`LawBuilder`] starts from.
pub const LAYOUTS: [&schema::Layout; 3] = [&COULOMB, &ADHESIVE, &RATE_STATE];

/// A law selected and parametrised by `PROPS`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FrictionLaw {
    /// `PROPS(1) = 1`.
    Coulomb(Coulomb),
    /// `PROPS(1) = 2`: adhesive friction (seed 004).
    Adhesive(AdhesiveProps),
    /// `PROPS(1) = 1` with anisotropy, a μ law, HHT or damping (`PROPS(3)`, `PROPS(8..20)`).
    CoulombExtended(ExtendedCoulomb),
    /// `PROPS(1) = 3`: rate-and-state friction (Dieterich–Ruina).
    RateState(RateState),
}

impl FrictionLaw {
    /// The law as messages name it, with its code: "PROPS(1) = 3 (rate-and-state law)".
    #[must_use]
    pub fn name_with_code(&self) -> &'static str {
        match self {
            FrictionLaw::Coulomb(_) | FrictionLaw::CoulombExtended(_) => {
                "PROPS(1) = 1 (Coulomb law)"
            }
            FrictionLaw::Adhesive(_) => "PROPS(1) = 2 (adhesive law)",
            FrictionLaw::RateState(_) => "PROPS(1) = 3 (rate-and-state law)",
        }
    }

    /// `task` run with the law this holds, as its own type (one match; static dispatch).
    #[inline(always)]
    pub fn run_with<T: PointLawTask>(&self, task: T) -> T::Output {
        match self {
            FrictionLaw::Coulomb(law) => task.run(law),
            FrictionLaw::CoulombExtended(law) => task.run(law),
            FrictionLaw::Adhesive(a) => task.run(&a.law),
            FrictionLaw::RateState(law) => task.run(law),
        }
    }

    /// Law 1's plain form, for an entry point that serves only it (VFRIC, the batch): the
    /// extended form and every other law are refused, the message naming what was given and
    /// then `why` (what the routine serves instead).
    pub fn into_plain_coulomb(self, why: &str) -> Result<Coulomb, LawError> {
        match self {
            FrictionLaw::Coulomb(law) => Ok(law),
            FrictionLaw::CoulombExtended(_) => Err(LawError::Parameter(format!(
                "extended law-1 PROPS (PROPS(3) != PROPS(2) or PROPS(8..20)): {why}"
            ))),
            other => Err(LawError::Parameter(format!(
                "{}: {why}",
                other.name_with_code()
            ))),
        }
    }

    /// Law 1 as the extended Coulomb law (the plain one wrapped), for an entry point that
    /// serves law 1 only; another law is refused, the message naming it and then `why` (what
    /// the routine serves instead).
    pub fn into_coulomb_extended(self, why: &str) -> Result<ExtendedCoulomb, LawError> {
        match self {
            FrictionLaw::Coulomb(base) => Ok(ExtendedCoulomb::new(base)),
            FrictionLaw::CoulombExtended(law) => Ok(law),
            other => Err(LawError::Parameter(format!(
                "{}: {why}",
                other.name_with_code()
            ))),
        }
    }
}

/// The law interface through the law enum: each method is one `match` to the variant's own
/// implementation (static dispatch, no `dyn`). A new law is a variant and one arm per method.
impl PointLaw for FrictionLaw {
    fn name(&self) -> &'static str {
        match self {
            FrictionLaw::Coulomb(law) => law.name(),
            FrictionLaw::CoulombExtended(law) => law.name(),
            FrictionLaw::Adhesive(a) => a.law.name(),
            FrictionLaw::RateState(law) => law.name(),
        }
    }

    fn nstatv(&self, nfdir: usize) -> usize {
        match self {
            FrictionLaw::Coulomb(law) => law.nstatv(nfdir),
            FrictionLaw::CoulombExtended(law) => law.nstatv(nfdir),
            FrictionLaw::Adhesive(a) => a.law.nstatv(nfdir),
            FrictionLaw::RateState(law) => law.nstatv(nfdir),
        }
    }

    fn exact_stick(&self) -> bool {
        match self {
            FrictionLaw::Coulomb(law) => law.exact_stick(),
            FrictionLaw::CoulombExtended(law) => law.exact_stick(),
            FrictionLaw::Adhesive(a) => a.law.exact_stick(),
            FrictionLaw::RateState(law) => law.exact_stick(),
        }
    }

    fn needs(&self, nfdir: usize) -> Needs {
        match self {
            FrictionLaw::Coulomb(law) => law.needs(nfdir),
            FrictionLaw::CoulombExtended(law) => law.needs(nfdir),
            FrictionLaw::Adhesive(a) => a.law.needs(nfdir),
            FrictionLaw::RateState(law) => law.needs(nfdir),
        }
    }

    fn update_point<const N: usize>(&self, at: &PointInput<'_, N>) -> PointResult<N> {
        match self {
            FrictionLaw::Coulomb(law) => law.update_point(at),
            FrictionLaw::CoulombExtended(law) => law.update_point(at),
            FrictionLaw::Adhesive(a) => a.law.update_point(at),
            FrictionLaw::RateState(law) => law.update_point(at),
        }
    }

    fn coefficients(&self, rate: f64, pressure: f64, temperature: f64) -> Option<[[f64; 2]; 4]> {
        match self {
            // Written as trait calls: ExtendedCoulomb has an inherent `coefficients` too.
            FrictionLaw::Coulomb(law) => PointLaw::coefficients(law, rate, pressure, temperature),
            FrictionLaw::CoulombExtended(law) => {
                PointLaw::coefficients(law, rate, pressure, temperature)
            }
            FrictionLaw::Adhesive(a) => PointLaw::coefficients(&a.law, rate, pressure, temperature),
            FrictionLaw::RateState(law) => PointLaw::coefficients(law, rate, pressure, temperature),
        }
    }
}

/// Reads `PROPS(1)` (the law code) and the law's parameters.
///
/// Runs on every call, so valid `PROPS` take a branch-light path that only decides "valid or
/// not"; anything else goes to the slow path that names the offending entry. A property test
/// checks that both paths agree.
#[inline(always)]
pub fn friction_law(props: &[f64]) -> Result<FrictionLaw, LawError> {
    if careful_path_only() {
        return friction_law_checked(props);
    }
    match coulomb_fast(props) {
        Some(law) => Ok(FrictionLaw::Coulomb(law)),
        None => match fast_extended_friction_law(props) {
            Some(law) => Ok(law),
            None => match adhesive::adhesive_fast(props) {
                Some(law) => Ok(law),
                None => friction_law_checked(props),
            },
        },
    }
}

/// Unit tests only: while `on`, every fast `PROPS` reader of this thread declines
/// ([`fast_plain_coulomb`], [`fast_extended_coulomb`], [`fast_decay_lean`], the fast
/// layouts of [`friction_law`], the adhesive fast path), so every call of the entry points
/// takes the careful (checked) path: how a test compares the two paths on the same arguments,
/// as `abi::batch`'s baseline switch does for the batch kernel. Outside `cargo test` of this
/// crate the switch does not exist and the readers test a constant `false`.
#[cfg(test)]
pub(crate) fn force_careful_path(on: bool) {
    crate::switch::force(Path::Careful, on);
}

#[inline(always)]
pub(super) fn careful_path_only() -> bool {
    crate::switch::forced(Path::Careful)
}

/// Top bit clear exactly when 0 ≤ v < ∞: adding +0 turns −0 into +0; after that a value is
/// in range exactly when its sign bit is clear and its exponent is not all ones, i.e. when
/// neither its bits nor its bits + 2⁵² have the top bit set. OR-ing the flags of several values
/// tests them all with one test of the top bit (plain integer operations, no branch per value).
#[inline(always)]
pub(crate) fn range_flag(v: f64) -> u64 {
    let b = (v + 0.0).to_bits();
    b | b.wrapping_add(1 << 52)
}

/// The law codes `PROPS(1)` may take, for messages.
const LAW_CODES: &str = "1 = Coulomb, 2 = adhesive, 3 = rate-and-state";

/// The slow path of [`friction_law`], which says what is wrong.
#[cold]
#[inline(never)]
pub fn friction_law_checked(props: &[f64]) -> Result<FrictionLaw, LawError> {
    let Some(&code) = props.first() else {
        return Err(LawError::Parameter(format!(
            "NPROPS = 0: PROPS(1) must select a law ({LAW_CODES})"
        )));
    };
    if code == f64::from(LAW_COULOMB) {
        coulomb_extended(props)
    } else if code == f64::from(LAW_ADHESIVE) {
        adhesive::adhesive(props).map(AdhesiveProps::into_friction_law)
    } else if code == f64::from(LAW_RATE_STATE) {
        rate_state(props).map(FrictionLaw::RateState)
    } else if code.is_finite() && code.fract() == 0.0 {
        Err(LawError::Parameter(format!(
            "PROPS(1) = {code} is not a known law code ({LAW_CODES})"
        )))
    } else {
        Err(LawError::Parameter(format!(
            "PROPS(1) = {code} must be an integer law code ({LAW_CODES})"
        )))
    }
}

/// The law `props` select as written: law 2 stays the adhesive law even in its Coulomb special
/// case, which [`friction_law`] runs as law 1 (for VFRIC, which serves law 1 only).
pub fn friction_law_as_written(props: &[f64]) -> Result<FrictionLaw, LawError> {
    if props.first() == Some(&f64::from(LAW_ADHESIVE)) {
        adhesive::adhesive(props).map(FrictionLaw::Adhesive)
    } else {
        friction_law(props)
    }
}

/// The interface law (`uinter_`: normal contact, friction and heat) `props` select: today the
/// adhesive interface, `PROPS(1) = 2`; every other code is refused by name.
pub fn interface_law(props: &[f64]) -> Result<AdhesiveProps, LawError> {
    match props.first() {
        Some(&code) if code == f64::from(LAW_ADHESIVE) => adhesive_props(props),
        code => Err(not_uinter_law(code.copied())),
    }
}

#[cold]
#[inline(never)]
fn not_uinter_law(code: Option<f64>) -> LawError {
    let code = code.map_or("absent (NPROPS = 0)".to_string(), |c| c.to_string());
    LawError::Parameter(format!(
        "PROPS(1) = {code}: UINTER needs PROPS(1) = 2 (the adhesive interface law); the other \
         laws are tangential only (FRIC)"
    ))
}

/// The friction law `props` select, for a routine that can look the interaction's μ table up
/// (`fric_`, `fric_coef_`): `table` is called only when the law asks for one (law 1 with its μ
/// table, `PROPS(8) = 2` as law 1's layout says), so the caller reads no `PROPS` entry itself. Every
/// other law and layout is [`friction_law`]'s.
pub fn friction_law_with_table(
    props: &[f64],
    table: impl FnOnce() -> Result<&'static FrictionTable, LawError>,
) -> Result<FrictionLaw, LawError> {
    if props.first() == Some(&f64::from(LAW_COULOMB)) && coulomb::selects_mu_table(props) {
        let table = table().map_err(|e| e.said_of("PROPS(8) = 2"))?;
        coulomb_extended_with_table(props, Some(table))
    } else {
        friction_law(props)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::abi::IflFricInput;
    use crate::abi::test_point::{UNWRITTEN, fric_point, fric_point_input};
    use crate::laws::coulomb::{CriticalSlip, StickMode};
    use proptest::prelude::*;

    /// Turns [`force_careful_path`] on for the guard's life (off again on a failed assertion).
    struct CarefulPath;

    impl CarefulPath {
        fn on() -> Self {
            force_careful_path(true);
            CarefulPath
        }
    }

    impl Drop for CarefulPath {
        fn drop(&mut self) {
            force_careful_path(false);
        }
    }

    /// The switch does what it says: the fast readers decline the plain, extended, decay-lean
    /// and adhesive layouts they accept without it, and the checked path still builds the
    /// same law.
    #[test]
    fn the_careful_path_switch_makes_the_fast_readers_decline() {
        let plain = [1.0, 0.3, 0.0, 0.0, 1e-3, 0.0, 0.0];
        let mut decay = [0.0; COULOMB_EXTENDED_NPROPS];
        decay[..10].copy_from_slice(&[1.0, 0.5, 0.0, 0.0, 1e-3, 0.0, 0.0, 1.0, 0.2, 3.0]);
        let adhesive_props_array = AdhesiveBuilder::new().coeff(0.3).sa(1.0).build();
        let fast_plain = fast_plain_coulomb(&plain);
        assert!(fast_plain.is_some());
        assert!(fast_extended_coulomb(&decay).is_some() && fast_decay_lean(&decay).is_some());
        let fast_law = friction_law(&decay).unwrap();
        let fast_adhesive = adhesive_props(&adhesive_props_array).unwrap();
        let _careful = CarefulPath::on();
        assert_eq!(fast_plain_coulomb(&plain), None);
        assert!(fast_extended_coulomb(&decay).is_none() && fast_decay_lean(&decay).is_none());
        assert_eq!(friction_law(&decay).unwrap(), fast_law);
        assert_eq!(
            friction_law(&plain).unwrap(),
            FrictionLaw::Coulomb(fast_plain.unwrap())
        );
        assert_eq!(
            adhesive_props(&adhesive_props_array).unwrap(),
            fast_adhesive
        );
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 500, failure_persistence: None, ..ProptestConfig::default() })]
        /// `fric_`'s fast path for the decay law's lean layout (through `ifl_fric_point`, which
        /// is `fric_` itself) against the careful path on the very same arguments (LM = 0 both times; the switch, not an argument, sends the
        /// second call to the careful path): every output bit for bit, `PNEWDT` left alone, the
        /// guards past NFDIR and NSTATV intact; NFDIR 1 and 2, stick and slip, with and without
        /// τ_max, frozen μ, p dependence and θ̄ dependence (`TEMP` read only then).
        #[test]
        fn fric_decay_fast_path_agrees_with_the_careful_path(
            nfdir in 1..=2i32,
            mu_s in 0.05..1.0f64,
            ratio in 0.1..1.0f64,
            d_c in 0.1..20.0f64,
            gamma_crit in 1e-4..1e-2f64,
            tau_max in prop_oneof![Just(0.0), 1.0..100.0f64],
            frozen in prop::bool::ANY,
            press in 0.0..100.0f64,
            dpress in -1.0..1.0f64,
            dgam in prop::array::uniform2(-2e-2..2e-2f64),
            tau in prop::array::uniform2(-20.0..20.0f64),
            slip in 0.0..1.0f64,
            rate in 0.0..5.0f64,
            dtime in 1e-3..1.0f64,
            p_ref in prop_oneof![Just(0.0), 10.0..500.0f64],
            temperature in prop_oneof![Just(None), (-0.02..0.02f64, 0.0..100.0f64).prop_map(Some)],
            temp in prop::array::uniform2(0.0..200.0f64),
        ) {
            let mut props = [0.0; COULOMB_EXTENDED_NPROPS];
            props[..10].copy_from_slice(&[
                1.0, mu_s, 0.0, tau_max, gamma_crit, 0.0, 0.0, 1.0, ratio * mu_s, d_c,
            ]);
            props[10] = p_ref;
            if let Some((b_theta, theta_ref)) = temperature {
                props[11] = b_theta;
                props[12] = theta_ref;
            }
            props[19] = if frozen { 1.0 } else { 0.0 };
            prop_assert!(fast_decay_lean(&props).is_some());
            // Two copies of the same STATEV, four unwritten slots past NSTATV = 3 in each.
            let mut fast_statev = [slip, rate, 0.0, UNWRITTEN, UNWRITTEN, UNWRITTEN, UNWRITTEN];
            let mut careful_statev = fast_statev;
            let mut input = fric_point_input(nfdir, &props, &mut fast_statev, 3);
            input.press = press;
            input.dpress = dpress;
            input.dtime = dtime;
            input.temp = temp;
            input.dgam = dgam;
            input.tau = tau;
            let (_, fast) = fric_point(&input);
            let (_, careful) = {
                let _careful = CarefulPath::on();
                fric_point(&IflFricInput { statev: careful_statev.as_mut_ptr(), ..input })
            };
            let message = crate::report::with_last_error(|e| e.to_string_lossy().into_owned());
            prop_assert_eq!(fast.pnewdt, 1e36, "{}", message);
            prop_assert_eq!(careful.pnewdt, 1e36);
            prop_assert_eq!(fast.lm, careful.lm);
            prop_assert_eq!(fast.tau.map(f64::to_bits), careful.tau.map(f64::to_bits));
            prop_assert_eq!(fast.ddtddg.map(f64::to_bits), careful.ddtddg.map(f64::to_bits));
            prop_assert_eq!(fast.ddtddp.map(f64::to_bits), careful.ddtddp.map(f64::to_bits));
            prop_assert_eq!(fast.dslip.map(f64::to_bits), careful.dslip.map(f64::to_bits));
            prop_assert_eq!(
                (fast.sed.to_bits(), fast.sfd.to_bits()),
                (careful.sed.to_bits(), careful.sfd.to_bits())
            );
            prop_assert_eq!(fast.ddtddt.map(f64::to_bits), careful.ddtddt.map(f64::to_bits));
            prop_assert_eq!(fast_statev.map(f64::to_bits), careful_statev.map(f64::to_bits));
            // Nothing past NSTATV or NFDIR is written: the STATEV slots stay unwritten, and
            // what ifl_fric_point presets past NFDIR (TAU the input's, the rest +0) stays so.
            prop_assert!(fast_statev[3..].iter().all(|x| *x == UNWRITTEN));
            let n = nfdir as usize;
            prop_assert_eq!(&fast.tau[n..], &input.tau[n..]);
            let past_nfdir = fast.ddtddg[n * n..]
                .iter()
                .chain(&fast.ddtddp[n..])
                .chain(&fast.dslip[n..])
                .chain(&fast.ddtddt[2 * n..]);
            prop_assert!(past_nfdir.map(|x| x.to_bits()).all(|b| b == 0));
        }
    }

    fn entry() -> impl Strategy<Value = f64> {
        prop_oneof![
            Just(0.0),
            Just(1.0),
            Just(2.0),
            Just(-1.0),
            Just(f64::NAN),
            Just(f64::INFINITY),
            0.0..10.0f64,
        ]
    }

    proptest! {
        /// The fast path accepts exactly what the checked path accepts, with the same result.
        #[test]
        fn fast_and_checked_paths_agree(mut props in prop::collection::vec(entry(), 0..9), lead in prop::bool::ANY) {
            if lead && !props.is_empty() {
                props[0] = 1.0;
            }
            let fast = coulomb_fast(&props);
            let checked = friction_law_checked(&props);
            match (fast, checked) {
                (Some(f), Ok(FrictionLaw::Coulomb(c))) => prop_assert_eq!(f, c),
                (Some(_), Ok(other)) => prop_assert!(false, "fast path gave Coulomb, checked {other:?}"),
                (None, Err(_)) => {}
                // PROPS(1) = 2 is never the Coulomb fast path's (even in its Coulomb special case).
                (None, Ok(_)) if props[0] == 2.0 => {}
                // Longer PROPS with trailing zeros are valid but left to the checked path.
                (None, Ok(FrictionLaw::Coulomb(_))) => prop_assert!(props.len() > COULOMB_NPROPS),
                // Anisotropy or an extended entry: not the fast path's business.
                (None, Ok(_)) => {}
                (Some(_), Err(e)) => prop_assert!(false, "fast path accepted {props:?}: {e}"),
            }
        }
    }

    /// The edges of the fast path's one-compare range test (0 ≤ v < ∞ for μ, τ_max, γ_crit
    /// and the tolerance), value by value in every position, against the checked path.
    #[test]
    fn fast_path_range_edges_agree_with_checked_path() {
        for position in [1, 3, 4, 5] {
            for v in range_edges() {
                let mut props = vec![1.0, 0.3, 0.0, 0.0, 1e-3, 0.0, 0.0];
                props[position] = v;
                let fast = coulomb_fast(&props);
                match friction_law_checked(&props) {
                    Ok(FrictionLaw::Coulomb(c)) => {
                        assert_eq!(fast, Some(c), "PROPS({}) = {v:e}", position + 1);
                    }
                    other => assert!(
                        fast.is_none(),
                        "PROPS({}) = {v:e}: fast {fast:?}, checked {other:?}",
                        position + 1
                    ),
                }
                // Short PROPS (padded out of line) when the entry is within them.
                props.truncate(position + 1);
                let short_checked =
                    matches!(friction_law_checked(&props), Ok(FrictionLaw::Coulomb(_)));
                assert_eq!(coulomb_fast(&props).is_some(), short_checked);
            }
        }
    }

    /// Values at the edges of every range test of the `PROPS` parsers: the f64 edges (signed
    /// zeros, the smallest normal and subnormals, ±f64::MAX, infinities, NaNs of both signs)
    /// and the code values 0.5, 2 and 3.
    fn range_edges() -> impl Iterator<Item = f64> {
        crate::testing::EDGE_VALUES
            .into_iter()
            .chain([0.5, 2.0, 3.0])
    }

    /// A decay-law layout (μ_s = 0.6, γ_crit = 10⁻³, μ_k = 0.3, d_c = 4) of the whole law-1 length.
    fn decay_layout() -> [f64; COULOMB_EXTENDED_NPROPS] {
        let mut decay = [0.0; COULOMB_EXTENDED_NPROPS];
        decay[..10].copy_from_slice(&[1.0, 0.6, 0.0, 0.0, 1e-3, 0.0, 0.0, 1.0, 0.3, 4.0]);
        decay
    }

    /// The edges of the extended fast path's tests (its plans' ranges, intervals and pins),
    /// value by value in every position, on a layout of each plan: decay law (with and without
    /// damping), steady transport, constant μ anisotropic (no HHT or damping) and constant μ
    /// with HHT and damping, against the checked path.
    #[test]
    fn extended_fast_path_range_edges_agree_with_checked_path() {
        let decay = decay_layout();
        let mut damped = decay;
        damped[16] = 2.0;
        let mut spinning = [0.0; COULOMB_EXTENDED_NPROPS];
        spinning[..7].copy_from_slice(&[1.0, 0.6, 0.0, 0.0, 0.0, 0.0, 3.0]);
        spinning[13] = 10.0;
        let anisotropic = CoulombBuilder::new()
            .mu(0.6)
            .mu2(0.3)
            .gamma_crit(1e-3)
            .build();
        let dynamic = CoulombBuilder::new()
            .mu(0.6)
            .hht_alpha(-0.1)
            .damping(2.0)
            .damping_clearance(0.1)
            .damping_fraction(0.5)
            .build();
        let [anisotropic, dynamic] = [anisotropic, dynamic].map(|v| {
            let mut a = [0.0; COULOMB_EXTENDED_NPROPS];
            a.copy_from_slice(&v);
            a
        });
        for layout in [decay, damped, spinning, anisotropic, dynamic] {
            assert!(fast_extended_friction_law(&layout).is_some(), "{layout:?}");
            for position in 1..COULOMB_EXTENDED_NPROPS {
                for v in range_edges() {
                    let mut props = layout;
                    props[position] = v;
                    let fast = fast_extended_friction_law(&props);
                    match coulomb_extended(&props) {
                        Ok(law) => assert_eq!(fast, Some(law), "PROPS({}) = {v:e}", position + 1),
                        Err(e) => assert!(
                            fast.is_none(),
                            "PROPS({}) = {v:e}: fast {fast:?}, checked {e}",
                            position + 1
                        ),
                    }
                }
            }
        }
    }

    /// Whether `props` (20 entries) is the decay law's lean layout, read off the entries: law
    /// 1, isotropic, elastic stick, exponential decay, PROPS(14..19) all ±0.
    fn is_lean_decay_layout(props: &[f64; COULOMB_EXTENDED_NPROPS]) -> bool {
        props[0] == 1.0
            && (props[2] == 0.0 || props[2] == props[1])
            && props[6] == 0.0
            && props[7] == 1.0
            && props[13..19].iter().all(|v| *v == 0.0)
    }

    /// The lean parser against the checked one on a lean layout: when the checked parser
    /// accepts and the layout is lean, the lean parser gives the same law; otherwise it refuses.
    fn check_lean_against_checked(props: &[f64; COULOMB_EXTENDED_NPROPS]) -> Result<(), String> {
        let lean = fast_decay_lean(props);
        match coulomb_extended(props) {
            Ok(FrictionLaw::CoulombExtended(law)) if is_lean_decay_layout(props) => {
                if lean == Some(law) {
                    Ok(())
                } else {
                    Err(format!("{props:?}: lean {lean:?}, checked {law:?}"))
                }
            }
            Ok(law) => match lean {
                None => Ok(()),
                Some(l) => Err(format!("{props:?} is not lean ({law:?}) but gave {l:?}")),
            },
            Err(e) => match lean {
                None => Ok(()),
                Some(l) => Err(format!("{props:?} is refused ({e}) but gave {l:?}")),
            },
        }
    }

    /// The rate fast path's parser ([`fast_decay_lean`]): the range edges in every
    /// position of lean decay layouts (with τ_max, p_ref, Θ(θ̄), frozen μ, PROPS(3) = μ or not)
    /// against the checked parser.
    #[test]
    fn lean_decay_parser_range_edges_agree_with_checked_path() {
        let decay = decay_layout();
        let mut full = decay;
        full[2] = 0.6;
        full[3] = 50.0;
        full[5] = 0.01;
        full[10] = 80.0;
        full[11] = 0.01;
        full[12] = 20.0;
        full[19] = 1.0;
        let mut checked_any = 0;
        for layout in [decay, full] {
            assert!(fast_decay_lean(&layout).is_some());
            for position in 0..COULOMB_EXTENDED_NPROPS {
                for v in range_edges() {
                    let mut props = layout;
                    props[position] = v;
                    if let Err(e) = check_lean_against_checked(&props) {
                        panic!("PROPS({}) = {v:e}: {e}", position + 1);
                    }
                    checked_any += usize::from(fast_decay_lean(&props).is_some());
                }
            }
        }
        // Both answers occur (the edges are not all refused).
        assert!(checked_any > 100, "{checked_any}");
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 5000, failure_persistence: None, ..ProptestConfig::default() })]

        /// The rate fast path's parser on random 20-entry layouts near the lean one (PROPS(1),
        /// PROPS(7), PROPS(8) and PROPS(14..19) mostly at their lean values).
        #[test]
        fn lean_decay_parser_agrees_with_checked_path(
            // A vector, not `uniform20`: twenty copies of the entry strategy overflow the test
            // thread's stack in a debug build.
            entries in prop::collection::vec(coulomb::tests::entry(), COULOMB_EXTENDED_NPROPS),
            keep in prop::array::uniform3(prop::bool::weighted(0.8)),
        ) {
            let mut props = [0.0; COULOMB_EXTENDED_NPROPS];
            props.copy_from_slice(&entries);
            if keep[0] {
                props[0] = 1.0;
                props[6] = 0.0;
            }
            if keep[1] {
                props[7] = 1.0;
            }
            if keep[2] {
                props[13..19].fill(0.0);
            }
            prop_assert!(check_lean_against_checked(&props).is_ok(), "{:?}", check_lean_against_checked(&props));
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 5000, failure_persistence: None, ..ProptestConfig::default() })]

        /// The extended fast path accepts exactly what the checked path accepts (up to 20
        /// entries), with the same law.
        #[test]
        fn extended_fast_and_checked_paths_agree(
            mut props in prop::collection::vec(coulomb::tests::entry(), 2..23),
            mu in prop_oneof![Just(0.0), Just(0.3), Just(-0.1), 0.0..1.0f64],
            // Steady-state transport often enough to reach its entries: PROPS(7) = 3 with
            // ω, the axis and the γ̇_crit variant (PROPS(14..16)), PROPS(5) cleared or not, the
            // other entries but μ cleared or not (else few draws are valid).
            transport in prop::option::weighted(
                0.3,
                (
                    prop_oneof![2 => 0.01..10.0f64, 1 => coulomb::tests::entry()],
                    prop_oneof![2 => (0..4).prop_map(f64::from), 1 => coulomb::tests::entry()],
                    prop_oneof![Just(0.0), Just(1.0), coulomb::tests::entry()],
                    prop::bool::ANY,
                    prop::bool::ANY,
                ),
            ),
        ) {
            props[0] = 1.0;
            props[1] = mu;
            if let Some((omega, axis, variant, clear_gamma, clear_rest)) = transport {
                if props.len() < 16 {
                    props.resize(16, 0.0);
                }
                props[6] = 3.0;
                props[13] = omega;
                props[14] = axis;
                props[15] = variant;
                if clear_gamma {
                    props[4] = 0.0;
                }
                if clear_rest {
                    for i in [2, 3, 5, 7, 8, 9, 10, 11, 12] {
                        props[i] = 0.0;
                    }
                    for v in props.iter_mut().skip(16) {
                        *v = 0.0;
                    }
                }
            }
            let fast = fast_extended_friction_law(&props);
            let checked = coulomb_extended(&props);
            match (fast, checked) {
                (Some(f), Ok(c)) => prop_assert_eq!(f, c),
                (None, Err(_)) => {}
                // Longer arrays, and the constant stick stiffness (`PROPS(7) = 4`, which no
                // fast plan takes: the checked reader reads it at every call), go the slow way.
                (None, Ok(c)) => prop_assert!(
                    props.len() > COULOMB_EXTENDED_NPROPS || props[6] == 4.0,
                    "{props:?} → {c:?}"
                ),
                (Some(f), Err(e)) => prop_assert!(false, "fast path accepted {props:?} as {f:?}: {e}"),
            }
        }
    }

    #[test]
    fn minimal_props_take_defaults() {
        let Ok(FrictionLaw::Coulomb(c)) = friction_law(&[1.0, 0.3]) else {
            panic!("plain Coulomb expected")
        };
        assert_eq!(c.mu(), 0.3);
        assert_eq!(c.shear_limit(), None);
        assert_eq!(c.critical_slip(), CriticalSlip::Tolerance(0.005));
        assert_eq!(c.stick(), StickMode::Elastic);
    }

    #[test]
    fn full_props() {
        let Ok(FrictionLaw::Coulomb(c)) = friction_law(&[1.0, 0.3, 0.0, 7.0, 1e-3, 0.01, 1.0])
        else {
            panic!("plain Coulomb expected")
        };
        assert_eq!(c.shear_limit(), Some(7.0));
        assert_eq!(c.critical_slip(), CriticalSlip::Absolute(1e-3));
        assert_eq!(c.stick(), StickMode::Exact);
    }

    #[test]
    fn bad_props_name_the_entry() {
        for (props, needle) in [
            (&[][..], "NPROPS = 0"),
            (&[1.0][..], "NPROPS = 1"),
            (&[3.0, 0.3][..], "PROPS(1) = 3"),
            (&[1.5, 0.3][..], "integer"),
            (&[1.0, -0.3][..], "PROPS(2)"),
            (&[1.0, 0.3, -0.4][..], "PROPS(3)"),
            (&[1.0, 0.3, 0.0, -1.0][..], "PROPS(4)"),
            (&[1.0, 0.3, 0.0, 0.0, -1.0][..], "PROPS(5)"),
            (&[1.0, 0.3, 0.0, 0.0, 0.0, -1.0][..], "PROPS(6)"),
            (&[1.0, 0.3, 0.0, 0.0, 0.0, 0.0, 5.0][..], "PROPS(7)"),
            (&[1.0, 0.3, 0.0, 0.0, 0.0, 0.0, 3.0][..], "PROPS(14)"),
            (
                &[
                    1.0, 0.3, 0.0, 0.0, 0.0, 0.0, 3.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 5.0, 3.0, 2.0,
                ][..],
                "PROPS(16) = 2 must select the allowable viscous slip rate",
            ),
            (&[1.0, 0.3, 0.0, 0.0, 0.0, 0.0, 0.0, 2.0][..], "PROPS(8)"),
            (
                &[1.0, 0.3, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.1][..],
                "PROPS(9)",
            ),
            (
                &[1.0, 0.3, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, -0.1, 1.0][..],
                "PROPS(9)",
            ),
            (
                &[1.0, 0.3, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.1, -1.0][..],
                "PROPS(10)",
            ),
            (
                &[1.0, 0.3, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.1, 0.0][..],
                "PROPS(10)",
            ),
            (
                &[1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.1, 1.0][..],
                "PROPS(2)",
            ),
            // μ_k/μ_s overflows with a subnormal μ_s: named by the pair, not by d_c.
            (
                &[1.0, 1e-310, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.1, 1.0][..],
                "PROPS(9) = μ_k = 0.1 over PROPS(2) = μ_s = 1e-310: μ_k/μ_s = inf overflows",
            ),
            (
                &[1.0, 0.3, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -5.0][..],
                "PROPS(11)",
            ),
            (
                &[
                    1.0,
                    0.3,
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                    f64::NAN,
                ][..],
                "PROPS(12)",
            ),
            (
                &[
                    1.0, 0.3, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 20.0,
                ][..],
                "PROPS(13)",
            ),
            (
                &[
                    1.0, 0.3, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.5,
                ][..],
                "PROPS(14)",
            ),
            (
                &[
                    1.0, 0.3, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0,
                ][..],
                "PROPS(15)",
            ),
            (
                &[
                    1.0, 0.3, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
                    -2.0,
                ][..],
                "PROPS(17)",
            ),
            (
                &[
                    1.0, 0.3, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
                    0.0, 1.0,
                ][..],
                "PROPS(18)",
            ),
            (
                &[
                    1.0, 0.3, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
                    1.0, 1.0, 1.5,
                ][..],
                "PROPS(19)",
            ),
            (
                &[
                    1.0, 0.3, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
                    0.0, 0.0, 0.0, 1.0,
                ][..],
                "PROPS(20)",
            ),
            (
                &[
                    1.0, 0.3, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.1, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
                    0.0, 0.0, 0.0, 2.0,
                ][..],
                "PROPS(20)",
            ),
            (
                &[
                    1.0, 0.3, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
                    0.0, 0.0, 0.0, 0.0, 1.0,
                ][..],
                "PROPS(21)",
            ),
        ] {
            let e = friction_law(props).unwrap_err().to_string();
            assert!(e.contains(needle), "{props:?}: {e}");
        }
    }
}
