//! `vfric_`: the Abaqus/Explicit VFRIC user subroutine (abi.md, section "VFRIC"), double
//! precision, for the plain Coulomb law of `PROPS(1) = 1` in its force form
//! ([`crate::laws::coulomb_kinematic`]). Decision and limits: `docs/vfric.md`.

use std::ffi::{c_char, c_int};

use super::{count, host_site, read};
use crate::LawError;
use crate::laws::coulomb_kinematic::KinematicCoulomb;
use crate::props::friction_law_as_written;
use crate::report::report;

/// The Fortran `REAL` of the Abaqus/Explicit build `vfric_` is compiled for: `f64` for the
/// double-precision executable (the default), `f32` with the cargo feature `explicit-single`
/// (`vaba_param.inc` = `implicit real`). The law runs in `f64` either way: every `f32` input
/// converts exactly, and the result rounds back once (docs/vfric.md).
#[cfg(not(feature = "explicit-single"))]
pub type IflReal = f64;
/// The Fortran `REAL` of the Abaqus/Explicit build `vfric_` is compiled for (see above).
#[cfg(feature = "explicit-single")]
pub type IflReal = f32;

/// Abaqus/Explicit `VFRIC` (double precision build by default, `vaba_param.inc` = `implicit
/// real*8`; single precision with the cargo feature `explicit-single`, see [`IflReal`]):
/// the friction force of the `nContact` contact points of a block, callable from Fortran as
/// `CALL VFRIC(...)`; 42 arguments + 3 hidden lengths (`surfInt`, `surfSlv`, `surfMst`).
///
/// `PROPS` has the law-1 layout of `fric_` (docs/props.md), plain Coulomb only: μ =
/// `PROPS(2)`, τ_max = `PROPS(4)` (a force cap τ_max·`areaSlv` of the point's slave node),
/// `PROPS(7)` = 2 rough friction; γ_crit and the slip tolerance are ignored (kinematic stick is
/// exact). For contact point k:
///
/// `fTangential(1,k) = −min(μ·fNormal(k), τ_max·areaSlv(jConSlvid(k)), fStickForce(k))`
/// (0 when `fNormal(k) < 0`; −`fStickForce(k)` with rough friction), `fTangential(2,k) = 0`
/// when `nFricDir = 2` (the local 1-direction is the slip direction).
///
/// `statev` is not written (the law keeps no state in kinematic contact). Every other argument
/// is only read for sizes or not at all.
///
/// Bad input at a point (NaN or infinite `fNormal`, a negative or non-finite `fStickForce`, a
/// bad area or slave-node index when τ_max is set): that point gets no friction force (0) and
/// one message per distinct cause is reported, naming `VFRIC`, the interaction and the point.
/// A fault of the whole call (bad `PROPS`, an extended or adhesive law, `nFricDir` not 1 or 2,
/// NULL arrays, an internal panic): every point gets 0 and the cause is reported. VFRIC has no
/// `PNEWDT`; `INTERFACIAL_STRICT=1` aborts on the first error instead.
///
/// # Safety
/// Pointers valid for the VFRIC signature: `fTangential(nFricDir,nContact)`,
/// `fStickForce(nContact)`, `fNormal(nContact)`, `jConSlvid(nContact)`, `areaSlv(nSlvNod)`,
/// `props(nProps)`, names of the given hidden lengths; the other pointers are not dereferenced.
#[allow(clippy::too_many_arguments)]
#[unsafe(no_mangle)]
// The view `VfricArgs` (a field per parameter but the `unread` ones, bound to `args`) is written
// by the attribute from this parameter list (macros/).
#[interfacial_macros::with_view(
    view = struct VfricArgs as args,
    unread = (statev, k_step, k_inc, n_fac_nod, n_mst_nod, n_dir, n_state_var, n_temp, n_pred,
              num_def_tfv, j_slv_uid, j_mst_uid, j_con_mstid, tim_step, tim_glb, d_tim_cur,
              surf_slv, surf_mst, l_cont_type, d_slip_fric, f_tang_prev, friction_work, shape,
              coord_slv, coord_mst, dircos_sl, dircos_n, temp_slv, pre_def_slv, temp_mst,
              pre_def_mst, surf_slv_len, surf_mst_len),
)]
pub unsafe extern "C" fn vfric_(
    f_tangential: *mut IflReal,
    statev: *mut IflReal,
    k_step: *const c_int,
    k_inc: *const c_int,
    n_contact: *const c_int,
    n_fac_nod: *const c_int,
    n_slv_nod: *const c_int,
    n_mst_nod: *const c_int,
    n_fric_dir: *const c_int,
    n_dir: *const c_int,
    n_state_var: *const c_int,
    n_props: *const c_int,
    n_temp: *const c_int,
    n_pred: *const c_int,
    num_def_tfv: *const c_int,
    j_slv_uid: *const c_int,
    j_mst_uid: *const c_int,
    j_con_slvid: *const c_int,
    j_con_mstid: *const c_int,
    tim_step: *const IflReal,
    tim_glb: *const IflReal,
    d_tim_cur: *const IflReal,
    surf_int: *const c_char,
    surf_slv: *const c_char,
    surf_mst: *const c_char,
    l_cont_type: *const c_int,
    d_slip_fric: *const IflReal,
    f_stick_force: *const IflReal,
    f_tang_prev: *const IflReal,
    f_normal: *const IflReal,
    friction_work: *const IflReal,
    shape: *const IflReal,
    coord_slv: *const IflReal,
    coord_mst: *const IflReal,
    dircos_sl: *const IflReal,
    dircos_n: *const IflReal,
    props: *const IflReal,
    area_slv: *const IflReal,
    temp_slv: *const IflReal,
    pre_def_slv: *const IflReal,
    temp_mst: *const IflReal,
    pre_def_mst: *const IflReal,
    surf_int_len: usize,
    surf_slv_len: usize,
    surf_mst_len: usize,
) {
    fortran_boundary!(
        args,
        // SAFETY: the name of its hidden length, per the contract above.
        || unsafe { host_site("VFRIC", surf_int, surf_int_len, "block".into()) }
    );
}

impl VfricArgs {
    /// `nContact` and `nFricDir` when both are readable and valid.
    ///
    /// # Safety
    /// As [`vfric_`].
    unsafe fn sizes(&self) -> Result<(usize, usize), LawError> {
        // SAFETY: scalars passed by reference, NULL refused by `read`.
        let (nc, nf) = unsafe {
            (
                read(self.n_contact, "nContact")?,
                read(self.n_fric_dir, "nFricDir")?,
            )
        };
        let n = count("nContact", nc)?;
        let nf = match nf {
            1 | 2 => nf as usize,
            _ => {
                return Err(LawError::Parameter(format!(
                    "nFricDir = {nf}; expected 1 (2-D) or 2 (3-D)"
                )));
            }
        };
        Ok((n, nf))
    }

    /// # Safety
    /// As [`vfric_`].
    unsafe fn run(&self) -> Result<(), LawError> {
        // SAFETY (whole body): arrays of the sizes the VFRIC contract gives, read after their
        // sizes were checked; every output entry written is inside fTangential(nFricDir,
        // nContact).
        unsafe {
            let (n, nf) = self.sizes()?;
            let nprops = count("nProps", read(self.n_props, "nProps")?)?;
            let props = reals(self.props, nprops, "props")?;
            let props: Vec<f64> = props.iter().copied().map(to_f64).collect();
            // Law 2 refused in every form, its Coulomb special case included (docs/vfric.md).
            let law = friction_law_as_written(&props)?.into_plain_coulomb(
                "VFRIC runs the plain Coulomb law (law 1) only (docs/vfric.md)",
            )?;
            let law = KinematicCoulomb::new(&law);
            if n == 0 {
                return Ok(());
            }
            if self.f_tangential.is_null() {
                return Err(LawError::Input("fTangential is a NULL pointer".into()));
            }
            let normal = reals(self.f_normal, n, "fNormal")?;
            let stick = reals(self.f_stick_force, n, "fStickForce")?;
            let area = if law.needs_area() {
                let nodes = count("nSlvNod", read(self.n_slv_nod, "nSlvNod")?)?;
                if self.j_con_slvid.is_null() {
                    return Err(LawError::Input("jConSlvid is a NULL pointer".into()));
                }
                let ids = std::slice::from_raw_parts(self.j_con_slvid, n);
                Some((ids, reals(self.area_slv, nodes, "areaSlv")?))
            } else {
                None
            };
            for k in 0..n {
                let a = match area {
                    None => Ok(0.0),
                    Some((ids, areas)) => {
                        let id = ids[k];
                        usize::try_from(id)
                            .ok()
                            .and_then(|i| i.checked_sub(1))
                            .and_then(|i| areas.get(i).copied().map(to_f64))
                            .ok_or_else(|| {
                                LawError::Input(format!(
                                    "jConSlvid({}) = {id} is not a slave node 1..{}",
                                    k + 1,
                                    areas.len()
                                ))
                            })
                    }
                };
                let force = a.and_then(|a| law.force(to_f64(normal[k]), to_f64(stick[k]), a));
                let f = match force {
                    Ok(f) => f,
                    Err(e) => {
                        let place = format!("contact point {}", k + 1);
                        let site = host_site("VFRIC", self.surf_int, self.surf_int_len, place);
                        report(&site, &e.to_string(), true);
                        0.0
                    }
                };
                // fTangential(1,k) = −F against the slip (0 − F: +0 without friction);
                // fTangential(2,k) = 0.
                // In single precision the one rounding of the result: F is μ·F_N (an exact
                // product of two f32 in f64, so this is the correctly rounded f32 product),
                // τ_max·A likewise, or F_stick itself.
                self.f_tangential.add(k * nf).write(to_real(0.0 - f));
                if nf == 2 {
                    self.f_tangential.add(k * nf + 1).write(0.0);
                }
            }
            Ok(())
        }
    }

    /// The safe output of a failed call: no friction force anywhere (when the sizes can be
    /// read).
    ///
    /// # Safety
    /// As [`vfric_`].
    unsafe fn fail(&self) {
        // SAFETY: sizes checked by `sizes`; fTangential(nFricDir,nContact) writable.
        unsafe {
            if let Ok((n, nf)) = self.sizes() {
                if !self.f_tangential.is_null() {
                    for i in 0..n * nf {
                        self.f_tangential.add(i).write(0.0);
                    }
                }
            }
        }
    }
}

/// Borrows `len` reals of the build's precision (NULL allowed only when `len` is 0).
///
/// # Safety
/// `p` is NULL or points to `len` readable `IflReal`s.
unsafe fn reals<'a>(p: *const IflReal, len: usize, name: &str) -> Result<&'a [IflReal], LawError> {
    if len == 0 {
        Ok(&[])
    } else if p.is_null() {
        Err(LawError::Input(format!("{name} is a NULL pointer")))
    } else {
        // SAFETY: as documented.
        Ok(unsafe { std::slice::from_raw_parts(p, len) })
    }
}

/// A real of the build's precision in f64 (exact).
#[inline]
#[allow(clippy::useless_conversion)]
fn to_f64(x: IflReal) -> f64 {
    f64::from(x)
}

/// The f64 result in the build's precision (one rounding in single precision).
#[inline]
#[allow(clippy::cast_possible_truncation, clippy::unnecessary_cast)]
fn to_real(x: f64) -> IflReal {
    x as IflReal
}
