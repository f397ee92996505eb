//! The interface pore-pressure kernel (seed 000): its linearization against central finite
//! differences of its own residual in every variant and basis, each simplification (closed
//! contact, steady state, small sliding) against the general form under its assumptions, the
//! side-swap invariant, and bad input refused through `ifl_pore_pressure` and its
//! length-carrying form `ifl_pore_pressure_n`.
// Entries of 4-vectors and 4×4 matrices compared index by index read best with indices.
#![allow(clippy::needless_range_loop)]

use std::ffi::CStr;

use interfacial::abi::{
    IflPorePressureVariant, IflStatus, ifl_last_error, ifl_pore_pressure, ifl_pore_pressure_n,
};
use interfacial::laws::pore_pressure::{
    Basis, Contact, H, InterfacePoint, P_JUMP, P_MEAN, PointFault, PorePressureTerms, Q_HAT,
    Regime, Sliding, Variant, interface_terms,
};
use proptest::prelude::*;

fn all_variants() -> Vec<Variant> {
    let mut v = Vec::new();
    for contact in [Contact::Open, Contact::Closed] {
        for regime in [Regime::Transient, Regime::Steady] {
            for sliding in [Sliding::Small, Sliding::Finite] {
                v.push(Variant {
                    contact,
                    regime,
                    sliding,
                });
            }
        }
    }
    v
}

const POINT: InterfacePoint = InterfacePoint {
    p1: 130.0,
    p2: 70.0,
    q_hat: -2.5e-3,
    h: 4e-4,
    dh: 1.5e-4,
    dt: 0.8,
};

fn terms(point: &InterfacePoint, variant: Variant, basis: Basis) -> PorePressureTerms {
    interface_terms(point, variant).unwrap().in_basis(basis)
}

/// The point moved along unknown `j` of `basis` by `e` (h moves with Δh: the start-of-increment
/// opening h − Δh is fixed).
fn moved(point: &InterfacePoint, basis: Basis, j: usize, e: f64) -> InterfacePoint {
    let mut p = *point;
    match (basis, j) {
        (_, H) => {
            p.h += e;
            p.dh += e;
        }
        (_, Q_HAT) => p.q_hat += e,
        (Basis::PerSide, P_MEAN) => p.p1 += e,
        (Basis::PerSide, _) => p.p2 += e,
        // p̄ += e moves both sides; p̂ += e moves them apart.
        (Basis::MeanJump, P_MEAN) => {
            p.p1 += e;
            p.p2 += e;
        }
        (Basis::MeanJump, _) => {
            p.p1 += e;
            p.p2 -= e;
        }
    }
    p
}

#[test]
fn tangent_matches_central_differences_in_every_variant_and_basis() {
    for variant in all_variants() {
        for basis in [Basis::MeanJump, Basis::PerSide] {
            let t = terms(&POINT, variant, basis);
            for j in 0..4 {
                let e = 1e-3;
                let plus = terms(&moved(&POINT, basis, j, e), variant, basis).residual;
                let minus = terms(&moved(&POINT, basis, j, -e), variant, basis).residual;
                for i in 0..4 {
                    let fd = (plus[i] - minus[i]) / (2.0 * e);
                    // The residual is linear in the unknowns: central differences are exact up to
                    // the round-off of the residual (|r| ≤ 130) divided by 2e.
                    assert!(
                        (fd - t.tangent[i][j]).abs() <= 1e-9,
                        "{variant:?} {basis:?}: d r[{i}]/d x[{j}] = {} but FD {fd}",
                        t.tangent[i][j]
                    );
                }
            }
        }
    }
}

#[test]
fn the_tangent_has_the_seed_entries() {
    // Open, transient: dh δp̄ + dp̄ δh + Δt (dq̂ δp̂ + dp̂ δq̂), with the leading minus.
    let t = terms(&POINT, Variant::GENERAL, Basis::MeanJump);
    let mut expected = [[0.0; 4]; 4];
    expected[P_MEAN][H] = -1.0;
    expected[H][P_MEAN] = -1.0;
    expected[P_JUMP][Q_HAT] = -POINT.dt;
    expected[Q_HAT][P_JUMP] = -POINT.dt;
    assert_eq!(t.tangent, expected);
    // Residual by hand: p̄ = 100, p̂ = 30.
    assert_eq!(
        t.residual,
        [-100.0, -POINT.dh, -POINT.dt * POINT.q_hat, -POINT.dt * 30.0]
    );
    // Per side by hand: δp̄ = (δp₁ + δp₂)/2, δp̂ = (δp₁ − δp₂)/2.
    let s = terms(&POINT, Variant::GENERAL, Basis::PerSide);
    let r_p1 = 0.5 * (-POINT.dh) + 0.5 * (-POINT.dt * POINT.q_hat);
    let r_p2 = 0.5 * (-POINT.dh) - 0.5 * (-POINT.dt * POINT.q_hat);
    assert_eq!(s.residual, [-100.0, r_p1, r_p2, -POINT.dt * 30.0]);
    // ∂(−Δt p̂)/∂p₂ = +Δt/2; the per-side tangent stays symmetric.
    assert_eq!(s.tangent[Q_HAT][2], 0.5 * POINT.dt);
    for i in 0..4 {
        for j in 0..4 {
            assert_eq!(s.tangent[i][j], s.tangent[j][i]);
        }
    }
}

#[test]
fn closed_contact_is_the_general_form_with_no_opening() {
    for regime in [Regime::Transient, Regime::Steady] {
        for sliding in [Sliding::Small, Sliding::Finite] {
            let open = Variant {
                contact: Contact::Open,
                regime,
                sliding,
            };
            let closed = Variant {
                contact: Contact::Closed,
                ..open
            };
            // Δh = 0 in the general form gives the closed residual and geometric terms...
            let still = InterfacePoint { dh: 0.0, ..POINT };
            let g = terms(&still, open, Basis::MeanJump);
            let c = terms(&POINT, closed, Basis::MeanJump);
            assert_eq!(c.residual, g.residual);
            assert_eq!(c.geometric, g.geometric);
            // ...and dh = 0 removes the column of h from its tangent.
            for i in 0..4 {
                for j in 0..4 {
                    let expected = if j == H { 0.0 } else { g.tangent[i][j] };
                    assert_eq!(
                        c.tangent[i][j], expected,
                        "{regime:?} {sliding:?} [{i}][{j}]"
                    );
                }
            }
        }
    }
}

#[test]
fn steady_state_is_the_closed_transient_form_in_rate_form() {
    // The steady form drops the transient terms (Δh δp̄) and writes the flow in rate form: the
    // closed transient form with the factor Δt set to 1, whatever the contact flag.
    for contact in [Contact::Open, Contact::Closed] {
        for sliding in [Sliding::Small, Sliding::Finite] {
            let steady = Variant {
                contact,
                regime: Regime::Steady,
                sliding,
            };
            let closed_transient = Variant {
                contact: Contact::Closed,
                regime: Regime::Transient,
                sliding,
            };
            let unit = InterfacePoint { dt: 1.0, ..POINT };
            for basis in [Basis::MeanJump, Basis::PerSide] {
                assert_eq!(
                    terms(&POINT, steady, basis),
                    terms(&unit, closed_transient, basis)
                );
            }
        }
    }
}

#[test]
fn small_sliding_drops_only_the_geometric_terms() {
    for v in all_variants()
        .into_iter()
        .filter(|v| v.sliding == Sliding::Finite)
    {
        let small = Variant {
            sliding: Sliding::Small,
            ..v
        };
        for basis in [Basis::MeanJump, Basis::PerSide] {
            let f = terms(&POINT, v, basis);
            let s = terms(&POINT, small, basis);
            assert_eq!(s.residual, f.residual);
            assert_eq!(s.tangent, f.tangent);
            assert_eq!(s.geometric, [0.0; 4]);
            // The integrand is bilinear: each geometric term has the residual's coefficient.
            assert_eq!(f.geometric, f.residual);
        }
    }
}

fn swapped(p: &InterfacePoint) -> InterfacePoint {
    InterfacePoint {
        p1: p.p2,
        p2: p.p1,
        q_hat: -p.q_hat,
        ..*p
    }
}

proptest! {
    #[test]
    fn swapping_the_sides_flips_the_jump_and_the_flux_and_nothing_else(
        p1 in -1e6f64..1e6, p2 in -1e6f64..1e6, q in -1e3f64..1e3, h in -1.0f64..1.0,
        dh in -1.0f64..1.0, dt in 1e-6f64..1e3, which in 0usize..8,
    ) {
        let v = all_variants()[which];
        let p = InterfacePoint { p1, p2, q_hat: q, h, dh, dt };
        let a = terms(&p, v, Basis::MeanJump);
        let b = terms(&swapped(&p), v, Basis::MeanJump);
        let flip = [1.0, 1.0, -1.0, -1.0];
        for i in 0..4 {
            prop_assert_eq!(b.residual[i], flip[i] * a.residual[i]);
            prop_assert_eq!(b.geometric[i], flip[i] * a.geometric[i]);
        }
        prop_assert_eq!(b.tangent, a.tangent);
        // Per side the swap exchanges the two pressure entries and negates the q̂ entry.
        let a = terms(&p, v, Basis::PerSide);
        let b = terms(&swapped(&p), v, Basis::PerSide);
        let perm = [0usize, 2, 1, 3];
        let sign = [1.0, 1.0, 1.0, -1.0];
        for i in 0..4 {
            prop_assert_eq!(b.residual[i], sign[i] * a.residual[perm[i]]);
            for j in 0..4 {
                prop_assert_eq!(b.tangent[i][j], sign[i] * sign[j] * a.tangent[perm[i]][perm[j]]);
            }
        }
    }

    #[test]
    fn finite_input_never_gives_nan_through_the_abi(
        p1 in prop::num::f64::NORMAL | prop::num::f64::ZERO,
        p2 in prop::num::f64::NORMAL | prop::num::f64::ZERO,
        q in prop::num::f64::NORMAL | prop::num::f64::ZERO,
        dt in prop::num::f64::POSITIVE,
        flags in 0i32..16,
    ) {
        let (v, _, _) = decoded(flags);
        let (status, r, t, g) = call(v, [p1, p2, q, 0.0, 0.0, dt]);
        prop_assert!(matches!(status, IflStatus::Ok | IflStatus::NumericalFailure | IflStatus::BadInput));
        prop_assert!(r.iter().chain(t.iter()).chain(g.iter()).all(|x| x.is_finite()));
        if status != IflStatus::Ok {
            prop_assert!(r.iter().chain(t.iter()).chain(g.iter()).all(|x| *x == 0.0));
        }
    }
}

type Outputs = (IflStatus, [f64; 4], [f64; 16], [f64; 4]);

/// The reference point as the entry points' scalar arguments `p1, p2, q_hat, h, dh, dt`.
const GOOD: [f64; 6] = [POINT.p1, POINT.p2, POINT.q_hat, POINT.h, POINT.dh, POINT.dt];

/// The outputs of one call of `entry` on `RESIDUAL(4)`, `TANGENT(4,4)`, `GEOMETRIC(4)`
/// prefilled with 7 (so that what the call wrote shows).
fn outputs(entry: impl FnOnce(*mut f64, *mut f64, *mut f64) -> IflStatus) -> Outputs {
    let (mut r, mut t, mut g) = ([7.0; 4], [7.0; 16], [7.0; 4]);
    let s = entry(r.as_mut_ptr(), t.as_mut_ptr(), g.as_mut_ptr());
    (s, r, t, g)
}

fn call(v: IflPorePressureVariant, x: [f64; 6]) -> Outputs {
    let [p1, p2, q, h, dh, dt] = x;
    // SAFETY: arrays of 4, 16 and 4 doubles; a NUL-terminated name.
    outputs(|r, t, g| unsafe {
        ifl_pore_pressure(c"column".as_ptr(), v, p1, p2, q, h, dh, dt, r, t, g)
    })
}

fn last_error() -> String {
    // SAFETY: the library's thread-local buffer, NUL-terminated.
    unsafe { CStr::from_ptr(ifl_last_error()) }
        .to_string_lossy()
        .into_owned()
}

const GENERAL_FLAGS: IflPorePressureVariant = IflPorePressureVariant {
    open: 1,
    steady: 0,
    finite_sliding: 1,
    per_side: 0,
};

#[test]
fn the_abi_returns_the_core_terms_in_fortran_order() {
    for per_side in [0, 1] {
        let v = IflPorePressureVariant {
            per_side,
            ..GENERAL_FLAGS
        };
        let x = GOOD;
        let (s, r, t, g) = call(v, x);
        assert_eq!(s, IflStatus::Ok);
        let basis = if per_side == 1 {
            Basis::PerSide
        } else {
            Basis::MeanJump
        };
        let core = terms(&POINT, Variant::GENERAL, basis);
        assert_eq!(r, core.residual);
        assert_eq!(g, core.geometric);
        for i in 0..4 {
            for j in 0..4 {
                // TANGENT(i,j) of a Fortran TANGENT(4,4).
                assert_eq!(t[i + 4 * j], core.tangent[i][j]);
            }
        }
    }
}

#[test]
fn bad_input_is_refused_with_a_clear_message_and_zero_outputs() {
    let good = GOOD;
    let cases: [(IflPorePressureVariant, usize, f64, IflStatus, &str); 7] = [
        (
            GENERAL_FLAGS,
            0,
            f64::NAN,
            IflStatus::BadInput,
            "p1 = NaN is not finite",
        ),
        (
            GENERAL_FLAGS,
            2,
            f64::INFINITY,
            IflStatus::BadInput,
            "q_hat = inf",
        ),
        (
            GENERAL_FLAGS,
            4,
            f64::NEG_INFINITY,
            IflStatus::BadInput,
            "dh = -inf",
        ),
        (
            GENERAL_FLAGS,
            5,
            0.0,
            IflStatus::BadInput,
            "dt = 0: a transient point",
        ),
        (GENERAL_FLAGS, 5, -1.0, IflStatus::BadInput, "dt = -1"),
        (
            IflPorePressureVariant {
                steady: 2,
                ..GENERAL_FLAGS
            },
            0,
            POINT.p1,
            IflStatus::BadParameter,
            "variant.steady = 2; expected 0 or 1",
        ),
        (
            GENERAL_FLAGS,
            5,
            1e300,
            IflStatus::NumericalFailure,
            "overflow",
        ),
    ];
    for (v, index, value, status, cause) in cases {
        let mut x = good;
        x[index] = value;
        if status == IflStatus::NumericalFailure {
            x[2] = 1e300;
        }
        let (s, r, t, g) = call(v, x);
        assert_eq!(s, status, "{cause}");
        let msg = last_error();
        assert!(
            msg.contains("ifl_pore_pressure")
                && msg.contains("interaction 'column'")
                && msg.contains(cause),
            "{msg}"
        );
        assert_eq!((r, t, g), ([0.0; 4], [0.0; 16], [0.0; 4]));
    }
    // The steady state does not read dt: a zero or NaN time increment is accepted there.
    let steady = IflPorePressureVariant {
        steady: 1,
        ..GENERAL_FLAGS
    };
    let mut x = good;
    x[5] = f64::NAN;
    assert_eq!(call(steady, x).0, IflStatus::Ok);
    // A NULL output is refused, the others zeroed.
    let (mut r, mut g) = ([7.0; 4], [7.0; 4]);
    // SAFETY: NULL tangent is the case under test; the other arrays hold 4 doubles.
    let s = unsafe {
        ifl_pore_pressure(
            std::ptr::null(),
            GENERAL_FLAGS,
            1.0,
            1.0,
            0.0,
            0.0,
            0.0,
            1.0,
            r.as_mut_ptr(),
            std::ptr::null_mut(),
            g.as_mut_ptr(),
        )
    };
    assert_eq!(s, IflStatus::BadInput);
    assert!(last_error().contains("NULL"), "{}", last_error());
    assert_eq!((r, g), ([0.0; 4], [0.0; 4]));
}

#[test]
fn every_flag_combination_returns_the_core_terms_bit_for_bit() {
    // The ABI answers valid points on a lean path specialised per variant; it must give the
    // checked core's terms exactly.
    for flags in 0..16 {
        let (v, variant, basis) = decoded(flags);
        let out = call(v, GOOD);
        assert_eq!(out.0, IflStatus::Ok, "flags {flags}");
        assert_bitwise(
            &out,
            &terms(&POINT, variant, basis),
            &format!("flags {flags}"),
        );
    }
}

/// The ABI's outputs are the core's terms bit for bit (`TANGENT(4,4)` in Fortran order).
fn assert_bitwise(out: &Outputs, core: &PorePressureTerms, context: &str) {
    let bits = |a: &[f64]| a.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
    let (_, r, t, g) = out;
    assert_eq!(bits(r), bits(&core.residual), "{context}");
    assert_eq!(bits(g), bits(&core.geometric), "{context}");
    let core_t: Vec<f64> = (0..16).map(|k| core.tangent[k % 4][k / 4]).collect();
    assert_eq!(bits(t), bits(&core_t), "{context}");
}

/// `ifl_pore_pressure_n` on `len` bytes of `name` (NULL for `None`).
fn call_n(name: Option<&[u8]>, len: usize, v: IflPorePressureVariant, x: [f64; 6]) -> Outputs {
    let [p1, p2, q, h, dh, dt] = x;
    let name = name.map_or(std::ptr::null(), |n| n.as_ptr().cast());
    // SAFETY: `len` <= readable bytes of a non-NULL name (the callers'); a NULL name is
    // allowed; arrays of 4, 16 and 4 doubles.
    outputs(|r, t, g| unsafe { ifl_pore_pressure_n(name, len, v, p1, p2, q, h, dh, dt, r, t, g) })
}

#[test]
fn the_length_carrying_form_answers_as_the_nul_terminated_one() {
    let good = GOOD;
    let bits = |o: &Outputs| {
        (
            o.0,
            o.1.map(f64::to_bits),
            o.2.map(f64::to_bits),
            o.3.map(f64::to_bits),
        )
    };
    for flags in 0..16 {
        let (v, _, _) = decoded(flags);
        assert_eq!(
            bits(&call_n(Some(b"column"), 6, v, good)),
            bits(&call(v, good)),
            "flags {flags}"
        );
    }
}

#[test]
fn the_length_carrying_form_reads_only_its_length_and_needs_no_nul() {
    let mut x = GOOD;
    x[5] = 0.0;
    // A Fortran CHARACTER*12: blank-padded, no NUL, and bytes after it that are not the name's.
    let buffer = b"column      XYZ";
    let (s, r, t, g) = call_n(Some(buffer), 12, GENERAL_FLAGS, x);
    assert_eq!(s, IflStatus::BadInput);
    let msg = last_error();
    assert!(
        msg.contains(
            "ifl_pore_pressure_n (or the Fortran module's ifl_pore_pressure): interaction 'column' "
        ) && msg.contains("dt = 0"),
        "{msg}"
    );
    assert!(!msg.contains("XYZ"), "{msg}");
    assert_eq!((r, t, g), ([0.0; 4], [0.0; 16], [0.0; 4]));
    // Length 0 (any pointer, here NULL) and a NULL name with a length: no name, same refusal.
    for len in [0, 5] {
        let (s, r, t, g) = call_n(None, len, GENERAL_FLAGS, x);
        assert_eq!(s, IflStatus::BadInput);
        assert!(last_error().contains("interaction ''"), "{}", last_error());
        assert_eq!((r, t, g), ([0.0; 4], [0.0; 16], [0.0; 4]));
    }
}

/// The flags of `flags` (bit 0 open, 1 steady, 2 finite sliding, 3 per side) as the ABI's
/// struct and as the core's variant and basis.
fn decoded(flags: i32) -> (IflPorePressureVariant, Variant, Basis) {
    let v = IflPorePressureVariant {
        open: flags & 1,
        steady: (flags >> 1) & 1,
        finite_sliding: (flags >> 2) & 1,
        per_side: (flags >> 3) & 1,
    };
    let variant = Variant {
        contact: [Contact::Closed, Contact::Open][(flags & 1) as usize],
        regime: [Regime::Transient, Regime::Steady][((flags >> 1) & 1) as usize],
        sliding: [Sliding::Small, Sliding::Finite][((flags >> 2) & 1) as usize],
    };
    let basis = [Basis::MeanJump, Basis::PerSide][((flags >> 3) & 1) as usize];
    (v, variant, basis)
}

#[test]
fn the_abi_refuses_exactly_what_the_checked_core_refuses() {
    // The ABI's fast path folds its checks into one comparison on the results; the checked
    // core validates input by input. Every special value in every input (and the pairs that
    // cancel or overflow together), in every flag combination: same status, and on success the
    // same terms bit for bit.
    let specials = [
        1.0,
        -2.5,
        0.0,
        -0.0,
        5e-324,
        1e300,
        -1e300,
        f64::MAX,
        f64::MIN,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NAN,
    ];
    let good = GOOD;
    let mut inputs: Vec<[f64; 6]> = Vec::new();
    for i in 0..6 {
        for &x in &specials {
            let mut p = good;
            p[i] = x;
            inputs.push(p);
        }
    }
    for (i, j) in [(0, 1), (2, 5), (0, 5), (1, 5)] {
        for &x in &specials {
            for &y in &specials {
                let mut p = good;
                p[i] = x;
                p[j] = y;
                inputs.push(p);
            }
        }
    }
    let mut refused = 0;
    for flags in 0..16 {
        let (v, variant, basis) = decoded(flags);
        for x in &inputs {
            let point = InterfacePoint {
                p1: x[0],
                p2: x[1],
                q_hat: x[2],
                h: x[3],
                dh: x[4],
                dt: x[5],
            };
            let out = call(v, *x);
            let (s, r, t, g) = out;
            match interface_terms(&point, variant) {
                Ok(core) => {
                    assert_eq!(s, IflStatus::Ok, "flags {flags}, {x:?}");
                    let context = format!("flags {flags}, {x:?}");
                    assert_bitwise(&out, &core.in_basis(basis), &context);
                }
                Err(fault) => {
                    refused += 1;
                    let want = if fault == PointFault::Overflow {
                        IflStatus::NumericalFailure
                    } else {
                        IflStatus::BadInput
                    };
                    assert_eq!(s, want, "flags {flags}, {x:?}: {fault}");
                    assert_eq!((r, t, g), ([0.0; 4], [0.0; 16], [0.0; 4]));
                }
            }
        }
    }
    // The sweep reaches refusals of both kinds, not only accepted points.
    assert!(refused > 1000, "{refused}");
}

#[test]
fn a_flag_other_than_0_or_1_is_refused_naming_the_flag() {
    let x = GOOD;
    for bad in [-1, 2, i32::MIN, i32::MAX] {
        for (k, name) in ["open", "steady", "finite_sliding", "per_side"]
            .into_iter()
            .enumerate()
        {
            let mut flags = [0; 4];
            flags[k] = bad;
            let v = IflPorePressureVariant {
                open: flags[0],
                steady: flags[1],
                finite_sliding: flags[2],
                per_side: flags[3],
            };
            let (s, r, t, g) = call(v, x);
            assert_eq!(s, IflStatus::BadParameter, "{name} = {bad}");
            let msg = last_error();
            assert!(
                msg.contains(&format!("variant.{name} = {bad}; expected 0 or 1")),
                "{msg}"
            );
            assert_eq!((r, t, g), ([0.0; 4], [0.0; 16], [0.0; 4]));
        }
    }
}

#[test]
fn a_success_leaves_the_last_error_as_every_entry_point_does() {
    // docs/install.md: a successful call does not clear the thread's last error.
    let good = GOOD;
    let mut bad = good;
    bad[0] = f64::NAN;
    assert_eq!(call(GENERAL_FLAGS, bad).0, IflStatus::BadInput);
    let before = last_error();
    assert!(before.contains("p1 = NaN"), "{before}");
    assert_eq!(call(GENERAL_FLAGS, good).0, IflStatus::Ok);
    assert_eq!(
        call_n(Some(b"column"), 6, GENERAL_FLAGS, good).0,
        IflStatus::Ok
    );
    assert_eq!(last_error(), before);
    interfacial::abi::ifl_clear_error();
    assert_eq!(last_error(), "");
}
