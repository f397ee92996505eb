//! The configuration parser on any bytes: `Config::parse` must return a configuration or an
//! error that names the file and a line, never panic; a configuration that parses must answer
//! every lookup, and its laws must give a finite k ≥ 0 or an error at any finite point.
//!
//! Shared by the `config` fuzz target and `tests/fuzz_regressions.rs` (included there by path).

use interfacial::config::Config;

/// Names looked up in a configuration that parses.
const NAMES: [&[u8]; 6] = [b"SI1", b"si1     ", b"A", b"*", b"", b"GAP-PTAB"];

/// Points (clearance, pressure, θ_A, θ_B) at which each law found is evaluated.
const POINTS: [[f64; 4]; 6] = [
    [0.0, 0.0, 20.0, 20.0],
    [1e-3, 50.0, 300.0, 290.0],
    [-1.0, -1.0, -10.0, 1000.0],
    [1e300, 1e300, 1e300, -1e300],
    [5e-324, 5e-324, 5e-324, 0.0],
    [f64::MAX, -f64::MAX, 0.0, 0.0],
];

/// Parses `data` (lossily decoded as UTF-8) and checks the properties above.
pub fn check(data: &[u8]) -> Result<(), String> {
    let text = String::from_utf8_lossy(data);
    let cfg = match Config::parse("fuzz.toml", &text) {
        Ok(cfg) => cfg,
        Err(e) => {
            return if e.starts_with("fuzz.toml:") && e.len() > "fuzz.toml:".len() {
                Ok(())
            } else {
                Err(format!("error does not name the file and line: {e:?}"))
            };
        }
    };
    for name in NAMES {
        let Some(law) = cfg.gap_law(name) else {
            continue;
        };
        for [d, p, ta, tb] in POINTS {
            if let Ok(r) = law.evaluate(d, p, ta, tb)
                && !(r.k.is_finite() && r.k >= 0.0)
            {
                return Err(format!("k = {} at {:?} for {law:?}", r.k, [d, p, ta, tb]));
            }
        }
    }
    Ok(())
}
