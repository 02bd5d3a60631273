//! The in-plane mode table of a configuration (`plate.in_plane_*`): the
//! requested ⟨k, l⟩ per family from [`super::InPlaneDiscretisation`], a
//! cos/sin pair per k ≥ 1, a torsional and a radial mode per k = 0, sorted
//! by frequency. `modes` lists it beside the bending modes.
//!
//! The edges are the in-plane pair the spin prestress uses too
//! (`plate.in_plane_inner`, `plate.in_plane_outer`); the radial resolution is
//! `plate.radial_splines` per field, `auto` being [`super::DEFAULT_SPLINES`].

use super::{
    InPlaneDiscretisation, InPlaneEdge, InPlaneError, InPlaneFamily, InPlanePlate, DEFAULT_SPLINES,
};
use crate::config::{CentrifugalConfig, PlateConfig, RadialSplines};

/// What the angular factors of an in-plane table entry are.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum InPlaneShape {
    /// k = 0: u_θ = V(r), u_r = 0.
    Torsional,
    /// k = 0: u_r = U(r), u_θ = 0.
    Radial,
    /// u_r = U cos kθ, u_θ = V sin kθ.
    Cos,
    /// u_r = U sin kθ, u_θ = −V cos kθ.
    Sin,
}

impl InPlaneShape {
    /// `torsional`, `radial`, `cos` or `sin`.
    pub fn name(self) -> &'static str {
        match self {
            InPlaneShape::Torsional => "torsional",
            InPlaneShape::Radial => "radial",
            InPlaneShape::Cos => "cos",
            InPlaneShape::Sin => "sin",
        }
    }

    /// (factor of U in u_r, factor of V in u_θ) at θ for k.
    pub fn angular(self, k: u32, theta: f64) -> (f64, f64) {
        let (s, c) = (k as f64 * theta).sin_cos();
        match self {
            InPlaneShape::Torsional => (0.0, 1.0),
            InPlaneShape::Radial => (1.0, 0.0),
            InPlaneShape::Cos => (c, s),
            InPlaneShape::Sin => (s, -c),
        }
    }
}

/// One entry of the in-plane table.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InPlaneEntry {
    /// Nodal diameters.
    pub k: u32,
    /// Order in ascending frequency for k (and family at k = 0).
    pub l: u32,
    /// Angular form.
    pub shape: InPlaneShape,
    /// ω, rad/s.
    pub omega: f64,
    /// ω/2π, Hz.
    pub frequency_hz: f64,
    /// c_k ∫ ρh (U² + V²) r dr of the unit-peak shape, kg.
    pub modal_mass: f64,
}

/// The in-plane modes a configuration requests.
#[derive(Debug, Clone, PartialEq)]
pub struct InPlaneTable {
    /// The entries, ascending in frequency.
    pub entries: Vec<InPlaneEntry>,
    /// The requested ⟨k, l⟩ that are rigid-body motions of a free–free
    /// annulus, with the family (`torsional` for k = 0, `coupled` for k = 1).
    pub skipped: Vec<(u32, u32, &'static str)>,
    /// The B-splines per field used.
    pub splines: usize,
    /// The edges used.
    pub edges: [InPlaneEdge; 2],
}

impl InPlaneTable {
    /// The table of `plate.in_plane_nodal_diameters` × `plate.in_plane_orders`
    /// (empty when no k is requested).
    pub fn new(plate: &PlateConfig, edges: &CentrifugalConfig) -> Result<Self, InPlaneError> {
        let ip = in_plane_plate(plate, edges);
        let splines = match plate.radial_splines {
            RadialSplines::Auto => DEFAULT_SPLINES,
            RadialSplines::Fixed(n) => n,
        };
        let mut table = InPlaneTable {
            entries: Vec::new(),
            skipped: Vec::new(),
            splines,
            edges: [ip.inner_edge, ip.outer_edge],
        };
        if plate.in_plane_nodal_diameters.is_empty() {
            return Ok(table);
        }
        let disc = InPlaneDiscretisation::new(&ip, splines)?;
        let orders = plate
            .in_plane_orders
            .iter()
            .max()
            .map_or(1, |&l| l as usize + 1);
        for &k in &plate.in_plane_nodal_diameters {
            for &family in InPlaneFamily::of(k) {
                let modes = disc.modes(k, family, orders)?;
                for &l in &plate.in_plane_orders {
                    if ip.is_rigid_body(k, family, l) {
                        table.skipped.push((k, l, family.name()));
                        continue;
                    }
                    let Some(m) = modes.iter().find(|m| m.l == l) else {
                        unreachable!("modes returns every elastic l below orders")
                    };
                    let shapes: &[InPlaneShape] = match family {
                        InPlaneFamily::Torsional => &[InPlaneShape::Torsional],
                        InPlaneFamily::Radial => &[InPlaneShape::Radial],
                        InPlaneFamily::Coupled => &[InPlaneShape::Cos, InPlaneShape::Sin],
                    };
                    table
                        .entries
                        .extend(shapes.iter().map(|&shape| InPlaneEntry {
                            k,
                            l,
                            shape,
                            omega: m.omega,
                            frequency_hz: m.frequency_hz,
                            modal_mass: m.modal_mass,
                        }));
                }
            }
        }
        table.entries.sort_by(|a, b| {
            a.omega
                .total_cmp(&b.omega)
                .then(a.k.cmp(&b.k))
                .then(a.shape.cmp(&b.shape))
        });
        table.skipped.sort_unstable();
        Ok(table)
    }
}

/// The in-plane plate of a configuration: its material and geometry with the
/// in-plane edges `plate.in_plane_inner` (`auto` follows
/// `plate.inner_boundary`) and `plate.in_plane_outer`.
pub fn in_plane_plate(plate: &PlateConfig, edges: &CentrifugalConfig) -> InPlanePlate {
    let edge = |fixed: bool| {
        if fixed {
            InPlaneEdge::Fixed
        } else {
            InPlaneEdge::Free
        }
    };
    InPlanePlate {
        youngs_modulus: plate.youngs_modulus,
        poisson_ratio: plate.poisson_ratio,
        density: plate.density,
        thickness: plate.thickness,
        inner_radius: plate.inner_radius,
        outer_radius: plate.outer_radius,
        inner_edge: edge(edges.in_plane_inner.is_fixed(plate.inner_boundary)),
        outer_edge: edge(edges.in_plane_outer.is_fixed()),
    }
}
