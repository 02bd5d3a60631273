//! The in-plane waves of a spinning annulus by Chebyshev collocation of the
//! strong form — written for the tests, sharing no numerics with the
//! library (no B-splines, no Galerkin, no quadrature; the Lamé stresses from
//! `lame.rs`; only faer's dense LU and eigenvalues).
//!
//! In the turning frame, per unit thickness, with the wave
//! u_r = U(r) cos(kθ + ωt), u_θ = V(r) sin(kθ + ωt):
//!
//!   −ρω² U − 2ρΩω V − ρΩ² U = S_r' + k T/r + (S_r − S_θ)/r + Ω² g_r,
//!   −ρω² V − 2ρΩω U − ρΩ² V = T' − k S_θ/r + 2T/r + Ω² g_θ,
//!
//! S_r = Ē (U' + ν (U + kV)/r), S_θ = Ē ((U + kV)/r + ν U'),
//! T = G (V' − V/r − kU/r) (the plane-stress Navier equations in polar
//! form, Coriolis −2ρΩ u̇_θ / +2ρΩ u̇_r, centrifugal ρΩ² u), and the
//! prestress's force h div(σ⁰ ∇u_c) per Cartesian component, written with
//! u_x + i u_y = (u_r + i u_θ) e^{iθ}:
//!
//!   g_r = (1/r)(r σ_r U')' − σ_θ ((k² + 1) U + 2k V)/r²,
//!   g_θ = (1/r)(r σ_r V')' − σ_θ ((k² + 1) V + 2k U)/r².
//!
//! Edges: fixed U = V = 0; free S_r = T = 0 (σ_r vanishes there, so the
//! prestress adds nothing). ω > 0 is the wave travelling against the spin.
#![allow(dead_code)]

use super::lame::Lame;
use faer::linalg::solvers::Solve;
use faer::Mat;

/// The annulus (SI) with its in-plane edges (true: fixed).
#[derive(Debug, Clone, Copy)]
pub struct SpinningAnnulus {
    pub youngs_modulus: f64,
    pub poisson_ratio: f64,
    pub density: f64,
    pub inner_radius: f64,
    pub outer_radius: f64,
    pub inner_fixed: bool,
    pub outer_fixed: bool,
}

impl SpinningAnnulus {
    /// The annulus and material of `plate` with the rim free and the hub
    /// fixed (`inner_fixed`) or free.
    pub fn of(plate: &annular_plate::config::PlateConfig, inner_fixed: bool) -> SpinningAnnulus {
        SpinningAnnulus {
            youngs_modulus: plate.youngs_modulus,
            poisson_ratio: plate.poisson_ratio,
            density: plate.density,
            inner_radius: plate.inner_radius,
            outer_radius: plate.outer_radius,
            inner_fixed,
            outer_fixed: false,
        }
    }
}

/// Chebyshev points x_j = cos(jπ/N) and the differentiation matrix (Trefethen, cheb.m).
fn cheb(n: usize) -> (Vec<f64>, Mat<f64>) {
    let x: Vec<f64> = (0..=n)
        .map(|j| (std::f64::consts::PI * j as f64 / n as f64).cos())
        .collect();
    let c = |j: usize| {
        (if j == 0 || j == n { 2.0 } else { 1.0 }) * if j.is_multiple_of(2) { 1.0 } else { -1.0 }
    };
    let mut d = Mat::<f64>::from_fn(n + 1, n + 1, |i, j| {
        if i == j {
            0.0
        } else {
            c(i) / c(j) / (x[i] - x[j])
        }
    });
    for i in 0..=n {
        let s: f64 = (0..=n).filter(|&j| j != i).map(|j| d[(i, j)]).sum();
        d[(i, i)] = -s;
    }
    (x, d)
}

/// Every root ω (rad/s) of the collocated problem on N + 1 points as
/// (real, imaginary) parts. Roots far above the lowest few are not converged.
pub fn roots(a: &SpinningAnnulus, lame: &Lame, k: u32, spin: f64, n: usize) -> Vec<(f64, f64)> {
    let (ri, ra, nu) = (a.inner_radius, a.outer_radius, a.poisson_ratio);
    let g_mod = a.youngs_modulus / (2.0 * (1.0 + nu));
    let e_bar = a.youngs_modulus / (1.0 - nu * nu);
    // Units: length d = (r_a − r_i)/2, stress G, frequency √(G/ρ)/d.
    let d_len = 0.5 * (ra - ri);
    let w_unit = (g_mod / a.density).sqrt() / d_len;
    let (x, dx) = cheb(n);
    let m = n + 1;
    let r: Vec<f64> = x.iter().map(|&xi| 0.5 * (ra + ri) / d_len + xi).collect();
    let eb = e_bar / g_mod;
    let kf = k as f64;
    let spin_hat = spin / w_unit;
    // σ per unit Ω² in units of ρ d².
    let stress: Vec<(f64, f64)> = r
        .iter()
        .map(|&rr| {
            let (sr, st, _) = lame.at(rr * d_len);
            (
                sr / (a.density * d_len * d_len),
                st / (a.density * d_len * d_len),
            )
        })
        .collect();
    let diag = |f: &dyn Fn(usize) -> f64| {
        Mat::<f64>::from_fn(m, m, |i, j| if i == j { f(i) } else { 0.0 })
    };
    let inv_r = diag(&|i| 1.0 / r[i]);
    let id = diag(&|_| 1.0);
    let zero = Mat::<f64>::zeros(m, m);
    // Stresses as (U-part, V-part) operators.
    let sr = (eb * (&dx + nu * &inv_r), eb * nu * kf * &inv_r);
    let st = (eb * (&inv_r + nu * &dx), eb * kf * &inv_r);
    let t = (-kf * &inv_r, &dx - &inv_r);
    let row_r = |p: usize| -> Mat<f64> {
        let (s_r, s_t, tt) = match p {
            0 => (&sr.0, &st.0, &t.0),
            _ => (&sr.1, &st.1, &t.1),
        };
        &dx * s_r + kf * &inv_r * tt + &inv_r * (s_r - s_t)
    };
    let row_t = |p: usize| -> Mat<f64> {
        let (s_t, tt) = match p {
            0 => (&st.0, &t.0),
            _ => (&st.1, &t.1),
        };
        &dx * tt - kf * &inv_r * s_t + 2.0 * &inv_r * tt
    };
    // Prestress: (1/r)(r σ_r f')' and σ_θ/r².
    let flux = &inv_r * &dx * diag(&|i| r[i] * stress[i].0) * &dx;
    let hoop = diag(&|i| stress[i].1 / (r[i] * r[i]));
    let geo_same = &flux - (kf * kf + 1.0) * &hoop;
    let geo_cross = -2.0 * kf * &hoop;
    let s2 = spin_hat * spin_hat;
    // L y + ω (2Ω P) y + ω² y = 0 with L = elastic + Ω² (prestress + 1).
    let block = |uu: Mat<f64>, uv: Mat<f64>, vu: Mat<f64>, vv: Mat<f64>| {
        Mat::<f64>::from_fn(2 * m, 2 * m, |i, j| match (i < m, j < m) {
            (true, true) => uu[(i, j)],
            (true, false) => uv[(i, j - m)],
            (false, true) => vu[(i - m, j)],
            (false, false) => vv[(i - m, j - m)],
        })
    };
    let l = block(
        row_r(0) + s2 * (&geo_same + &id),
        row_r(1) + s2 * &geo_cross,
        row_t(0) + s2 * &geo_cross,
        row_t(1) + s2 * (&geo_same + &id),
    );
    let coriolis = block(
        zero.clone(),
        2.0 * spin_hat * &id,
        2.0 * spin_hat * &id,
        zero.clone(),
    );
    // Edge rows replace the collocation rows at x = 1 (r_a, j = 0) and x = −1 (r_i, j = N).
    let edge_rows = |j: usize, fixed: bool| -> [Vec<f64>; 2] {
        let mut u_row = vec![0.0; 2 * m];
        let mut v_row = vec![0.0; 2 * m];
        if fixed {
            u_row[j] = 1.0;
            v_row[m + j] = 1.0;
        } else {
            for c in 0..m {
                u_row[c] = sr.0[(j, c)];
                u_row[m + c] = sr.1[(j, c)];
                v_row[c] = t.0[(j, c)];
                v_row[m + c] = t.1[(j, c)];
            }
        }
        [u_row, v_row]
    };
    let boundary = [0, n, m, m + n];
    let mut bc = edge_rows(0, a.outer_fixed).to_vec();
    bc.extend(edge_rows(n, a.inner_fixed));
    // bc rows in the order of `boundary`'s equations (U at r_a, V at r_a, U at r_i, V at r_i).
    let interior: Vec<usize> = (0..2 * m).filter(|i| !boundary.contains(i)).collect();
    let unknowns_b = [0, m, n, m + n];
    let cb = Mat::<f64>::from_fn(4, 4, |i, j| bc[i][unknowns_b[j]]);
    let ci = Mat::<f64>::from_fn(4, interior.len(), |i, j| bc[i][interior[j]]);
    // y_B = −C_B⁻¹ C_I y_I.
    let p = -1.0 * cb.partial_piv_lu().solve(&ci);
    let ni = interior.len();
    let reduced = Mat::<f64>::from_fn(ni, ni, |i, j| {
        let row = interior[i];
        let mut v = l[(row, interior[j])];
        for (b, &col) in unknowns_b.iter().enumerate() {
            v += l[(row, col)] * p[(b, j)];
        }
        v
    });
    let c1 = Mat::<f64>::from_fn(ni, ni, |i, j| coriolis[(interior[i], interior[j])]);
    // Companion E (y, ωy) = ω (y, ωy): E = [[0, I], [−L̃, −C]]; shift-invert about s.
    let shift = -0.3;
    let e_shifted = Mat::<f64>::from_fn(2 * ni, 2 * ni, |i, j| {
        let e = match (i < ni, j < ni) {
            (true, true) => 0.0,
            (true, false) => f64::from(u8::from(i == j - ni)),
            (false, true) => -reduced[(i - ni, j)],
            (false, false) => -c1[(i - ni, j - ni)],
        };
        e - if i == j { shift } else { 0.0 }
    });
    let inverse = e_shifted
        .partial_piv_lu()
        .solve(Mat::<f64>::identity(2 * ni, 2 * ni));
    inverse
        .eigenvalues()
        .expect("eigenvalues of a finite matrix")
        .into_iter()
        .map(|z| {
            let w = 1.0 / faer::c64::new(z.re, z.im);
            ((shift + w.re) * w_unit, w.im * w_unit)
        })
        .collect()
}
