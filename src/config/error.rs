//! Why a parameter file or parameter set was rejected.
//!
//! Small variants with context (in the style of faer's errors); every
//! message names the full parameter key (`plate.inner_radius`), the offending
//! value and the rule it breaks, in plain English for the person who wrote the
//! file.

use std::path::PathBuf;

use thiserror::Error;

/// The two degenerate geometries of the paper's section 4.2.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Degeneracy {
    /// r_i/r_a < 1e-6: an (almost) solid circular plate.
    SolidCircularPlate,
    /// (r_a − r_i)/r_a < 1e-3: an (almost) infinitely narrow ring.
    NarrowRing,
}

/// A rejected parameter file or parameter value.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum ConfigError {
    // ---- reading the file -------------------------------------------------
    #[error("cannot read the parameter file {}: {message}", path.display())]
    Io { path: PathBuf, message: String },

    #[error("the parameter file is not valid YAML for ROS 2 parameters: {message}")]
    Yaml { message: String },

    #[error("{quantity} = {value:e}, derived from {keys}, lies outside [{low:e}, {high:e}]: the model cannot be built in floating point; check the values and units of {keys}")]
    DerivedOutOfRange {
        quantity: &'static str,
        value: f64,
        low: f64,
        high: f64,
        keys: &'static str,
    },

    #[error("line {line}: the YAML nests deeper than {limit} levels; a ROS 2 parameter file needs about four (node, ros__parameters, section, key) and flat arrays")]
    TooDeep { line: usize, limit: usize },

    #[error("the parameter file {} has {bytes} bytes, more than the limit of {limit} bytes", path.display())]
    TooLarge {
        path: PathBuf,
        bytes: u64,
        limit: u64,
    },

    #[error("the parameter file has no entry for the node `{node}` (entries found: {}); add `{node}:` or `/**:` with `ros__parameters:` under it", list_or_none(found))]
    NoEntryForNode { node: String, found: Vec<String> },

    #[error("the parameter file entry `{entry}` has no `ros__parameters:` map (a ROS 2 parameter file reads `<node name>: ros__parameters: ...`)")]
    MissingRosParameters { entry: String },

    #[error("the parameter file entry `{entry}` holds `{key}`, but only `ros__parameters` is allowed directly under a node name")]
    UnexpectedEntryKey { entry: String, key: String },

    #[error("{key} holds a nested list or a map inside a list; ROS 2 parameters are flat arrays of booleans, integers, doubles or strings")]
    NestedList { key: String },

    #[error("{key} mixes {first} and {other} elements; a ROS 2 array holds one type (integers may be mixed into a list of doubles)")]
    MixedList {
        key: String,
        first: &'static str,
        other: &'static str,
    },

    #[error(
        "{key} has no value (YAML null); give a value or leave the key out to use its default"
    )]
    MissingValue { key: String },

    #[error("{key} is given twice in the same parameter file entry (for example once nested and once as a dotted name)")]
    DuplicateKey { key: String },

    #[error("`{name}` is not a valid parameter name: {reason}")]
    BadParameterName { name: String, reason: String },

    #[error("cannot parse the value `{text}` given for {key}: {message}")]
    BadOverride {
        key: String,
        text: String,
        message: String,
    },

    // ---- names and types ---------------------------------------------------
    #[error("unknown parameter {key}{}", suggestion_text(suggestion))]
    UnknownKey {
        key: String,
        suggestion: Option<String>,
    },

    #[error("{key} must be {expected}, found {found}")]
    WrongType {
        key: String,
        expected: &'static str,
        found: String,
    },

    #[error("{key} = {value} is not a boundary condition; use one of: free, supported, clamped, supported_soft (the last with plate.theory: mindlin)")]
    UnknownBoundary { key: String, value: String },

    #[error("{key} = supported_soft is an edge of Mindlin plate theory (w = 0 with the normal free to twist), but plate.theory = kirchhoff; set plate.theory: mindlin or use supported")]
    SoftSupportNeedsMindlin { key: &'static str },

    #[error("{key} = {value} is not one of: {}", allowed.join(", "))]
    UnknownChoice {
        key: String,
        value: String,
        allowed: &'static [&'static str],
    },

    // ---- single values -----------------------------------------------------
    #[error("{key} must be a finite number (got NaN or infinity)")]
    NonFinite { key: String },

    #[error("{key} = {} must be greater than zero", num(*value))]
    NotPositive { key: String, value: f64 },

    #[error("{key} = {} must not be negative", num(*value))]
    Negative { key: String, value: f64 },

    #[error("{key} = {} exceeds its maximum of {}", num(*value), num(*max))]
    AboveMaximum { key: String, value: f64, max: f64 },

    #[error("{key} = {} is out of its declared range: it must be {rule}", num(*value))]
    OutOfRange {
        key: String,
        value: f64,
        rule: String,
    },

    #[error("{key} must not be empty")]
    Empty { key: String },
    /// A caliper key against its geometric rule (`calipers.*`, docs/scenes.md).
    #[error("{key} = {} breaks its rule: {rule}", num(*value))]
    CaliperRule {
        key: String,
        value: f64,
        rule: String,
    },
    #[error("{key} is required with calipers.angles_deg (the pads' radial extent, m)")]
    CaliperKeyMissing { key: &'static str },

    #[error("{key} lists {value} more than once; each entry must be distinct")]
    Duplicate { key: String, value: i64 },

    #[error("{key} must have {expected} elements, found {len}")]
    WrongLength {
        key: String,
        len: usize,
        expected: usize,
    },

    // ---- the plate ---------------------------------------------------------
    #[error("plate.inner_radius = {} must be smaller than plate.outer_radius = {} (an annulus with r_i ≥ r_a does not exist; paper section 4.2)", num(*inner), num(*outer))]
    InnerRadiusNotBelowOuter { inner: f64, outer: f64 },

    #[error("{}", degenerate_text(*kind, *inner, *outer))]
    DegenerateGeometry {
        kind: Degeneracy,
        inner: f64,
        outer: f64,
    },

    #[error("give exactly one of plate.poisson_ratio (= {}) and plate.shear_modulus (= {}), not both", num(*poisson_ratio), num(*shear_modulus))]
    PoissonAndShearModulus {
        poisson_ratio: f64,
        shear_modulus: f64,
    },

    #[error("{}", poisson_text(*nu, *from_shear_modulus))]
    PoissonRatioOutOfRange { nu: f64, from_shear_modulus: bool },

    #[error("plate.radial_splines = {splines}: the {inner}–{outer} boundaries remove {removed} B-splines, leaving {free} free coefficients, but nodal circles up to l = {max_l} need at least {} (use plate.radial_splines ≥ {needed})", max_l + 4)]
    TooFewRadialSplines {
        splines: usize,
        needed: usize,
        free: usize,
        removed: usize,
        max_l: u32,
        inner: &'static str,
        outer: &'static str,
    },

    #[error("plate.radial_splines = {found}: give `auto` (the count per nodal-diameter number that reaches plate.frequency_tolerance) or an integer count ≤ 400")]
    RadialSplinesNotAutoOrCount { found: String },

    #[error("plate.frequency_tolerance = {} must lie in [{}, {}] (a relative frequency error; below ~1e-8 double precision limits the radial discretisation, docs/convergence.md)", num(*value), num(*low), num(*high))]
    FrequencyToleranceOutOfRange { value: f64, low: f64, high: f64 },

    #[error("plate.damping[{index}] = {value} must lie in [0, 1) (a modal damping ratio)")]
    DampingOutOfRange { index: usize, value: f64 },

    #[error("plate.damping has {len} values; give 1 (for all modes) or exactly {n_modes} (one per mode)")]
    DampingLength { len: usize, n_modes: usize },

    #[error("plate.nodal_diameters × plate.nodal_circles select only the rigid-body modes {skipped:?} of a free–free plate, which the floating frame carries; select at least one elastic mode")]
    NoElasticModes { skipped: Vec<(u32, u32)> },

    // ---- nodes and loads ---------------------------------------------------
    #[error("{key}[{index}] = {value} must lie in [0, 1] (the paper's ξ coordinate, section 4.1)")]
    NodeOutOfUnitInterval {
        key: String,
        index: usize,
        value: f64,
    },

    #[error("{key_a} has {len_a} values but {key_b} has {len_b}; they must have the same length")]
    LengthMismatch {
        key_a: String,
        len_a: usize,
        key_b: String,
        len_b: usize,
    },

    #[error("{}", wrench_length_text(key, *len, *nodes))]
    WrenchLength {
        key: String,
        len: usize,
        nodes: usize,
    },

    #[error("{key}: the {what} of node {node} (from 1) has magnitude {}, above {limit_key} = {}", num(*value), num(*limit))]
    WrenchAboveLimit {
        key: String,
        node: usize,
        what: &'static str,
        value: f64,
        limit_key: &'static str,
        limit: f64,
    },

    // ---- joint, reference --------------------------------------------------
    #[error("joint.speed = {} rad/s exceeds limits.max_speed = {} rad/s in magnitude", num(*speed), num(*max_speed))]
    SpeedAboveLimit { speed: f64, max_speed: f64 },

    #[error("reference.tilt = {tilt} rad must satisfy |tilt| < π/2")]
    TiltOutOfRange { tilt: f64 },

    // ---- load models (pads, tool, links) and initial state ------------------
    #[error("{key} names {kind} node {node} (nodes count from 1), but the scene has {} {kind} node(s) (nodes.{kind}_radial / nodes.{kind}_angular)", count)]
    NoSuchNode {
        key: String,
        node: i64,
        kind: &'static str,
        count: usize,
    },

    #[error("{key} is given but {enabling_key} is empty or missing, so this load model is off; give {enabling_key} or remove {key}")]
    KeyWithoutSection {
        key: String,
        enabling_key: &'static str,
    },

    #[error("pads.contact_pad: pads are numbered from 1 without gaps, but pad {pad} has no contact point (pads used: 1..={pads})")]
    PadWithoutContacts { pad: usize, pads: usize },

    #[error("pads.clamp_force has {len} values; give 1 (for every pad) or one per pad ({pads})")]
    ClampForceLength { len: usize, pads: usize },

    #[error("pads.static_friction_coefficient is given but pads.contact_surface is mid_plane: the speed-dependent μ(v) needs the sliding velocity of the faces; set pads.contact_surface: faces or remove it")]
    StaticFrictionNeedsFaces,

    #[error("{rule}")]
    PadMass { rule: &'static str },

    #[error("tool.ale_node = {node} is at ξ_r = {radial} (nodes.ale_radial[{}]); the tool cuts the rim, so its ALE node must be at ξ_r = 1", node - 1)]
    ToolNotOnRim { node: usize, radial: f64 },

    #[error("tool.depth_of_cut = {} m reaches beyond the annulus: it must be smaller than plate.outer_radius − plate.inner_radius = {} m", num(*depth), num(*width))]
    DepthOfCutBeyondPlate { depth: f64, width: f64 },
}

/// A number for messages: plain for ordinary magnitudes, `2.1e11` for large or tiny ones.
fn num(x: f64) -> String {
    if x != 0.0 && x.is_finite() && (x.abs() >= 1e6 || x.abs() < 1e-4) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}

fn wrench_length_text(key: &str, len: usize, nodes: usize) -> String {
    let kind = if key.starts_with("loads.ale") {
        "ale"
    } else {
        "lagrange"
    };
    if nodes == 0 {
        format!(
            "{key} has {len} values but there are no {kind} nodes (nodes.{kind}_radial / nodes.{kind}_angular); \
             leave it empty or add the nodes"
        )
    } else {
        format!(
            "{key} has {len} values; it must be empty or hold 6 per node (fx fy fz mx my mz), {} for {nodes} node(s)",
            6 * nodes
        )
    }
}

fn list_or_none(found: &[String]) -> String {
    if found.is_empty() {
        "none".to_string()
    } else {
        found
            .iter()
            .map(|f| format!("`{f}`"))
            .collect::<Vec<_>>()
            .join(", ")
    }
}

fn suggestion_text(suggestion: &Option<String>) -> String {
    match suggestion {
        Some(s) => format!(" (did you mean {s}?)"),
        None => " (see docs/parameters.md for the known parameters)".to_string(),
    }
}

fn poisson_text(nu: f64, from_shear_modulus: bool) -> String {
    if from_shear_modulus {
        format!(
            "plate.shear_modulus gives the Poisson ratio ν = E/(2G) − 1 = {nu} (with plate.youngs_modulus), \
             outside the open interval (−1, 0.5); the shear modulus must exceed plate.youngs_modulus / 3"
        )
    } else {
        format!("plate.poisson_ratio = {nu} must lie in the open interval (−1, 0.5)")
    }
}

fn degenerate_text(kind: Degeneracy, inner: f64, outer: f64) -> String {
    match kind {
        Degeneracy::SolidCircularPlate => format!(
            "plate.inner_radius = {} m is below 1e-6 × plate.outer_radius = {} m: the model is no solid \
             circular plate (the displacements at the inner radius fail the compatibility conditions, paper section 4.2); \
             use a small but finite inner radius of at least 1e-6 × the outer radius: with a free inner edge it \
             approaches the solid plate, with a supported or clamped one a plate pinned at its centre",
            num(inner),
            num(outer)
        ),
        Degeneracy::NarrowRing => format!(
            "plate.inner_radius = {} m and plate.outer_radius = {} m leave a ring narrower than 1e-3 of the \
             outer radius: the eigenfrequencies of a very narrow ring go to infinity (paper section 4.2); use a wider annulus",
            num(inner),
            num(outer)
        ),
    }
}
