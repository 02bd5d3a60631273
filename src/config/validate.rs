//! From a flat [`Params`] set to the validated [`Config`].
//!
//! Every key this crate accepts is declared once in [`super::table`]; any
//! other key is rejected (with the nearest known key as a suggestion). Each
//! section has a `read_<section>` function that reads its keys and checks the
//! rules the table states (the load models' sections: `load_model_sections.rs`).
//!
//! Adding a section: declare its keys in the table, write `read_<section>`
//! and call it in [`config_from_params`] (plus the field in [`Config`]);
//! docs/parameters.md is generated from the table.

use std::f64::consts::FRAC_PI_2;

use super::check::suggest;
use super::error::Degeneracy;
use super::load_model_sections::{at_most, read_links, read_pads, read_springs, read_tool};
use super::raw::{positive, read_choice, Reader};
use super::{
    Boundary, Config, ConfigError, Coordinates, InitialConfig, IntegratorKind, JointConfig,
    LimitsConfig, LoadsConfig, NodePosition, NodesConfig, Params, PlateConfig, RadialSplines,
    ReferenceConfig, SimulationConfig, Surface, WrenchConfig,
};

/// Every accepted parameter name: the declared table ([`super::table`]).
pub(super) fn known_keys() -> Vec<&'static str> {
    super::table::params().map(|p| p.key).collect()
}

const INTEGRATORS: &[&str] = &["exponential", "implicit_midpoint", "rk4"];
const COORDINATES: &[&str] = &["ale", "lagrangian"];
const SURFACES: &[&str] = &["top", "bottom", "mid"];

/// Largest nodal-diameter number k accepted.
const MAX_NODAL_DIAMETER: i64 = 200;
/// Largest nodal-circle number l accepted.
const MAX_NODAL_CIRCLE: i64 = 50;
/// Largest `plate.radial_splines`.
const MAX_RADIAL_SPLINES: i64 = 400;
/// Range of `plate.frequency_tolerance`.
const MIN_FREQUENCY_TOLERANCE: f64 = 1e-9;
const MAX_FREQUENCY_TOLERANCE: f64 = 1e-2;
/// Smallest r_i / r_a (paper 4.2: no solid circular plate).
const MIN_RADIUS_RATIO: f64 = 1e-6;
/// Smallest (r_a − r_i) / r_a (paper 4.2: frequencies of a narrow ring go to infinity).
const MIN_RELATIVE_WIDTH: f64 = 1e-3;

pub(super) fn config_from_params(params: &Params) -> Result<Config, ConfigError> {
    let known = known_keys();
    check_unknown_keys(params, &known)?;
    super::check::check_params(params)?;
    let r = Reader::new(params, &known);

    let plate = read_plate(&r)?;
    let limits = read_limits(&r)?;
    let mut nodes = read_nodes(&r)?;
    let caliper_contacts = super::calipers::read_calipers(&r, &plate, &mut nodes)?;
    let loads = read_loads(&r, &nodes, &limits)?;
    let joint = read_joint(&r, &limits)?;
    let reference = read_reference(&r)?;
    let gravity = r.vec3("gravity")?;
    let simulation = read_simulation(&r)?;
    let _use_sim_time = r.bool("use_sim_time")?;
    let pads = read_pads(&r, &nodes, &limits, caliper_contacts)?;
    let tool = read_tool(&r, &plate, &nodes)?;
    let links = read_links(&r, &nodes, &limits)?;
    let springs = read_springs(&r, &nodes)?;
    let initial = read_initial(&r, &plate, &limits)?;
    let centrifugal = super::centrifugal::read_centrifugal(&r)?;
    if pads.as_ref().is_some_and(|p| p.mass > 0.0) && simulation.integrator != IntegratorKind::Rk4 {
        return Err(ConfigError::PadMass { rule: "pads.mass > 0 needs simulation.integrator: rk4 (the pads' axial motion is integrated at every stage)" });
    }

    Ok(Config {
        plate,
        nodes,
        loads,
        joint,
        reference,
        gravity,
        simulation,
        limits,
        pads,
        tool,
        links,
        springs,
        initial,
        centrifugal,
    })
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

// ---- plate -------------------------------------------------------------------

fn read_plate(r: &Reader) -> Result<PlateConfig, ConfigError> {
    let inner = r.f64("plate.inner_radius")?;
    let outer = r.positive("plate.outer_radius")?;
    if inner < 0.0 {
        return Err(ConfigError::NotPositive {
            key: "plate.inner_radius".into(),
            value: inner,
        });
    }
    if inner >= outer {
        return Err(ConfigError::InnerRadiusNotBelowOuter { inner, outer });
    }
    if inner / outer < MIN_RADIUS_RATIO {
        return Err(ConfigError::DegenerateGeometry {
            kind: Degeneracy::SolidCircularPlate,
            inner,
            outer,
        });
    }
    // A ring exactly 1e-3 wide must pass despite the rounding of (r_a − r_i)/r_a.
    if (outer - inner) / outer < MIN_RELATIVE_WIDTH * (1.0 - 1e-9) {
        return Err(ConfigError::DegenerateGeometry {
            kind: Degeneracy::NarrowRing,
            inner,
            outer,
        });
    }

    let thickness = r.positive("plate.thickness")?;
    let density = r.positive("plate.density")?;
    let youngs_modulus = r.positive("plate.youngs_modulus")?;
    let poisson_ratio = read_poisson_ratio(r, youngs_modulus)?;

    let inner_boundary = read_boundary(r, "plate.inner_boundary")?;
    let outer_boundary = read_boundary(r, "plate.outer_boundary")?;

    let nodal_diameters = read_index_list(r, "plate.nodal_diameters", MAX_NODAL_DIAMETER)?;
    let nodal_circles = read_index_list(r, "plate.nodal_circles", MAX_NODAL_CIRCLE)?;

    let radial_splines = read_radial_splines(r)?;
    let frequency_tolerance = r.positive("plate.frequency_tolerance")?;
    if !(MIN_FREQUENCY_TOLERANCE..=MAX_FREQUENCY_TOLERANCE).contains(&frequency_tolerance) {
        return Err(ConfigError::FrequencyToleranceOutOfRange {
            value: frequency_tolerance,
            low: MIN_FREQUENCY_TOLERANCE,
            high: MAX_FREQUENCY_TOLERANCE,
        });
    }

    let mut plate = PlateConfig {
        inner_radius: inner,
        outer_radius: outer,
        thickness,
        density,
        youngs_modulus,
        poisson_ratio,
        inner_boundary,
        outer_boundary,
        nodal_diameters,
        nodal_circles,
        damping: Vec::new(),
        radial_splines,
        frequency_tolerance,
        residual_flexibility: r.bool("plate.residual_flexibility")?,
    };

    check_derived(&plate)?;
    let needed = plate.min_radial_splines();
    if let RadialSplines::Fixed(splines) = plate.radial_splines {
        if splines < needed {
            let removed =
                inner_boundary.essential_conditions() + outer_boundary.essential_conditions();
            return Err(ConfigError::TooFewRadialSplines {
                splines,
                needed,
                free: splines.saturating_sub(removed),
                removed,
                max_l: plate.nodal_circles.iter().copied().max().unwrap_or(0),
                inner: inner_boundary.name(),
                outer: outer_boundary.name(),
            });
        }
    }

    let n_modes = plate.mode_count();
    if n_modes == 0 {
        return Err(ConfigError::NoElasticModes {
            skipped: rigid_body_modes_selected(&plate),
        });
    }
    let damping = r.f64_array("plate.damping")?;
    for (index, &value) in damping.iter().enumerate() {
        if !(0.0..1.0).contains(&value) {
            return Err(ConfigError::DampingOutOfRange { index, value });
        }
    }
    if damping.len() != 1 && damping.len() != n_modes {
        return Err(ConfigError::DampingLength {
            len: damping.len(),
            n_modes,
        });
    }
    plate.damping = damping;
    Ok(plate)
}

/// `plate.radial_splines`: `auto` or an integer count in 0..=400 (the
/// minimum for the requested l is checked with the plate).
fn read_radial_splines(r: &Reader) -> Result<RadialSplines, ConfigError> {
    const KEY: &str = "plate.radial_splines";
    if !r.has(KEY) {
        return Ok(RadialSplines::Auto);
    }
    if let Ok(name) = r.string(KEY) {
        return match name.trim() {
            "auto" => Ok(RadialSplines::Auto),
            _ => Err(ConfigError::RadialSplinesNotAutoOrCount {
                found: format!("\"{name}\""),
            }),
        };
    }
    let splines = r.i64(KEY).map_err(|e| match e {
        ConfigError::WrongType { key, found, .. } => ConfigError::WrongType {
            key,
            expected: "`auto` or an integer",
            found,
        },
        other => other,
    })?;
    if splines < 0 {
        return Err(ConfigError::Negative {
            key: KEY.into(),
            value: splines as f64,
        });
    }
    if splines > MAX_RADIAL_SPLINES {
        return Err(ConfigError::AboveMaximum {
            key: KEY.into(),
            value: splines as f64,
            max: MAX_RADIAL_SPLINES as f64,
        });
    }
    Ok(RadialSplines::Fixed(splines as usize))
}

/// The quantities the model is built from must be representable with room
/// to spare: flexural rigidity D (eq. 2), mass per area ρh and the frequency
/// scale D/(ρh r_a⁴). Each is refused with the keys it comes from.
fn check_derived(plate: &PlateConfig) -> Result<(), ConfigError> {
    let rigidity =
        super::bending_rigidity(plate.youngs_modulus, plate.thickness, plate.poisson_ratio);
    let areal_density = plate.density * plate.thickness;
    let scale = rigidity / (areal_density * plate.outer_radius.powi(4));
    let checks = [
        (
            "the flexural rigidity D = E h³ / (12 (1 − ν²))",
            rigidity,
            DERIVED_RANGE,
            "plate.youngs_modulus, plate.thickness, plate.poisson_ratio",
        ),
        (
            "the mass per area ρ h",
            areal_density,
            DERIVED_RANGE,
            "plate.density, plate.thickness",
        ),
        (
            "the frequency scale D / (ρ h r_a⁴)",
            scale,
            FREQUENCY_SCALE_RANGE,
            "plate.youngs_modulus, plate.density, plate.thickness, plate.outer_radius",
        ),
    ];
    for (quantity, value, (low, high), keys) in checks {
        if !(low..=high).contains(&value) {
            return Err(ConfigError::DerivedOutOfRange {
                quantity,
                value,
                low,
                high,
                keys,
            });
        }
    }
    Ok(())
}

/// Range of D (N·m) and ρ h (kg/m²): 40 decades around any real plate.
const DERIVED_RANGE: (f64, f64) = (1e-20, 1e20);
/// Range of D / (ρ h r_a⁴) (1/s²): frequencies from 1e-10 to 1e15 rad/s.
const FREQUENCY_SCALE_RANGE: (f64, f64) = (1e-20, 1e30);

/// ν from `plate.poisson_ratio` or from `plate.shear_modulus` (ν = E/2G − 1), exactly one of them.
fn read_poisson_ratio(r: &Reader, youngs_modulus: f64) -> Result<f64, ConfigError> {
    let given = r.f64_opt("plate.poisson_ratio")?;
    let shear = r.f64_opt("plate.shear_modulus")?;
    let (nu, from_shear_modulus) = match (given, shear) {
        (Some(poisson_ratio), Some(shear_modulus)) => {
            return Err(ConfigError::PoissonAndShearModulus {
                poisson_ratio,
                shear_modulus,
            })
        }
        (Some(nu), None) => (nu, false),
        (None, Some(g)) => {
            let g = positive("plate.shear_modulus", g)?;
            (youngs_modulus / (2.0 * g) - 1.0, true)
        }
        (None, None) => (r.f64("plate.poisson_ratio")?, false),
    };
    if !(nu > -1.0 && nu < 0.5) {
        return Err(ConfigError::PoissonRatioOutOfRange {
            nu,
            from_shear_modulus,
        });
    }
    Ok(nu)
}

fn read_boundary(r: &Reader, key: &str) -> Result<Boundary, ConfigError> {
    let name = r.string(key)?;
    Boundary::from_name(name.trim()).ok_or(ConfigError::UnknownBoundary {
        key: key.to_string(),
        value: name,
    })
}

/// A non-empty list of distinct integers in 0..=max.
fn read_index_list(r: &Reader, key: &str, max: i64) -> Result<Vec<u32>, ConfigError> {
    let values = r.i64_array(key)?;
    if values.is_empty() {
        return Err(ConfigError::Empty {
            key: key.to_string(),
        });
    }
    let mut out: Vec<u32> = Vec::with_capacity(values.len());
    for &v in &values {
        if v < 0 {
            return Err(ConfigError::Negative {
                key: key.to_string(),
                value: v as f64,
            });
        }
        if v > max {
            return Err(ConfigError::AboveMaximum {
                key: key.to_string(),
                value: v as f64,
                max: max as f64,
            });
        }
        if out.contains(&(v as u32)) {
            return Err(ConfigError::Duplicate {
                key: key.to_string(),
                value: v,
            });
        }
        out.push(v as u32);
    }
    Ok(out)
}

/// The requested ⟨k, l⟩ that are rigid-body motions of a free–free plate.
fn rigid_body_modes_selected(plate: &PlateConfig) -> Vec<(u32, u32)> {
    if !(plate.inner_boundary == Boundary::Free && plate.outer_boundary == Boundary::Free) {
        return Vec::new();
    }
    [(0, 0), (1, 0)]
        .into_iter()
        .filter(|(k, l)| plate.nodal_diameters.contains(k) && plate.nodal_circles.contains(l))
        .collect()
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
    Ok(SimulationConfig {
        rate_hz,
        substeps,
        integrator,
        coordinates,
        realtime_factor,
        publish_divisor,
        rk4_step_limit,
        midpoint_step_limit,
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
