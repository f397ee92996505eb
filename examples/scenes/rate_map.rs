//! F4 rate-stability maps: steady sliding at the steepest rate of the scene (v₁) under the
//! exponential decay law, over (Δt, d_c) with a soft stick spring, for the law solved at the
//! end-of-increment rate and with μ frozen at the start-of-increment rate. Each cell is one run
//! of two time units at v₁ from first contact; it "settles" when the end stress is τ_law(v₁) to
//! 1e-9 relative, "oscillates" otherwise, or is a library cut-back (PNEWDT < 1). The closed-form
//! limit of [`VelocitySteps::rate_stability_limit`] (Δt = 2|dτ/dv|/k_s implicit, |dτ/dv|/k_s
//! frozen, with |dτ/dv| ∝ d_c·exp(−d_c v₁)) is drawn on the map, and the driver checks that the
//! measured boundary of every row with d_c·v₁ ≤ 1 lies within one grid cell of it.

use crate::stability::log_space;
use crate::velocity::{RateLaw, VelocitySteps};

/// The class of one cell.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RateCell {
    /// Steady sliding reached: τ = τ_law(v₁).
    Settles,
    /// The sliding rate keeps oscillating.
    Oscillates,
    /// The library asked for a smaller step.
    CutBack,
}

impl RateCell {
    /// Name in CSV files and legends.
    pub fn name(self) -> &'static str {
        match self {
            RateCell::Settles => "settles to τ_law(v)",
            RateCell::Oscillates => "rate oscillates (unstable)",
            RateCell::CutBack => "cut-back (PNEWDT<1)",
        }
    }
}

/// One map.
pub struct RateMap {
    /// The law (decay implicit or frozen).
    pub law: RateLaw,
    /// Allowable elastic slip of the stick spring.
    pub gamma_crit: f64,
    /// The scene with one rate, v₁, held for two time units.
    pub scene: VelocitySteps,
    /// Column values.
    pub dts: Vec<f64>,
    /// Row values.
    pub decays: Vec<f64>,
    /// `cells[row][column]`.
    pub cells: Vec<Vec<RateCell>>,
}

impl RateMap {
    /// Runs the map: `nx` × `ny` cells over Δt ∈ [1e-4, 0.1] and d_c ∈ [0.5, 50].
    pub fn run(base: &VelocitySteps, law: RateLaw, gamma_crit: f64, nx: usize, ny: usize) -> Self {
        let mut scene = base.clone();
        scene.rates = vec![base.rates[0]];
        scene.hold = 2.0;
        let dts = log_space(1e-4, 0.1, nx);
        let decays = log_space(0.5, 50.0, ny);
        let cells = decays
            .iter()
            .map(|&dc| {
                let mut s = scene.clone();
                s.decay = dc;
                let tau = s.tau_law(law, s.rates[0]);
                dts.iter()
                    .map(|&dt| {
                        let r = s.run(law, gamma_crit, dt);
                        if !r.ok {
                            RateCell::CutBack
                        } else if r.steady_error * s.swing(law) <= 1e-9 * tau {
                            RateCell::Settles
                        } else {
                            RateCell::Oscillates
                        }
                    })
                    .collect()
            })
            .collect();
        RateMap {
            law,
            gamma_crit,
            scene,
            dts,
            decays,
            cells,
        }
    }

    /// The closed-form smallest stable Δt of row `r`.
    pub fn limit(&self, r: usize) -> f64 {
        let mut s = self.scene.clone();
        s.decay = self.decays[r];
        s.rate_stability_limit(self.law, self.gamma_crit)
    }

    /// Row `r` is held to the linearised limit: the law has one, and d_c·v₁ ≤ 1. Further down the decay the run's
    /// start from v = 0 crosses rates where |dτ/dv| is up to exp(d_c v₁) times steeper, and the
    /// implicit scheme can lock into a sustained oscillation above the linear limit (measured:
    /// up to 2.4 × it at d_c v₁ = 2.5); the limit is then necessary, not sufficient.
    /// A law without a step limit (the implicit laws' rate-following stiffness: limit 0) has no
    /// boundary to hold: its map must settle in every cell instead (finding F4-map-implicit).
    pub fn checked(&self, r: usize) -> bool {
        self.limit(r) > 0.0 && self.decays[r] * self.scene.rates[0] <= 1.0
    }

    /// Row `r`: the measured boundary (first settling column) and the closed form's (first
    /// column above the limit) agree within one cell; rows not [`checked`](Self::checked) pass.
    pub fn boundary_matches(&self, r: usize) -> bool {
        if !self.checked(r) {
            return true;
        }
        let limit = self.limit(r);
        let measured = self.cells[r].iter().position(|c| *c == RateCell::Settles);
        let theory = self.dts.iter().position(|&dt| dt > limit);
        match (measured, theory) {
            (Some(m), Some(t)) => m.abs_diff(t) <= 1,
            (None, None) => true,
            _ => false,
        }
    }

    /// Title of the map.
    pub fn title(&self) -> String {
        format!(
            "F4 rate stability, decay law {}, γ_crit = {:e} m, v = {} m/s",
            if self.law == RateLaw::DecayFrozen {
                "with μ frozen"
            } else {
                "implicit"
            },
            self.gamma_crit,
            self.scene.rates[0]
        )
    }
}
