//! The spin terms of the in-plane modes in the dynamics (docs/in_plane.md,
//! "Spinning" and "In the dynamics"): in the turning frame, per k,
//!
//! m q̈ + (c + Ω G) q̇ + (m ω² + Ω² K_Ω) q = f,                         (S1)
//!
//! m, c, ω diagonal (modal mass, 2ζωm, the modes' ω), G and K_Ω the modal
//! Coriolis and spin stiffness of [`InPlaneDiscretisation::modal_spin`] over
//! the block's modes: [cos partners; sin partners] for k ≥ 1 (G couples the
//! partners), the radial and torsional modes for k = 0 (G couples the two
//! families). The torsional modes keep their coupling s with the joint
//! (docs/in_plane.md, "In the dynamics", Joint): its Euler force is a load of the block.
//!
//! # Descriptions
//!
//! The turning frame is the Lagrangian description. A k ≥ 1 block's G is
//! [[0, 2B], [−2B, 0]] over [cos; sin] and K_Ω is the same block for both
//! partners, so both commute with the rotation R(kχ) of eq. (20) acting on
//! each (cos, sin) pair. In the ALE description the terms keep their form
//! with the Lagrangian velocity seen in ALE axes, q̄̇ − kΩ J q̄ (J x = (−x_s,
//! x_c)), in place of q̇ — the same substitution as the damping's.

use crate::config::Coordinates;
use crate::model::in_plane::{InPlaneDiscretisation, InPlaneMode, InPlaneShape};
use crate::model::prestress::LamePrestress;

/// The spin terms of one k over its in-plane modes.
#[derive(Debug, Clone, PartialEq)]
pub struct InPlaneSpinBlock {
    /// Nodal diameters.
    pub k: u32,
    /// State indices of the block's modal coordinates: the cos partners then
    /// the sin partners in the same order for k ≥ 1; the k = 0 modes in the
    /// table's order.
    pub modes: Vec<usize>,
    /// G[a, b] / m_a, row-major n × n, per rad/s of spin, 1/s per rad/s.
    pub g_over_m: Vec<f64>,
    /// K_Ω[a, b] / m_a, row-major n × n, per (rad/s)² of spin.
    pub k_over_m: Vec<f64>,
}

impl InPlaneSpinBlock {
    /// The block of k from the table's modes `entries` (state index, shape,
    /// radial functions) of that k; `None` when it has no mode.
    pub(crate) fn new(
        disc: &InPlaneDiscretisation,
        prestress: &LamePrestress,
        k: u32,
        entries: &[(usize, InPlaneShape, &InPlaneMode, f64)],
    ) -> Option<InPlaneSpinBlock> {
        let own: Vec<_> = entries
            .iter()
            .filter(|e| k == 0 || e.1 == InPlaneShape::Cos)
            .collect();
        if own.is_empty() {
            return None;
        }
        let radial: Vec<InPlaneMode> = own.iter().map(|e| e.2.clone()).collect();
        let mut modes: Vec<usize> = own.iter().map(|e| e.0).collect();
        let mut mass: Vec<f64> = own.iter().map(|e| e.3).collect();
        if k != 0 {
            for e in &own {
                let Some(s) = entries
                    .iter()
                    .find(|p| p.1 == InPlaneShape::Sin && p.2.l == e.2.l)
                else {
                    unreachable!("the table lists a sin partner with every cos mode")
                };
                modes.push(s.0);
                mass.push(s.3);
            }
        }
        let spin = disc.modal_spin(k, prestress, &radial);
        let n = modes.len();
        let per_mass = |m: &faer::Mat<f64>| -> Vec<f64> {
            (0..n * n)
                .map(|x| m[(x / n, x % n)] / mass[x / n])
                .collect()
        };
        Some(InPlaneSpinBlock {
            k,
            modes,
            g_over_m: per_mass(&spin.gyroscopic),
            k_over_m: per_mass(&spin.spin_stiffness),
        })
    }

    /// The number of modal coordinates.
    pub fn len(&self) -> usize {
        self.modes.len()
    }

    /// Whether there are none.
    pub fn is_empty(&self) -> bool {
        self.modes.is_empty()
    }

    /// The Lagrangian velocity of coordinate b in `coords`' axes (module
    /// docs): q̄̇ − kΩ J q̄ in the ALE description.
    #[inline]
    fn velocity(&self, coords: Coordinates, speed: f64, b: usize, q: &[f64], v: &[f64]) -> f64 {
        let i = self.modes[b];
        if self.k == 0 || coords == Coordinates::Lagrangian {
            return v[i];
        }
        let half = self.len() / 2;
        let kw = self.k as f64 * speed;
        if b < half {
            v[i] + kw * q[self.modes[b + half]]
        } else {
            v[i] - kw * q[self.modes[b - half]]
        }
    }

    /// −M⁻¹ (Ω G (q̄̇ − kΩ 𝒥 q̄) + Ω² K_Ω q̄) of the ALE description
    /// (module docs) as matrix entries of ẏ = A y, y = (q̄, q̄̇) with `n`
    /// modes: `add(row, column, value)` per entry, the rows those of q̄̈. With
    /// 𝒥 x = (−x_s, x_c) over [cos; sin], −ΩG(−kΩ𝒥) = kΩ² G𝒥: on the
    /// cos column b the term kΩ² G[a, b] lands on the sin partner with a
    /// minus sign, on the sin column with a plus sign on the cos partner —
    /// the same sums as [`InPlaneSpinBlock::row_acceleration`] in ALE.
    pub fn add_ale_system(&self, speed: f64, n: usize, mut add: impl FnMut(usize, usize, f64)) {
        let len = self.len();
        let (half, kw) = (len / 2, self.k as f64 * speed);
        for (a, &i) in self.modes.iter().enumerate() {
            for (b, &j) in self.modes.iter().enumerate() {
                let g = speed * self.g_over_m[a * len + b];
                add(n + i, n + j, -g);
                add(n + i, j, -speed * speed * self.k_over_m[a * len + b]);
                if self.k != 0 {
                    if b < half {
                        add(n + i, self.modes[b + half], -g * kw);
                    } else {
                        add(n + i, self.modes[b - half], g * kw);
                    }
                }
            }
        }
    }

    /// (Ω G q̇ + Ω² K_Ω q)_a / m_a of row a, in `coords`.
    #[inline]
    pub fn row_acceleration(
        &self,
        coords: Coordinates,
        speed: f64,
        a: usize,
        q: &[f64],
        v: &[f64],
    ) -> f64 {
        let n = self.len();
        let (g, s) = (
            &self.g_over_m[a * n..(a + 1) * n],
            &self.k_over_m[a * n..(a + 1) * n],
        );
        let mut sum = 0.0;
        for b in 0..n {
            let w = self.velocity(coords, speed, b, q, v);
            sum += speed * g[b] * w + speed * speed * s[b] * q[self.modes[b]];
        }
        sum
    }
}

/// The spin terms of every k with in-plane modes.
#[derive(Debug, Clone, PartialEq)]
pub struct InPlaneSpinTerms {
    pub blocks: Vec<InPlaneSpinBlock>,
    /// Gershgorin bounds of the spin terms over every block: the largest
    /// row sum of |K_Ω/m| (per (rad/s)²) and of |G/m| (per rad/s). A mode's
    /// turning-frame rate is then within √(ω² + Ω² b_K) + |Ω| b_G.
    pub rate_bounds: (f64, f64),
}

impl InPlaneSpinTerms {
    /// The terms of `blocks`, with their [`InPlaneSpinTerms::rate_bounds`].
    pub fn new(blocks: Vec<InPlaneSpinBlock>) -> InPlaneSpinTerms {
        let row_sums = |m: &[f64], n: usize| {
            m.chunks_exact(n.max(1))
                .map(|row| row.iter().map(|x| x.abs()).sum::<f64>())
                .fold(0.0f64, f64::max)
        };
        let rate_bounds = blocks.iter().fold((0.0f64, 0.0f64), |(k, g), b| {
            let n = b.modes.len();
            (
                k.max(row_sums(&b.k_over_m, n)),
                g.max(row_sums(&b.g_over_m, n)),
            )
        });
        InPlaneSpinTerms {
            blocks,
            rate_bounds,
        }
    }

    /// acc −= M⁻¹ (Ω G q̇ + Ω² K_Ω q) over every block, in `coords`.
    pub fn subtract_accelerations(
        &self,
        coords: Coordinates,
        speed: f64,
        q: &[f64],
        v: &[f64],
        acc: &mut [f64],
    ) {
        if speed == 0.0 {
            return;
        }
        for b in &self.blocks {
            for (a, &i) in b.modes.iter().enumerate() {
                acc[i] -= b.row_acceleration(coords, speed, a, q, v);
            }
        }
    }

    /// (Ω G q̇ + Ω² K_Ω q) of state index `i` over its mass, in the
    /// Lagrangian description (0 for an index in no block).
    pub fn acceleration_of(&self, i: usize, speed: f64, q: &[f64], v: &[f64]) -> f64 {
        self.blocks
            .iter()
            .find_map(|b| {
                let a = b.modes.iter().position(|&m| m == i)?;
                Some(b.row_acceleration(Coordinates::Lagrangian, speed, a, q, v))
            })
            .unwrap_or(0.0)
    }
}
