//! Nodal lines of a mode: the nodal circles (roots of its radial function
//! strictly inside the annulus) and the nodal half-diameters of its angular
//! factor.

use super::{AngularShape, PlateModel};
use std::f64::consts::PI;

/// Radii of the nodal circles of a radial function: sign changes strictly inside (r_i, r_a).
pub fn nodal_radii(model: &PlateModel, mode: usize) -> Vec<f64> {
    let m = &model.modes()[mode];
    let shape = &model.radial_shapes()[m.radial];
    let (ri, ra) = (model.plate().inner_radius, model.plate().outer_radius);
    let n = 4000;
    let peak = (0..=n)
        .map(|i| shape.value(ri + (ra - ri) * i as f64 / n as f64).abs())
        .fold(0.0, f64::max);
    let tiny = 1e-9 * peak;
    let mut roots = Vec::new();
    let mut prev: Option<(f64, f64)> = None;
    for i in 0..=n {
        let r = ri + (ra - ri) * i as f64 / n as f64;
        let v = shape.value(r);
        if v.abs() <= tiny {
            continue; // an edge with w = 0, or exactly on a root (picked up by the neighbours)
        }
        if let Some((r0, v0)) = prev {
            if v0.signum() != v.signum() {
                let (mut a, mut b, mut fa) = (r0, r, v0);
                for _ in 0..60 {
                    let c = 0.5 * (a + b);
                    let fc = shape.value(c);
                    if fc.signum() == fa.signum() {
                        a = c;
                        fa = fc;
                    } else {
                        b = c;
                    }
                }
                roots.push(0.5 * (a + b));
            }
        }
        prev = Some((r, v));
    }
    roots
}

/// Angles of the nodal half-diameters of a mode (2k of them for k ≥ 1).
pub fn nodal_angles(k: u32, shape: AngularShape) -> Vec<f64> {
    let kf = k as f64;
    match shape {
        AngularShape::Axisymmetric => vec![],
        AngularShape::Cos => (0..2 * k)
            .map(|j| (0.5 * PI + j as f64 * PI) / kf)
            .collect(),
        AngularShape::Sin => (0..2 * k).map(|j| j as f64 * PI / kf).collect(),
    }
}
