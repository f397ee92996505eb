//! Frictional heating: the `[interactions.NAME.heat]` table of the configuration file (every
//! build) and CalculiX's `fricheat_` through the ABI (the CalculiX variant:
//! `cargo test --features calculix --test fricheat`). The file is read once per process, so the
//! ABI tests set `INTERFACIAL_CONFIG` before their first call.

use interfacial::config::Config;
use interfacial::laws::frictional_heat::SlidingSpeed;

fn parse(text: &str) -> Result<Config, String> {
    Config::parse("heat.toml", text)
}

/// Two heat tables, read by the parser's tests and (with the CalculiX variant) by the ABI's:
/// Brake's with its own slave share and sliding speed, Pad's with Charron's share from the
/// effusivities and the host's speed, next to a thermal law of the same interaction. No "*"
/// entry: the parser's test adds one ([`FALLBACK`]).
const HEAT: &str = r#"
[interactions.Brake.heat]
fraction = 0.95
slave_share = 0.3
speed = 12.5

[interactions.Pad.heat]
fraction = 1.0
slave_effusivity = 8000.0
master_effusivity = 12000.0

[interactions.Pad.conductance]
law = "constant"
k = 4.0
"#;

/// The heat of every interaction [`HEAT`] does not list.
const FALLBACK: &str = r#"
[interactions."*".heat]
fraction = 0.5
slave_share = 0.5
"#;

#[test]
fn heat_tables_are_read_per_interaction_with_the_fallback() {
    let cfg = parse(&format!("{HEAT}{FALLBACK}")).unwrap();
    let brake = cfg.frictional_heat(b"BRAKE   ").unwrap();
    assert_eq!(brake.fraction(), 0.95);
    assert_eq!(brake.slave_share(), 0.3);
    assert_eq!(brake.speed(), SlidingSpeed::Given(12.5));
    // Charron's share: e_s/(e_s + e_m), and no speed: the host's relative velocity.
    let pad = cfg.frictional_heat(b"pad").unwrap();
    assert!((pad.slave_share() - 8000.0 / 20000.0).abs() <= 1e-15);
    assert_eq!(pad.speed(), SlidingSpeed::FromHost);
    // The heat table does not disturb the thermal law of the same interaction.
    let k = cfg
        .gap_law(b"PAD")
        .unwrap()
        .evaluate(0.0, 1.0, 20.0, 20.0)
        .unwrap()
        .k;
    assert_eq!(k, 4.0);
    // A heat-only interaction has no thermal law (and there is no "*" conductance).
    assert!(cfg.gap_law(b"BRAKE").is_none());
    // Any other name, and a prefix or an extension of a listed one, takes "*".
    for other in [&b"Clutch"[..], b"BRAK", b"BRAKES"] {
        let h = cfg.frictional_heat(other).unwrap();
        assert_eq!((h.fraction(), h.slave_share()), (0.5, 0.5));
    }
    // Without a "*" heat entry, an unlisted name has no law.
    let cfg = parse("[interactions.A.heat]\nfraction = 1.0\nslave_share = 0.0\n").unwrap();
    assert!(cfg.frictional_heat(b"B").is_none());
}

#[test]
fn bad_heat_tables_name_file_line_and_key() {
    for (text, line, needle) in [
        (
            "[interactions.A.heat]\nslave_share = 0.5\n",
            1,
            "interactions.A.heat.fraction: required",
        ),
        (
            "[interactions.A.heat]\nfraction = 0.0\nslave_share = 0.5\n",
            2,
            "interactions.A.heat.fraction: fraction = 0 ",
        ),
        (
            "[interactions.A.heat]\nfraction = 1.2\nslave_share = 0.5\n",
            2,
            "must be in (0, 1]",
        ),
        (
            "[interactions.A.heat]\nfraction = 1.0\nslave_share = 1.5\n",
            3,
            "interactions.A.heat.slave_share: slave_share = 1.5",
        ),
        (
            "[interactions.A.heat]\nfraction = 1.0\n\nslave_share = -0.5\n",
            4,
            "interactions.A.heat.slave_share",
        ),
        (
            "[interactions.A.heat]\nfraction = 1.0\n",
            1,
            "interactions.A.heat.slave_share: required",
        ),
        (
            "[interactions.A.heat]\nfraction = 1.0\nslave_share = 0.5\nslave_effusivity = 1.0\nmaster_effusivity = 1.0\n",
            3,
            "not both",
        ),
        (
            "[interactions.A.heat]\nfraction = 1.0\nmaster_effusivity = 1.0\n",
            3,
            "give both slave_effusivity and master_effusivity",
        ),
        (
            "[interactions.A.heat]\nfraction = 1.0\nslave_effusivity = 1.0\nmaster_effusivity = -3.0\n",
            4,
            "interactions.A.heat.master_effusivity: master_effusivity = -3",
        ),
        (
            "[interactions.A.heat]\nfraction = 1.0\nslave_effusivity = 0.0\nmaster_effusivity = 3.0\n",
            3,
            "interactions.A.heat.slave_effusivity: slave_effusivity = 0",
        ),
        (
            "[interactions.A.heat]\nfraction = 1.0\nslave_share = 0.5\nspeed = 0.0\n",
            4,
            "interactions.A.heat.speed: speed = 0 must be finite and > 0",
        ),
        (
            "[interactions.A.heat]\nfraction = 1.0\nslave_share = 0.5\nsped = 1.0\n",
            4,
            "unknown field `sped`",
        ),
        (
            "[interactions.A.heat]\nfraction = \"most\"\nslave_share = 0.5\n",
            2,
            "",
        ),
    ] {
        let e = parse(text).unwrap_err();
        assert!(e.starts_with(&format!("heat.toml:{line}:")), "{text}: {e}");
        assert!(e.contains(needle), "{text}: {e}");
    }
}

#[cfg(feature = "calculix")]
#[path = "common/config_file.rs"]
mod config_file;

#[cfg(feature = "calculix")]
mod abi {
    use super::{HEAT, config_file};

    use std::ffi::{CStr, c_char, c_int};

    use interfacial::abi::{
        fricheat::{FRICHEAT_HOST_SPEED, fricheat_},
        ifl_clear_error, ifl_last_error,
    };

    /// Outputs before the call, to see what is written.
    const GUARD: f64 = -7.5e300;

    /// One call with CalculiX's argument list, `ET` passed as NULL when `with_et` is false;
    /// returns (ET, F, VNORM) as they are after the call.
    fn call(name: &str, with_et: bool) -> (f64, f64, f64) {
        config_file::config_once("fricheat", HEAT);
        let mut ciname = [b' '; 80];
        ciname[..name.len()].copy_from_slice(name.as_bytes());
        let (mut et, mut f, mut vnorm) = (GUARD, GUARD, GUARD);
        let et_ptr: *mut f64 = if with_et {
            &mut et
        } else {
            std::ptr::null_mut()
        };
        let time = [1.0, 2.0];
        let ints: [c_int; 7] = [17, 3, 1, 1, 6, 2, 5];
        let (um, area, pressure, coords) = (0.3, 0.25, 19.6, [0.0, 0.5, 1.0]);
        // SAFETY: every pointer valid for the call (ET NULL or valid), CINAME of length 80.
        unsafe {
            fricheat_(
                et_ptr,
                &mut f,
                &mut vnorm,
                time.as_ptr(),
                ciname.as_ptr().cast::<c_char>(),
                &ints[0],
                &ints[1],
                &ints[2],
                &ints[3],
                &ints[4],
                &um,
                &ints[5],
                &ints[6],
                &area,
                &pressure,
                coords.as_ptr(),
                80,
            );
        }
        (et, f, vnorm)
    }

    fn last_error() -> String {
        // SAFETY: the library's NUL-terminated message of this thread.
        unsafe { CStr::from_ptr(ifl_last_error()) }
            .to_string_lossy()
            .into_owned()
    }

    #[test]
    fn the_interactions_law_comes_back_in_et_f_vnorm() {
        let (et, f, v) = call("brake", true);
        assert_eq!((et, f, v), (0.95, 0.3, 12.5));
        // Charron's share 8000/(8000 + 12000), and no speed: CalculiX's own relative velocity
        // (< −0.5).
        let (et, f, v) = call("PAD", true);
        assert_eq!(et, 1.0);
        assert!((f - 0.4).abs() <= 1e-15, "{f}");
        assert_eq!(v, FRICHEAT_HOST_SPEED);
        assert!(v < -0.5);
    }

    #[test]
    fn an_unknown_interaction_gives_no_heat_and_says_why() {
        ifl_clear_error();
        let (et, f, v) = call("CLUTCH", true);
        assert_eq!((et, f, v), (0.0, 0.0, 0.0));
        let m = last_error();
        for needle in [
            "FRICHEAT",
            "CLUTCH",
            "contact element 17",
            "has no [interactions.CLUTCH.heat]",
        ] {
            assert!(m.contains(needle), "{needle}: {m}");
        }
    }

    #[test]
    fn a_null_output_is_refused_and_the_others_get_the_safe_values() {
        ifl_clear_error();
        let (et, f, v) = call("BRAKE", false);
        assert_eq!(et, GUARD, "nothing written through a NULL ET");
        assert_eq!((f, v), (0.0, 0.0));
        let m = last_error();
        assert!(m.contains("ET is a NULL pointer"), "{m}");
    }
}
