//! The brake pads' parameters (`pads.*`, and `calipers.*` that make their
//! contact points: `pad_calipers.rs`): their declaration and the reader that
//! checks their rules into the pads' validated section ([`PadsConfig`], from
//! which the registered builder makes the model).

use super::pad_calipers::read_calipers;
pub use super::pad_calipers::PadContact;
use crate::config::model_sections::{
    at_most, no_other_keys, node_refs, non_negative, positive, read_choice,
};
use crate::config::table::{param, Section, Ty, Value};
use crate::config::{
    ConfigError, IntegratorKind, LimitsConfig, LoadModelSection, ModelParameters, NodesConfig,
    Reader, SectionContext, SectionData,
};
use serde::Serialize;

const CALIPERS: &[&str] = &["floating", "fixed"];
const CONTACT_SURFACES: &[&str] = &["faces", "mid_plane"];

/// Largest plausible friction coefficient.
pub const MAX_FRICTION_COEFFICIENT: f64 = 2.0;

/// How a pad's clamp force is applied (`pads.caliper`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Caliper {
    /// The caliper is held where the clamp force puts it on an undeformed disc.
    Fixed,
    /// The clamp force is a force (hydraulic piston, floating caliper): each
    /// face's pad is a rigid backing plate pressed with it.
    Floating,
}

impl Caliper {
    /// The parameter value (`fixed`, `floating`).
    pub fn name(self) -> &'static str {
        match self {
            Caliper::Fixed => "fixed",
            Caliper::Floating => "floating",
        }
    }
}

/// Where the pads' friction acts (`pads.contact_surface`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ContactSurface {
    /// On the faces z = ±h/2, from the sliding velocity of the face point
    /// (the friction couple and the sliding-direction terms; docs/scenes.md).
    Faces,
    /// At the mid-plane node, along −sign Ω e_θ (the paper's model).
    MidPlane,
}

impl ContactSurface {
    /// The parameter value (`faces`, `mid_plane`).
    pub fn name(self) -> &'static str {
        match self {
            ContactSurface::Faces => "faces",
            ContactSurface::MidPlane => "mid_plane",
        }
    }
}

/// Brake pads (`pads.*`, paper 5.3 and Fig. 18): at every contact point an
/// axial spring-damper on each face against the pad's backing plate, pressed
/// with the pad's clamp force, and friction μN along the deformed surface.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PadsConfig {
    /// The contact points of the pads.
    pub contacts: Vec<PadContact>,
    /// Initial clamp force of each pad, N: the force each face of the disc is
    /// pressed with, shared equally by the pad's contact points.
    pub clamp_force: Vec<f64>,
    /// Axial contact stiffness k_c per contact point and face, N/m.
    pub contact_stiffness: f64,
    /// Axial contact damping c_c per contact point and face, N·s/m.
    pub contact_damping: f64,
    /// Friction coefficient μ.
    pub friction_coefficient: f64,
    /// A face whose normal force would pull is released (N ≥ 0).
    pub lift_off: bool,
    /// Friction follows the deformed surface (the paper's follower forces).
    pub follower_friction: bool,
    /// Fixed or floating caliper (`pads.caliper`).
    pub caliper: Caliper,
    /// Where the pads act: on the faces or the mid-plane (`pads.contact_surface`).
    pub contact_surface: ContactSurface,
    /// μ_s of the speed-dependent friction law μ(v) = μ + (μ_s − μ) e^(−v/v_S)
    /// (`pads.static_friction_coefficient`; `None`: constant μ; faces only).
    pub static_friction_coefficient: Option<f64>,
    /// v_S of that law, m/s (`pads.stribeck_speed`).
    pub stribeck_speed: f64,
    /// Mass of each face's pad, kg (`pads.mass`; 0: massless pads).
    pub mass: f64,
    /// k_b behind a fixed caliper's massive pad, N/m (`pads.backing_stiffness`).
    pub backing_stiffness: Option<f64>,
    /// k_t and c_t of the lining's tangential patch per contact point and
    /// face (`pads.shear_stiffness`, `pads.shear_damping`; `None`: rigid).
    pub shear: Option<(f64, f64)>,
}

impl PadsConfig {
    /// Number of pads (the largest pad index + 1).
    pub fn pad_count(&self) -> usize {
        self.contacts.iter().map(|c| c.pad + 1).max().unwrap_or(0)
    }
}

impl LoadModelSection for PadsConfig {
    const SECTION: &'static str = "pads";
    const CAN_SQUEAL: bool = true;
}

/// The pads' keys, and the calipers' that make their contact points.
pub const SECTIONS: &[Section] = &[
    Section {
        name: "pads",
        title: "`pads` — brake pads (paper 5.3, Fig. 18; docs/scenes.md)",
        before: "Off unless `pads.ale_nodes` (or `calipers.angles_deg`) is given; the other `pads.*` keys are refused without it.",
        after: "",
        params: &[
            param("pads.ale_nodes", Ty::IntegerArray, "integer array", "—", Value::Integers(&[]), "[]", "each an existing ALE node (from 1), distinct", "contact points: at each a pad presses on each face of the disc"),
            param("pads.contact_pad", Ty::IntegerArray, "integer array", "—", Value::None, "all 1", "same length as `pads.ale_nodes`; pads numbered 1..P without gaps", "the pad each contact point belongs to (a pad shares one clamp force)"),
            param("pads.clamp_force", Ty::DoubleArray, "double array", "N", Value::Doubles(&[0.0]), "[0]", "each ≥ 0 and ≤ `limits.max_force`; 1 value (all pads) or one per pad", "clamp force per pad at t = 0: the force each face is pressed with, shared by the pad's contact points (the command `set_pad_clamp_force` changes it)"),
            param("pads.contact_stiffness", Ty::Double, "double", "N/m", Value::Double(5000000.0), "5e6", "> 0", "axial stiffness k_c per contact point and face").above(0.0),
            param("pads.contact_damping", Ty::Double, "double", "N·s/m", Value::Double(0.0), "0", "≥ 0", "axial damping c_c per contact point and face (on the gap-closing rate ∂w/∂t at the fixed point)").min(0.0),
            param("pads.friction_coefficient", Ty::Double, "double", "—", Value::Double(0.4), "0.4", "≥ 0, ≤ 2", "μ: friction μN per face against the sliding direction"),
            param("pads.lift_off", Ty::Bool, "bool", "—", Value::Bool(false), "false", "—", "a contact that would pull is released (N ≥ 0)"),
            param("pads.follower_friction", Ty::Bool, "bool", "—", Value::Bool(true), "true", "—", "friction lies in the deformed surface (follower forces, the squeal mechanism)"),
            param("pads.caliper", Ty::String, "string", "—", Value::Str("floating"), "`floating`", "`floating` or `fixed`", "`floating`: each face's pad is a rigid backing plate pressed with the clamp force (a force, as from a hydraulic piston); `fixed`: the caliper stays where the clamp force puts it on an undeformed disc"),
            param("pads.contact_surface", Ty::String, "string", "—", Value::Str("faces"), "`faces`", "`faces` or `mid_plane`", "`faces`: each pad's friction acts on its face (z = ±h/2) against the sliding velocity of the face point — rotation, the vibration's in-plane −z∇(Dw/Dt) and normal Ω ∂w/∂θ — regularised Coulomb, so the two faces' normal-force difference makes a couple (docs/scenes.md); `mid_plane`: at the mid-plane node along −sign Ω e_θ (the paper's model)"),
            param("pads.static_friction_coefficient", Ty::Double, "double", "—", Value::None, "not given (constant μ)", "≥ 0, ≤ 2; only with `pads.contact_surface: faces`", "μ_s of the speed-dependent friction μ(v) = μ + (μ_s − μ) e^(−v/v_S), v the face's sliding speed (a falling μ(v), μ_s > μ, feeds energy into the vibration; docs/scenes.md)"),
            param("pads.stribeck_speed", Ty::Double, "double", "m/s", Value::Double(1.0), "1", "> 0", "v_S of that law").above(0.0),
            param("pads.mass", Ty::Double, "double", "kg", Value::Double(0.0), "0", "≥ 0, finite; > 0 needs `simulation.integrator: rk4` or `contact_exponential`", "mass m_p of each face's pad (lining and backing plate), moving axially between its contact springs k_c, c_c and the caliper: the pad's compression and rate are state, in series with the residual flexibility when `plate.residual_flexibility` (docs/scenes.md, \"Pad mass\"); 0: massless pads (the backing force balances the contacts at every instant)").min(0.0),
            param("pads.shear_stiffness", Ty::Double, "double", "N/m", Value::None, "not given (rigid lining)", "> 0, finite; with `pads.shear_damping`, `pads.contact_surface: faces`, constant μ (no `pads.static_friction_coefficient`) and `simulation.integrator: rk4` or `contact_exponential`", "k_t of the lining's tangential patch per contact point and face, in series with the friction: each face's friction acts on a massless patch, k_t x + c_t ẋ = friction, and the face slides relative to the patch (stick when that relative velocity vanishes; docs/scenes.md, \"Pad shear\"). From lining data: G A / t per pad face (shear modulus G of lining and shim, pad area A, thickness t), divided by the pad's contact points").above(0.0),
            param("pads.shear_damping", Ty::Double, "double", "N·s/m", Value::None, "not given", "> 0, finite; required with `pads.shear_stiffness`, refused without it", "c_t of the patch per contact point and face, parallel to k_t: from the lining's loss factor η at the squeal frequency ω, c_t = η k_t / ω (per pad face likewise divided by its contact points)").above(0.0),
            param("pads.backing_stiffness", Ty::Double, "double", "N/m", Value::None, "not given", "> 0, finite; required with `pads.mass` > 0 and `pads.caliper: fixed`, refused otherwise", "k_b of the fixed caliper behind each massive pad: the backing force is N₀ − k_b (x − N₀/(n k_c)), x the pad's compression of its contact springs").above(0.0),
        ],
    },
    Section {
        name: "calipers",
        title: "`calipers` — pads as annular sectors (docs/scenes.md, \"Calipers\")",
        before: "Off unless `calipers.angles_deg` is given; then the calipers make the pads' contact points (ALE nodes appended after `nodes.ale_*`, pad p = caliper p) in place of `pads.ale_nodes`, and the `pads.*` data keys apply to them.",
        after: "",
        params: &[
            param("calipers.angles_deg", Ty::DoubleArray, "double array", "deg", Value::Doubles(&[]), "[]", "each in [−360, 360]", "centre angle θ of each caliper in the space-fixed frame (one pad per face each; e.g. [0] or [0, 180])"),
            param("calipers.arc_deg", Ty::Double, "double", "deg", Value::Double(60.0), "60", "> 0; calipers × arc ≤ 360", "angular extent of each pad"),
            param("calipers.inner_radius", Ty::Double, "double", "m", Value::None, "required", "plate.inner_radius ≤ r < plate.outer_radius", "inner radius of the pads"),
            param("calipers.outer_radius", Ty::Double, "double", "m", Value::None, "required", "> calipers.inner_radius, ≤ plate.outer_radius", "outer radius of the pads"),
            param("calipers.points_radial", Ty::Integer, "integer", "—", Value::Integer(1), "1", "≥ 1", "contact points across the radius: rings of equal area, each point at its ring's mean friction radius (uniform pressure)").min(1.0),
            param("calipers.points_circumferential", Ty::Integer, "integer", "—", Value::Integer(6), "6", "≥ 1; all points together ≤ 400", "contact points along the arc, at the centres of equal sub-arcs").min(1.0),
        ],
    },
];

/// The pads' parameters: their keys and their reader.
pub const PARAMETERS: ModelParameters = ModelParameters {
    sections: SECTIONS,
    read,
};

/// `calipers.*` and `pads.*`: the section when the calipers or
/// `pads.ale_nodes` make contact points (the calipers' appended to the ALE
/// nodes); pads with mass need an integrator that integrates their motion.
fn read(r: &Reader, ctx: &mut SectionContext) -> Result<Option<Box<dyn SectionData>>, ConfigError> {
    let contacts = match read_calipers(r, ctx.plate, ctx.nodes)? {
        Some(contacts) => contacts,
        None => match read_pad_contacts(r, ctx.nodes)? {
            Some(contacts) => contacts,
            None => return Ok(None),
        },
    };
    let pads = contacts.iter().map(|c| c.pad + 1).max().unwrap_or(1);
    let section = read_pad_data(r, ctx.limits, contacts, pads)?;
    if section.mass > 0.0
        && !matches!(
            ctx.simulation.integrator,
            IntegratorKind::Rk4 | IntegratorKind::ContactExponential
        )
    {
        return Err(ConfigError::PadMass { rule: "pads.mass > 0 needs simulation.integrator: rk4 or contact_exponential (the pads' axial motion is integrated with the modes)" });
    }
    check_shear_integrator(section.shear.is_some(), ctx.simulation.integrator)?;
    Ok(Some(section.boxed()))
}

/// The contacts of `pads.ale_nodes` and `pads.contact_pad`; `None` (and no
/// other `pads.*` key) when not given.
fn read_pad_contacts(
    r: &Reader,
    nodes: &NodesConfig,
) -> Result<Option<Vec<PadContact>>, ConfigError> {
    let numbers = r.i64_array("pads.ale_nodes")?;
    if numbers.is_empty() {
        no_other_keys(r, "pads", "pads.ale_nodes")?;
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
) -> Result<PadsConfig, ConfigError> {
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
    let shear = read_shear(r, contact_surface, static_friction_coefficient)?;
    Ok(PadsConfig {
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
        shear,
    })
}

/// `pads.mass` (≥ 0) and `pads.backing_stiffness` (> 0; given exactly when
/// the pads have mass and the caliper is fixed).
fn read_pad_mass(r: &Reader, caliper: Caliper) -> Result<(f64, Option<f64>), ConfigError> {
    let mass = non_negative("pads.mass", r.f64("pads.mass")?)?;
    let backing = match r.f64_opt("pads.backing_stiffness")? {
        Some(k) => Some(positive("pads.backing_stiffness", k)?),
        None => None,
    };
    match (mass > 0.0, caliper, backing) {
        (true, Caliper::Fixed, None) => Err(ConfigError::PadMass { rule: "pads.backing_stiffness must be given with pads.mass > 0 and pads.caliper: fixed (the stiffness that holds each pad to the caliper)" }),
        (true, Caliper::Floating, Some(_)) => Err(ConfigError::PadMass { rule: "pads.backing_stiffness applies to pads.caliper: fixed only (a floating caliper presses each pad with the clamp force)" }),
        (false, _, Some(_)) => Err(ConfigError::PadMass { rule: "pads.backing_stiffness needs pads.mass > 0 (massless pads have no backing spring)" }),
        _ => Ok((mass, backing)),
    }
}

/// `pads.shear_stiffness` and `pads.shear_damping`: both or neither, each
/// > 0 and finite, with friction on the faces at constant μ.
fn read_shear(
    r: &Reader,
    surface: ContactSurface,
    static_friction: Option<f64>,
) -> Result<Option<(f64, f64)>, ConfigError> {
    let positive_finite = |key: &str| -> Result<Option<f64>, ConfigError> {
        match r.f64_opt(key)? {
            None => Ok(None),
            Some(x) if !x.is_finite() => Err(ConfigError::NonFinite {
                key: key.to_string(),
            }),
            Some(x) => positive(key, x).map(Some),
        }
    };
    let stiffness = positive_finite("pads.shear_stiffness")?;
    let damping = positive_finite("pads.shear_damping")?;
    let (k, c) = match (stiffness, damping) {
        (None, None) => return Ok(None),
        (Some(k), Some(c)) => (k, c),
        (Some(_), None) => return Err(ConfigError::PadShear { rule: "pads.shear_stiffness needs pads.shear_damping > 0 (without damping the sliding patch is an infinitely stiff constraint)" }),
        (None, Some(_)) => return Err(ConfigError::PadShear { rule: "pads.shear_damping needs pads.shear_stiffness (a damper beside a rigid lining does nothing)" }),
    };
    if surface == ContactSurface::MidPlane {
        return Err(ConfigError::PadShear { rule: "pads.shear_stiffness needs pads.contact_surface: faces (the patch carries the friction of a face against the face point's sliding velocity)" });
    }
    if static_friction.is_some() {
        return Err(ConfigError::PadShear { rule: "pads.shear_stiffness is refused with pads.static_friction_coefficient: the patch is solved for constant μ" });
    }
    Ok(Some((k, c)))
}

/// Patches are continuous state: only RK4 and `contact_exponential` integrate them.
fn check_shear_integrator(shear: bool, integrator: IntegratorKind) -> Result<(), ConfigError> {
    if shear
        && !matches!(
            integrator,
            IntegratorKind::Rk4 | IntegratorKind::ContactExponential
        )
    {
        return Err(ConfigError::PadShear { rule: "pads.shear_stiffness needs simulation.integrator: rk4 or contact_exponential (the patches' deflections are integrated with the modes)" });
    }
    Ok(())
}
