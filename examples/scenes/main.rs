//! The main job: speed against accuracy for the contact laws, through the entry points a host
//! calls (`fric_`, `gapcon_`).
//!
//!     cargo run --release --example scenes                 # everything (under 30 s)
//!     cargo run --release --example scenes -- --quick      # reduced sweeps and maps
//!     cargo run --release --example scenes -- --out DIR    # charts and CSV to DIR
//!     cargo run --release --example scenes -- --point my.toml   # your own scene file only
//!     cargo run --release --example scenes -- --verbose    # every table, every file
//!
//! 1. Closed-form checks of every scene (F1–F5 through `fric_`; T1, T2 through `gapcon_`; A1
//!    through `uinter_`).
//! 2. Work-precision sweeps of the scenes in `examples/scenes/data/*.toml` (F6 stick-slip
//!    oscillator, F1 pull through a spring, F2 circle, F4 velocity steps with the rate laws:
//!    decay law implicit and with μ frozen, adhesive law): every method over its step sizes, error
//!    against the closed form, wall time and `fric_` calls, each point held to the accuracy its
//!    chart claims (dashed on the charts).
//! 3. Stability maps of F6 over (Δt, γ_crit), with the explicit limit, and the check that the
//!    measured explicit boundary is within one grid cell of 2/sqrt((k + K_f)/m); a map with an
//!    unguarded host that cuts back when `fric_` refuses (PNEWDT < 1); the F4 rate maps.
//! 4. Findings (`findings.rs`): every figure README.md and docs/scenes.md quote, recomputed; on
//!    the full run a finding without its data fails.
//! 5. P1, the two-layer consolidation column through `ifl_pore_pressure` (consolidation.rs; a
//!    `--point` file with a `[column]` table runs alone; docs/pore-pressure.md).
//!
//! Writes `<out>/<scene>-work-precision.csv`, `<out>/<scene>-error-vs-time.svg`,
//! `<out>/<scene>-error-vs-calls.svg`, `<out>/F6-map-<n>.csv` and `.svg`, `<out>/checks.csv` and
//! `<out>/findings.csv` (default `<out>` = `target/scenes`), every CSV RFC 4180. Prints a banner,
//! a line per scene and a summary table. Exits non-zero when a check, a claim or a finding
//! fails. The job itself is `job.rs` (`tests/scenes_job.rs` runs it); how to read and extend it:
//! `docs/scenes.md`.

mod charts;
mod checks;
mod circle;
mod column;
mod consolidation;
mod csvfile;
mod findings;
mod job;
mod oscillator;
mod pull;
mod rate_map;
mod rate_state;
mod scene;
mod stability;
mod velocity;
mod weakening;

fn main() {
    let opts = match job::Options::parse(std::env::args().skip(1)) {
        Ok(o) => o,
        Err(e) => {
            eprintln!("{e}");
            std::process::exit(2);
        }
    };
    std::process::exit(job::run(&opts));
}
