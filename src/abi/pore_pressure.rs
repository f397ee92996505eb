//! `ifl_pore_pressure` and `ifl_pore_pressure_n` (the same with a length-carrying name): the
//! interface pore-pressure kernel (seed 000, interface pore pressure) through the native API.
//! No physics here: flags are decoded, pointers checked, and [`crate::laws::pore_pressure`]
//! does the rest.

use std::ffi::{CStr, c_char, c_int};

use super::native::IflStatus;
use super::{boundary, write_array};
use crate::LawError;
use crate::laws::pore_pressure::{
    Basis, Contact, InterfacePoint, PorePressureTerms, Regime, Sliding, Variant, interface_terms,
    interface_terms_lean,
};
use crate::report::Site;

/// The variant of the interface pore-pressure kernel, one integer flag per choice (each 0 or 1;
/// any other value is refused with `IFL_STATUS_BAD_PARAMETER`). All zeros is the closed-contact,
/// transient, small-sliding form in the (h, p̄, p̂, q̂) basis, the form most hosts need.
///
/// Fortran: `type, bind(C) :: ifl_pore_pressure_variant; integer(c_int) :: open, steady,
/// finite_sliding, per_side; end type`, passed by value.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct IflPorePressureVariant {
    /// 0 = closed contact (Δh = 0, dh = 0), 1 = open contact (the gap's volume change Δh
    /// enters both sides' mass balance).
    pub open: c_int,
    /// 0 = transient (fluxes integrated over Δt, Δt > 0 required), 1 = steady state (rate form;
    /// `dt` is not read and the contact flag has no effect).
    pub steady: c_int,
    /// 0 = small sliding (geometric coefficients written as zeros), 1 = finite sliding.
    pub finite_sliding: c_int,
    /// 0 = unknowns (h, p̄, p̂, q̂), 1 = unknowns (h, p₁, p₂, q̂).
    pub per_side: c_int,
}

/// A flag of the variant: 0 or 1, anything else refused by name.
fn flag(name: &str, v: c_int) -> Result<(), LawError> {
    match v {
        0 | 1 => Ok(()),
        other => Err(LawError::Parameter(format!(
            "variant.{name} = {other}; expected 0 or 1"
        ))),
    }
}

/// The lean path for the variant whose flags are the bits of `FLAGS` (open, steady,
/// finite_sliding, per_side from bit 0): writes the terms and returns true, or returns false
/// (nothing written) when the inputs need the careful path.
///
/// # Safety
/// `residual`, `tangent` and `geometric` are non-NULL and point to 4, 16 and 4 writable doubles.
#[inline(always)]
unsafe fn lean_as<const FLAGS: c_int>(
    point: &InterfacePoint,
    (residual, tangent, geometric): (*mut f64, *mut f64, *mut f64),
) -> bool {
    let Some((variant, basis)) = decode_lean(IflPorePressureVariant {
        open: FLAGS & 1,
        steady: (FLAGS >> 1) & 1,
        finite_sliding: (FLAGS >> 2) & 1,
        per_side: (FLAGS >> 3) & 1,
    }) else {
        return false;
    };
    match interface_terms_lean(point, variant) {
        Some(t) => {
            // SAFETY: non-NULL, 4, 16 and 4 writable doubles (this function's contract).
            unsafe { write_terms(residual, tangent, geometric, &t.in_basis(basis)) };
            true
        }
        None => false,
    }
}

/// [`decode`] without messages: `None` for a flag other than 0 or 1.
#[inline(always)]
fn decode_lean(v: IflPorePressureVariant) -> Option<(Variant, Basis)> {
    if (v.open | v.steady | v.finite_sliding | v.per_side) & !1 != 0 {
        return None;
    }
    Some(variant_of(v))
}

/// The flags, each 0 or 1, read as the kernel's variant and basis, or the first flag (in the
/// order of the fields) that is neither, named.
fn decode(v: IflPorePressureVariant) -> Result<(Variant, Basis), LawError> {
    flag("open", v.open)?;
    flag("steady", v.steady)?;
    flag("finite_sliding", v.finite_sliding)?;
    flag("per_side", v.per_side)?;
    Ok(variant_of(v))
}

/// The variant and basis of flags already checked to be 0 or 1 (1 selects the named choice).
#[inline(always)]
fn variant_of(v: IflPorePressureVariant) -> (Variant, Basis) {
    let variant = Variant {
        contact: if v.open == 1 {
            Contact::Open
        } else {
            Contact::Closed
        },
        regime: if v.steady == 1 {
            Regime::Steady
        } else {
            Regime::Transient
        },
        sliding: if v.finite_sliding == 1 {
            Sliding::Finite
        } else {
            Sliding::Small
        },
    };
    let basis = if v.per_side == 1 {
        Basis::PerSide
    } else {
        Basis::MeanJump
    };
    (variant, basis)
}

/// The kernel's point from the entry points' scalar arguments (end of increment).
#[inline(always)]
fn interface_point(p1: f64, p2: f64, q_hat: f64, h: f64, dh: f64, dt: f64) -> InterfacePoint {
    InterfacePoint {
        p1,
        p2,
        q_hat,
        h,
        dh,
        dt,
    }
}

/// The interface pore-pressure terms of one integration point (seed 000):
/// δΠ = −[Δh δp̄ + p̄ δh + Δt (q̂ δp̂ + p̂ δq̂)] per unit area, p̄ = (p₁ + p₂)/2,
/// p̂ = (p₁ − p₂)/2, and its linearization, in the variant `variant`.
///
/// Inputs (end of increment): `p1`, `p2` pore pressures of side 1 and side 2; `q_hat` the flux
/// variable (the fluid volume flux per unit area from side 1 to side 2 is `q_hat/2`); `h` the
/// normal opening (positive apart; not used by any term, checked only); `dh` its increment
/// (read with open contact in transient analysis); `dt` the time increment (transient: > 0;
/// steady: not read). Unknowns x = (h, p̄, p̂, q̂), or (h, p₁, p₂, q̂) with `variant.per_side = 1`.
///
/// Outputs (caller-owned, none may be NULL):
/// - `residual[4]`: coefficient of δx_i in δΠ (sign included: add it to the internal virtual
///   work, the sign of −∫p δε_v);
/// - `tangent[16]`: column-major 4×4 (Fortran `TANGENT(4,4)`), `tangent[i + 4*j]` =
///   ∂residual_i/∂x_j (for j = h with the start-of-increment opening fixed, dΔh = dh);
/// - `geometric[4]`: coefficient of dδx_i, the change of the variation from the host's contact
///   geometry; all zeros in small sliding.
///
/// `interaction` (NUL-terminated, may be NULL) only names the caller in error messages;
/// [`ifl_pore_pressure_n`] takes it with its length instead (no NUL needed).
/// Returns `IFL_STATUS_OK`; on a NaN or infinite input or `dt <= 0` in a transient analysis
/// `IFL_STATUS_BAD_INPUT`, on a flag other than 0 or 1 `IFL_STATUS_BAD_PARAMETER`, on an
/// overflow of finite inputs `IFL_STATUS_NUMERICAL_FAILURE`, on a NULL output
/// `IFL_STATUS_BAD_INPUT`; on failure every non-NULL output is zeroed and the message (naming
/// `ifl_pore_pressure`, the interaction and the cause) is in `ifl_last_error`.
///
/// # Safety
/// `interaction` is NULL or NUL-terminated; `residual` and `geometric` point to 4 writable
/// doubles and `tangent` to 16, or are NULL.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
// Parameters a line per role (name and variant / inputs / outputs), as the header groups them:
// the list is written out for cbindgen, in each of the two exports.
#[rustfmt::skip]
pub unsafe extern "C" fn ifl_pore_pressure(
    interaction: *const c_char, variant: IflPorePressureVariant,
    p1: f64, p2: f64, q_hat: f64, h: f64, dh: f64, dt: f64,
    residual: *mut f64, tangent: *mut f64, geometric: *mut f64) -> IflStatus {
    let point = interface_point(p1, p2, q_hat, h, dh, dt);
    // SAFETY: forwarded from the caller.
    if unsafe { lean(variant, &point, residual, tangent, geometric) } {
        return IflStatus::Ok;
    }
    let (lo, hi) = words(variant);
    // SAFETY: forwarded from the caller.
    unsafe {
        careful_terminated(
            interaction, lo, hi,
            p1, p2, q_hat, h, dh, dt,
            residual, tangent, geometric,
        )
    }
}

/// [`ifl_pore_pressure`] with the interaction's name given as `interaction_len` bytes at
/// `interaction`, as Fortran passes a `CHARACTER` (blank-padded, no NUL): nothing past
/// `interaction_len` is read, trailing blanks and NULs are dropped from messages. For Fortran,
/// the `interfacial` module's `ifl_pore_pressure(name, ...)` calls it with `len(name)`.
/// Everything else (inputs, outputs, statuses) is as [`ifl_pore_pressure`]; messages name
/// `ifl_pore_pressure_n`.
///
/// # Safety
/// `interaction` is NULL or points to `interaction_len` readable bytes (any pointer when
/// `interaction_len` is 0); the outputs as [`ifl_pore_pressure`].
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
// Parameters a line per role, as in `ifl_pore_pressure`.
#[rustfmt::skip]
pub unsafe extern "C" fn ifl_pore_pressure_n(
    interaction: *const c_char, interaction_len: usize, variant: IflPorePressureVariant,
    p1: f64, p2: f64, q_hat: f64, h: f64, dh: f64, dt: f64,
    residual: *mut f64, tangent: *mut f64, geometric: *mut f64) -> IflStatus {
    let point = interface_point(p1, p2, q_hat, h, dh, dt);
    // SAFETY: forwarded from the caller.
    if unsafe { lean(variant, &point, residual, tangent, geometric) } {
        return IflStatus::Ok;
    }
    // SAFETY: forwarded from the caller.
    unsafe {
        careful(
            Name::Counted(interaction, interaction_len), variant,
            &point,
            residual, tangent, geometric,
        )
    }
}

/// How the caller gave the interaction's name (read only on the careful path, for messages).
#[derive(Clone, Copy)]
enum Name {
    /// NUL-terminated or NULL ([`ifl_pore_pressure`]).
    Terminated(*const c_char),
    /// `len` bytes, no NUL needed ([`ifl_pore_pressure_n`]).
    Counted(*const c_char, usize),
}

impl Name {
    fn routine(self) -> &'static str {
        match self {
            Name::Terminated(_) => "ifl_pore_pressure",
            // Named as both: the Fortran module's ifl_pore_pressure(name, ...) is this call.
            Name::Counted(..) => "ifl_pore_pressure_n (or the Fortran module's ifl_pore_pressure)",
        }
    }

    /// The name as shown in messages, trailing blanks and NULs dropped.
    ///
    /// # Safety
    /// As the entry point that made it.
    unsafe fn shown(self) -> String {
        let bytes: &[u8] = match self {
            Name::Terminated(p) | Name::Counted(p, _) if p.is_null() => &[],
            Name::Counted(_, 0) => &[],
            // SAFETY: NUL-terminated by contract.
            Name::Terminated(p) => unsafe { CStr::from_ptr(p) }.to_bytes(),
            // SAFETY: `len` readable bytes by contract.
            Name::Counted(p, len) => unsafe { std::slice::from_raw_parts(p.cast::<u8>(), len) },
        };
        let end = bytes
            .iter()
            .rposition(|b| !b.is_ascii_whitespace() && *b != 0)
            .map_or(0, |i| i + 1);
        String::from_utf8_lossy(&bytes[..end]).into_owned()
    }
}

/// The variant as the two machine words it arrives in: open | steady << 32 and
/// finite_sliding | per_side << 32.
#[inline(always)]
fn words(v: IflPorePressureVariant) -> (u64, u64) {
    let word = |a: c_int, b: c_int| u64::from(a as u32) | (u64::from(b as u32) << 32);
    (word(v.open, v.steady), word(v.finite_sliding, v.per_side))
}

/// The lean path of both entry points: writes the terms and returns true for valid flags,
/// pointers and inputs; returns false, writing nothing, for anything else.
///
/// # Safety
/// As [`ifl_pore_pressure`] for the outputs.
#[inline(always)]
unsafe fn lean(
    variant: IflPorePressureVariant,
    point: &InterfacePoint,
    residual: *mut f64,
    tangent: *mut f64,
    geometric: *mut f64,
) -> bool {
    // Plain arithmetic and stores: no allocation, no formatting, no indexing that could panic,
    // so no unwinding to catch (the careful path runs inside `boundary`).
    // Every flag is 0 or 1 exactly when no bit but 0 and 32 of either word is set.
    let (lo, hi) = words(variant);
    let flags_bad = (lo | hi) & !0x0000_0001_0000_0001 != 0;
    // Non-short-circuit `|`: one branch for the three pointers and the four flags together.
    let pointers_null = residual.is_null() | tangent.is_null() | geometric.is_null();
    if !(pointers_null | flags_bad) {
        // One straight-line copy per variant (the flags are constants in each), chosen by
        // open | steady << 1 | finite_sliding << 2 | per_side << 3: with x = lo | hi << 2 the
        // bits 0 and 2 are open and finite_sliding, x >> 31 brings steady (bit 32) to 1 and
        // per_side (bit 34) to 3.
        let out = (residual, tangent, geometric);
        let x = lo | (hi << 2);
        // SAFETY: non-NULL (tested above); 4, 16 and 4 writable doubles by contract.
        let done = unsafe {
            match (x | (x >> 31)) & 15 {
                0 => lean_as::<0>(point, out),
                1 => lean_as::<1>(point, out),
                2 => lean_as::<2>(point, out),
                3 => lean_as::<3>(point, out),
                4 => lean_as::<4>(point, out),
                5 => lean_as::<5>(point, out),
                6 => lean_as::<6>(point, out),
                7 => lean_as::<7>(point, out),
                8 => lean_as::<8>(point, out),
                9 => lean_as::<9>(point, out),
                10 => lean_as::<10>(point, out),
                11 => lean_as::<11>(point, out),
                12 => lean_as::<12>(point, out),
                13 => lean_as::<13>(point, out),
                14 => lean_as::<14>(point, out),
                _ => lean_as::<15>(point, out),
            }
        };
        return done;
    }
    false
}

/// [`careful`] for [`ifl_pore_pressure`], its arguments in the registers they arrived in (six
/// integer words, six doubles). `extern "C"` makes it nounwind to the caller (its body catches
/// every panic in [`boundary`]), so the entry point needs no unwind landing pad around the call
/// and reaches it by a plain jump, with no frame of its own.
///
/// # Safety
/// As [`ifl_pore_pressure`].
#[cold]
#[inline(never)]
#[allow(clippy::too_many_arguments)]
#[rustfmt::skip]
unsafe extern "C" fn careful_terminated(
    interaction: *const c_char, lo: u64, hi: u64,
    p1: f64, p2: f64, q_hat: f64, h: f64, dh: f64, dt: f64,
    residual: *mut f64, tangent: *mut f64, geometric: *mut f64) -> IflStatus {
    let variant = IflPorePressureVariant {
        open: lo as u32 as c_int,
        steady: (lo >> 32) as u32 as c_int,
        finite_sliding: hi as u32 as c_int,
        per_side: (hi >> 32) as u32 as c_int,
    };
    let point = interface_point(p1, p2, q_hat, h, dh, dt);
    // SAFETY: forwarded from the caller.
    unsafe {
        careful(
            Name::Terminated(interaction),
            variant,
            &point,
            residual,
            tangent,
            geometric,
        )
    }
}

/// The careful path of both entry points: every check with its message, inside [`boundary`].
/// Kept out of line so that the lean path's frame stays small.
///
/// # Safety
/// As [`ifl_pore_pressure`] for the outputs, as the entry point for `name`.
#[cold]
#[inline(never)]
unsafe fn careful(
    name: Name,
    variant: IflPorePressureVariant,
    point: &InterfacePoint,
    residual: *mut f64,
    tangent: *mut f64,
    geometric: *mut f64,
) -> IflStatus {
    let run = || -> Result<(), LawError> {
        if residual.is_null() || tangent.is_null() || geometric.is_null() {
            return Err(LawError::Input(
                "residual, tangent or geometric is a NULL pointer".into(),
            ));
        }
        let (variant, basis) = decode(variant)?;
        let terms = interface_terms(point, variant)?.in_basis(basis);
        // SAFETY: non-NULL, 4, 16 and 4 writable doubles by contract.
        unsafe { write_terms(residual, tangent, geometric, &terms) };
        Ok(())
    };
    let on_fault = || {
        // SAFETY: NULL is skipped; otherwise writable by contract.
        unsafe { write_terms(residual, tangent, geometric, &PorePressureTerms::default()) };
    };
    boundary(
        || Site {
            routine: name.routine(),
            // SAFETY: as the entry point that made `name`.
            interaction: unsafe { name.shown() },
            place: "native call".into(),
        },
        run,
        on_fault,
    )
    .into()
}

/// # Safety
/// Each pointer is NULL or points to 4, 16 and 4 writable doubles.
#[inline(always)]
unsafe fn write_terms(
    residual: *mut f64,
    tangent: *mut f64,
    geometric: *mut f64,
    t: &PorePressureTerms,
) {
    // SAFETY: forwarded from the caller.
    unsafe {
        write_array(residual, &t.residual);
        if !tangent.is_null() {
            // Column-major TANGENT(i,j) at i + 4j, stored in address order.
            for j in 0..4 {
                for i in 0..4 {
                    tangent.add(i + 4 * j).write(t.tangent[i][j]);
                }
            }
        }
        write_array(geometric, &t.geometric);
    }
}
