//! Decoders and property checks of the fuzz targets. The modules are also compiled into the
//! tests by path (`tests/common/fuzz_cases.rs`), so a crash input replays as a plain `cargo
//! test`; they name each other by `super::`, which is this crate's root here and that module
//! there. Each case describes its entry point's arguments as a table read by [`args`], the one
//! decoder, holder and caller every case shares (docs/fuzzing.md).

pub mod args;
pub mod at_exit;
pub mod batch_case;
pub mod bytes;
pub mod config_case;
pub mod contract;
pub mod fric_case;
pub mod fric_coef_case;
pub mod gapcon_case;
pub mod uinter_case;
pub mod vfric_case;

/// Sends the library's messages to `/dev/null` (the fuzzer meets thousands of distinct
/// causes) unless `INTERFACIAL_LOG` is set already. Called from a target's `init`.
pub fn quiet_log() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        if std::env::var_os("INTERFACIAL_LOG").is_none() {
            // SAFETY: from the fuzz target's init, before the first call into the library,
            // and `Once` blocks any other thread until it is done.
            unsafe { std::env::set_var("INTERFACIAL_LOG", "/dev/null") };
        }
    });
}

/// A fuzz target over one case type: `fuzz_case!(FricCase, "fric_")` decodes every input with
/// `FricCase::decode`, runs its property check and panics (a crash for libFuzzer) naming the
/// entry point, the property violated and the decoded input. `init:` replaces
/// [`quiet_log`] as the set-up before the first input.
#[macro_export]
macro_rules! fuzz_case {
    ($case:ty, $entry:literal) => {
        $crate::fuzz_case!($case, $entry, init: $crate::quiet_log());
    };
    ($case:ty, $entry:literal, init: $init:expr) => {
        libfuzzer_sys::fuzz_target!(
            init: $init,
            |data: &[u8]| {
                let case = <$case>::decode(data);
                if let Err(e) = case.check() {
                    panic!("{} property violated: {e}\ninput: {case:?}", $entry);
                }
            }
        );
    };
}
