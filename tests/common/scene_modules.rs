// The main job's modules (examples/scenes/), compiled into a scene test by
// `include!("common/scene_modules.rs")` at the test's root, where `crate::checks` and the others
// resolve as they do in the job. Paths are relative to this file.

#[path = "../../examples/scenes/charts.rs"]
mod charts;
#[path = "../../examples/scenes/checks.rs"]
mod checks;
#[path = "../../examples/scenes/circle.rs"]
mod circle;
#[path = "../../examples/scenes/column.rs"]
mod column;
#[path = "../../examples/scenes/consolidation.rs"]
mod consolidation;
#[path = "../../examples/scenes/csvfile.rs"]
mod csvfile;
#[path = "../../examples/scenes/findings.rs"]
mod findings;
#[path = "../../examples/scenes/job.rs"]
mod job;
#[path = "../../examples/scenes/oscillator.rs"]
mod oscillator;
#[path = "../../examples/scenes/pull.rs"]
mod pull;
#[path = "../../examples/scenes/rate_map.rs"]
mod rate_map;
#[path = "../../examples/scenes/rate_state.rs"]
mod rate_state;
#[path = "../../examples/scenes/scene.rs"]
mod scene;
#[path = "../../examples/scenes/stability.rs"]
mod stability;
#[path = "../../examples/scenes/velocity.rs"]
mod velocity;
#[path = "../../examples/scenes/weakening.rs"]
mod weakening;
