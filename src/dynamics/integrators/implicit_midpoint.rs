//! Implicit midpoint rule for the affine modal ODE ẏ = A(t) y + g(t):
//! (I − h/2 A(t_m)) y₁ = (I + h/2 A(t_m)) y₀ + h g(t_m), solved per mode
//! (Lagrangian, 2×2) or per pair (ALE, 4×4, coupled by the gyroscopic terms).
//! Node loads that depend on the state (followers) are taken at the step start.

use super::equations::{pair_force, ModalEquations, ModeConstants, ReferenceMotion};
use crate::config::Coordinates;
use crate::dynamics::loads::StepLoads;
use nalgebra::{Matrix4, Vector4};

/// Advance (q, v) in place over h, the loads held. `mid` is the reference
/// motion at the step's midpoint (its harmonics of χ and speed Ω there, the
/// joint's α).
pub fn advance(
    equations: ModalEquations<'_>,
    h: f64,
    mid: ReferenceMotion<'_>,
    loads: &StepLoads,
    q: &mut [f64],
    v: &mut [f64],
) {
    let ModalEquations {
        scene,
        consts,
        coords,
    } = equations;
    let ReferenceMotion {
        harmonics: harm_mid,
        speed: speed_mid,
        accel,
    } = mid;
    let (ale_frame, plate_frame) = (&loads.ale_frame[..], &loads.plate_frame[..]);
    let hh = 0.5 * h;
    let single = |c: ModeConstants, f: f64, q: &mut f64, v: &mut f64| {
        // A = [[0, 1], [−w², −c]]; solve (I − hh A) y1 = (I + hh A) y0 + h (0, f/m).
        let (w2, cd) = (c.omega_eff_sq, c.damping_rate);
        let r0 = *q + hh * *v;
        let r1 = *v + hh * (-w2 * *q - cd * *v) + h * f / c.mass;
        // [[1, −hh], [hh w2, 1 + hh c]]
        let det = (1.0 + hh * cd) + hh * hh * w2;
        let q1 = ((1.0 + hh * cd) * r0 + hh * r1) / det;
        let v1 = (r1 - hh * w2 * r0) / det;
        *q = q1;
        *v = v1;
    };
    for &i in &scene.layout.axisymmetric {
        single(consts[i], ale_frame[i], &mut q[i], &mut v[i]);
    }
    for p in &scene.layout.pairs {
        let (fc, fs) = pair_force(coords, harm_mid[p.k as usize], p, ale_frame, plate_frame);
        let (ic, is) = (p.cos, p.sin);
        let c = consts[ic];
        match coords {
            Coordinates::Lagrangian => {
                single(c, fc, &mut q[ic], &mut v[ic]);
                single(consts[is], fs, &mut q[is], &mut v[is]);
            }
            Coordinates::Ale => {
                let kw = p.k as f64 * speed_mid;
                let stiff = kw * kw - c.omega_eff_sq;
                let skew = p.k as f64 * accel + c.damping_rate * kw;
                let cd = c.damping_rate;
                // y = (q_c, q_s, v_c, v_s); v̇ = K q + C v + f/m.
                #[rustfmt::skip]
                let a = Matrix4::new(
                    0.0, 0.0, 1.0, 0.0,
                    0.0, 0.0, 0.0, 1.0,
                    stiff, -skew, -cd, -2.0 * kw,
                    skew, stiff, 2.0 * kw, -cd,
                );
                let y0 = Vector4::new(q[ic], q[is], v[ic], v[is]);
                let g = Vector4::new(0.0, 0.0, fc / c.mass, fs / c.mass);
                let lhs = Matrix4::identity() - a * hh;
                let rhs = y0 + a * y0 * hh + g * h;
                let y1 = lhs.lu().solve(&rhs).unwrap_or(Vector4::repeat(f64::NAN));
                q[ic] = y1[0];
                q[is] = y1[1];
                v[ic] = y1[2];
                v[is] = y1[3];
            }
        }
    }
}
