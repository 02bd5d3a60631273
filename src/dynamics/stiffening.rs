//! Centrifugal stiffening in the dynamics (`plate.centrifugal_stiffening`,
//! docs/rotor_dynamics.md): the modal geometric stiffness Ω(t)² G_k of the
//! Lamé prestress ([`ModalGeometricStiffness`]) arranged by mode index.
//!
//! Per nodal-diameter number k the retained l couple through G_k; cos never
//! couples with sin, and the block is the same for both families. Since the
//! prestress is axisymmetric the term commutes with the ALE rotation R(kχ) of
//! eq. (20): in either description the equations gain −Ω² M⁻¹ G_k q per
//! family (q the family's amplitudes over l), with Ω the joint speed at the
//! instant — nothing else (the kinematic terms of the ALE equations do not
//! involve G).

use crate::config::CentrifugalConfig;
use crate::model::{ModalGeometricStiffness, PlateModel};

/// G_k of one k, by mode index.
#[derive(Debug, Clone, PartialEq)]
pub struct StiffeningBlock {
    pub k: u32,
    /// Mode indices of the cos family over the retained l, ascending (k = 0:
    /// the axisymmetric modes).
    pub cos: Vec<usize>,
    /// Mode indices of the sin family, same l order (empty for k = 0).
    pub sin: Vec<usize>,
    /// G[a, b] / m_a, row-major n × n: the acceleration of mode a per unit
    /// amplitude of mode b and per (rad/s)² of spin, 1/1.
    pub g_over_m: Vec<f64>,
}

impl StiffeningBlock {
    /// Number of retained l.
    pub fn len(&self) -> usize {
        self.cos.len()
    }

    pub fn is_empty(&self) -> bool {
        self.cos.is_empty()
    }

    /// The families of this k (cos, then sin when k ≥ 1).
    pub fn families(&self) -> impl Iterator<Item = &[usize]> {
        [self.cos.as_slice(), self.sin.as_slice()]
            .into_iter()
            .filter(|f| !f.is_empty())
    }
}

/// The geometric stiffness of every retained k.
#[derive(Debug, Clone, PartialEq)]
pub struct Stiffening {
    pub blocks: Vec<StiffeningBlock>,
    /// Bound on the largest |eigenvalue| of M⁻¹ G over all k (Gershgorin on
    /// M^{-1/2} G M^{-1/2}): Ω² times it bounds the stiffening of ω² (step limits).
    pub rate_bound: f64,
}

impl Stiffening {
    /// G_k of the retained modes of `model` for the prestress of `centrifugal`.
    pub fn new(model: &PlateModel, centrifugal: &CentrifugalConfig) -> Stiffening {
        let g = ModalGeometricStiffness::new(model, centrifugal);
        let modes = model.modes();
        let mut rate_bound = 0.0f64;
        let blocks = g
            .blocks
            .iter()
            .map(|b| {
                let n = b.radial.len();
                let family_member = |r: usize, cos: bool| {
                    modes.iter().position(|m| {
                        m.radial == r
                            && (m.k == 0 || (m.shape == crate::model::AngularShape::Cos) == cos)
                    })
                };
                let cos: Vec<usize> = b
                    .radial
                    .iter()
                    .filter_map(|&r| family_member(r, true))
                    .collect();
                let sin: Vec<usize> = if b.k == 0 {
                    Vec::new()
                } else {
                    b.radial
                        .iter()
                        .filter_map(|&r| family_member(r, false))
                        .collect()
                };
                debug_assert_eq!(cos.len(), n, "every retained radial shape is a mode");
                let mass: Vec<f64> = cos.iter().map(|&i| modes[i].modal_mass).collect();
                let mut g_over_m = vec![0.0; n * n];
                for a in 0..n {
                    let mut row = 0.0;
                    for c in 0..n {
                        g_over_m[a * n + c] = b.matrix[a * n + c] / mass[a];
                        row += b.matrix[a * n + c].abs() / (mass[a] * mass[c]).sqrt();
                    }
                    rate_bound = rate_bound.max(row);
                }
                StiffeningBlock {
                    k: b.k,
                    cos,
                    sin,
                    g_over_m,
                }
            })
            .collect();
        Stiffening { blocks, rate_bound }
    }

    /// acc −= Ω² M⁻¹ G q for every family (either description: G commutes with R(kχ)).
    #[inline]
    pub fn subtract_accelerations(&self, speed_sq: f64, q: &[f64], acc: &mut [f64]) {
        for b in &self.blocks {
            let n = b.len();
            for family in b.families() {
                for (a, &ia) in family.iter().enumerate() {
                    let row = &b.g_over_m[a * n..(a + 1) * n];
                    let gq: f64 = row.iter().zip(family).map(|(g, &ic)| g * q[ic]).sum();
                    acc[ia] -= speed_sq * gq;
                }
            }
        }
    }

    /// Add −Ω² M⁻¹ G to the velocity rows of a first-order system matrix
    /// `a` (rows n + i hold q̈_i, columns j hold q_j).
    pub fn add_to_system(
        &self,
        speed_sq: f64,
        n_modes: usize,
        mut a: impl FnMut(usize, usize, f64),
    ) {
        for b in &self.blocks {
            let n = b.len();
            for family in b.families() {
                for (r, &ir) in family.iter().enumerate() {
                    for (c, &ic) in family.iter().enumerate() {
                        a(n_modes + ir, ic, -speed_sq * b.g_over_m[r * n + c]);
                    }
                }
            }
        }
    }
}
