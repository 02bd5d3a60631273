//! The in-plane modes of a hub-fixed, rim-free disc as the in-plane pad
//! tests see them: the torsional family exact (Bessel functions, no library
//! numerics), the radial family and the k ≥ 1 pairs from the library's
//! B-spline modes with their angular factors written out here.

#![allow(dead_code)]

use super::bessel::jy_seq;
use super::in_plane_exact::torsional_fixed_free_beta;
use annular_plate::config::{Config, PlateConfig};
use annular_plate::dynamics::Simulation;
use annular_plate::model::in_plane::{
    in_plane_plate, InPlaneDiscretisation, InPlaneFamily, InPlaneShape, InPlaneTable,
};

/// The exact torsional mode l of the fixed–free annulus: ω, V(r) scaled to
/// a positive unit peak, its value at the rim, its modal mass
/// m = 2π∫ρh V² r dr and its joint coupling s = 2π∫ρh V r² dr (Simpson,
/// 20 000 cells), as tests/in_plane_dynamics.rs builds it.
pub struct Torsion {
    pub omega: f64,
    pub v: Box<dyn Fn(f64) -> f64>,
    pub v_rim: f64,
    pub mass: f64,
    pub coupling: f64,
}

pub fn exact_torsion(plate: &PlateConfig, l: usize) -> Torsion {
    let (ri, ra, h) = (plate.inner_radius, plate.outer_radius, plate.thickness);
    let (rho, e, nu) = (plate.density, plate.youngs_modulus, plate.poisson_ratio);
    let beta = torsional_fixed_free_beta(ri, ra, l);
    let g = e / (2.0 * (1.0 + nu));
    let (ji, yi) = jy_seq(1, beta * ri);
    let raw = move |r: f64| {
        let (j, y) = jy_seq(1, beta * r);
        j[1] * yi[1] - y[1] * ji[1]
    };
    let n = 20_000;
    let dr = (ra - ri) / n as f64;
    let peak = (0..=n)
        .map(|i| raw(ri + i as f64 * dr))
        .fold(0.0f64, |a, v| if v.abs() > a.abs() { v } else { a });
    let v = move |r: f64| raw(r) / peak;
    let simpson = |f: &dyn Fn(f64) -> f64| {
        (0..=n)
            .map(|i| {
                let w = if i == 0 || i == n {
                    1.0
                } else if i % 2 == 1 {
                    4.0
                } else {
                    2.0
                };
                w * f(ri + i as f64 * dr)
            })
            .sum::<f64>()
            * dr
            / 3.0
    };
    let tau = std::f64::consts::TAU * rho * h;
    Torsion {
        omega: beta * (g / rho).sqrt(),
        v_rim: v(ra),
        mass: tau * simpson(&|r| v(r) * v(r) * r),
        coupling: tau * simpson(&|r| v(r) * r * r),
        v: Box::new(v),
    }
}

/// (u_r, u_θ, ∂_θ u_r, ∂_θ u_θ) at (r, θ).
pub type Polar = Box<dyn Fn(f64, f64) -> [f64; 4]>;

/// One in-plane mode as the test sees it: its state index, k, m, ω and its
/// polar displacement (u_r, u_θ) and their θ-derivatives at (r, θ).
pub struct TestMode {
    pub index: usize,
    pub k: u32,
    pub mass: f64,
    pub omega: f64,
    pub polar: Polar,
}

/// The in-plane modes of `config` for the test: the torsional ones from the
/// exact solution, the radial ones and the k ≥ 1 pairs from the library's
/// B-spline modes (U, V evaluated here), with their angular factors
/// cos/sin kθ written out (cos: u_r = U cos kθ, u_θ = V sin kθ; sin:
/// u_r = U sin kθ, u_θ = −V cos kθ).
pub fn test_modes(config: &Config, sim: &Simulation) -> Vec<TestMode> {
    let ip = sim.scene().in_plane.as_ref().unwrap();
    let table = InPlaneTable::new(&config.plate, &config.centrifugal).unwrap();
    let ip_plate = in_plane_plate(&config.plate, &config.centrifugal);
    let disc = InPlaneDiscretisation::new(&ip_plate, table.splines).unwrap();
    let orders = config.plate.in_plane_orders.len();
    let mut out = Vec::new();
    for (j, m) in ip.modes.iter().enumerate() {
        let index = ip.offset + j;
        let k = f64::from(m.k);
        let mode = |family| {
            disc.modes(m.k, family, orders)
                .unwrap()
                .into_iter()
                .find(|x| x.l == m.l)
                .unwrap()
        };
        let (mass, omega, polar): (f64, f64, Polar) = match m.shape {
            InPlaneShape::Torsional => {
                let t = exact_torsion(&config.plate, m.l as usize);
                let v = t.v;
                (t.mass, t.omega, Box::new(move |r, _| [0.0, v(r), 0.0, 0.0]))
            }
            InPlaneShape::Radial => {
                let x = mode(InPlaneFamily::Radial);
                (
                    x.modal_mass,
                    x.omega,
                    Box::new(move |r, _| [x.eval(r).u, 0.0, 0.0, 0.0]),
                )
            }
            InPlaneShape::Cos => {
                let x = mode(InPlaneFamily::Coupled);
                (
                    x.modal_mass,
                    x.omega,
                    Box::new(move |r, t| {
                        let e = x.eval(r);
                        let (s, c) = (k * t).sin_cos();
                        [e.u * c, e.v * s, -k * e.u * s, k * e.v * c]
                    }),
                )
            }
            InPlaneShape::Sin => {
                let x = mode(InPlaneFamily::Coupled);
                (
                    x.modal_mass,
                    x.omega,
                    Box::new(move |r, t| {
                        let e = x.eval(r);
                        let (s, c) = (k * t).sin_cos();
                        [e.u * s, -e.v * c, k * e.u * c, k * e.v * s]
                    }),
                )
            }
        };
        out.push(TestMode {
            index,
            k: m.k,
            mass,
            omega,
            polar,
        });
    }
    out
}

/// V at a contact at radius `r`: with `plate.residual_flexibility` the
/// friction is spread over the node's load patch |r' − r| ≤ c (clipped to
/// the annulus), so its mean ∫V r' dr' / ∫r' dr' (Simpson, 2000 cells);
/// otherwise the point value.
pub fn patch_mean(config: &Config, t: &Torsion, r: f64) -> f64 {
    if !config.plate.residual_flexibility {
        return (t.v)(r);
    }
    let c = config.plate.residual_patch_half_width();
    let patch = super::mindlin_static::Patch::new(
        config.plate.inner_radius,
        config.plate.outer_radius,
        r,
        c,
    );
    let n = 2000;
    let dr = (patch.hi - patch.lo) / n as f64;
    let sum: f64 = (0..=n)
        .map(|i| {
            let w = if i == 0 || i == n {
                1.0
            } else {
                (2 + 2 * (i % 2)) as f64
            };
            let x = patch.lo + i as f64 * dr;
            w * (t.v)(x) * x
        })
        .sum();
    sum * dr / 3.0 / patch.area_factor()
}
