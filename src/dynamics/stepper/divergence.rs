//! The divergence guard: a step whose state is not finite or not plausible
//! is undone and reported.

use crate::dynamics::error::{Divergence, StepError};
use crate::dynamics::scene::Scene;
use crate::dynamics::state::State;

/// max |v| over finite values, in four independent lanes (no early exit).
fn largest_magnitude(values: &[f64]) -> f64 {
    let mut m = [0.0f64; 4];
    let chunks = values.chunks_exact(4);
    for &v in chunks.remainder() {
        m[0] = m[0].max(v.abs());
    }
    for c in chunks {
        for j in 0..4 {
            m[j] = m[j].max(c[j].abs());
        }
    }
    m[0].max(m[1]).max(m[2].max(m[3]))
}

/// Divergence guard: everything finite, amplitudes within the plausibility limit.
pub(super) fn check(scene: &Scene, state: &State) -> Result<(), StepError> {
    let diverged = |cause| {
        Err(StepError::Diverged {
            time: state.time,
            cause,
        })
    };
    if !state.is_finite_except_load_models()
        || !scene.load_models.state_is_finite(&state.load_models)
    {
        return diverged(Divergence::NonFinite);
    }
    let limit = scene.limits.max_deflection_thicknesses * scene.model.plate().thickness;
    // One vectorizable pass; the search for the culprit only when some amplitude is beyond the limit.
    if largest_magnitude(&state.q) > limit {
        let bending = &state.q[..scene.model.n_modes()];
        if let Some((i, &q)) = bending.iter().enumerate().find(|(_, q)| q.abs() > limit) {
            let m = &scene.model.modes()[i];
            return diverged(Divergence::ModeBeyondLimit {
                mode: i,
                k: m.k,
                l: m.l,
                shape: m.shape,
                value: q,
                limit,
            });
        }
        if let Some(ip) = &scene.in_plane {
            let in_plane = &state.q[ip.offset..];
            if let Some((j, &q)) = in_plane.iter().enumerate().find(|(_, q)| q.abs() > limit) {
                let m = &ip.modes[j];
                return diverged(Divergence::InPlaneModeBeyondLimit {
                    mode: ip.offset + j,
                    k: m.k,
                    l: m.l,
                    value: q,
                    limit,
                });
            }
        }
    }
    if let Some(ip) = &scene.in_plane {
        if state.speed.abs() > ip.speed_bound {
            return Err(StepError::InPlaneSpin {
                speed: state.speed,
                limit: ip.speed_bound,
            });
        }
    }
    if state.speed.abs() > scene.limits.max_speed * 1.5 {
        return diverged(Divergence::SpeedBeyondLimit {
            speed: state.speed,
            limit: scene.limits.max_speed,
        });
    }
    Ok(())
}
