//! Residual flexibility of the truncated in-plane modes between the node
//! frames (`plate.residual_flexibility` with in-plane modes; docs/in_plane.md,
//! "Node frames"): the quasi-static in-plane displacement the modes left out
//! add at node a per unit in-plane force at node b, from
//! [`residual_kernel`] over the nodes' load patches.
//!
//! Nodes are numbered ALE first, then Lagrangian, as the bending residual
//! ([`super::residual`]). The kernel's 2 × 2 compliance C(Δ), Δ = θ_a − θ_b,
//! maps the polar force components (F_r, F_θ) at b to the patch means
//! (ū_r, ū_θ) at a. Two nodes of the same kind keep Δ: a constant matrix. An
//! ALE node at θ and a material node at φ are Δ = ±(θ − φ − χ) apart: their
//! C is tabulated once on [0, 2π] with values and slopes and read by cubic
//! Hermite interpolation, O(1) per pair. C is not even (its off-diagonal
//! terms are odd), so the table spans the whole turn.

use super::node_frame::{NodeFrame, NodeKind};
use crate::model::in_plane::{
    residual_kernel, InPlaneDiscretisation, InPlaneKernel, InPlaneMode, LoadPatch,
};
use std::f64::consts::TAU;

/// Intervals of the angle table on [0, 2π].
const TABLE_INTERVALS: usize = 2048;

/// Rows (ū_r, ū_θ) at a, columns (F_r, F_θ) at b, m/N.
type Compliance = [[f64; 2]; 2];

/// C(Δ) on a uniform grid of [0, 2π]: values and derivatives.
#[derive(Debug, Clone, PartialEq)]
struct AngleTable {
    values: Vec<Compliance>,
    slopes: Vec<Compliance>,
}

impl AngleTable {
    fn new(kernel: &InPlaneKernel) -> AngleTable {
        let h = TAU / TABLE_INTERVALS as f64;
        let grid = (0..=TABLE_INTERVALS).map(|i| i as f64 * h);
        AngleTable {
            values: grid.clone().map(|d| kernel.at(d)).collect(),
            slopes: grid.map(|d| slope(kernel, d)).collect(),
        }
    }

    fn at(&self, delta: f64) -> Compliance {
        self.piece(delta, |t, h| {
            let (t2, t3) = (t * t, t * t * t);
            [
                2.0 * t3 - 3.0 * t2 + 1.0,
                (t3 - 2.0 * t2 + t) * h,
                -2.0 * t3 + 3.0 * t2,
                (t3 - t2) * h,
            ]
        })
    }

    /// dC/dΔ of [`AngleTable::at`]'s interpolant (the derivative of the
    /// same cubic Hermite piece).
    fn slope_at(&self, delta: f64) -> Compliance {
        self.piece(delta, |t, h| {
            [
                (6.0 * t * t - 6.0 * t) / h,
                3.0 * t * t - 4.0 * t + 1.0,
                (-6.0 * t * t + 6.0 * t) / h,
                3.0 * t * t - 2.0 * t,
            ]
        })
    }

    /// The Hermite piece holding Δ, weighted by `basis(t, h)` (t in [0, 1]
    /// across the interval of length h): value, slope, value, slope at its ends.
    fn piece(&self, delta: f64, basis: impl Fn(f64, f64) -> [f64; 4]) -> Compliance {
        let x = delta.rem_euclid(TAU);
        let h = TAU / TABLE_INTERVALS as f64;
        let i = ((x / h) as usize).min(TABLE_INTERVALS - 1);
        let [w0, w1, w2, w3] = basis(x / h - i as f64, h);
        let (v0, v1, d0, d1) = (
            &self.values[i],
            &self.values[i + 1],
            &self.slopes[i],
            &self.slopes[i + 1],
        );
        std::array::from_fn(|r| {
            std::array::from_fn(|c| w0 * v0[r][c] + w1 * d0[r][c] + w2 * v1[r][c] + w3 * d1[r][c])
        })
    }
}

/// dC/dΔ of [`InPlaneKernel::at`], term by term.
fn slope(kernel: &InPlaneKernel, delta: f64) -> Compliance {
    let mut d = [[0.0; 2]; 2];
    for (k, g) in kernel.coefficients.iter().enumerate() {
        let kf = k as f64;
        let (s, c) = (kf * delta).sin_cos();
        d[0][0] -= g[0] * kf * s;
        d[0][1] -= g[1] * kf * c;
        d[1][0] += g[2] * kf * c;
        d[1][1] -= g[3] * kf * s;
    }
    d
}

/// One pair's compliance.
#[derive(Debug, Clone, PartialEq)]
enum PairCompliance {
    /// C(offset) and dC/dΔ there (offset = angle_a − angle_b).
    Constant(Compliance, Compliance),
    /// C(offset + sign χ): offset = angle_a − angle_b, sign −1 when a is the
    /// ALE node, +1 when b is.
    Turning {
        offset: f64,
        sign: f64,
        table: usize,
    },
}

/// In-plane residual compliances between all node frames of a scene.
#[derive(Debug, Clone, PartialEq)]
pub struct InPlaneResidual {
    n: usize,
    pairs: Vec<PairCompliance>,
    tables: Vec<AngleTable>,
    /// Per node (cos, sin) of its angle in its parent frame.
    turns: Vec<(f64, f64)>,
}

impl InPlaneResidual {
    /// The compliances between `nodes` (ALE first, then Lagrangian) as load
    /// patches of half-width `c` (m), less the retained `modes` (one entry
    /// per ⟨k, l⟩ and family: the cos partner stands for the pair).
    pub fn new(
        disc: &InPlaneDiscretisation,
        modes: &[InPlaneMode],
        nodes: &[&NodeFrame],
        c: f64,
    ) -> InPlaneResidual {
        let (ri, ra) = (disc.plate().inner_radius, disc.plate().outer_radius);
        let (radii, index) = super::node_frame::distinct_radii(nodes);
        let patches: Vec<LoadPatch> = radii
            .iter()
            .map(|&r| LoadPatch::new(ri, ra, r, c))
            .collect();
        let harmonics = disc.patch_harmonics(&patches);
        let n = nodes.len();
        let mut pairs = Vec::with_capacity(n * n);
        let mut tables = Vec::new();
        let mut table_of: Vec<((usize, usize), usize)> = Vec::new();
        for (a, na) in nodes.iter().enumerate() {
            for (b, nb) in nodes.iter().enumerate() {
                let key = (index[a], index[b]);
                let offset = na.angle - nb.angle;
                if na.kind == nb.kind {
                    let kernel = residual_kernel(&harmonics, modes, key.0, key.1);
                    pairs.push(PairCompliance::Constant(
                        kernel.at(offset),
                        slope(&kernel, offset),
                    ));
                    continue;
                }
                let table = match table_of.iter().find(|(k, _)| *k == key) {
                    Some(&(_, t)) => t,
                    None => {
                        let kernel = residual_kernel(&harmonics, modes, key.0, key.1);
                        tables.push(AngleTable::new(&kernel));
                        table_of.push((key, tables.len() - 1));
                        tables.len() - 1
                    }
                };
                let sign = if na.kind == NodeKind::Ale { -1.0 } else { 1.0 };
                pairs.push(PairCompliance::Turning {
                    offset,
                    sign,
                    table,
                });
            }
        }
        InPlaneResidual {
            n,
            pairs,
            tables,
            turns: nodes
                .iter()
                .map(|nd| (nd.angle.cos(), nd.angle.sin()))
                .collect(),
        }
    }

    /// Compliance between nodes a and b at joint angle χ (polar components), m/N.
    #[inline]
    fn between(&self, a: usize, b: usize, chi: f64) -> Compliance {
        match &self.pairs[a * self.n + b] {
            PairCompliance::Constant(c, _) => *c,
            PairCompliance::Turning {
                offset,
                sign,
                table,
            } => self.tables[*table].at(offset + sign * chi),
        }
    }

    /// C, ∂C/∂χ and ∂C/∂θ_a between nodes a and b at joint angle χ.
    fn with_slopes(&self, a: usize, b: usize, chi: f64) -> [Compliance; 3] {
        match &self.pairs[a * self.n + b] {
            PairCompliance::Constant(c, d) => [*c, [[0.0; 2]; 2], *d],
            PairCompliance::Turning {
                offset,
                sign,
                table,
            } => {
                let t = &self.tables[*table];
                let d = t.slope_at(offset + sign * chi);
                let by_chi = d.map(|row| row.map(|x| sign * x));
                [t.at(offset + sign * chi), by_chi, d]
            }
        }
    }

    /// The rates of the residual in-plane displacement at node a under the
    /// held forces `force(b)` (as [`InPlaneResidual::displacement`]) at
    /// joint angle χ and speed Ω, m/s: the frame's own (Ω ∂u/∂χ: nonzero
    /// where the node and the force turn against each other) and the
    /// material's under an ALE node (`ale`), which adds the transport
    /// Ω ∂(u_r, u_θ)/∂θ in the plate's turning axes (as the modes' part,
    /// `InPlaneDynamics::ale_turn`); for a Lagrangian node the two are the
    /// same.
    pub fn rates(
        &self,
        a: usize,
        chi: f64,
        speed: f64,
        ale: bool,
        force: impl Fn(usize) -> [f64; 2],
    ) -> ([f64; 2], [f64; 2]) {
        let (mut frame, mut along) = ([0.0; 2], [0.0; 2]);
        for b in 0..self.n {
            let f = force(b);
            if f == [0.0, 0.0] {
                continue;
            }
            let (c, s) = self.turns[b];
            let fp = [c * f[0] + s * f[1], -s * f[0] + c * f[1]];
            let [_, by_chi, by_theta] = self.with_slopes(a, b, chi);
            for r in 0..2 {
                frame[r] += speed * (by_chi[r][0] * fp[0] + by_chi[r][1] * fp[1]);
                along[r] += by_theta[r][0] * fp[0] + by_theta[r][1] * fp[1];
            }
        }
        let material = if ale {
            [frame[0] + speed * along[0], frame[1] + speed * along[1]]
        } else {
            frame
        };
        let (c, s) = self.turns[a];
        let cartesian = |p: [f64; 2]| [c * p[0] - s * p[1], s * p[0] + c * p[1]];
        (cartesian(frame), cartesian(material))
    }

    /// The residual in-plane displacement (u_x, u_y) at node a, in its
    /// parent frame's axes, under the in-plane forces `force(b)` (N, (F_x,
    /// F_y) in node b's parent frame's axes) at every node, m.
    pub fn displacement(&self, a: usize, chi: f64, force: impl Fn(usize) -> [f64; 2]) -> [f64; 2] {
        let (mut ur, mut ut) = (0.0, 0.0);
        for b in 0..self.n {
            let f = force(b);
            if f == [0.0, 0.0] {
                continue;
            }
            let (c, s) = self.turns[b];
            let (fr, ft) = (c * f[0] + s * f[1], -s * f[0] + c * f[1]);
            let m = self.between(a, b, chi);
            ur += m[0][0] * fr + m[0][1] * ft;
            ut += m[1][0] * fr + m[1][1] * ft;
        }
        let (c, s) = self.turns[a];
        [c * ur - s * ut, s * ur + c * ut]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kernel() -> InPlaneKernel {
        InPlaneKernel {
            coefficients: vec![
                [1.0, 0.0, 0.0, 2.0],
                [0.5, 0.3, -0.2, 0.4],
                [0.1, 0.05, 0.07, -0.03],
            ],
        }
    }

    #[test]
    fn the_table_reads_the_series_between_and_on_its_grid_points() {
        let (k, table) = (kernel(), AngleTable::new(&kernel()));
        for delta in [-7.0, -0.4, 0.0, 0.001, 1.3, 3.0, 6.2, 9.5] {
            let (got, want) = (table.at(delta), k.at(delta));
            for r in 0..2 {
                for c in 0..2 {
                    assert!(
                        (got[r][c] - want[r][c]).abs() < 1e-10,
                        "Δ = {delta}: {got:?} vs {want:?}"
                    );
                }
            }
        }
    }

    #[test]
    fn the_slope_is_the_central_difference_of_the_series() {
        let (k, eps) = (kernel(), 1e-6);
        for delta in [0.0, 0.7, 2.9, 5.5] {
            let (p, m, d) = (k.at(delta + eps), k.at(delta - eps), slope(&k, delta));
            for r in 0..2 {
                for c in 0..2 {
                    let fd = (p[r][c] - m[r][c]) / (2.0 * eps);
                    assert!((fd - d[r][c]).abs() < 1e-8, "{fd} vs {}", d[r][c]);
                }
            }
        }
    }
}
