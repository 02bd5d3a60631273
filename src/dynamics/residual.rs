//! The residual compliance between the scene's node frames
//! (`plate.residual_flexibility`, docs/residual_flexibility.md): the static
//! deflection the truncated modes add at node a per unit transverse force at
//! node b, from [`PlateModel::residual_kernel`].
//!
//! Nodes are numbered ALE first, then Lagrangian. Two nodes of the same kind
//! keep their angle difference (both space-fixed, or both turning with the
//! plate): a constant. An ALE node at θ and a material node at φ are
//! Δ = θ − φ − χ apart: their compliance C(Δ) is tabulated once on [0, π]
//! (even, 2π-periodic) with values and slopes, and read by cubic Hermite
//! interpolation: O(1) per pair and step.

use super::node_frame::NodeFrame;
use crate::model::mindlin::PatchHarmonics;
use crate::model::{PlateModel, ResidualKernel, StaticHarmonics};
use std::f64::consts::PI;

/// Intervals of the angle table on [0, π].
const TABLE_INTERVALS: usize = 1024;

/// C(Δ) on a uniform grid of [0, π]: values and derivatives.
#[derive(Debug, Clone)]
struct AngleTable {
    values: Vec<f64>,
    slopes: Vec<f64>,
}

impl AngleTable {
    fn new(kernel: &ResidualKernel) -> Self {
        let (values, slopes) = kernel.on_grid(TABLE_INTERVALS);
        AngleTable { values, slopes }
    }

    fn at(&self, delta: f64) -> f64 {
        // Fold into [0, π]: C is even and 2π-periodic.
        let mut x = delta.rem_euclid(std::f64::consts::TAU);
        if x > PI {
            x = std::f64::consts::TAU - x;
        }
        let h = PI / TABLE_INTERVALS as f64;
        let i = ((x / h) as usize).min(TABLE_INTERVALS - 1);
        let t = x / h - i as f64;
        let (y0, y1) = (self.values[i], self.values[i + 1]);
        let (d0, d1) = (self.slopes[i] * h, self.slopes[i + 1] * h);
        let t2 = t * t;
        let t3 = t2 * t;
        (2.0 * t3 - 3.0 * t2 + 1.0) * y0
            + (t3 - 2.0 * t2 + t) * d0
            + (-2.0 * t3 + 3.0 * t2) * y1
            + (t3 - t2) * d1
    }
}

/// The static harmonics of the node radii: of points (Kirchhoff) or of load
/// patches (Mindlin).
enum Kernels {
    Points(StaticHarmonics),
    Patches(PatchHarmonics),
}

impl Kernels {
    fn new(model: &PlateModel, radii: &[f64], patch: Option<f64>) -> Kernels {
        match patch {
            None => Kernels::Points(model.static_harmonics(radii)),
            Some(c) => Kernels::Patches(
                model
                    .mindlin_patch_harmonics(radii, c)
                    .expect("the model was built on this Mindlin discretisation"),
            ),
        }
    }

    fn between(&self, model: &PlateModel, a: usize, b: usize) -> ResidualKernel {
        match self {
            Kernels::Points(h) => model.residual_kernel(h, a, b),
            Kernels::Patches(h) => model.mindlin_residual_kernel(h, a, b),
        }
    }
}

/// One pair's compliance.
#[derive(Debug, Clone)]
enum PairCompliance {
    Constant(f64),
    /// ALE node angle θ minus the material node's angle φ; C(θ − φ − χ).
    Turning {
        offset: f64,
        table: usize,
    },
}

/// Residual compliances between all node frames of a scene, m/N.
#[derive(Debug, Clone)]
pub struct ResidualCompliance {
    n: usize,
    pairs: Vec<PairCompliance>,
    tables: Vec<AngleTable>,
}

impl ResidualCompliance {
    /// The compliances between the nodes `ale` and `lagrange`: between
    /// points (Kirchhoff, `patch` None) or between load patches of half-width
    /// `patch` (m; Mindlin, [`PlateModel::mindlin_residual_kernel`]).
    pub fn new(
        model: &PlateModel,
        ale: &[NodeFrame],
        lagrange: &[NodeFrame],
        patch: Option<f64>,
    ) -> ResidualCompliance {
        let nodes: Vec<&NodeFrame> = ale.iter().chain(lagrange).collect();
        let n = nodes.len();
        let (radii, index) = super::node_frame::distinct_radii(&nodes);
        let kernels = Kernels::new(model, &radii, patch);
        let mut pairs = Vec::with_capacity(n * n);
        let mut tables = Vec::new();
        // Tables are shared by pairs of the same radii (either order: C is symmetric in the radii).
        let mut table_of: Vec<((usize, usize), usize)> = Vec::new();
        for a in 0..n {
            for b in 0..n {
                let (na, nb) = (nodes[a], nodes[b]);
                let (ia, ib) = (index[a], index[b]);
                let key = (ia.min(ib), ia.max(ib));
                if na.kind == nb.kind {
                    let kernel = kernels.between(model, ia, ib);
                    pairs.push(PairCompliance::Constant(kernel.at(na.angle - nb.angle)));
                } else {
                    let table = match table_of.iter().find(|(k, _)| *k == key) {
                        Some(&(_, t)) => t,
                        None => {
                            tables.push(AngleTable::new(&kernels.between(model, key.0, key.1)));
                            table_of.push((key, tables.len() - 1));
                            tables.len() - 1
                        }
                    };
                    // Δ = θ_ale − φ_material − χ; written as offset ∓ χ by which node is the ALE one.
                    let offset = if na.kind == super::NodeKind::Ale {
                        na.angle - nb.angle
                    } else {
                        nb.angle - na.angle
                    };
                    pairs.push(PairCompliance::Turning { offset, table });
                }
            }
        }
        ResidualCompliance { n, pairs, tables }
    }

    /// Number of node frames (ALE first, then Lagrangian).
    pub fn len(&self) -> usize {
        self.n
    }

    pub fn is_empty(&self) -> bool {
        self.n == 0
    }

    /// Compliance between nodes a and b at joint angle χ, m/N.
    #[inline]
    pub fn between(&self, a: usize, b: usize, chi: f64) -> f64 {
        match self.pairs[a * self.n + b] {
            PairCompliance::Constant(c) => c,
            PairCompliance::Turning { offset, table } => self.tables[table].at(offset - chi),
        }
    }

    /// Residual deflection at node a under transverse forces `force(b)` (N) at every node.
    pub fn deflection(&self, a: usize, chi: f64, force: impl Fn(usize) -> f64) -> f64 {
        (0..self.n)
            .map(|b| {
                let f = force(b);
                if f == 0.0 {
                    0.0
                } else {
                    self.between(a, b, chi) * f
                }
            })
            .sum()
    }
}
