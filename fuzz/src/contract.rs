//! What every entry point owes its host, checked the same way by every case: the message of a
//! call ([`last_error`]), the `CHARACTER` arguments ([`Names`]), what it wrote ([`UNWRITTEN`]),
//! and for the Abaqus routines that refuse by lowering `PNEWDT` (FRIC, UINTER) the refusal
//! itself ([`pnewdt_refusal`]). That the inputs are left alone is checked once, by
//! [`super::args::call`].

use std::ffi::{CStr, c_char};

use interfacial::abi::ifl_last_error;

/// Written into every output before the call, to see what the call wrote.
pub const UNWRITTEN: f64 = -7.77e77;

/// Whether `x` is still [`UNWRITTEN`] (bit for bit).
pub fn unwritten(x: &f64) -> bool {
    x.to_bits() == UNWRITTEN.to_bits()
}

/// The three `CHARACTER` arguments of a call (`CINAME`, `SLNAME`, `MSNAME`; `surfInt`,
/// `surfSec`, `surfMain`): the bytes the host passes, no NUL, each hidden length its length.
#[derive(Clone, Debug, PartialEq)]
pub struct Names {
    pub interaction: Vec<u8>,
    pub secondary: Vec<u8>,
    pub main: Vec<u8>,
}

impl Names {
    /// `interaction` blank-padded to 80 bytes and blank surface names, as a `CHARACTER*80`.
    pub fn padded(interaction: &str) -> Names {
        let mut name = interaction.as_bytes().to_vec();
        name.resize(80, b' ');
        Names {
            interaction: name,
            secondary: vec![b' '; 80],
            main: vec![b' '; 80],
        }
    }

    /// No names (an entry point without `CHARACTER` arguments).
    pub fn none() -> Names {
        Names {
            interaction: Vec::new(),
            secondary: Vec::new(),
            main: Vec::new(),
        }
    }

    /// The three pointers, in argument order.
    pub fn pointers(&self) -> [*const c_char; 3] {
        [&self.interaction, &self.secondary, &self.main].map(|n| n.as_ptr().cast::<c_char>())
    }

    /// The three hidden lengths, in argument order.
    pub fn lengths(&self) -> [usize; 3] {
        [&self.interaction, &self.secondary, &self.main].map(Vec::len)
    }
}

/// The library's last message on this thread ("" when the last call succeeded).
pub fn last_error() -> String {
    // SAFETY: `ifl_last_error` never returns NULL; it points at this thread's NUL-terminated
    // buffer, left alone until the next call on this thread.
    unsafe { CStr::from_ptr(ifl_last_error()) }
        .to_string_lossy()
        .into_owned()
}

/// Whether a call of `routine` (FRIC, UINTER) refused, `PNEWDT` having gone from `before` to
/// `after` with `message`; an error when the answer breaks the contract: a refusal (and only a
/// refusal) changes `PNEWDT`, to below 1, and reports one message naming the routine and the
/// interaction.
pub fn pnewdt_refusal(
    before: f64,
    after: f64,
    message: &str,
    routine: &str,
) -> Result<bool, String> {
    let refused = after.to_bits() != before.to_bits();
    if refused == message.is_empty() {
        return Err(format!(
            "PNEWDT {before} -> {after} but message {message:?}: a refusal must lower PNEWDT and \
             report"
        ));
    }
    if refused {
        if after.is_nan() || after >= 1.0 {
            return Err(format!("refused with PNEWDT = {after}"));
        }
        if !message.starts_with(&format!("interfacial: {routine}: interaction '")) {
            return Err(format!("message does not name routine: {message:?}"));
        }
    }
    Ok(refused)
}

/// The Euclidean norm of `v`, formed without overflow or underflow of the squares.
pub fn norm(v: &[f64]) -> f64 {
    v.iter().fold(0.0f64, |s, x| s.hypot(*x))
}

/// The adhesive law's strength parameters (`PROPS(1) = 2`, docs/props.md): μ_d, μ_s, S_a, k_μ
/// = `PROPS(2)`, `PROPS(3)`, `PROPS(4)`, `PROPS(6)`, each 0 when absent.
pub fn adhesive_props(props: &[f64]) -> [f64; 4] {
    [1, 2, 3, 5].map(|i| props.get(i).copied().unwrap_or(0.0))
}

/// The slip rate an adhesive-law call's strength is judged at (seed 004): the rate the call
/// reports in `STATEV(2)`, and after a slip (start status `STATEV(3)` = 1) at least the start
/// rate, since a stick increment keeps the stiffness of the start rate (docs/props.md, the
/// rate-dependent formulation): its strength is g(start rate). `statev0` on entry, `statev` on
/// exit.
pub fn adhesive_rate(statev0: &[f64], statev: &[f64]) -> f64 {
    let start_rate = if statev0.get(2) == Some(&1.0) {
        statev0.get(1).copied().unwrap_or(0.0).max(0.0)
    } else {
        0.0
    };
    statev[1].max(start_rate)
}
