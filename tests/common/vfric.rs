//! One `vfric_` (Abaqus/Explicit VFRIC) call on a block of contact points as Abaqus/Explicit
//! makes it, in the build's precision (`IflReal`): shared by vfric.rs and last_error.rs
//! (included there by path).

use std::ffi::c_int;

use interfacial::abi::vfric::{IflReal, vfric_};

/// What fTangential holds before the call (and its two guard entries after it).
pub const SENTINEL: IflReal = -777.0;

/// The inputs of one call that the law reads: nFricDir, PROPS, per point F_N and F_stick, the
/// nodal areas and each point's node (jConSlvUid), as docs/vfric.md names them.
pub struct Block {
    pub nfricdir: c_int,
    pub props: Vec<IflReal>,
    pub f_normal: Vec<IflReal>,
    pub f_stick: Vec<IflReal>,
    pub area: Vec<IflReal>,
    pub jconslvid: Vec<c_int>,
}

/// Calls vfric_ as Abaqus/Explicit does; returns fTangential with two guard entries.
pub fn call(b: &Block) -> Vec<IflReal> {
    let n = b.f_normal.len();
    let nf = b.nfricdir.clamp(1, 3) as usize;
    let mut ftan = vec![SENTINEL; nf * n + 2];
    let mut statev: Vec<IflReal> = vec![5.0; 2 * b.area.len().max(1)];
    let ints = |v: usize| v as c_int;
    let (nc, nfac, nslv, nmst) = (ints(n), 4, ints(b.area.len()), 4);
    let (ndir, nsv, nprops) = (b.nfricdir + 1, 2, ints(b.props.len()));
    let zero_i: c_int = 0;
    let one_i: c_int = 1;
    let r0: IflReal = 0.0;
    let dummy: Vec<IflReal> = vec![0.0; 16 * (n + b.area.len() + 4)];
    let idummy: Vec<c_int> = vec![1; 4 * (n + b.area.len() + 4)];
    let name = [b' '; 80];
    let mut interaction = [b' '; 80];
    interaction[..4].copy_from_slice(b"CP-9");
    // SAFETY: every array is at least as long as the VFRIC dimensions given.
    unsafe {
        vfric_(
            ftan.as_mut_ptr(),
            statev.as_mut_ptr(),
            &one_i,
            &one_i,
            &nc,
            &nfac,
            &nslv,
            &nmst,
            &b.nfricdir,
            &ndir,
            &nsv,
            &nprops,
            &zero_i,
            &zero_i,
            &one_i,
            idummy.as_ptr(),
            idummy.as_ptr(),
            b.jconslvid.as_ptr(),
            idummy.as_ptr(),
            &r0,
            &r0,
            &r0,
            interaction.as_ptr().cast(),
            name.as_ptr().cast(),
            name.as_ptr().cast(),
            &one_i,
            dummy.as_ptr(),
            b.f_stick.as_ptr(),
            dummy.as_ptr(),
            b.f_normal.as_ptr(),
            dummy.as_ptr(),
            dummy.as_ptr(),
            dummy.as_ptr(),
            dummy.as_ptr(),
            dummy.as_ptr(),
            dummy.as_ptr(),
            b.props.as_ptr(),
            b.area.as_ptr(),
            dummy.as_ptr(),
            dummy.as_ptr(),
            dummy.as_ptr(),
            dummy.as_ptr(),
            80,
            80,
            80,
        );
    }
    assert!(statev.iter().all(|x| *x == 5.0), "STATEV is not written");
    ftan
}
