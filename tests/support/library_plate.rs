//! The library's side of the exact plate solutions: its boundary conditions as
//! the exact solution's edges, and the library plate for an exact annulus.
#![allow(dead_code)]

use super::exact_plate::{Edge, Material};
use annular_plate::config::{Boundary, PlateConfig};

/// The exact Kirchhoff solution's edge for the library's boundary condition
/// (`supported_soft` is Mindlin's only: no Kirchhoff edge).
pub fn edge(b: Boundary) -> Edge {
    match b {
        Boundary::Free => Edge::Free,
        Boundary::Supported => Edge::Supported,
        Boundary::Clamped => Edge::Clamped,
        Boundary::SupportedSoft => panic!("supported_soft has no Kirchhoff edge"),
    }
}

/// The library plate (undamped, default radial splines) of an annulus r_i..r_a
/// of `material` with the edges `inner`, `outer` and the modes ks × ls.
pub fn annulus_config(
    (inner_radius, outer_radius): (f64, f64),
    (inner, outer): (Boundary, Boundary),
    ks: &[u32],
    ls: &[u32],
    material: Material,
) -> PlateConfig {
    let mut cfg = PlateConfig::lathe_disc();
    cfg.inner_radius = inner_radius;
    cfg.outer_radius = outer_radius;
    cfg.thickness = material.thickness;
    cfg.density = material.density;
    cfg.youngs_modulus = material.youngs_modulus;
    cfg.poisson_ratio = material.poisson_ratio;
    cfg.inner_boundary = inner;
    cfg.outer_boundary = outer;
    cfg.nodal_diameters = ks.to_vec();
    cfg.nodal_circles = ls.to_vec();
    cfg.damping = vec![0.0];
    cfg
}
