//! From a flat [`Params`] set to the validated [`Config`].
//!
//! Every key this crate accepts is declared once ([`super::Parameters`]: the
//! configuration's sections in [`super::table`], the load models' in their
//! own files); any other key is rejected (with the nearest known key as a
//! suggestion). Each section has a `read_<section>` function that reads its
//! keys and checks the rules the declaration states (the plate's:
//! `plate_section.rs`); each load model's reader is called through its
//! declaration ([`super::ModelParameters::read`]).
//!
//! Adding a section of the configuration: declare its keys in the table,
//! write `read_<section>` and call it in [`config_from_params`] (plus the
//! field in [`Config`]); a load model's section needs none of this
//! (docs/architecture.md). docs/parameters.md is generated from the declarations.

use std::f64::consts::FRAC_PI_2;

use super::check::suggest;
use super::model_sections::{at_most, LoadModelSections, SectionContext};
use super::plate_section::read_plate;
use super::raw::{positive, read_choice, Reader};
use super::{
    Config, ConfigError, Coordinates, InitialConfig, IntegratorKind, JointConfig, LimitsConfig,
    LoadsConfig, NodePosition, NodesConfig, Parameters, Params, PlateConfig, ReferenceConfig,
    SimulationConfig, Surface, WrenchConfig,
};

const INTEGRATORS: &[&str] = &[
    "exponential",
    "implicit_midpoint",
    "rk4",
    "contact_exponential",
];
const COORDINATES: &[&str] = &["ale", "lagrangian"];
const SURFACES: &[&str] = &["top", "bottom", "mid"];

pub(super) fn config_from_params(
    decl: &Parameters,
    params: &Params,
) -> Result<Config, ConfigError> {
    let known = decl.known_keys();
    check_unknown_keys(params, &known)?;
    decl.check_params(params)?;
    let r = Reader::new(params, decl, &known);

    let plate = read_plate(&r)?;
    let limits = read_limits(&r)?;
    let mut nodes = read_nodes(&r)?;
    let simulation = read_simulation(&r)?;
    let load_models = read_load_models(&r, &plate, &limits, &simulation, &mut nodes)?;
    let loads = read_loads(&r, &nodes, &limits)?;
    let joint = read_joint(&r, &limits)?;
    let reference = read_reference(&r)?;
    let gravity = r.vec3("gravity")?;
    let _use_sim_time = r.bool("use_sim_time")?;
    let initial = read_initial(&r, &plate, &limits)?;
    let centrifugal = super::centrifugal::read_centrifugal(&r)?;

    Ok(Config {
        plate,
        nodes,
        loads,
        joint,
        reference,
        gravity,
        simulation,
        limits,
        load_models,
        initial,
        centrifugal,
    })
}

/// Every load model's sections, through the readers the registry declares.
fn read_load_models(
    r: &Reader,
    plate: &PlateConfig,
    limits: &LimitsConfig,
    simulation: &SimulationConfig,
    nodes: &mut NodesConfig,
) -> Result<LoadModelSections, ConfigError> {
    let mut ctx = SectionContext {
        plate,
        limits,
        simulation,
        nodes,
    };
    let mut sections = LoadModelSections::default();
    for model in r.parameters().models {
        if let Some(section) = (model.read)(r, &mut ctx)? {
            sections.set(section);
        }
    }
    Ok(sections)
}

// ---- unknown keys ------------------------------------------------------------

fn check_unknown_keys(params: &Params, known: &[&str]) -> Result<(), ConfigError> {
    for (key, _) in params.iter() {
        if !known.contains(&key) {
            return Err(ConfigError::UnknownKey {
                key: key.to_string(),
                suggestion: suggest(key, known),
            });
        }
    }
    Ok(())
}

// ---- nodes and loads ---------------------------------------------------------

fn read_nodes(r: &Reader) -> Result<NodesConfig, ConfigError> {
    let lagrange = read_node_list(r, "nodes.lagrange_radial", "nodes.lagrange_angular")?;
    let ale = read_node_list(r, "nodes.ale_radial", "nodes.ale_angular")?;
    Ok(NodesConfig {
        lagrange_surface: read_surfaces(
            r,
            "nodes.lagrange_surface",
            "nodes.lagrange_radial",
            lagrange.len(),
        )?,
        ale_surface: read_surfaces(r, "nodes.ale_surface", "nodes.ale_radial", ale.len())?,
        lagrange,
        ale,
    })
}

/// `top|bottom|mid` per node; not given: all `mid`.
fn read_surfaces(
    r: &Reader,
    key: &str,
    nodes_key: &str,
    nodes: usize,
) -> Result<Vec<Surface>, ConfigError> {
    let names = r.string_array(key)?;
    if names.is_empty() {
        return Ok(vec![Surface::Mid; nodes]);
    }
    if names.len() != nodes {
        return Err(ConfigError::LengthMismatch {
            key_a: key.to_string(),
            len_a: names.len(),
            key_b: nodes_key.to_string(),
            len_b: nodes,
        });
    }
    names
        .iter()
        .enumerate()
        .map(|(index, name)| match name.trim() {
            "top" => Ok(Surface::Top),
            "bottom" => Ok(Surface::Bottom),
            "mid" => Ok(Surface::Mid),
            _ => Err(ConfigError::UnknownChoice {
                key: format!("{key}[{index}]"),
                value: name.clone(),
                allowed: SURFACES,
            }),
        })
        .collect()
}

fn read_node_list(
    r: &Reader,
    radial_key: &str,
    angular_key: &str,
) -> Result<Vec<NodePosition>, ConfigError> {
    let radial = r.f64_array(radial_key)?;
    let angular = r.f64_array(angular_key)?;
    for (key, values) in [(radial_key, &radial), (angular_key, &angular)] {
        for (index, &value) in values.iter().enumerate() {
            if !(0.0..=1.0).contains(&value) {
                return Err(ConfigError::NodeOutOfUnitInterval {
                    key: key.to_string(),
                    index,
                    value,
                });
            }
        }
    }
    if radial.len() != angular.len() {
        return Err(ConfigError::LengthMismatch {
            key_a: radial_key.to_string(),
            len_a: radial.len(),
            key_b: angular_key.to_string(),
            len_b: angular.len(),
        });
    }
    Ok(radial
        .into_iter()
        .zip(angular)
        .map(|(radial, angular)| NodePosition { radial, angular })
        .collect())
}

fn read_loads(
    r: &Reader,
    nodes: &NodesConfig,
    limits: &LimitsConfig,
) -> Result<LoadsConfig, ConfigError> {
    Ok(LoadsConfig {
        ale: read_wrenches(r, "loads.ale_wrench", nodes.ale.len(), limits)?,
        lagrange: read_wrenches(r, "loads.lagrange_wrench", nodes.lagrange.len(), limits)?,
        follower: r.bool("loads.follower")?,
    })
}

/// One wrench per node: empty → zeros, else 6 numbers per node.
fn read_wrenches(
    r: &Reader,
    key: &str,
    nodes: usize,
    limits: &LimitsConfig,
) -> Result<Vec<WrenchConfig>, ConfigError> {
    let values = r.f64_array(key)?;
    if values.is_empty() {
        return Ok(vec![WrenchConfig::default(); nodes]);
    }
    if values.len() != 6 * nodes {
        return Err(ConfigError::WrenchLength {
            key: key.to_string(),
            len: values.len(),
            nodes,
        });
    }
    let mut wrenches = Vec::with_capacity(nodes);
    for (i, chunk) in values.chunks_exact(6).enumerate() {
        let force = [chunk[0], chunk[1], chunk[2]];
        let moment = [chunk[3], chunk[4], chunk[5]];
        let checks = [
            ("force", norm(force), "limits.max_force", limits.max_force),
            (
                "moment",
                norm(moment),
                "limits.max_moment",
                limits.max_moment,
            ),
        ];
        for (what, value, limit_key, limit) in checks {
            if value > limit {
                return Err(ConfigError::WrenchAboveLimit {
                    key: key.to_string(),
                    node: i + 1,
                    what,
                    value,
                    limit_key,
                    limit,
                });
            }
        }
        wrenches.push(WrenchConfig { force, moment });
    }
    Ok(wrenches)
}

fn norm(v: [f64; 3]) -> f64 {
    (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
}

// ---- joint, reference, simulation, limits -------------------------------------

fn read_joint(r: &Reader, limits: &LimitsConfig) -> Result<JointConfig, ConfigError> {
    let speed = r.f64("joint.speed")?;
    if speed.abs() > limits.max_speed {
        return Err(ConfigError::SpeedAboveLimit {
            speed,
            max_speed: limits.max_speed,
        });
    }
    let max_acceleration = r.positive("joint.max_acceleration")?;
    let max_torque = match r.f64_opt("joint.max_torque")? {
        Some(t) => Some(positive("joint.max_torque", t)?),
        None => None,
    };
    let initial_position = r.f64("joint.initial_position")?;
    Ok(JointConfig {
        speed,
        max_acceleration,
        max_torque,
        initial_position,
    })
}

fn read_reference(r: &Reader) -> Result<ReferenceConfig, ConfigError> {
    let tilt = r.f64("reference.tilt")?;
    if tilt.abs() >= FRAC_PI_2 {
        return Err(ConfigError::TiltOutOfRange { tilt });
    }
    Ok(ReferenceConfig {
        tilt,
        angular_velocity: r.vec3("reference.angular_velocity")?,
        acceleration: r.vec3("reference.acceleration")?,
    })
}

/// Types, ranges and defaults of these keys are the table's (`config::check`
/// ran before); only the choices are read here.
fn read_simulation(r: &Reader) -> Result<SimulationConfig, ConfigError> {
    let rate_hz = r.f64("simulation.rate_hz")?;
    let substeps = r.u32("simulation.substeps")?;
    let integrator = read_choice(
        r,
        "simulation.integrator",
        INTEGRATORS,
        IntegratorKind::from_name,
    )?;
    let coordinates = read_choice(
        r,
        "simulation.coordinates",
        COORDINATES,
        Coordinates::from_name,
    )?;
    let realtime_factor = r.f64("simulation.realtime_factor")?;
    let publish_divisor = r.u32("simulation.publish_divisor")?;
    let rk4_step_limit = r.f64("simulation.rk4_step_limit")?;
    let midpoint_step_limit = r.f64("simulation.midpoint_step_limit")?;
    let contact_tolerance = r.f64("simulation.contact_tolerance")?;
    Ok(SimulationConfig {
        rate_hz,
        substeps,
        integrator,
        coordinates,
        realtime_factor,
        publish_divisor,
        rk4_step_limit,
        midpoint_step_limit,
        contact_tolerance,
    })
}

fn read_limits(r: &Reader) -> Result<LimitsConfig, ConfigError> {
    Ok(LimitsConfig {
        max_force: r.positive("limits.max_force")?,
        max_moment: r.positive("limits.max_moment")?,
        max_speed: r.positive("limits.max_speed")?,
        max_deflection_thicknesses: r.positive("limits.max_deflection_thicknesses")?,
    })
}

// ---- load models and initial state (paper section 5; docs/scenes.md) ------------

fn read_initial(
    r: &Reader,
    plate: &PlateConfig,
    limits: &LimitsConfig,
) -> Result<InitialConfig, ConfigError> {
    let n = plate.mode_count();
    let max_q = limits.max_deflection_thicknesses * plate.thickness;
    let mut out = InitialConfig::default();
    for (key, slot) in [("initial.q", &mut out.q), ("initial.q_dot", &mut out.q_dot)] {
        let values = r.f64_array(key)?;
        if !values.is_empty() && values.len() != n {
            return Err(ConfigError::WrongLength {
                key: key.to_string(),
                len: values.len(),
                expected: n,
            });
        }
        if key == "initial.q" {
            for (index, &q) in values.iter().enumerate() {
                at_most(&format!("{key}[{index}]"), q, max_q)?;
            }
        }
        *slot = values;
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn known_keys() -> Vec<&'static str> {
        crate::dynamics::load_models::PARAMETERS.known_keys()
    }

    #[test]
    fn suggestions() {
        let known = known_keys();
        assert_eq!(
            suggest("plate.inner_raduis", &known).as_deref(),
            Some("plate.inner_radius")
        );
        assert_eq!(
            suggest("simulation.speed", &known).as_deref(),
            Some("joint.speed")
        );
        assert_eq!(
            suggest("plate.poisson", &known).as_deref(),
            Some("plate.poisson_ratio")
        );
        assert_eq!(
            suggest("Plate.Thickness", &known).as_deref(),
            Some("plate.thickness")
        );
        assert_eq!(suggest("completely.different", &known), None);
    }

    #[test]
    fn known_keys_are_distinct() {
        let known = known_keys();
        let mut unique = known.clone();
        unique.sort();
        unique.dedup();
        assert_eq!(unique.len(), known.len(), "a key is listed twice");
    }
}
