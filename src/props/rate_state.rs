//! `PROPS` layout of rate-and-state friction (`PROPS(1) = 3`, [`crate::laws::rate_state`]),
//! described once in [`RATE_STATE`]: the checked parser, the defaults, [`RateStateBuilder`]
//! and the docs/props.md table all come from it (src/props/schema.rs).

use crate::LawError;
use crate::laws::coulomb::{Coulomb, DEFAULT_SLIP_TOLERANCE};
use crate::laws::rate_state::{CoefficientForm, RateState, RateStateParameters, StateEvolution};

use super::builder::{LawBuilder, entry_setters};
use super::schema::Default::{self, Described, Required};
use super::schema::{Class, Entry, Layout, Rule};

/// `PROPS(1)` code of rate-and-state friction.
pub const LAW_RATE_STATE: i32 = 3;

/// Number of `PROPS` entries the law reads (`PROPS(1..11)`).
pub const RATE_STATE_NPROPS: usize = RATE_STATE.entries.len();

/// The rate-and-state layout (the symbols of the rate-and-state literature).
#[rustfmt::skip]
pub const RATE_STATE: Layout = Layout {
    law: "rate-and-state law",
    code: LAW_RATE_STATE,
    entries: &[
        Entry::law_code(LAW_RATE_STATE),
        Entry::new(2, "mu0", "steady-state friction coefficient at V₀", Class::NonNegative)
            .symbol("μ₀").when_absent(Required),
        Entry::new(3, "a", "direct-effect coefficient", Class::NonNegative)
            .symbol("a").when_absent(Required),
        Entry::new(4, "b", "evolution-effect coefficient", Class::Finite)
            .symbol("b").note("b > a: velocity weakening"),
        Entry::new(5, "v0", "reference slip rate", Class::Positive)
            .symbol("V₀").unit("velocity").when_absent(Required),
        Entry::new(6, "L", "characteristic slip distance of the state evolution", Class::Positive)
            .symbol("L").unit("length").when_absent(Required).note("also D_c"),
        Entry::new(7, "evolution", "state evolution law", EVOLUTION),
        Entry::new(8, "form", "expression of μ", FORM),
        Entry::new(9, "gamma_crit", "allowable elastic slip", Class::OffOrPositive)
            .symbol("γ_crit").unit("length")
            .when_absent(Described("`PROPS(10)` × `CHRLNGTH`")).note("absolute"),
        Entry::new(10, "slip_tolerance", "slip tolerance", Class::OffOrPositive)
            .when_absent(Default::Value(DEFAULT_SLIP_TOLERANCE))
            .note("γ_crit = tolerance × `CHRLNGTH`"),
        Entry::new(11, "theta0", "initial state θ (read when `STATEV(4)` = 0)", Class::OffOrPositive)
            .symbol("θ₀").unit("time").when_absent(Described("L/V₀, the steady state at V₀")),
    ],
    rules: &[Rule::PositiveWhen {
        entry: 3,
        on: 8,
        value: 1,
        why: "the regularised form divides by a",
    }],
    variants: &[],
};

/// `PROPS(7)`.
const EVOLUTION: Class = Class::Choice(&[
    (0, "aging law dθ/dt = 1 − Vθ/L"),
    (1, "slip law dθ/dt = −(Vθ/L)·ln(Vθ/L)"),
]);

/// `PROPS(8)`.
const FORM: Class = Class::Choice(&[
    (0, "μ₀ + a·ln(V/V₀) + b·ln(V₀θ/L)"),
    (
        1,
        "regularised a·asinh(V/(2V₀)·exp((μ₀ + b·ln(V₀θ/L))/a)), finite at V → 0",
    ),
]);

/// A law-3 `PROPS` array built by entry name (tests, scenes, fuzz decoders): every entry
/// starts at its "0 / absent" value, `PROPS(1) = 3`.
pub type RateStateBuilder = LawBuilder<LAW_RATE_STATE>;

impl RateStateBuilder {
    entry_setters!("law 3", {
        mu0 => "mu0",
        a => "a",
        b => "b",
        v0 => "v0",
        l => "L",
        evolution => "evolution",
        form => "form",
        gamma_crit => "gamma_crit",
        slip_tolerance => "slip_tolerance",
        theta0 => "theta0",
    });
}

/// The law of `PROPS(1) = 3`: the layout's check (classes, rules, messages naming the entry),
/// then the law from the validated entries.
pub fn rate_state(props: &[f64]) -> Result<RateState, LawError> {
    let e = RATE_STATE.check::<RATE_STATE_NPROPS>(props)?;
    let p = RateStateParameters {
        mu0: e[1],
        a: e[2],
        b: e[3],
        v0: e[4],
        l: e[5],
        evolution: if e[6] == 1.0 {
            StateEvolution::Slip
        } else {
            StateEvolution::Aging
        },
        form: if e[7] == 1.0 {
            CoefficientForm::Regularized
        } else {
            CoefficientForm::Logarithmic
        },
    };
    // γ_crit as law 1 takes it: absolute when given, else the tolerance × CHRLNGTH.
    let stick = if e[8] > 0.0 {
        Coulomb::new(e[1]).and_then(|c| c.with_critical_slip_absolute(e[8]))
    } else {
        let tolerance = if e[9] > 0.0 {
            e[9]
        } else {
            DEFAULT_SLIP_TOLERANCE
        };
        Coulomb::new(e[1]).and_then(|c| c.with_slip_tolerance(tolerance))
    }?;
    RateState::new(p, stick, e[10])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn builder_reaches_its_entries_and_the_law_reads_them() {
        let props = RateStateBuilder::new()
            .mu0(0.6)
            .a(0.01)
            .b(0.015)
            .v0(1e-6)
            .l(1e-5)
            .evolution(1.0)
            .form(1.0)
            .gamma_crit(1e-7)
            .theta0(3.0)
            .build();
        assert_eq!(props.len(), 11);
        assert_eq!(props[0], 3.0);
        let law = rate_state(&props).unwrap();
        let p = law.parameters();
        assert_eq!((p.mu0, p.a, p.b, p.v0, p.l), (0.6, 0.01, 0.015, 1e-6, 1e-5));
        assert_eq!(p.evolution, StateEvolution::Slip);
        assert_eq!(p.form, CoefficientForm::Regularized);
        assert_eq!(law.theta_initial(), 3.0);
        // θ₀ absent: L/V₀.
        let short = RateStateBuilder::new()
            .mu0(0.6)
            .a(0.01)
            .v0(1e-6)
            .l(1e-5)
            .build_first(6);
        assert_eq!(rate_state(&short).unwrap().theta_initial(), 1e-5 / 1e-6);
    }

    #[test]
    fn bad_entries_are_named() {
        let good = RateStateBuilder::new()
            .mu0(0.6)
            .a(0.01)
            .b(0.015)
            .v0(1e-6)
            .l(1e-5);
        for (props, index) in [
            (good.clone().a(-0.01).build(), "PROPS(3)"),
            (good.clone().v0(0.0).build(), "PROPS(5)"),
            (good.clone().v0(-1.0).build(), "PROPS(5)"),
            (good.clone().l(0.0).build(), "PROPS(6)"),
            (good.clone().l(f64::NAN).build(), "PROPS(6)"),
            (good.clone().evolution(2.0).build(), "PROPS(7)"),
            (good.clone().form(0.5).build(), "PROPS(8)"),
            (good.clone().a(0.0).form(1.0).build(), "PROPS(3)"),
            (good.clone().theta0(-1.0).build(), "PROPS(11)"),
            (good.build_first(5), "NPROPS"),
        ] {
            let msg = rate_state(&props).unwrap_err().to_string();
            assert!(msg.contains(index), "{index}: {msg}");
        }
    }
}
