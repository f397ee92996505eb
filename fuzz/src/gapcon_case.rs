//! One `gapcon_` call decoded from fuzzer bytes, against a fixed configuration file with every
//! conductance law and radiation; arrays of exactly the declared lengths.
//!
//! Shared by the `gapcon` fuzz target and `tests/fuzz_regressions.rs` (included there by path).

use std::ffi::CString;
use std::sync::Once;

use super::args::{Args, Len, Outputs, call};
use super::at_exit::remove_at_exit;
use super::bytes::Bytes;
use super::contract::{Names, UNWRITTEN};
use interfacial::abi::{IflConductance, IflStatus, gapcon_, ifl_gap_conductance};

/// The configuration every `gapcon_` case runs against: one interaction per law, radiation in
/// kelvin and in °C, and no `"*"` entry, so unknown names take the error path.
pub const CONFIG: &str = include_str!("../gapcon.toml");

/// The configured names (and one that is not).
pub const NAMES: [&str; 8] = [
    "CONST", "PTAB", "CTAB", "GAS", "CMY", "RADK", "BOTH", "NONE",
];

/// Writes [`CONFIG`] to a file and points `INTERFACIAL_CONFIG` at it, before the first call;
/// sends the library's messages to `/dev/null` unless `INTERFACIAL_LOG` is already set.
pub fn setup() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        let path = std::env::temp_dir().join(format!(
            "interfacial-fuzz-gapcon-{}.toml",
            std::process::id()
        ));
        std::fs::write(&path, CONFIG).expect("write the fuzz configuration");
        // SAFETY: set once, before any call into the library reads the environment (Once
        // blocks other threads until it is done).
        unsafe {
            std::env::set_var("INTERFACIAL_CONFIG", &path);
            if std::env::var_os("INTERFACIAL_LOG").is_none() {
                std::env::set_var("INTERFACIAL_LOG", "/dev/null");
            }
        }
        remove_at_exit(path);
    });
}

/// Every `gapcon_` argument: `args` by Fortran name (`D(2)`: clearance, pressure; `TEMP(2)`;
/// `NOEL`, `NODE`, `NPRED`; `FLOWM(2)`, `PREDEF(2,NPRED)`, `TIME(2)`, `COORDS(3)`, never read,
/// all NaN).
#[derive(Clone, Debug)]
pub struct GapconCase {
    pub args: Args,
    /// `CINAME`, `SLNAME`, `MSNAME`.
    pub names: Names,
}

impl GapconCase {
    /// Decodes any byte string; names are mostly configured ones, in any case and padding.
    pub fn decode(data: &[u8]) -> Self {
        let mut b = Bytes::new(data);
        let sel = b.u8();
        let base = NAMES[usize::from(sel) % NAMES.len()];
        let mut ciname: Vec<u8> = if sel & 0x80 == 0 {
            base.bytes().collect()
        } else {
            let l = usize::from(b.u8() % 24);
            b.bytes(l)
        };
        if sel & 0x40 != 0 {
            ciname.make_ascii_lowercase();
        }
        let pad = usize::from(b.u8());
        let filler = if pad & 0x80 == 0 { b' ' } else { 0 };
        ciname.resize(ciname.len() + (pad & 0x7f), filler);
        let mut a = Args::new();
        a.set_int("NPRED", b.pick(&[1, 0, 2]));
        a.put("D", b.reals(2));
        a.put("TEMP", b.reals(2));
        let names = Names {
            interaction: ciname,
            secondary: vec![b' '; 80],
            main: vec![b' '; usize::from(b.u8() % 81)],
        };
        a.set_int("NOEL", i32::from(b.u16()));
        a.set_int("NODE", i32::from(b.u16()));
        for (name, n) in [("FLOWM", 2), ("TIME", 2), ("COORDS", 3)] {
            a.put(name, vec![f64::NAN; n]);
        }
        a.put("PREDEF", vec![f64::NAN; a.count(Len::Times(2, "NPRED"))]);
        GapconCase { args: a, names }
    }

    /// Calls `gapcon_` and checks: `AK(1)` finite and ≥ 0 on success, 0 with a message naming
    /// GAPCON on failure; `AK(2..5)` and every input left alone. Returns `AK(1)`.
    pub fn check(&self) -> Result<f64, String> {
        setup();
        let out = call(
            &self.args,
            &self.names,
            &[],
            &[("AK", Len::Fixed(5))],
            |a, names, o| {
                let [ci, sl, ms] = names.pointers();
                let [ci_len, sl_len, ms_len] = names.lengths();
                let (kstep, kinc) = (1i32, 1i32);
                // SAFETY: AK(5), D(2), TEMP(2) and the names with their exact hidden lengths; the
                // unread arrays have their declared lengths too.
                unsafe {
                    gapcon_(
                        o.ptr_mut("AK"),
                        a.ptr("D"),
                        a.ptr("FLOWM"),
                        a.ptr("TEMP"),
                        a.ptr("PREDEF"),
                        a.ptr("TIME"),
                        ci,
                        sl,
                        ms,
                        a.ptr("COORDS"),
                        a.int_ptr("NOEL"),
                        a.int_ptr("NODE"),
                        a.int_ptr("NPRED"),
                        &kstep,
                        &kinc,
                        // AREA, never read (CalculiX's variant only).
                        #[cfg(feature = "calculix")]
                        &f64::NAN,
                        ci_len,
                        sl_len,
                        ms_len,
                    )
                };
            },
        )?;
        let Outputs { args, message } = &out;
        let ak = &args["AK"];
        if ak[1..].iter().any(|x| *x != UNWRITTEN) {
            return Err(format!("AK(2..5) written: {ak:?}"));
        }
        let k = ak[0];
        if message.is_empty() {
            if !(k.is_finite() && k >= 0.0) {
                return Err(format!("success with AK(1) = {k}: {self:?}"));
            }
        } else {
            if k != 0.0 {
                return Err(format!("failure with AK(1) = {k}: {message}"));
            }
            if !message.starts_with("interfacial: GAPCON: interaction '") {
                return Err(format!("message does not name the routine: {message:?}"));
            }
        }
        self.check_native(k, message.is_empty())?;
        Ok(k)
    }

    /// `ifl_gap_conductance` with the same name (when it has no NUL before its padding), the
    /// clearance `D(1)`, the pressure `D(2)` and the surface temperatures: the same law, so it
    /// succeeds exactly when `gapcon_` did, with k bit for bit `AK(1)` and finite derivatives;
    /// on failure `*out` is zeroed. A NULL `out` is refused without a crash.
    fn check_native(&self, ak1: f64, gapcon_ok: bool) -> Result<(), String> {
        let end = self
            .names
            .interaction
            .iter()
            .rposition(|b| *b != 0 && *b != b' ')
            .map_or(0, |i| i + 1);
        let core = &self.names.interaction[..end];
        let Ok(name) = CString::new(core) else {
            return Ok(()); // a NUL inside the name: not expressible as a C string
        };
        let mut out = IflConductance {
            k: UNWRITTEN,
            ..IflConductance::default()
        };
        let [clearance, pressure] = [0, 1].map(|i| self.args["D"][i]);
        let [theta_a, theta_b] = [0, 1].map(|i| self.args["TEMP"][i]);
        // SAFETY: a NUL-terminated name; `out` writable, or NULL (which must be refused with
        // nothing written).
        let native = |out: *mut IflConductance| unsafe {
            ifl_gap_conductance(name.as_ptr(), clearance, pressure, theta_a, theta_b, out)
        };
        let status = native(&mut out);
        if gapcon_ok {
            if status != IflStatus::Ok || out.k.to_bits() != ak1.to_bits() {
                return Err(format!(
                    "ifl_gap_conductance disagrees with gapcon_ (AK(1) = {ak1}): {status:?} {out:?}"
                ));
            }
            let all = [
                out.dk_dd,
                out.dk_dp,
                out.dk_dtheta_mean,
                out.dq_dtheta_a,
                out.dq_dtheta_b,
            ];
            if all.iter().any(|x| !x.is_finite()) {
                return Err(format!(
                    "ifl_gap_conductance: non-finite derivative {out:?}"
                ));
            }
        } else if status == IflStatus::Ok || out != IflConductance::default() {
            return Err(format!(
                "gapcon_ refused but ifl_gap_conductance gave {status:?} {out:?}"
            ));
        }
        let null = native(std::ptr::null_mut());
        if null != IflStatus::BadInput {
            return Err(format!("NULL out gave {null:?}"));
        }
        Ok(())
    }
}
