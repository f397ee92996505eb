//! Scene P1 (docs/scene-definitions.md): a 1-D column of two porous layers joined by the interface
//! pore-pressure kernel (`ifl_pore_pressure`, seed 000), with a small host of its own:
//! - linear 1-D u–p elements (settlement w and excess pore pressure p at every node; Terzaghi's
//!   assumptions: incompressible grains and fluid, constrained modulus M, Darcy flux
//!   v = −k ∂p/∂z, so c_v = k·M), backward Euler in time;
//! - at the interface, two nodes (one per layer) joined by a closed, small-sliding contact point:
//!   a Lagrange multiplier λ (the effective contact pressure) ties the settlements, h = w₂ − w₁ = 0,
//!   and the kernel adds p̄δh + Δt(q̂δp̂ + p̂δq̂) with q̂ one more unknown;
//! - the same column meshed without an interface (shared node), for comparison;
//! - the series solution of two-layer consolidation (derived below).
//!
//! z points down from the top (z = 0) to the base (z = H₁ + H₂); layer 1 is on top. Stresses and
//! the load are positive in compression; w is positive downwards.
//!
//! Weak form (per unit area; the continuity equation multiplied by −Δt so that the system is
//! symmetric, the same sign as the kernel's δΠ^ipp):
//!   ∫ M w′δw′ − ∫ p δw′ − q₀ δw(0) + [−λ δh − δλ h + δΠ^ipp] = 0,
//!   −∫ Δw′ δp − Δt ∫ k p′δp′ (+ the interface's −Δt q̂ δp̂) = 0.
//! The layer's natural boundary term at the interface, −Δt v δp₁ + Δt v δp₂ with v the downward
//! flux, is what −Δt q̂ δp̂ = −Δt (q̂/2)(δp₁ − δp₂) replaces: v = q̂/2.

use interfacial::abi::{IflPorePressureVariant, IflStatus, ifl_last_error, ifl_pore_pressure};
use serde::Deserialize;

/// One porous layer.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Layer {
    /// Thickness H_i.
    pub thickness: f64,
    /// Permeability k_i (Darcy: v = −k ∂p/∂z; k = k_hydraulic/γ_w).
    pub permeability: f64,
    /// Constrained (oedometric) modulus M_i = 1/m_v.
    pub modulus: f64,
    /// Elements in the layer.
    pub elements: usize,
}

impl Layer {
    /// Coefficient of consolidation c_v = k·M.
    pub fn cv(&self) -> f64 {
        self.permeability * self.modulus
    }
}

/// Drainage of a boundary.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "lowercase")]
pub enum Drainage {
    /// p = 0.
    Drained,
    /// No flow.
    Undrained,
}

/// The column of a P1 scene file (`[column]`).
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Column {
    /// Step load q₀ on the top (total stress, compression positive), applied at t = 0.
    pub load: f64,
    /// Drainage at the top (z = 0).
    pub top: Drainage,
    /// Drainage at the base.
    pub bottom: Drainage,
    /// Layer 1 (top) and layer 2 (bottom).
    pub layers: [Layer; 2],
    /// Time increment Δt.
    pub dt: f64,
    /// End time.
    pub end: f64,
    /// Depths at which u(z, t) is written (0 ≤ z ≤ H₁ + H₂; at z = H₁ the side-1 node).
    pub depths: Vec<f64>,
    /// Times at which u(z, t) and U(t) are written (0 < t ≤ end).
    pub times: Vec<f64>,
}

impl Column {
    /// Total height.
    pub fn height(&self) -> f64 {
        self.layers[0].thickness + self.layers[1].thickness
    }

    /// Final settlement q₀·Σ H_i/M_i.
    pub fn final_settlement(&self) -> f64 {
        self.load
            * self
                .layers
                .iter()
                .map(|l| l.thickness / l.modulus)
                .sum::<f64>()
    }

    /// Checks the file's values; the message names the key.
    pub fn validate(&self) -> Result<(), String> {
        let positive = |name: &str, v: f64| {
            if v.is_finite() && v > 0.0 {
                Ok(())
            } else {
                Err(format!("column.{name} = {v} must be finite and > 0"))
            }
        };
        positive("load", self.load)?;
        positive("dt", self.dt)?;
        positive("end", self.end)?;
        for (i, l) in self.layers.iter().enumerate() {
            positive(&format!("layers[{i}].thickness"), l.thickness)?;
            positive(&format!("layers[{i}].permeability"), l.permeability)?;
            positive(&format!("layers[{i}].modulus"), l.modulus)?;
            if l.elements == 0 || l.elements > 100_000 {
                return Err(format!(
                    "column.layers[{i}].elements = {} must be in 1..=100000",
                    l.elements
                ));
            }
        }
        if self.end / self.dt > 1e7 {
            return Err(format!(
                "column.end/column.dt = {:e} steps: at most 1e7",
                self.end / self.dt
            ));
        }
        if self.top == Drainage::Undrained && self.bottom == Drainage::Undrained {
            return Err(
                "column.top and column.bottom are both undrained: nothing consolidates".into(),
            );
        }
        let h = self.height();
        if let Some(z) = self.depths.iter().find(|z| !(0.0..=h).contains(*z)) {
            return Err(format!("column.depths: {z} is outside 0..={h}"));
        }
        if let Some(t) = self.times.iter().find(|t| !(**t > 0.0 && **t <= self.end)) {
            return Err(format!(
                "column.times: {t} is outside (0, end = {}]",
                self.end
            ));
        }
        Ok(())
    }
}

/// How the two layers are joined.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Join {
    /// Two nodes, a contact multiplier and the pore-pressure kernel.
    Interface,
    /// One shared node (the reference mesh).
    Shared,
}

/// What a run keeps.
#[derive(Clone, Debug)]
pub struct History {
    /// u(depth, time) for the requested depths (rows) and times (columns).
    pub u: Vec<Vec<f64>>,
    /// U(time) at the requested times (settlement of the top / final settlement).
    pub degree: Vec<f64>,
    /// Largest ‖R‖∞ after the Newton update over all steps, relative to the run's residual scale:
    /// the largest ‖R‖∞ before an update (the step load's). A per-step ratio would divide by the
    /// small residuals of the late steps, where the state hardly changes, and grow with the
    /// column's data rather than with the solver's error.
    pub newton_reduction: f64,
    /// Largest |p₁ − p₂| at the interface over all steps (0 without interface).
    pub jump: f64,
    /// Largest p/q₀ − 1 over the nodes of each layer and all steps (> 0: overshoot, a spatial
    /// oscillation).
    pub overshoot: [f64; 2],
    /// Largest −p/q₀ over all nodes and steps (> 0: negative excess pressure).
    pub undershoot: f64,
    /// Kernel calls.
    pub kernel_calls: usize,
    /// Steps taken.
    pub steps: usize,
}

// ---------------------------------------------------------------------------------------------
// Banded LU with partial pivoting (LAPACK dgbtrf's scheme: U gets kl + ku super-diagonals).

/// A square band matrix, rows stored over columns i − kl ..= i + kl + ku.
#[derive(Clone, Debug)]
pub struct Band {
    n: usize,
    kl: usize,
    width: usize,
    a: Vec<f64>,
    pivot: Vec<usize>,
    /// Row scales 1/max|A_ij| (the rows mix forces and lengths: equilibration keeps the
    /// pivoting meaningful).
    scale: Vec<f64>,
}

impl Band {
    /// Zero matrix with `kl` sub- and `ku` super-diagonals.
    pub fn new(n: usize, kl: usize, ku: usize) -> Band {
        let width = 2 * kl + ku + 1;
        Band {
            n,
            kl,
            width,
            a: vec![0.0; n * width],
            pivot: vec![0; n],
            scale: vec![1.0; n],
        }
    }

    #[inline]
    fn at(&self, i: usize, j: usize) -> usize {
        debug_assert!(j + self.kl >= i && j < i + self.width - self.kl);
        i * self.width + (j + self.kl - i)
    }

    /// A[i][j] += v.
    pub fn add(&mut self, i: usize, j: usize, v: f64) {
        let k = self.at(i, j);
        self.a[k] += v;
    }

    /// Replaces row i by the identity row (a Dirichlet condition).
    pub fn identity_row(&mut self, i: usize) {
        let start = i * self.width;
        self.a[start..start + self.width].fill(0.0);
        let k = self.at(i, i);
        self.a[k] = 1.0;
    }

    /// In-place factorisation of the row-equilibrated matrix; an error names the zero pivot.
    pub fn factor(&mut self) -> Result<(), String> {
        let (n, kl) = (self.n, self.kl);
        for i in 0..n {
            let row = &mut self.a[i * self.width..(i + 1) * self.width];
            let big = row.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            if big == 0.0 || !big.is_finite() {
                return Err(format!("empty or non-finite row {i} in the column matrix"));
            }
            self.scale[i] = 1.0 / big;
            row.iter_mut().for_each(|v| *v /= big);
        }
        let reach = self.width - kl - 1; // kl + ku
        for k in 0..n {
            let last = (k + kl).min(n - 1);
            let mut p = k;
            let mut best = self.a[self.at(k, k)].abs();
            for i in k + 1..=last {
                let v = self.a[self.at(i, k)].abs();
                if v > best {
                    best = v;
                    p = i;
                }
            }
            if best == 0.0 || !best.is_finite() {
                return Err(format!("singular column matrix at row {k}"));
            }
            self.pivot[k] = p;
            let right = (k + reach).min(n - 1);
            if p != k {
                for j in k..=right {
                    let (x, y) = (self.at(k, j), self.at(p, j));
                    self.a.swap(x, y);
                }
            }
            let d = self.a[self.at(k, k)];
            for i in k + 1..=last {
                let l = self.a[self.at(i, k)] / d;
                let li = self.at(i, k);
                self.a[li] = l;
                if l != 0.0 {
                    for j in k + 1..=right {
                        let kj = self.a[self.at(k, j)];
                        let ij = self.at(i, j);
                        self.a[ij] -= l * kj;
                    }
                }
            }
        }
        Ok(())
    }

    /// max |R_i|/max_j |A_ij|: a residual in the equilibrated rows' units.
    pub fn scaled_norm(&self, r: &[f64]) -> f64 {
        r.iter()
            .zip(&self.scale)
            .fold(0.0f64, |m, (v, s)| m.max((v * s).abs()))
    }

    /// Solves A·x = b in place after [`Band::factor`].
    pub fn solve(&self, b: &mut [f64]) {
        let (n, kl) = (self.n, self.kl);
        let reach = self.width - kl - 1;
        for (v, s) in b.iter_mut().zip(&self.scale) {
            *v *= s;
        }
        for k in 0..n {
            let p = self.pivot[k];
            b.swap(k, p);
            for i in k + 1..=(k + kl).min(n - 1) {
                b[i] -= self.a[self.at(i, k)] * b[k];
            }
        }
        for k in (0..n).rev() {
            let mut s = b[k];
            let last = (k + reach).min(n - 1);
            for (j, bj) in b.iter().enumerate().take(last + 1).skip(k + 1) {
                s -= self.a[self.at(k, j)] * bj;
            }
            b[k] = s / self.a[self.at(k, k)];
        }
    }
}

// ---------------------------------------------------------------------------------------------
// The host: degrees of freedom, elements, the interface point.

/// The (w, p) dofs of two nodes: an element's ends, or the nodes either side of the interface.
#[derive(Clone, Copy, Debug)]
struct NodePair {
    w: [usize; 2],
    p: [usize; 2],
}

impl NodePair {
    /// From two entries (z, w dof, p dof) of the node list.
    fn of(a: (f64, usize, usize), b: (f64, usize, usize)) -> NodePair {
        NodePair {
            w: [a.1, b.1],
            p: [a.2, b.2],
        }
    }
}

/// One element: its nodes, length and layer.
#[derive(Clone, Copy, Debug)]
struct Element {
    nodes: NodePair,
    length: f64,
    permeability: f64,
    modulus: f64,
}

/// The interface's dofs: its two nodes, the contact multiplier λ and the flux q̂.
#[derive(Clone, Copy, Debug)]
struct InterfaceDofs {
    nodes: NodePair,
    lambda: usize,
    q_hat: usize,
}

/// A meshed column.
pub struct Mesh {
    /// Unknowns.
    pub n: usize,
    elements: Vec<Element>,
    interface: Option<InterfaceDofs>,
    /// Node depths and their (w, p) dofs, top to bottom (both interface nodes listed).
    nodes: Vec<(f64, usize, usize)>,
    /// Index in `nodes` of the first node that belongs to layer 2 only.
    layer_2_first: usize,
    top_w: usize,
    top_p: usize,
    base_w: usize,
    base_p: usize,
}

/// Half-bandwidth of every mesh: the interface row of w₁ reaches p₂ five dofs away.
const BAND: usize = 5;

impl Mesh {
    /// Meshes `column` with `refine` times the file's element counts.
    pub fn new(column: &Column, join: Join, refine: usize) -> Mesh {
        let [l1, l2] = &column.layers;
        let (n1, n2) = (l1.elements * refine, l2.elements * refine);
        let mut nodes = Vec::new();
        let mut elements = Vec::new();
        let mut next = 0;
        let node = |nodes: &mut Vec<(f64, usize, usize)>, next: &mut usize, z: f64| {
            nodes.push((z, *next, *next + 1));
            *next += 2;
        };
        for i in 0..=n1 {
            node(&mut nodes, &mut next, l1.thickness * i as f64 / n1 as f64);
        }
        let interface = match join {
            Join::Interface => {
                let lambda = next;
                next += 2;
                node(&mut nodes, &mut next, l1.thickness);
                Some(InterfaceDofs {
                    nodes: NodePair::of(nodes[n1], nodes[n1 + 1]),
                    lambda,
                    q_hat: lambda + 1,
                })
            }
            Join::Shared => None,
        };
        for j in 1..=n2 {
            node(
                &mut nodes,
                &mut next,
                l1.thickness + l2.thickness * j as f64 / n2 as f64,
            );
        }
        let layer_of = |e: usize| if e < n1 { l1 } else { l2 };
        let first_of_layer_2 = if interface.is_some() { n1 + 1 } else { n1 };
        for e in 0..n1 + n2 {
            let (a, b) = if e < n1 {
                (e, e + 1)
            } else {
                let a = first_of_layer_2 + (e - n1);
                (a, a + 1)
            };
            let l = layer_of(e);
            elements.push(Element {
                nodes: NodePair::of(nodes[a], nodes[b]),
                length: nodes[b].0 - nodes[a].0,
                permeability: l.permeability,
                modulus: l.modulus,
            });
        }
        let last = nodes.len() - 1;
        Mesh {
            n: next,
            elements,
            interface,
            layer_2_first: n1 + 1,
            top_w: nodes[0].1,
            top_p: nodes[0].2,
            base_w: nodes[last].1,
            base_p: nodes[last].2,
            nodes,
        }
    }

    /// Excess pore pressure at depth z (linear in the element; the side-1 node at z = H₁).
    pub fn pressure_at(&self, x: &[f64], z: f64) -> f64 {
        for pair in self.nodes.windows(2) {
            let (za, _, pa) = pair[0];
            let (zb, _, pb) = pair[1];
            if z >= za && z <= zb && zb > za {
                let s = (z - za) / (zb - za);
                return (1.0 - s) * x[pa] + s * x[pb];
            }
        }
        x[self.nodes[self.nodes.len() - 1].2]
    }

    /// Every node's pore pressure.
    pub fn pressures<'a>(&'a self, x: &'a [f64]) -> impl Iterator<Item = f64> + 'a {
        self.nodes.iter().map(move |n| x[n.2])
    }

    /// Top settlement.
    pub fn settlement(&self, x: &[f64]) -> f64 {
        x[self.top_w]
    }

    /// The interface pressures (p₁, p₂) and q̂, when there is an interface.
    pub fn interface_state(&self, x: &[f64]) -> Option<(f64, f64, f64)> {
        self.interface
            .map(|i| (x[i.nodes.p[0]], x[i.nodes.p[1]], x[i.q_hat]))
    }
}

/// Transient or steady assembly.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Analysis {
    /// Backward Euler with this Δt from the previous state.
    Transient(f64),
    /// Steady seepage (rate form, no skeleton terms in the mass balance).
    Steady,
}

/// Pore pressures held at the top and the base (None: the natural no-flow condition).
#[derive(Clone, Copy, Debug)]
pub struct Boundary {
    /// Load q₀ on the top.
    pub load: f64,
    /// p at the top, if drained.
    pub p_top: Option<f64>,
    /// p at the base, if drained.
    pub p_base: Option<f64>,
}

/// Calls the kernel for the interface point: per-side residual, tangent (row-major [i][j]).
fn kernel(
    analysis: Analysis,
    p1: f64,
    p2: f64,
    q_hat: f64,
    calls: &mut usize,
) -> Result<([f64; 4], [[f64; 4]; 4]), String> {
    let variant = IflPorePressureVariant {
        open: 0,
        steady: i32::from(analysis == Analysis::Steady),
        finite_sliding: 0,
        per_side: 1,
    };
    let dt = match analysis {
        Analysis::Transient(dt) => dt,
        Analysis::Steady => 0.0,
    };
    let (mut r, mut t, mut g) = ([0.0; 4], [0.0; 16], [0.0; 4]);
    *calls += 1;
    // SAFETY: arrays of 4, 16 and 4 doubles; a NUL-terminated name.
    let status = unsafe {
        ifl_pore_pressure(
            c"P1 column".as_ptr(),
            variant,
            p1,
            p2,
            q_hat,
            0.0,
            0.0,
            dt,
            r.as_mut_ptr(),
            t.as_mut_ptr(),
            g.as_mut_ptr(),
        )
    };
    if status != IflStatus::Ok {
        // SAFETY: the library's thread-local, NUL-terminated message.
        let msg = unsafe { std::ffi::CStr::from_ptr(ifl_last_error()) };
        return Err(msg.to_string_lossy().into_owned());
    }
    let tangent = std::array::from_fn(|i| std::array::from_fn(|j| t[i + 4 * j]));
    Ok((r, tangent))
}

impl Mesh {
    /// Residual R(x) (and, with `band`, the tangent ∂R/∂x) of the step from `prev`.
    #[allow(clippy::too_many_arguments)]
    fn assemble(
        &self,
        x: &[f64],
        prev: &[f64],
        analysis: Analysis,
        bc: &Boundary,
        r: &mut [f64],
        mut band: Option<&mut Band>,
        calls: &mut usize,
    ) -> Result<(), String> {
        r.fill(0.0);
        let flux_time = match analysis {
            Analysis::Transient(dt) => dt,
            Analysis::Steady => 1.0,
        };
        let skeleton = matches!(analysis, Analysis::Transient(_));
        for e in &self.elements {
            let (l, k, m) = (e.length, e.permeability, e.modulus);
            let [wa, wb] = e.nodes.w;
            let [pa, pb] = e.nodes.p;
            // ∫ M w′δw′: M/ℓ [[1, −1], [−1, 1]].
            let s = m / l * (x[wa] - x[wb]);
            r[wa] += s;
            r[wb] -= s;
            // −∫ p δw′ with p linear: ±(p_a + p_b)/2.
            let pm = 0.5 * (x[pa] + x[pb]);
            r[wa] += pm;
            r[wb] -= pm;
            // −∫ Δw′ δp: −(Δw_b − Δw_a)/2 on each node (transient only).
            if skeleton {
                let dv = -0.5 * ((x[wb] - prev[wb]) - (x[wa] - prev[wa]));
                r[pa] += dv;
                r[pb] += dv;
            }
            // −Δt ∫ k p′δp′: −Δt k/ℓ [[1, −1], [−1, 1]].
            let f = -flux_time * k / l * (x[pa] - x[pb]);
            r[pa] += f;
            r[pb] -= f;
            if let Some(b) = band.as_deref_mut() {
                b.add(wa, wa, m / l);
                b.add(wa, wb, -m / l);
                b.add(wb, wa, -m / l);
                b.add(wb, wb, m / l);
                for (row, sign) in [(wa, 0.5), (wb, -0.5)] {
                    b.add(row, pa, sign);
                    b.add(row, pb, sign);
                }
                if skeleton {
                    for row in [pa, pb] {
                        b.add(row, wa, 0.5);
                        b.add(row, wb, -0.5);
                    }
                }
                let c = flux_time * k / l;
                b.add(pa, pa, -c);
                b.add(pa, pb, c);
                b.add(pb, pa, c);
                b.add(pb, pb, -c);
            }
        }
        if let Some(i) = self.interface {
            let [w1, w2] = i.nodes.w;
            let [p1, p2] = i.nodes.p;
            // Closed normal contact by a Lagrange multiplier: −λ δh − δλ h, h = w₂ − w₁.
            let h = x[w2] - x[w1];
            let lambda = x[i.lambda];
            r[w1] += lambda;
            r[w2] -= lambda;
            r[i.lambda] -= h;
            // The pore-pressure kernel, unknowns (h, p₁, p₂, q̂) with δh = δw₂ − δw₁.
            let (kr, kt) = kernel(analysis, x[p1], x[p2], x[i.q_hat], calls)?;
            r[w1] -= kr[0];
            r[w2] += kr[0];
            r[p1] += kr[1];
            r[p2] += kr[2];
            r[i.q_hat] += kr[3];
            if let Some(b) = band.as_deref_mut() {
                b.add(w1, i.lambda, 1.0);
                b.add(w2, i.lambda, -1.0);
                b.add(i.lambda, w1, 1.0);
                b.add(i.lambda, w2, -1.0);
                // Rows: δh → (−w₁, +w₂); columns: dh → (−w₁, +w₂) (zero in closed contact).
                let rows: [&[(usize, f64)]; 4] = [
                    &[(w1, -1.0), (w2, 1.0)],
                    &[(p1, 1.0)],
                    &[(p2, 1.0)],
                    &[(i.q_hat, 1.0)],
                ];
                for (a, ra) in rows.iter().enumerate() {
                    for (c, rc) in rows.iter().enumerate() {
                        if kt[a][c] != 0.0 {
                            for &(row, sr) in *ra {
                                for &(col, sc) in *rc {
                                    b.add(row, col, sr * sc * kt[a][c]);
                                }
                            }
                        }
                    }
                }
            }
        }
        // External work of the load on the top.
        r[self.top_w] -= bc.load;
        // Dirichlet rows: the base does not move; drained boundaries hold p.
        let mut fixed = vec![(self.base_w, 0.0)];
        if let Some(p) = bc.p_top {
            fixed.push((self.top_p, p));
        }
        if let Some(p) = bc.p_base {
            fixed.push((self.base_p, p));
        }
        for (dof, value) in fixed {
            r[dof] = x[dof] - value;
            if let Some(b) = band.as_deref_mut() {
                b.identity_row(dof);
            }
        }
        Ok(())
    }

    /// The factorised tangent (the problem is linear: one factorisation serves every step).
    fn tangent(
        &self,
        analysis: Analysis,
        bc: &Boundary,
        calls: &mut usize,
    ) -> Result<Band, String> {
        let mut band = Band::new(self.n, BAND, BAND);
        let zero = vec![0.0; self.n];
        let mut r = vec![0.0; self.n];
        self.assemble(&zero, &zero, analysis, bc, &mut r, Some(&mut band), calls)?;
        band.factor()?;
        Ok(band)
    }

    /// One Newton iteration from `x` (the previous state); with `check`, returns ‖R‖∞ before and
    /// after it in the equilibrated rows (zeros otherwise).
    #[allow(clippy::too_many_arguments)]
    fn newton_step(
        &self,
        band: &Band,
        x: &mut [f64],
        prev: &[f64],
        analysis: Analysis,
        bc: &Boundary,
        r: &mut [f64],
        calls: &mut usize,
        check: bool,
    ) -> Result<(f64, f64), String> {
        self.assemble(x, prev, analysis, bc, r, None, calls)?;
        let before = band.scaled_norm(r);
        band.solve(r);
        for (xi, di) in x.iter_mut().zip(r.iter()) {
            *xi -= di;
        }
        if !check {
            return Ok((0.0, 0.0));
        }
        self.assemble(x, prev, analysis, bc, r, None, calls)?;
        Ok((before, band.scaled_norm(r)))
    }
}

/// Steady seepage through the column with p held at top and base: the pressures.
pub struct Steady {
    /// The mesh.
    pub mesh: Mesh,
    /// The solution.
    pub x: Vec<f64>,
    /// ‖R‖∞ after / before the Newton update.
    pub newton_reduction: f64,
}

/// Solves steady seepage (interface variant: steady, closed, small sliding).
pub fn steady(column: &Column, p_top: f64, p_base: f64) -> Result<Steady, String> {
    let mesh = Mesh::new(column, Join::Interface, 1);
    let bc = Boundary {
        load: 0.0,
        p_top: Some(p_top),
        p_base: Some(p_base),
    };
    let mut calls = 0;
    let band = mesh.tangent(Analysis::Steady, &bc, &mut calls)?;
    let mut x = vec![0.0; mesh.n];
    let prev = x.clone();
    let mut r = vec![0.0; mesh.n];
    let (before, after) = mesh.newton_step(
        &band,
        &mut x,
        &prev,
        Analysis::Steady,
        &bc,
        &mut r,
        &mut calls,
        true,
    )?;
    Ok(Steady {
        mesh,
        x,
        newton_reduction: if before > 0.0 { after / before } else { 0.0 },
    })
}

impl Steady {
    /// Flux v = q̂/2 across the interface (downwards).
    pub fn interface_flux(&self) -> f64 {
        self.mesh
            .interface_state(&self.x)
            .map_or(f64::NAN, |s| 0.5 * s.2)
    }

    /// The largest k/ℓ of any element: the scale of an element flux's round-off.
    pub fn largest_conductance(&self) -> f64 {
        self.mesh
            .elements
            .iter()
            .map(|e| e.permeability / e.length)
            .fold(0.0, f64::max)
    }

    /// Darcy flux −k Δp/ℓ of every element.
    pub fn element_fluxes(&self) -> Vec<f64> {
        self.mesh
            .elements
            .iter()
            .map(|e| -e.permeability * (self.x[e.nodes.p[1]] - self.x[e.nodes.p[0]]) / e.length)
            .collect()
    }

    /// (depth, pressure) of every node.
    pub fn nodal_pressures(&self) -> Vec<(f64, f64)> {
        self.mesh.nodes.iter().map(|n| (n.0, self.x[n.2])).collect()
    }
}

/// Runs the transient step-load problem with `refine` times the file's elements and Δt = `dt`
/// to `column.end`; `check` also evaluates the residual after every Newton update.
pub fn consolidate(
    column: &Column,
    join: Join,
    refine: usize,
    dt: f64,
    check: bool,
) -> Result<History, String> {
    let mesh = Mesh::new(column, join, refine);
    let bc = Boundary {
        load: column.load,
        p_top: (column.top == Drainage::Drained).then_some(0.0),
        p_base: (column.bottom == Drainage::Drained).then_some(0.0),
    };
    let mut calls = 0;
    let analysis = Analysis::Transient(dt);
    let band = mesh.tangent(analysis, &bc, &mut calls)?;
    // Enough steps to reach the end time (and so every requested time).
    let steps = (column.end / dt * (1.0 - 1e-12)).ceil().max(1.0) as usize;
    // Before the load: no settlement, no excess pressure (the first backward-Euler step takes
    // the undrained response and the first Δt of drainage together).
    let mut x = vec![0.0; mesh.n];
    let mut prev = x.clone();
    let mut r = vec![0.0; mesh.n];
    let nd = column.depths.len();
    let mut h = History {
        u: vec![vec![f64::NAN; column.times.len()]; nd],
        degree: vec![f64::NAN; column.times.len()],
        newton_reduction: 0.0,
        jump: 0.0,
        overshoot: [f64::NEG_INFINITY; 2],
        undershoot: f64::NEG_INFINITY,
        kernel_calls: 0,
        steps,
    };
    let s_final = column.final_settlement();
    let q0 = column.load;
    let mut t_prev = 0.0;
    let (mut largest_before, mut largest_after) = (0.0f64, 0.0f64);
    for n in 1..=steps {
        let t = n as f64 * dt;
        let (before, after) = mesh.newton_step(
            &band, &mut x, &prev, analysis, &bc, &mut r, &mut calls, check,
        )?;
        largest_before = largest_before.max(before);
        largest_after = largest_after.max(after);
        if largest_before > 0.0 {
            h.newton_reduction = largest_after / largest_before;
        }
        if let Some((p1, p2, _)) = mesh.interface_state(&x) {
            h.jump = h.jump.max((p1 - p2).abs());
        }
        for (node, p) in mesh.pressures(&x).enumerate() {
            let layer = usize::from(node >= mesh.layer_2_first);
            h.overshoot[layer] = h.overshoot[layer].max(p / q0 - 1.0);
            h.undershoot = h.undershoot.max(-p / q0);
        }
        // Requested times in (t_prev, t]: linear interpolation between the step ends (exact at
        // step ends; the load is on from t = 0⁺, so the state at t_prev = 0 is the loaded
        // undrained state p = q₀, w = 0 for interpolation purposes).
        for (c, &tr) in column.times.iter().enumerate() {
            if tr > t_prev && tr <= t * (1.0 + 1e-12) {
                let s = ((tr - t_prev) / dt).clamp(0.0, 1.0);
                for (row, &z) in column.depths.iter().enumerate() {
                    let before = if n == 1 {
                        undrained(column, z)
                    } else {
                        mesh.pressure_at(&prev, z)
                    };
                    h.u[row][c] = (1.0 - s) * before + s * mesh.pressure_at(&x, z);
                }
                let before = mesh.settlement(&prev) / s_final;
                h.degree[c] = (1.0 - s) * before + s * mesh.settlement(&x) / s_final;
            }
        }
        prev.copy_from_slice(&x);
        t_prev = t;
    }
    h.kernel_calls = calls;
    Ok(h)
}

/// Excess pressure just after loading: q₀ inside, 0 on a drained boundary.
fn undrained(column: &Column, z: f64) -> f64 {
    let drained_top = column.top == Drainage::Drained && z == 0.0;
    let drained_base = column.bottom == Drainage::Drained && z == column.height();
    if drained_top || drained_base {
        0.0
    } else {
        column.load
    }
}

// ---------------------------------------------------------------------------------------------
// The series solution of two-layer consolidation.
//
// Each layer obeys Terzaghi's equation ∂u/∂t = c_i ∂²u/∂z²; at the interface u and the flux
// k ∂u/∂z are continuous; u = 0 at a drained boundary, ∂u/∂z = 0 at an undrained one; u(z, 0⁺) =
// q₀. Separation of variables, u = Σ A_n Z_n(z) e^{−β_n² t}, with a_i = β/√c_i:
//   Z = sin(a₁ z)                          in layer 1 (drained top; cos(a₁ z) if undrained),
//   Z = B·cos(a₂ (H − z)) (undrained base) or B·sin(a₂ (H − z)) (drained base) in layer 2,
// and continuity of Z and k Z′ at z = H₁ gives the eigenvalue equation (drained top):
//   undrained base: k₁a₁ cos(a₁H₁) cos(a₂H₂) − k₂a₂ sin(a₁H₁) sin(a₂H₂) = 0,
//   drained base:   k₁a₁ cos(a₁H₁) sin(a₂H₂) + k₂a₂ sin(a₁H₁) cos(a₂H₂) = 0.
// (k u′)′ = (k/c) ∂u/∂t is a Sturm–Liouville problem with weight k/c = m_v = 1/M, so the Z_n are
// orthogonal in ∫ m_v Z_m Z_n dz and A_n = ∫ m_v q₀ Z_n / ∫ m_v Z_n²; the degree of
// consolidation by settlement is U = 1 − ∫ m_v u / ∫ m_v q₀. This is the classical layered
// solution (Gray 1945, Trans. ASCE 110:1327–1356; Schiffman & Stein 1970, J. Soil Mech. Found.
// Div. ASCE 96(SM4):1499–1504; Lee, Xie & Cheung 1992, Int. J. Numer. Anal. Meth. Geomech.
// 16:815–831), written out here for one drained and one drained-or-undrained boundary.

/// One term of the series.
#[derive(Clone, Copy, Debug)]
struct Mode {
    beta: f64,
    /// Amplitudes of the layer functions (layer 1, layer 2).
    amp: [f64; 2],
    /// A_n.
    coefficient: f64,
    /// ∫ m_v Z_n dz.
    weight: f64,
}

/// The series solution of a two-layer column.
pub struct Series {
    column: Column,
    modes: Vec<Mode>,
    /// True when the column is flipped (drained base, undrained top) to put the drained face on
    /// top.
    flipped: bool,
}

/// sin or cos of a layer function: layer 1 is a sine from the drained top; layer 2 a cosine
/// (undrained base) or a sine (drained base) from the base.
fn layer_function(drained_base: bool, layer: usize, a: f64, s: f64) -> f64 {
    if layer == 0 || drained_base {
        (a * s).sin()
    } else {
        (a * s).cos()
    }
}

/// ∫₀^L f(a s) ds and ∫₀^L f(a s)² ds for f = sin or cos.
fn integrals(sine: bool, a: f64, l: f64) -> (f64, f64) {
    if sine {
        (
            (1.0 - (a * l).cos()) / a,
            0.5 * l - (2.0 * a * l).sin() / (4.0 * a),
        )
    } else {
        ((a * l).sin() / a, 0.5 * l + (2.0 * a * l).sin() / (4.0 * a))
    }
}

impl Series {
    /// The series with every term whose decay reaches `t_min` above 1e-17.
    pub fn new(column: &Column, t_min: f64) -> Result<Series, String> {
        let flipped = column.top == Drainage::Undrained;
        let mut col = column.clone();
        if flipped {
            // Undrained top, drained base: the mirror image.
            col.layers.swap(0, 1);
            col.top = Drainage::Drained;
            col.bottom = Drainage::Undrained;
        }
        let drained_base = col.bottom == Drainage::Drained;
        let [l1, l2] = &col.layers;
        let (h1, h2) = (l1.thickness, l2.thickness);
        let (k1, k2) = (l1.permeability, l2.permeability);
        let (s1, s2) = (l1.cv().sqrt(), l2.cv().sqrt());
        let f = |b: f64| {
            let (a1, a2) = (b / s1, b / s2);
            if drained_base {
                k1 * a1 * (a1 * h1).cos() * (a2 * h2).sin()
                    + k2 * a2 * (a1 * h1).sin() * (a2 * h2).cos()
            } else {
                k1 * a1 * (a1 * h1).cos() * (a2 * h2).cos()
                    - k2 * a2 * (a1 * h1).sin() * (a2 * h2).sin()
            }
        };
        let beta_max = (40.0 / t_min).sqrt();
        // Roots are about π / (H₁/√c₁ + H₂/√c₂) apart; scan 200 times finer and bisect.
        let spacing = std::f64::consts::PI / (h1 / s1 + h2 / s2);
        let step = spacing / 200.0;
        let mut modes = Vec::new();
        let mut b0 = step * 1e-3;
        let mut f0 = f(b0);
        while b0 < beta_max {
            if modes.len() > 200_000 {
                return Err("series: more than 200000 terms (times too early)".into());
            }
            let b1 = b0 + step;
            let f1 = f(b1);
            if f0 == 0.0 || f0.signum() != f1.signum() {
                let (mut lo, mut hi, mut flo) = (b0, b1, f0);
                for _ in 0..200 {
                    let mid = 0.5 * (lo + hi);
                    if mid <= lo || mid >= hi {
                        break;
                    }
                    let fm = f(mid);
                    if fm.signum() == flo.signum() && fm != 0.0 {
                        lo = mid;
                        flo = fm;
                    } else {
                        hi = mid;
                    }
                }
                modes.push(Self::mode(&col, drained_base, 0.5 * (lo + hi)));
            }
            b0 = b1;
            f0 = f1;
        }
        Ok(Series {
            column: col,
            modes,
            flipped,
        })
    }

    fn mode(col: &Column, drained_base: bool, beta: f64) -> Mode {
        let [l1, l2] = &col.layers;
        let (h1, h2) = (l1.thickness, l2.thickness);
        let (a1, a2) = (beta / l1.cv().sqrt(), beta / l2.cv().sqrt());
        let (k1, k2) = (l1.permeability, l2.permeability);
        // Amplitudes (A, B) in the null space of the interface conditions
        //   A·Z₁(H₁) − B·Z₂(H₁) = 0,  k₁A·Z₁′(H₁) − k₂B·Z₂′(H₁) = 0;
        // of the two candidate vectors take the better conditioned one.
        let z1 = (a1 * h1).sin();
        let dz1 = a1 * (a1 * h1).cos();
        let (z2, dz2) = if drained_base {
            ((a2 * h2).sin(), -a2 * (a2 * h2).cos())
        } else {
            ((a2 * h2).cos(), a2 * (a2 * h2).sin())
        };
        let v1 = [z2, z1];
        let scale = (k1 * a1).max(k2 * a2);
        let v2 = [k2 * dz2 / scale, k1 * dz1 / scale];
        let norm = |v: [f64; 2]| v[0].hypot(v[1]);
        let amp = if norm(v1) >= norm(v2) { v1 } else { v2 };
        let (i1, i11) = integrals(true, a1, h1);
        let (i2, i22) = integrals(drained_base, a2, h2);
        let (m1, m2) = (1.0 / l1.modulus, 1.0 / l2.modulus);
        let weight = m1 * amp[0] * i1 + m2 * amp[1] * i2;
        let norm2 = m1 * amp[0] * amp[0] * i11 + m2 * amp[1] * amp[1] * i22;
        Mode {
            beta,
            amp,
            coefficient: col.load * weight / norm2,
            weight,
        }
    }

    /// Number of terms.
    pub fn terms(&self) -> usize {
        self.modes.len()
    }

    /// u(z, t) (z from the original top).
    pub fn pressure(&self, z: f64, t: f64) -> f64 {
        let c = &self.column;
        let z = if self.flipped { c.height() - z } else { z };
        let drained_base = c.bottom == Drainage::Drained;
        let h1 = c.layers[0].thickness;
        let (layer, s) = if z <= h1 { (0, z) } else { (1, c.height() - z) };
        let sqrt_c = c.layers[layer].cv().sqrt();
        self.modes
            .iter()
            .map(|m| {
                m.coefficient
                    * m.amp[layer]
                    * layer_function(drained_base, layer, m.beta / sqrt_c, s)
                    * (-m.beta * m.beta * t).exp()
            })
            .sum()
    }

    /// Degree of consolidation U(t) = 1 − ∫ m_v u / ∫ m_v q₀.
    pub fn degree(&self, t: f64) -> f64 {
        let c = &self.column;
        let total = c.final_settlement();
        let remaining: f64 = self
            .modes
            .iter()
            .map(|m| m.coefficient * m.weight * (-m.beta * m.beta * t).exp())
            .sum();
        1.0 - remaining / total
    }
}

/// Terzaghi's single-layer series for a layer of drainage path d, uniform u₀ = 1:
/// u = Σ (2/M) sin(M z/d) e^{−M² T}, M = π(2m + 1)/2, T = c t/d², z from the drained face.
pub fn terzaghi(z_over_d: f64, time_factor: f64) -> f64 {
    let mut sum = 0.0;
    for m in 0..100_000 {
        let big_m = std::f64::consts::PI * (2 * m + 1) as f64 / 2.0;
        let decay = (-big_m * big_m * time_factor).exp();
        if decay < 1e-18 {
            break;
        }
        sum += 2.0 / big_m * (big_m * z_over_d).sin() * decay;
    }
    sum
}

/// Degree of consolidation at early times, while the drained faces still see semi-infinite
/// layers: each drained face i has settled m_v,i·q₀·2·sqrt(c_i·t/π) (the error-function
/// solution), so U = Σ 2·q₀·sqrt(c_i·t/π)/M_i / (q₀·Σ H_i/M_i). Exact to e^{−H_i²/(4 c_i t)}.
pub fn early_degree(column: &Column, t: f64) -> f64 {
    let face = |layer: &Layer| {
        2.0 * column.load * (layer.cv() * t / std::f64::consts::PI).sqrt() / layer.modulus
    };
    let mut settled = 0.0;
    if column.top == Drainage::Drained {
        settled += face(&column.layers[0]);
    }
    if column.bottom == Drainage::Drained {
        settled += face(&column.layers[1]);
    }
    settled / column.final_settlement()
}

/// A time at which [`early_degree`] is exact to round-off: the diffusion length sqrt(c·t) is a
/// hundredth of the thinner drained layer.
pub fn early_time(column: &Column) -> f64 {
    column
        .layers
        .iter()
        .map(|l| 1e-4 * l.thickness * l.thickness / l.cv())
        .fold(f64::INFINITY, f64::min)
}
