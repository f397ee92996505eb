//! Scene P1 with a user's own column (`--point FILE.toml`): physically valid columns far from
//! the built-in one — layer ratios of permeability, stiffness and thickness from 0.01 to 100,
//! 10 to 100 elements per layer — pass every check of the scene. The checks that depend on the
//! data scale with it: the Newton residual against the run's largest residual, element fluxes
//! against their round-off, the observed orders by self-convergence. The main job's P1 code
//! (examples/scenes/consolidation.rs) is compiled in by path, so the test runs the same code.
#![allow(dead_code)]

include!("common/scene_modules.rs");

/// A P1 file: layer 1 fixed (1 m, k = 1e-3, M = 1e3), layer 2 = layer 1 × the ratios, with an
/// optional study table.
fn column_file(
    id: &str,
    [k_ratio, m_ratio, h_ratio]: [f64; 3],
    [n1, n2]: [usize; 2],
    study: bool,
) -> String {
    let h2 = h_ratio;
    let mut text = format!(
        r#"
id = "{id}"
title = "user column {id}"
tolerance = 0.02

[column]
load = 100.0
top = "drained"
bottom = "undrained"
dt = 0.005
end = 4.0
depths = [0.0, 0.5, 1.0, {mid}, {base}]
times = [0.1, 0.5, 1.0, 2.0, 4.0]

[[column.layers]]
thickness = 1.0
permeability = 1.0e-3
modulus = 1.0e3
elements = {n1}

[[column.layers]]
thickness = {h2}
permeability = {k2:e}
modulus = {m2:e}
elements = {n2}

[steady]
p_top = 100.0
p_base = 0.0
"#,
        mid = 1.0 + h2 / 2.0,
        base = 1.0 + h2,
        k2 = 1e-3 * k_ratio,
        m2 = 1e3 * m_ratio,
    );
    if study {
        text.push_str(
            r#"
[study]
dts = [0.1, 0.05, 0.025]
quick_dts = [0.05]
dt_sweep_refine = 2
refines = [1, 2, 4]
quick_refines = [1]
refine_sweep_dt = 2.0e-3
repeats = 1
dt_order = [0.8, 1.2]
mesh_order = [1.6, 2.4]
stability_ratios = [0.1, 0.2, 0.24, 0.26, 0.3, 0.5]
"#,
        );
    }
    text
}

fn run(id: &str, ratios: [f64; 3], elements: [usize; 2], study: bool) {
    let text = column_file(id, ratios, elements, study);
    let file = consolidation::parse(&text, id).expect("a valid column");
    let out = std::env::temp_dir().join(format!("interfacial-p1-user-{id}-{}", std::process::id()));
    std::fs::create_dir_all(&out).expect("the output directory");
    let outcome = consolidation::run(&file, false, &out).expect("the P1 run");
    let _ = std::fs::remove_dir_all(&out);
    let failed = checks::failures(&outcome.rows);
    assert!(
        failed.is_empty() && outcome.failures == 0,
        "{id} (k, M, h ratios {ratios:?}, elements {elements:?}):\n{}",
        failed.join("\n")
    );
    // The data-scaled checks are there, not skipped (and the study's, with a study).
    let mut expected = vec![
        "worst element flux -k dp/dz",
        "Newton: largest |R| after an update / largest before",
    ];
    if study {
        expected.extend([
            "observed order in Δt (backward Euler: 1)",
            "observed order in Δz (linear elements: 2)",
            "monotone from c·Δt/Δz² = 1/4",
        ]);
    }
    for quantity in expected {
        assert!(
            outcome.rows.iter().any(|r| r.quantity == quantity),
            "{id}: no row '{quantity}'"
        );
    }
}

/// The columns, each a `run`: (id, layer 2's k, M and h ratios to layer 1's, elements per
/// layer, with a study).
const COLUMNS: [(&str, [f64; 3], [usize; 2], bool); 4] = [
    // k and M a hundred times layer 1's, 10 elements per layer (a fixed Newton bound failed
    // such columns while their errors were within tolerance).
    ("stiff", [100.0, 100.0, 1.0], [10, 10], false),
    // k and M a hundredth of layer 1's, 100 elements per layer (the element fluxes' round-off
    // exceeded 1e-12·q there).
    ("soft", [0.01, 0.01, 1.0], [100, 100], false),
    // A tight but stiff, thin base layer with a study: self-converged orders and the first-step
    // bracket of the drained layer.
    ("mixed", [0.04, 70.0, 0.12], [13, 44], true),
    // Depths that are nodes of one mesh of the element sweep and not of the next (27 elements
    // per metre): the element order is observed in U.
    ("thick", [8.0, 2.0, 8.5], [27, 56], true),
];

/// Every column at once, a thread each (a failed one fails the test, naming its id, once all
/// have run).
#[test]
fn far_columns_pass_every_check() {
    std::thread::scope(|scope| {
        for (id, ratios, elements, study) in COLUMNS {
            scope.spawn(move || run(id, ratios, elements, study));
        }
    });
}
