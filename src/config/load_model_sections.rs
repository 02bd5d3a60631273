//! The load models' sections (`pads.*`, `tool.*`, `links.*`, `springs.*`):
//! each is off unless its enabling key names nodes, and then its keys are
//! read and checked as [`super::table`] states the rules. Called from
//! `config_from_params` in `validate.rs`.

use super::raw::{read_choice, Reader};
use super::{
    Caliper, ConfigError, ContactSurface, LimitsConfig, LinksConfig, NodesConfig, PadContact,
    PadsConfig, PlateConfig, SpringsConfig, ToolConfig, MAX_TOOL_FEED_RATE,
};

const CALIPERS: &[&str] = &["floating", "fixed"];
const CONTACT_SURFACES: &[&str] = &["faces", "mid_plane"];

/// Largest plausible friction coefficient.
const MAX_FRICTION_COEFFICIENT: f64 = 2.0;

/// A load model whose enabling key is empty must not be given other keys.
pub(super) fn no_other_keys(
    r: &Reader,
    table: &[&str],
    enabling_key: &'static str,
) -> Result<(), ConfigError> {
    match table.iter().find(|k| **k != enabling_key && r.has(k)) {
        Some(key) => Err(ConfigError::KeyWithoutSection {
            key: key.to_string(),
            enabling_key,
        }),
        None => Ok(()),
    }
}

/// Node numbers (from 1) of existing, distinct nodes of one kind → 0-based indices.
fn node_refs(
    key: &str,
    values: &[i64],
    kind: &'static str,
    count: usize,
) -> Result<Vec<usize>, ConfigError> {
    let mut out: Vec<usize> = Vec::with_capacity(values.len());
    for (index, &v) in values.iter().enumerate() {
        if v < 1 {
            return Err(ConfigError::NotPositive {
                key: format!("{key}[{index}]"),
                value: v as f64,
            });
        }
        if v as usize > count {
            return Err(ConfigError::NoSuchNode {
                key: format!("{key}[{index}]"),
                node: v,
                kind,
                count,
            });
        }
        if out.contains(&(v as usize - 1)) {
            return Err(ConfigError::Duplicate {
                key: key.to_string(),
                value: v,
            });
        }
        out.push(v as usize - 1);
    }
    Ok(out)
}

fn non_negative(key: &str, x: f64) -> Result<f64, ConfigError> {
    if x < 0.0 {
        Err(ConfigError::Negative {
            key: key.to_string(),
            value: x,
        })
    } else {
        Ok(x)
    }
}

pub(super) fn at_most(key: &str, x: f64, max: f64) -> Result<f64, ConfigError> {
    if x.abs() > max {
        Err(ConfigError::AboveMaximum {
            key: key.to_string(),
            value: x,
            max,
        })
    } else {
        Ok(x)
    }
}

/// `from_calipers`: the contacts the `calipers.*` keys made, which
/// enable the pads in place of `pads.ale_nodes`.
pub(super) fn read_pads(
    r: &Reader,
    nodes: &NodesConfig,
    limits: &LimitsConfig,
    from_calipers: Option<Vec<PadContact>>,
) -> Result<Option<PadsConfig>, ConfigError> {
    let contacts = match from_calipers {
        Some(contacts) => contacts,
        None => match read_pad_contacts(r, nodes)? {
            Some(contacts) => contacts,
            None => return Ok(None),
        },
    };
    let pads = contacts.iter().map(|c| c.pad + 1).max().unwrap_or(1);
    read_pad_data(r, limits, contacts, pads)
}

/// The contacts of `pads.ale_nodes` and `pads.contact_pad`; `None` (and no
/// other `pads.*` key) when not given.
fn read_pad_contacts(
    r: &Reader,
    nodes: &NodesConfig,
) -> Result<Option<Vec<PadContact>>, ConfigError> {
    let numbers = r.i64_array("pads.ale_nodes")?;
    if numbers.is_empty() {
        no_other_keys(r, &super::table::keys("pads"), "pads.ale_nodes")?;
        return Ok(None);
    }
    let node_index = node_refs("pads.ale_nodes", &numbers, "ale", nodes.ale.len())?;
    let pad_numbers = r.i64_array("pads.contact_pad")?;
    let pad_numbers = if pad_numbers.is_empty() {
        vec![1; node_index.len()]
    } else {
        pad_numbers
    };
    if pad_numbers.len() != node_index.len() {
        return Err(ConfigError::LengthMismatch {
            key_a: "pads.contact_pad".into(),
            len_a: pad_numbers.len(),
            key_b: "pads.ale_nodes".into(),
            len_b: node_index.len(),
        });
    }
    for (index, &p) in pad_numbers.iter().enumerate() {
        if p < 1 {
            return Err(ConfigError::NotPositive {
                key: format!("pads.contact_pad[{index}]"),
                value: p as f64,
            });
        }
    }
    let contacts: Vec<PadContact> = node_index
        .iter()
        .zip(&pad_numbers)
        .map(|(&node, &p)| PadContact {
            node,
            pad: p as usize - 1,
        })
        .collect();
    let pads = pad_numbers.iter().copied().max().unwrap_or(1) as usize;
    if let Some(pad) = (0..pads).find(|p| !contacts.iter().any(|c| c.pad == *p)) {
        return Err(ConfigError::PadWithoutContacts { pad: pad + 1, pads });
    }
    Ok(Some(contacts))
}

/// The pads' data keys for `contacts` in `pads` pads.
fn read_pad_data(
    r: &Reader,
    limits: &LimitsConfig,
    contacts: Vec<PadContact>,
    pads: usize,
) -> Result<Option<PadsConfig>, ConfigError> {
    let clamp = r.f64_array("pads.clamp_force")?;
    for (index, &f) in clamp.iter().enumerate() {
        let key = format!("pads.clamp_force[{index}]");
        non_negative(&key, f)?;
        at_most(&key, f, limits.max_force)?;
    }
    let clamp_force = match clamp.len() {
        1 => vec![clamp[0]; pads],
        n if n == pads => clamp,
        len => return Err(ConfigError::ClampForceLength { len, pads }),
    };
    let contact_stiffness = r.positive("pads.contact_stiffness")?;
    let contact_damping = non_negative("pads.contact_damping", r.f64("pads.contact_damping")?)?;
    let mu = r.f64("pads.friction_coefficient")?;
    let friction_coefficient = at_most(
        "pads.friction_coefficient",
        non_negative("pads.friction_coefficient", mu)?,
        MAX_FRICTION_COEFFICIENT,
    )?;
    let contact_surface = read_choice(r, "pads.contact_surface", CONTACT_SURFACES, |s| match s {
        "faces" => Some(ContactSurface::Faces),
        "mid_plane" => Some(ContactSurface::MidPlane),
        _ => None,
    })?;
    let static_friction_coefficient = match r.f64_opt("pads.static_friction_coefficient")? {
        None => None,
        Some(_) if contact_surface == ContactSurface::MidPlane => {
            return Err(ConfigError::StaticFrictionNeedsFaces)
        }
        Some(x) => Some(at_most(
            "pads.static_friction_coefficient",
            non_negative("pads.static_friction_coefficient", x)?,
            MAX_FRICTION_COEFFICIENT,
        )?),
    };
    let caliper = read_choice(r, "pads.caliper", CALIPERS, |s| match s {
        "floating" => Some(Caliper::Floating),
        "fixed" => Some(Caliper::Fixed),
        _ => None,
    })?;
    let (mass, backing_stiffness) = read_pad_mass(r, caliper)?;
    Ok(Some(PadsConfig {
        contacts,
        clamp_force,
        contact_stiffness,
        contact_damping,
        friction_coefficient,
        lift_off: r.bool("pads.lift_off")?,
        follower_friction: r.bool("pads.follower_friction")?,
        caliper,
        contact_surface,
        static_friction_coefficient,
        stribeck_speed: r.positive("pads.stribeck_speed")?,
        mass,
        backing_stiffness,
    }))
}

/// `pads.mass` (≥ 0) and `pads.backing_stiffness` (> 0; given exactly when
/// the pads have mass and the caliper is fixed).
fn read_pad_mass(r: &Reader, caliper: Caliper) -> Result<(f64, Option<f64>), ConfigError> {
    let mass = non_negative("pads.mass", r.f64("pads.mass")?)?;
    let backing = match r.f64_opt("pads.backing_stiffness")? {
        Some(k) => Some(super::raw::positive("pads.backing_stiffness", k)?),
        None => None,
    };
    match (mass > 0.0, caliper, backing) {
        (true, Caliper::Fixed, None) => Err(ConfigError::PadMass { rule: "pads.backing_stiffness must be given with pads.mass > 0 and pads.caliper: fixed (the stiffness that holds each pad to the caliper)" }),
        (true, Caliper::Floating, Some(_)) => Err(ConfigError::PadMass { rule: "pads.backing_stiffness applies to pads.caliper: fixed only (a floating caliper presses each pad with the clamp force)" }),
        (false, _, Some(_)) => Err(ConfigError::PadMass { rule: "pads.backing_stiffness needs pads.mass > 0 (massless pads have no backing spring)" }),
        _ => Ok((mass, backing)),
    }
}

pub(super) fn read_tool(
    r: &Reader,
    plate: &PlateConfig,
    nodes: &NodesConfig,
) -> Result<Option<ToolConfig>, ConfigError> {
    let number = r.i64("tool.ale_node")?;
    if number == 0 {
        no_other_keys(r, &super::table::keys("tool"), "tool.ale_node")?;
        return Ok(None);
    }
    let node =
        node_refs("tool.ale_node", &[number], "ale", nodes.ale.len()).map_err(|e| match e {
            ConfigError::NotPositive { value, .. } => ConfigError::Negative {
                key: "tool.ale_node".into(),
                value,
            },
            ConfigError::NoSuchNode {
                node, kind, count, ..
            } => ConfigError::NoSuchNode {
                key: "tool.ale_node".into(),
                node,
                kind,
                count,
            },
            other => other,
        })?[0];
    let radial = nodes.ale[node].radial;
    if (radial - 1.0).abs() > 1e-12 {
        return Err(ConfigError::ToolNotOnRim {
            node: node + 1,
            radial,
        });
    }
    let depth_of_cut = r.positive("tool.depth_of_cut")?;
    let width = plate.outer_radius - plate.inner_radius;
    if depth_of_cut >= width {
        return Err(ConfigError::DepthOfCutBeyondPlate {
            depth: depth_of_cut,
            width,
        });
    }
    let feed_rate = at_most(
        "tool.feed_rate",
        r.f64("tool.feed_rate")?,
        MAX_TOOL_FEED_RATE,
    )?;
    let start_clearance = non_negative("tool.start_clearance", r.f64("tool.start_clearance")?)?;
    let stiffness = r.positive("tool.stiffness")?;
    let damping = non_negative("tool.damping", r.f64("tool.damping")?)?;
    let specific_force = r.positive("tool.specific_force")?;
    let force_exponent = non_negative("tool.force_exponent", r.f64("tool.force_exponent")?)?;
    if force_exponent >= 1.0 {
        return Err(ConfigError::AboveMaximum {
            key: "tool.force_exponent".into(),
            value: force_exponent,
            max: 1.0,
        });
    }
    Ok(Some(ToolConfig {
        node,
        depth_of_cut,
        feed_rate,
        start_clearance,
        stiffness,
        damping,
        specific_force,
        force_exponent,
    }))
}

pub(super) fn read_links(
    r: &Reader,
    nodes: &NodesConfig,
    limits: &LimitsConfig,
) -> Result<Option<LinksConfig>, ConfigError> {
    let numbers = r.i64_array("links.lagrange_nodes")?;
    if numbers.is_empty() {
        no_other_keys(r, &super::table::keys("links"), "links.lagrange_nodes")?;
        return Ok(None);
    }
    let nodes = node_refs(
        "links.lagrange_nodes",
        &numbers,
        "lagrange",
        nodes.lagrange.len(),
    )?;
    let mean_force = at_most(
        "links.mean_force",
        r.f64("links.mean_force")?,
        limits.max_force,
    )?;
    let cyclic_force = at_most(
        "links.cyclic_force",
        r.f64("links.cyclic_force")?,
        limits.max_force,
    )?;
    let cyclic_phase = r.f64("links.cyclic_phase")?;
    Ok(Some(LinksConfig {
        nodes,
        mean_force,
        cyclic_force,
        cyclic_phase,
    }))
}

pub(super) fn read_springs(
    r: &Reader,
    nodes: &NodesConfig,
) -> Result<Option<SpringsConfig>, ConfigError> {
    let numbers = r.i64_array("springs.ale_nodes")?;
    if numbers.is_empty() {
        no_other_keys(r, &super::table::keys("springs"), "springs.ale_nodes")?;
        return Ok(None);
    }
    let nodes = node_refs("springs.ale_nodes", &numbers, "ale", nodes.ale.len())?;
    let stiffness = non_negative("springs.stiffness", r.f64("springs.stiffness")?)?;
    let damping = non_negative("springs.damping", r.f64("springs.damping")?)?;
    Ok(Some(SpringsConfig {
        nodes,
        stiffness,
        damping,
    }))
}
