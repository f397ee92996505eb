//! Scene P1's host and series (examples/scenes/column.rs, compiled in by path so that the test
//! runs the main job's code): steady seepage to round-off, the column with the interface kernel
//! equal to the column meshed without it, the series solution against Terzaghi's and against the
//! finite elements for every drainage case, the derived first-step monotonicity boundary
//! c·Δt/Δz² = 1/4, and scene files with bad values refused by key.
#![allow(dead_code)]

#[path = "../examples/scenes/column.rs"]
mod column;

use column::{
    Column, Drainage, Join, Series, consolidate, early_degree, early_time, steady, terzaghi,
};
use serde::Deserialize;

fn built_in() -> Column {
    let text = include_str!("../examples/scenes/data/p1.toml");
    let table: toml::Table = text.parse().expect("p1.toml");
    let column = table.get("column").expect("[column]").clone();
    let c = Column::deserialize(column).expect("column");
    c.validate().expect("valid");
    c
}

/// A short run of the built-in column (coarse Δt, early end) to keep debug builds quick.
fn short(mut c: Column, top: Drainage, bottom: Drainage) -> Column {
    c.top = top;
    c.bottom = bottom;
    c.dt = 0.01;
    c.end = 2.0;
    c.times = vec![0.2, 1.0, 2.0];
    c
}

#[test]
fn steady_seepage_is_linear_per_layer_with_the_series_flux() {
    let c = built_in();
    let (p_top, p_base) = (100.0, -20.0);
    let s = steady(&c, p_top, p_base).unwrap();
    let [l1, l2] = &c.layers;
    let q = (p_top - p_base) / (l1.thickness / l1.permeability + l2.thickness / l2.permeability);
    assert!((s.interface_flux() - q).abs() <= 1e-12 * q.abs());
    for f in s.element_fluxes() {
        assert!((f - q).abs() <= 1e-12 * q.abs(), "element flux {f} vs {q}");
    }
    let p_i = p_top - q * l1.thickness / l1.permeability;
    for (z, p) in s.nodal_pressures() {
        let exact = if z <= l1.thickness {
            p_top - q * z / l1.permeability
        } else {
            p_i - q * (z - l1.thickness) / l2.permeability
        };
        assert!(
            (p - exact).abs() <= 1e-12 * 120.0,
            "z = {z}: {p} vs {exact}"
        );
    }
    assert!(s.newton_reduction <= 1e-12);
}

#[test]
fn the_interface_kernel_reproduces_the_column_without_interface() {
    let c = short(built_in(), Drainage::Drained, Drainage::Undrained);
    let a = consolidate(&c, Join::Interface, 1, c.dt, true).unwrap();
    let b = consolidate(&c, Join::Shared, 1, c.dt, false).unwrap();
    for (ra, rb) in a.u.iter().zip(&b.u) {
        for (x, y) in ra.iter().zip(rb) {
            assert!((x - y).abs() <= 1e-10 * c.load, "{x} vs {y}");
        }
    }
    for (x, y) in a.degree.iter().zip(&b.degree) {
        assert!((x - y).abs() <= 1e-12);
    }
    // Stationarity in q̂: p₁ = p₂ at every step; the kernel's tangent makes one Newton
    // iteration exact.
    assert!(a.jump <= 1e-12 * c.load);
    assert!(a.newton_reduction <= 1e-10, "{}", a.newton_reduction);
    assert_eq!(a.kernel_calls, 1 + 2 * a.steps);
}

#[test]
fn the_series_of_two_alike_layers_is_terzaghis() {
    let mut c = built_in();
    c.layers[1].permeability = c.layers[0].permeability;
    c.layers[1].modulus = c.layers[0].modulus;
    let h = c.height();
    let cv = c.layers[0].cv();
    // Drained top, undrained base: drainage path H.
    let t = 0.2 * h * h / cv;
    let s = Series::new(&c, t).unwrap();
    for z in [0.1, 0.5, 1.0, 2.0, 2.9] {
        let want = c.load * terzaghi(z / h, 0.2);
        assert!((s.pressure(z, t) - want).abs() <= 1e-9 * c.load, "z = {z}");
    }
    // Drained both ends: path H/2, symmetric about mid-height.
    c.bottom = Drainage::Drained;
    let t = 0.2 * (h / 2.0) * (h / 2.0) / cv;
    let s = Series::new(&c, t).unwrap();
    for z in [0.3, 1.0, 1.5, 2.7] {
        let d = if z <= h / 2.0 { z } else { h - z };
        let want = c.load * terzaghi(d / (h / 2.0), 0.2);
        assert!((s.pressure(z, t) - want).abs() <= 1e-9 * c.load, "z = {z}");
    }
    // U by settlement for the single layer: 1 − Σ 2/M² e^{−M² T}.
    let tv: f64 = 0.2;
    let mut remaining = 0.0;
    for m in 0..1000 {
        let big = std::f64::consts::PI * (2 * m + 1) as f64 / 2.0;
        remaining += 2.0 / (big * big) * (-big * big * tv).exp();
    }
    assert!((s.degree(t) - (1.0 - remaining)).abs() <= 1e-9);
}

/// The (top, bottom) drainage cases of a column with at least one drained face: each face
/// drained or not, all but both undrained.
fn drainage_cases() -> impl Iterator<Item = (Drainage, Drainage)> {
    let faces = [Drainage::Drained, Drainage::Undrained];
    let pairs = faces
        .into_iter()
        .flat_map(move |top| faces.map(|bottom| (top, bottom)));
    pairs.filter(|&pair| pair != (Drainage::Undrained, Drainage::Undrained))
}

#[test]
fn finite_elements_converge_to_the_series_for_every_drainage_case() {
    for (top, bottom) in drainage_cases() {
        let c = short(built_in(), top, bottom);
        let s = Series::new(&c, 0.2).unwrap();
        let run = consolidate(&c, Join::Interface, 2, c.dt, false).unwrap();
        for (row, &z) in c.depths.iter().enumerate() {
            for (col, &t) in c.times.iter().enumerate() {
                let e = (run.u[row][col] - s.pressure(z, t)).abs() / c.load;
                assert!(e <= 0.02, "{top:?}/{bottom:?} z {z} t {t}: error {e}");
            }
        }
        for (col, &t) in c.times.iter().enumerate() {
            let e = (run.degree[col] - s.degree(t)).abs();
            assert!(e <= 0.01, "{top:?}/{bottom:?} U at t {t}: error {e}");
        }
    }
}

#[test]
fn the_first_step_is_monotone_from_c_dt_over_dz2_of_one_quarter() {
    let c = built_in();
    let dz = c.layers[0].thickness / c.layers[0].elements as f64;
    for (ratio, monotone) in [(0.2, false), (0.24, false), (0.26, true), (0.5, true)] {
        let dt = ratio * dz * dz / c.layers[0].cv();
        let mut one = c.clone();
        one.dt = dt;
        one.end = dt;
        one.times = vec![dt];
        let h = consolidate(&one, Join::Interface, 1, dt, false).unwrap();
        assert_eq!(
            h.overshoot[0] <= 1e-12,
            monotone,
            "ratio {ratio}: {}",
            h.overshoot[0]
        );
    }
}

#[test]
fn bad_scene_values_are_refused_by_key() {
    let good = built_in();
    type Spoil = Box<dyn Fn(&mut Column)>;
    let cases: [(&str, Spoil); 5] = [
        ("column.dt", Box::new(|c| c.dt = 0.0)),
        (
            "column.layers[1].permeability",
            Box::new(|c| c.layers[1].permeability = -1.0),
        ),
        (
            "column.layers[0].elements",
            Box::new(|c| c.layers[0].elements = 0),
        ),
        ("column.depths", Box::new(|c| c.depths.push(99.0))),
        ("both undrained", Box::new(|c| c.top = Drainage::Undrained)),
    ];
    for (key, spoil) in cases {
        let mut c = good.clone();
        if key == "both undrained" {
            c.bottom = Drainage::Undrained;
        }
        spoil(&mut c);
        let e = c.validate().unwrap_err();
        assert!(
            e.contains(key.split(' ').next().unwrap_or(key)),
            "{key}: {e}"
        );
    }
}

#[test]
fn the_series_misses_no_eigenvalue_at_early_times() {
    // Every term counts at an early time; the error-function solution at the drained faces is
    // exact there.
    for (top, bottom) in drainage_cases() {
        let mut c = built_in();
        c.top = top;
        c.bottom = bottom;
        let t = early_time(&c);
        let s = Series::new(&c, t).unwrap();
        assert!(s.terms() > 100, "{}", s.terms());
        let (got, want) = (s.degree(t), early_degree(&c, t));
        assert!(
            (got - want).abs() <= 1e-9,
            "{top:?}/{bottom:?}: {got} vs {want}"
        );
    }
}
