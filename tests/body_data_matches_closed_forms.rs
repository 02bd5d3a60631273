//! The body data of eq. (11) against closed forms and against direct
//! quadrature of the displacement field (13) over the plate.

use annular_plate::config::{Boundary, PlateConfig};
use annular_plate::model::{AngularShape, PlateModel};
use std::f64::consts::PI;

fn plate(inner: Boundary, outer: Boundary) -> PlateConfig {
    let mut c = PlateConfig::lathe_disc();
    c.inner_boundary = inner;
    c.outer_boundary = outer;
    c.nodal_diameters = vec![0, 1, 2, 3];
    c.nodal_circles = vec![0, 1];
    c
}

/// ∫∫ f(r, φ) r dr dφ over the annulus by tensor Gauss–Legendre (radial, 40 points
/// per 20 cells) × trapezoid in φ (exact for trigonometric polynomials).
fn integrate(c: &PlateConfig, f: impl Fn(f64, f64) -> f64) -> f64 {
    let gl = [
        (-0.861_136_311_594_052_6, 0.347_854_845_137_453_9),
        (-0.339_981_043_584_856_3, 0.652_145_154_862_546_1),
        (0.339_981_043_584_856_3, 0.652_145_154_862_546_1),
        (0.861_136_311_594_052_6, 0.347_854_845_137_453_9),
    ];
    let cells = 60;
    let n_phi = 64;
    let (a, b) = (c.inner_radius, c.outer_radius);
    let mut sum = 0.0;
    for cell in 0..cells {
        let lo = a + (b - a) * cell as f64 / cells as f64;
        let hi = a + (b - a) * (cell + 1) as f64 / cells as f64;
        for (x, w) in gl {
            let r = 0.5 * (lo + hi) + 0.5 * (hi - lo) * x;
            let wr = 0.5 * (hi - lo) * w;
            for j in 0..n_phi {
                let phi = 2.0 * PI * j as f64 / n_phi as f64;
                sum += wr * r * f(r, phi) * 2.0 * PI / n_phi as f64;
            }
        }
    }
    sum
}

#[test]
fn mass_and_inertia_match_the_annulus_closed_form() {
    let c = plate(Boundary::Clamped, Boundary::Free);
    let m = PlateModel::new(&c).unwrap();
    let b = m.body();
    let (ri, ra, h, rho) = (c.inner_radius, c.outer_radius, c.thickness, c.density);
    let mass = rho * PI * (ra * ra - ri * ri) * h;
    assert!((b.mass - mass).abs() < 1e-14 * mass);
    // Solid annulus: I_zz = m (r_a² + r_i²)/2, I_xx = I_yy = m (3(r_a² + r_i²) + h²)/12.
    let izz = 0.5 * mass * (ra * ra + ri * ri);
    let ixx = mass * (3.0 * (ra * ra + ri * ri) + h * h) / 12.0;
    let j = b.inertia;
    assert!((j[2][2] - izz).abs() < 1e-14 * izz);
    assert!((j[0][0] - ixx).abs() < 1e-14 * ixx && (j[1][1] - ixx).abs() < 1e-14 * ixx);
    for (r, row) in j.iter().enumerate() {
        for (s, v) in row.iter().enumerate() {
            if r != s {
                assert_eq!(*v, 0.0);
            }
        }
    }
    // … and the same by quadrature of ρh (x² + y²) over the mid-plane.
    let q = integrate(&c, |r, _| rho * h * r * r);
    assert!((q - izz).abs() < 1e-12 * izz);
}

#[test]
fn coupling_terms_are_non_zero_only_for_their_nodal_diameters_and_match_quadrature() {
    for (inner, outer) in [
        (Boundary::Clamped, Boundary::Free),
        (Boundary::Supported, Boundary::Free),
        (Boundary::Free, Boundary::Clamped),
    ] {
        let c = plate(inner, outer);
        let model = PlateModel::new(&c).unwrap();
        let b = model.body();
        let rho_h = c.density * c.thickness;
        for (i, mode) in model.modes().iter().enumerate() {
            let ct = b.translational_coupling(i);
            let cr = b.rotational_coupling(i);
            // Independent: ∫ ρh w_i dA and ∫ ρh (c × w_i e_z) dA = ρh ∫ (y w, −x w, 0) dA.
            let s = |f: &dyn Fn(f64, f64) -> f64| {
                integrate(&c, |r, phi| {
                    rho_h * model.mode_shape(i, r, phi).w * f(r, phi)
                })
            };
            let qt = s(&|_, _| 1.0);
            let qx = s(&|r, phi| r * phi.cos());
            let qy = s(&|r, phi| r * phi.sin());
            let scale = mode.modal_mass / c.outer_radius.min(1.0);
            assert!(
                (ct[2] - qt).abs() < 1e-9 * scale,
                "C_t mode {i}: {} vs {qt}",
                ct[2]
            );
            assert!(
                (cr[0] - qy).abs() < 1e-9 * scale && (cr[1] + qx).abs() < 1e-9 * scale,
                "C_r mode {i}"
            );
            assert_eq!(ct[0], 0.0);
            assert_eq!(ct[1], 0.0);
            assert_eq!(cr[2], 0.0);
            match mode.k {
                0 => {
                    assert!(
                        ct[2].abs() > 1e-3 * mode.modal_mass,
                        "k = 0 mode {i} must couple to translation"
                    );
                    assert_eq!(cr, [0.0; 3]);
                }
                1 => {
                    assert_eq!(ct[2], 0.0);
                    let expected_axis = if mode.shape == AngularShape::Cos {
                        1
                    } else {
                        0
                    };
                    assert!(
                        cr[expected_axis].abs() > 1e-3 * mode.modal_mass * c.inner_radius,
                        "k = 1 mode {i} must couple to rotation"
                    );
                }
                _ => {
                    assert_eq!(ct, [0.0; 3]);
                    assert_eq!(cr, [0.0; 3]);
                }
            }
        }
    }
}

#[test]
fn modal_mass_and_stiffness_match_quadrature_of_the_energies() {
    let c = plate(Boundary::Clamped, Boundary::Free);
    let model = PlateModel::new(&c).unwrap();
    let rho_h = c.density * c.thickness;
    for (i, mode) in model.modes().iter().enumerate() {
        let mm = integrate(&c, |r, phi| rho_h * model.mode_shape(i, r, phi).w.powi(2));
        assert!(
            (mm - mode.modal_mass).abs() < 1e-9 * mm,
            "modal mass {i}: {mm} vs {}",
            mode.modal_mass
        );
        assert!(
            (model.body().modal_stiffness[i] - mode.modal_mass * mode.omega.powi(2)).abs()
                < 1e-12 * model.body().modal_stiffness[i]
        );
        // Mass-orthogonality of distinct modes.
        for j in 0..i {
            let mij = integrate(&c, |r, phi| {
                rho_h * model.mode_shape(i, r, phi).w * model.mode_shape(j, r, phi).w
            });
            assert!(
                mij.abs() < 1e-9 * mode.modal_mass,
                "modes {i} and {j} not M-orthogonal: {mij}"
            );
        }
    }
}

#[test]
fn first_order_inertia_and_centre_of_mass_follow_the_deformed_mass_distribution() {
    let c = plate(Boundary::Supported, Boundary::Free);
    let model = PlateModel::new(&c).unwrap();
    let b = model.body();
    let rho_h = c.density * c.thickness;
    let n = model.n_modes();
    let q: Vec<f64> = (0..n).map(|i| 1e-5 * ((i as f64 * 1.7).sin())).collect();
    let w = |r: f64, phi: f64| model.deflection(&q, r, phi).w;
    // d_CM,z = ∫ ρh w dA / m; J_xz = −∫ ρh x w dA (first order, mid-plane).
    let zc = integrate(&c, |r, phi| rho_h * w(r, phi)) / b.mass;
    let jxz = -integrate(&c, |r, phi| rho_h * r * phi.cos() * w(r, phi));
    let jyz = -integrate(&c, |r, phi| rho_h * r * phi.sin() * w(r, phi));
    let d = b.center_of_mass(&q);
    let j = b.inertia_at(&q);
    assert!((d[2] - zc).abs() < 1e-9 * zc.abs().max(1e-12));
    assert!((j[0][2] - jxz).abs() < 1e-9 * jxz.abs() && (j[2][0] - jxz).abs() < 1e-9 * jxz.abs());
    assert!((j[1][2] - jyz).abs() < 1e-9 * jyz.abs());
    assert_eq!(j[0][0], b.inertia[0][0]);
}

#[test]
fn shape_derivatives_and_the_displacement_field_are_consistent() {
    let c = plate(Boundary::Clamped, Boundary::Free);
    let model = PlateModel::new(&c).unwrap();
    let n = model.n_modes();
    let q: Vec<f64> = (0..n).map(|i| 1e-4 / (1.0 + i as f64)).collect();
    let (r, phi, eps) = (0.11, 0.7, 1e-6);
    let s = model.deflection(&q, r, phi);
    let wr =
        (model.deflection(&q, r + eps, phi).w - model.deflection(&q, r - eps, phi).w) / (2.0 * eps);
    let wp =
        (model.deflection(&q, r, phi + eps).w - model.deflection(&q, r, phi - eps).w) / (2.0 * eps);
    assert!((s.w_r - wr).abs() < 1e-6 * s.w_r.abs().max(1e-6));
    assert!((s.w_phi - wp).abs() < 1e-6 * s.w_phi.abs().max(1e-6));
    // Eq. (13): a fibre at height z rotates with the slope: u = −z ∇w, u_z = w.
    let z = 0.004;
    let u = model.displacement(&q, r, phi, z);
    let (x, y) = (r * phi.cos(), r * phi.sin());
    let at = |x: f64, y: f64| model.deflection(&q, x.hypot(y), y.atan2(x)).w;
    let wx = (at(x + eps, y) - at(x - eps, y)) / (2.0 * eps);
    let wy = (at(x, y + eps) - at(x, y - eps)) / (2.0 * eps);
    assert!((u[0] + z * wx).abs() < 1e-6 * (z * wx).abs());
    assert!((u[1] + z * wy).abs() < 1e-6 * (z * wy).abs());
    assert_eq!(u[2], s.w);
}

#[test]
fn free_free_rigid_body_modes_are_skipped_and_listed() {
    let mut c = plate(Boundary::Free, Boundary::Free);
    c.nodal_diameters = vec![0, 1, 2];
    c.nodal_circles = vec![0, 1];
    let model = PlateModel::new(&c).unwrap();
    assert_eq!(model.skipped_rigid_body_modes(), &[(0, 0), (1, 0)]);
    assert_eq!(model.n_modes(), c.mode_count());
    assert_eq!(model.n_modes(), 2 + 1 + 2 + 2); // ⟨2,0⟩ pair, ⟨0,1⟩, ⟨1,1⟩ pair, ⟨2,1⟩ pair
    assert!(model.modes().iter().all(|m| m.frequency_hz > 100.0));
}
