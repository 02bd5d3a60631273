//! Calipers as users have them (`calipers.*`, docs/scenes.md "Calipers"):
//! each caliper is one pad per face covering an annular sector — inner and
//! outer radius, angular extent `calipers.arc_deg` about its centre angle —
//! discretised into `points_radial × points_circumferential` contact points.
//! The points become space-fixed ALE nodes appended after `nodes.ale_*` and
//! the contacts of pad p (caliper p, numbered from 1); the `pads.*` keys
//! (clamp force, contact stiffness per point, caliper kind, friction) apply.
//!
//! Uniform pressure: the pads share the clamp force equally among their
//! contacts (`pad.rs`), so each point stands for an equal area.
//! The sector is cut into `points_radial` rings of equal area,
//! ρ_j² = r_in² + j (r_out² − r_in²)/n_r, and each ring's point sits at its
//! mean friction radius (2/3)(ρ_{j+1}³ − ρ_j³)/(ρ_{j+1}² − ρ_j²), so the
//! friction torque of the points is that of the uniform pressure exactly:
//! μ N₀ (2/3)(r_out³ − r_in³)/(r_out² − r_in²) per face. Circumferentially the
//! points sit at the centres of `points_circumferential` equal sub-arcs.

use crate::config::model_sections::no_other_keys;
use crate::config::{ConfigError, NodePosition, NodesConfig, PlateConfig, Reader};
use serde::Serialize;

/// One pad contact point: an ALE node with a pad on each face of the disc.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PadContact {
    /// ALE node, 0-based (`pads.ale_nodes` counts from 1).
    pub node: usize,
    /// Pad it belongs to, 0-based (`pads.contact_pad` counts from 1).
    pub pad: usize,
}

/// Largest number of contact points of all calipers together.
const MAX_CALIPER_POINTS: i64 = 400;

fn rule(key: &str, value: f64, rule: String) -> ConfigError {
    ConfigError::CaliperRule {
        key: key.to_string(),
        value,
        rule,
    }
}

/// The radii (m) of `n` equal-area rings' mean friction radii between `inner` and `outer`.
pub fn ring_radii(inner: f64, outer: f64, n: usize) -> Vec<f64> {
    let area = (outer * outer - inner * inner) / n as f64;
    (0..n)
        .map(|j| {
            let a = (inner * inner + j as f64 * area).sqrt();
            let b = if j + 1 == n {
                outer
            } else {
                (inner * inner + (j + 1) as f64 * area).sqrt()
            };
            2.0 / 3.0 * (b * b * b - a * a * a) / (b * b - a * a)
        })
        .collect()
}

/// Reads `calipers.*`; if given, appends the contact points to `nodes.ale`
/// and returns the pads' contacts (pad p = caliper p).
pub(super) fn read_calipers(
    r: &Reader,
    plate: &PlateConfig,
    nodes: &mut NodesConfig,
) -> Result<Option<Vec<PadContact>>, ConfigError> {
    let angles = r.f64_array("calipers.angles_deg")?;
    if angles.is_empty() {
        no_other_keys(r, "calipers", "calipers.angles_deg")?;
        return Ok(None);
    }
    if r.has("pads.ale_nodes") || r.has("pads.contact_pad") {
        let key = if r.has("pads.ale_nodes") {
            "pads.ale_nodes"
        } else {
            "pads.contact_pad"
        };
        return Err(ConfigError::CaliperRule {
            key: key.into(),
            value: angles.len() as f64,
            rule: "with calipers.angles_deg the calipers make the contact points; give either calipers.* or pads.ale_nodes".into(),
        });
    }
    let count = angles.len();
    let arc = r.f64("calipers.arc_deg")?;
    if !(arc > 0.0 && arc * count as f64 <= 360.0) {
        return Err(rule(
            "calipers.arc_deg",
            arc,
            format!("must be > 0 and the {count} calipers' arcs must not overlap: ≤ 360°/{count}"),
        ));
    }
    for (index, &a) in angles.iter().enumerate() {
        if a.abs() > 360.0 {
            return Err(rule(
                &format!("calipers.angles_deg[{index}]"),
                a,
                "must lie in [−360°, 360°]".into(),
            ));
        }
    }
    let (ri, ra) = (plate.inner_radius, plate.outer_radius);
    let inner = r
        .f64_opt("calipers.inner_radius")?
        .ok_or(ConfigError::CaliperKeyMissing {
            key: "calipers.inner_radius",
        })?;
    let outer = r
        .f64_opt("calipers.outer_radius")?
        .ok_or(ConfigError::CaliperKeyMissing {
            key: "calipers.outer_radius",
        })?;
    if !(inner >= ri && inner < ra) {
        return Err(rule("calipers.inner_radius", inner, format!("must lie on the disc: plate.inner_radius ≤ r < plate.outer_radius = [{ri}, {ra}) m")));
    }
    if !(outer > inner && outer <= ra) {
        return Err(rule("calipers.outer_radius", outer, format!("must lie above calipers.inner_radius = {inner} m and at most plate.outer_radius = {ra} m")));
    }
    let nr = r.i64("calipers.points_radial")?;
    let nc = r.i64("calipers.points_circumferential")?;
    for (key, n) in [
        ("calipers.points_radial", nr),
        ("calipers.points_circumferential", nc),
    ] {
        if n < 1 {
            return Err(rule(key, n as f64, "must be ≥ 1".into()));
        }
    }
    if nr * nc * count as i64 > MAX_CALIPER_POINTS {
        return Err(rule(
            "calipers.points_circumferential",
            nc as f64,
            format!(
                "points_radial × points_circumferential × calipers must be ≤ {MAX_CALIPER_POINTS}"
            ),
        ));
    }
    let radii = ring_radii(inner, outer, nr as usize);
    let mut contacts = Vec::with_capacity((nr * nc) as usize * count);
    for (pad, &centre) in angles.iter().enumerate() {
        for c in 0..nc {
            let deg = centre + arc * ((c as f64 + 0.5) / nc as f64 - 0.5);
            let turns = (deg / 360.0).rem_euclid(1.0);
            for &radius in &radii {
                contacts.push(PadContact {
                    node: nodes.ale.len(),
                    pad,
                });
                nodes.ale.push(NodePosition {
                    radial: (radius - ri) / (ra - ri),
                    angular: turns,
                });
            }
        }
    }
    Ok(Some(contacts))
}
