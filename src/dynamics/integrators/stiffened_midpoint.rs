//! The implicit midpoint rule with centrifugal stiffening: Ω²G_k couples the
//! retained l of one k, so the 2×2 (per mode) and 4×4 (per ALE pair) solves
//! of [`implicit_midpoint`](super::implicit_midpoint) become one solve per k:
//! (I − h/2 A) y₁ = (I + h/2 A) y₀ + h g with y the amplitudes and rates of
//! the k's modes (cos and sin families) and A the modal ODE of
//! [`equations`](super::equations) at the midpoint speed plus −Ω_mid² M⁻¹G_k.
//! Same method, same order and A-stability as without stiffening. Dense LU
//! with partial pivoting ([`dense`](crate::dynamics::dense)) on scratch sized once.

use super::equations::{pair_force, ModalEquations, ReferenceMotion};
use crate::config::Coordinates;
use crate::dynamics::dense::{lu_factor, lu_solve};
use crate::dynamics::loads::StepLoads;
use crate::dynamics::scene::ModePair;
use crate::dynamics::stiffening::Stiffening;

/// Scratch for the largest block: no allocation per step.
#[derive(Debug, Clone, Default)]
pub struct StiffenedMidpoint {
    a: Vec<f64>,
    lhs: Vec<f64>,
    rhs: Vec<f64>,
    y: Vec<f64>,
    /// Row permutation and substitution scratch of the LU solve.
    perm: Vec<usize>,
    buf: Vec<f64>,
}

impl StiffenedMidpoint {
    pub fn new(stiffening: Option<&Stiffening>) -> StiffenedMidpoint {
        let d = stiffening.map_or(0, |s| {
            s.blocks.iter().map(|b| 4 * b.len()).max().unwrap_or(0)
        });
        StiffenedMidpoint {
            a: vec![0.0; d * d],
            lhs: vec![0.0; d * d],
            rhs: vec![0.0; d],
            y: vec![0.0; d],
            perm: vec![0; d],
            buf: vec![0.0; d],
        }
    }

    /// Advance (q, v) in place over h; arguments as
    /// [`implicit_midpoint::advance`](super::implicit_midpoint::advance),
    /// the blocks those of the scene's stiffening (a scene without it is
    /// stepped by that function).
    pub fn advance(
        &mut self,
        equations: ModalEquations<'_>,
        h: f64,
        mid: ReferenceMotion<'_>,
        loads: &StepLoads,
        q: &mut [f64],
        v: &mut [f64],
    ) {
        let Some(stiffening) = &equations.scene.stiffening else {
            return super::implicit_midpoint::advance(equations, h, mid, loads, q, v);
        };
        let ModalEquations { consts, coords, .. } = equations;
        let ReferenceMotion {
            harmonics: harm_mid,
            speed: speed_mid,
            accel,
        } = mid;
        let (ale_frame, plate_frame) = (&loads.ale_frame[..], &loads.plate_frame[..]);
        let speed_sq = speed_mid * speed_mid;
        for b in &stiffening.blocks {
            let n = b.len();
            let families = if b.k == 0 { 1 } else { 2 };
            let m = families * n; // modes in this block
            let d = 2 * m;
            // Local index of mode (family f, l a): f·n + a; rates at m + that.
            let index = |f: usize, a: usize| if f == 0 { b.cos[a] } else { b.sin[a] };
            let a = &mut self.a[..d * d];
            a.fill(0.0);
            let g = &mut self.rhs[..d];
            g.fill(0.0);
            for f in 0..families {
                for r in 0..n {
                    let row = m + f * n + r;
                    // In ALE coordinates a pair takes its cos mode's constants, as in implicit_midpoint.rs.
                    let c = if coords == Coordinates::Ale {
                        consts[b.cos[r]]
                    } else {
                        consts[index(f, r)]
                    };
                    a[(f * n + r) * d + row] = 1.0;
                    a[row * d + f * n + r] -= c.omega_eff_sq;
                    a[row * d + row] -= c.damping_rate;
                    for col in 0..n {
                        a[row * d + f * n + col] -= speed_sq * b.g_over_m[r * n + col];
                    }
                }
            }
            if b.k == 0 {
                for r in 0..n {
                    g[m + r] = ale_frame[b.cos[r]] / consts[b.cos[r]].mass;
                }
            } else {
                for r in 0..n {
                    let p = ModePair {
                        k: b.k,
                        cos: b.cos[r],
                        sin: b.sin[r],
                    };
                    let c = consts[p.cos];
                    let (fc, fs) =
                        pair_force(coords, harm_mid[p.k as usize], &p, ale_frame, plate_frame);
                    let (rc, rs) = (m + r, m + n + r);
                    g[rc] = fc / c.mass;
                    g[rs] = fs / c.mass;
                    if coords == Coordinates::Ale {
                        // The pair's ALE terms (equations.rs): acc_c += 2kΩ(−v_s) + skew(−q_s) + k²Ω² q_c, acc_s likewise.
                        let kw = p.k as f64 * speed_mid;
                        let skew = p.k as f64 * accel + c.damping_rate * kw;
                        let (qc, qs) = (r, n + r);
                        a[rc * d + qc] += kw * kw;
                        a[rs * d + qs] += kw * kw;
                        a[rc * d + rs] -= 2.0 * kw;
                        a[rs * d + rc] += 2.0 * kw;
                        a[rc * d + qs] -= skew;
                        a[rs * d + qc] += skew;
                    }
                }
            }
            let hh = 0.5 * h;
            for f in 0..families {
                for r in 0..n {
                    let i = index(f, r);
                    self.y[f * n + r] = q[i];
                    self.y[m + f * n + r] = v[i];
                }
            }
            let lhs = &mut self.lhs[..d * d];
            for i in 0..d {
                let ay: f64 = (0..d).map(|j| a[i * d + j] * self.y[j]).sum();
                g[i] = self.y[i] + hh * ay + h * g[i];
                for j in 0..d {
                    lhs[i * d + j] = if i == j { 1.0 } else { 0.0 } - hh * a[i * d + j];
                }
            }
            // A singular matrix gives NaN (caught by the step check).
            match lu_factor(lhs, &mut self.perm[..d], d) {
                Ok(()) => lu_solve(lhs, &self.perm[..d], g, &mut self.buf[..d], d),
                Err(_) => g.fill(f64::NAN),
            }
            for f in 0..families {
                for r in 0..n {
                    let i = index(f, r);
                    q[i] = g[f * n + r];
                    v[i] = g[m + f * n + r];
                }
            }
        }
    }
}
