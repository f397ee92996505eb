//! `ifl_pore_pressure` and `ifl_pore_pressure_n` (the interface pore-pressure kernel,
//! docs/pore-pressure.md) on any bytes. The decoding lives here, in the target.
//!
//! Bytes, in order (missing bytes read as 0):
//! - 1 byte: bit 0 picks the entry (0: NUL-terminated name, 1: name with its length), bits 1–3
//!   make `residual`, `tangent`, `geometric` NULL (each only when bits 4–7 are all set, so that
//!   most inputs reach the kernel);
//! - 4 bytes, one per flag (`open`, `steady`, `finite_sliding`, `per_side`): below 200 the flag
//!   is the byte's low bit, otherwise the byte minus 201 as an `int` (0 or 1 now and then, any
//!   other value refused);
//! - 6 inputs (`p1`, `p2`, `q_hat`, `h`, `dh`, `dt`), each one selector byte: below 16 a special
//!   value from `SPECIALS`, otherwise the next 8 bytes as an `f64` bit pattern;
//! - 1 byte: the name's length; then the name's bytes (any bytes, NULs and blanks included).
//!
//! Properties, for every input:
//! - no panic and no `IFL_STATUS_INTERNAL_ERROR` (which is what a caught panic becomes);
//! - the status, and on success every output bit for bit, equal to the checked core
//!   (`laws::pore_pressure::interface_terms` in the requested basis), whose refusal decides the
//!   status: a flag other than 0 or 1 → bad parameter, a NULL output or a non-finite input or
//!   Δt ≤ 0 in transient analysis → bad input, an overflow → numerical failure;
//! - on success every output finite (never NaN out of the inputs the kernel accepts);
//! - on failure every non-NULL output zeroed and a message that names the entry point;
//! - `ifl_pore_pressure_n` reads only its `len` bytes: the name is handed over in a buffer of
//!   exactly that length, so AddressSanitizer reports any read past it.
#![no_main]

use std::ffi::{CStr, CString, c_char, c_int};

use interfacial::abi::{
    IflPorePressureVariant, IflStatus, ifl_last_error, ifl_pore_pressure, ifl_pore_pressure_n,
};
use interfacial::laws::pore_pressure::{
    Basis, Contact, InterfacePoint, PointFault, Regime, Sliding, Variant, interface_terms,
};
use libfuzzer_sys::fuzz_target;

const SPECIALS: [f64; 16] = [
    0.0,
    -0.0,
    1.0,
    -1.0,
    0.5,
    1e-300,
    5e-324,
    1e300,
    -1e300,
    f64::MAX,
    f64::MIN,
    f64::MIN_POSITIVE,
    f64::INFINITY,
    f64::NEG_INFINITY,
    f64::NAN,
    1e154,
];

struct Bytes<'a>(&'a [u8]);

impl Bytes<'_> {
    fn byte(&mut self) -> u8 {
        match self.0.split_first() {
            Some((b, rest)) => {
                self.0 = rest;
                *b
            }
            None => 0,
        }
    }

    fn flag(&mut self) -> c_int {
        let b = self.byte();
        if b < 200 {
            c_int::from(b & 1)
        } else {
            c_int::from(b) - 201
        }
    }

    fn input(&mut self) -> f64 {
        let s = self.byte();
        if s < 16 {
            SPECIALS[usize::from(s)]
        } else {
            let mut raw = [0u8; 8];
            for r in &mut raw {
                *r = self.byte();
            }
            f64::from_le_bytes(raw)
        }
    }
}

/// The core's answer for `v` at `x`: `Ok` with the outputs in the ABI's layout, or the status.
fn expected(v: IflPorePressureVariant, x: &InterfacePoint) -> Result<Outputs, IflStatus> {
    let flag = |f: c_int| match f {
        0 => Ok(false),
        1 => Ok(true),
        _ => Err(IflStatus::BadParameter),
    };
    let variant = Variant {
        contact: if flag(v.open)? {
            Contact::Open
        } else {
            Contact::Closed
        },
        regime: if flag(v.steady)? {
            Regime::Steady
        } else {
            Regime::Transient
        },
        sliding: if flag(v.finite_sliding)? {
            Sliding::Finite
        } else {
            Sliding::Small
        },
    };
    let basis = if flag(v.per_side)? {
        Basis::PerSide
    } else {
        Basis::MeanJump
    };
    match interface_terms(x, variant) {
        Ok(t) => {
            let t = t.in_basis(basis);
            Ok(Outputs {
                residual: t.residual,
                tangent: std::array::from_fn(|k| t.tangent[k % 4][k / 4]),
                geometric: t.geometric,
            })
        }
        Err(PointFault::Overflow) => Err(IflStatus::NumericalFailure),
        Err(_) => Err(IflStatus::BadInput),
    }
}

#[derive(Debug, PartialEq)]
struct Outputs {
    residual: [f64; 4],
    tangent: [f64; 16],
    geometric: [f64; 4],
}

fn bits(o: &Outputs) -> Vec<u64> {
    o.residual
        .iter()
        .chain(&o.tangent)
        .chain(&o.geometric)
        .map(|x| x.to_bits())
        .collect()
}

fuzz_target!(
    init: {
        // Messages go nowhere: the fuzzer meets thousands of distinct causes.
        // SAFETY: before the first call into the library, on the only thread.
        unsafe { std::env::set_var("INTERFACIAL_LOG", "/dev/null") };
    },
    |data: &[u8]| {
        let mut b = Bytes(data);
        let head = b.byte();
        let counted = head & 1 == 1;
        let nulls = if head >> 4 == 0xF { (head >> 1) & 7 } else { 0 };
        let v = IflPorePressureVariant {
            open: b.flag(),
            steady: b.flag(),
            finite_sliding: b.flag(),
            per_side: b.flag(),
        };
        let x = InterfacePoint {
            p1: b.input(),
            p2: b.input(),
            q_hat: b.input(),
            h: b.input(),
            dh: b.input(),
            dt: b.input(),
        };
        let len = usize::from(b.byte());
        let name: Vec<u8> = (0..len).map(|_| b.byte()).collect();

        let mut out = Outputs {
            residual: [7.0; 4],
            tangent: [7.0; 16],
            geometric: [7.0; 4],
        };
        let ptr = |p: &mut [f64], bit: u8| {
            if nulls & bit != 0 {
                std::ptr::null_mut()
            } else {
                p.as_mut_ptr()
            }
        };
        let r = ptr(&mut out.residual, 1);
        let t = ptr(&mut out.tangent, 2);
        let g = ptr(&mut out.geometric, 4);
        let (status, routine) = if counted {
            // Exactly `len` bytes, on the heap: a read past them is an ASan report.
            let exact: Box<[u8]> = name.into_boxed_slice();
            // SAFETY: `exact` holds `len` readable bytes; outputs are 4, 16, 4 doubles or NULL.
            let s = unsafe {
                ifl_pore_pressure_n(
                    exact.as_ptr().cast::<c_char>(),
                    exact.len(),
                    v,
                    x.p1,
                    x.p2,
                    x.q_hat,
                    x.h,
                    x.dh,
                    x.dt,
                    r,
                    t,
                    g,
                )
            };
            (s, "ifl_pore_pressure_n")
        } else {
            let c = CString::new(name.into_iter().filter(|c| *c != 0).collect::<Vec<u8>>())
                .expect("NULs were filtered out");
            // SAFETY: NUL-terminated name; outputs are 4, 16, 4 doubles or NULL.
            let s = unsafe {
                ifl_pore_pressure(c.as_ptr(), v, x.p1, x.p2, x.q_hat, x.h, x.dh, x.dt, r, t, g)
            };
            (s, "ifl_pore_pressure:")
        };

        assert_ne!(status, IflStatus::InternalError, "a panic reached the boundary: {x:?} {v:?}");
        // A NULL output is refused (bad input) before anything else is looked at.
        let want = if nulls != 0 {
            Err(IflStatus::BadInput)
        } else {
            expected(v, &x)
        };
        match want {
            Ok(core) => {
                assert_eq!(status, IflStatus::Ok, "{x:?} {v:?}");
                assert_eq!(bits(&out), bits(&core), "{x:?} {v:?}");
                assert!(
                    bits(&out).iter().all(|b| f64::from_bits(*b).is_finite()),
                    "non-finite output: {out:?}"
                );
            }
            Err(s) => {
                assert_eq!(status, s, "{x:?} {v:?} nulls {nulls}");
                let zeroed = |a: &[f64], bit: u8| nulls & bit != 0 || a.iter().all(|y| *y == 0.0);
                assert!(
                    zeroed(&out.residual, 1) && zeroed(&out.tangent, 2) && zeroed(&out.geometric, 4),
                    "outputs not zeroed: {out:?}"
                );
                // SAFETY: the library's thread-local buffer, NUL-terminated.
                let msg = unsafe { CStr::from_ptr(ifl_last_error()) }.to_string_lossy();
                assert!(msg.contains(routine), "{msg}");
            }
        }
    }
);
