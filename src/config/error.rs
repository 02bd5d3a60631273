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
    /// The parameter file could not be read (missing, unreadable, not UTF-8).
    #[error("cannot read the parameter file {}: {message}", path.display())]
    Io {
        /// The file that was to be read.
        path: PathBuf,
        /// The operating system's reason.
        message: String,
    },

    /// The file is not YAML, or its YAML is not a ROS 2 parameter file.
    #[error("the parameter file is not valid YAML for ROS 2 parameters: {message}")]
    Yaml {
        /// The YAML reader's reason, with its line.
        message: String,
    },

    /// A quantity derived from several keys (the mass per area ρ h, the
    /// frequency scale D / (ρ h r_a⁴)) lies outside the range the model can
    /// be built with in floating point.
    #[error("{quantity} = {value:e}, derived from {keys}, lies outside [{low:e}, {high:e}]: the model cannot be built in floating point; check the values and units of {keys}")]
    DerivedOutOfRange {
        /// The derived quantity, by name.
        quantity: &'static str,
        /// Its value, in SI units.
        value: f64,
        /// The smallest value the model accepts.
        low: f64,
        /// The largest value the model accepts.
        high: f64,
        /// The keys it is derived from.
        keys: &'static str,
    },

    /// The YAML nests deeper than the reader allows (scanned before it is parsed).
    #[error("line {line}: the YAML nests deeper than {limit} levels; a ROS 2 parameter file needs about four (node, ros__parameters, section, key) and flat arrays")]
    TooDeep {
        /// The line (from 1) where the limit was passed.
        line: usize,
        /// The deepest nesting allowed.
        limit: usize,
    },

    /// The parameter file is larger than the reader allows (checked before it is read).
    #[error("the parameter file {} has {bytes} bytes, more than the limit of {limit} bytes", path.display())]
    TooLarge {
        /// The file.
        path: PathBuf,
        /// Its size, bytes.
        bytes: u64,
        /// The largest size allowed, bytes.
        limit: u64,
    },

    /// The file has no entry for this node's name nor a `/**` wildcard entry.
    #[error("the parameter file has no entry for the node `{node}` (entries found: {}); add `{node}:` or `/**:` with `ros__parameters:` under it", list_or_none(found))]
    NoEntryForNode {
        /// The node name looked for.
        node: String,
        /// The entries the file does have.
        found: Vec<String>,
    },

    /// A node entry has no `ros__parameters:` map under it.
    #[error("the parameter file entry `{entry}` has no `ros__parameters:` map (a ROS 2 parameter file reads `<node name>: ros__parameters: ...`)")]
    MissingRosParameters {
        /// The node entry.
        entry: String,
    },

    /// A node entry holds a key other than `ros__parameters`.
    #[error("the parameter file entry `{entry}` holds `{key}`, but only `ros__parameters` is allowed directly under a node name")]
    UnexpectedEntryKey {
        /// The node entry.
        entry: String,
        /// The key found directly under it.
        key: String,
    },

    /// A list holds a list or a map: ROS 2 parameters are flat arrays.
    #[error("{key} holds a nested list or a map inside a list; ROS 2 parameters are flat arrays of booleans, integers, doubles or strings")]
    NestedList {
        /// The parameter.
        key: String,
    },

    /// A list mixes element types (other than integers among doubles).
    #[error("{key} mixes {first} and {other} elements; a ROS 2 array holds one type (integers may be mixed into a list of doubles)")]
    MixedList {
        /// The parameter.
        key: String,
        /// The type of the first element.
        first: &'static str,
        /// The type of the first element that differs.
        other: &'static str,
    },

    /// A key is given with a YAML null instead of a value.
    #[error(
        "{key} has no value (YAML null); give a value or leave the key out to use its default"
    )]
    MissingValue {
        /// The parameter.
        key: String,
    },

    /// A key is given twice in one node entry (for example nested and dotted).
    #[error("{key} is given twice in the same parameter file entry (for example once nested and once as a dotted name)")]
    DuplicateKey {
        /// The parameter.
        key: String,
    },

    /// A name that is not a valid ROS 2 parameter name (empty segments, bad characters, too long).
    #[error("`{name}` is not a valid parameter name: {reason}")]
    BadParameterName {
        /// The name as given.
        name: String,
        /// The rule it breaks.
        reason: String,
    },

    /// A `key:=value` override on the command line whose value text does not parse.
    #[error("cannot parse the value `{text}` given for {key}: {message}")]
    BadOverride {
        /// The parameter.
        key: String,
        /// The value text as given.
        text: String,
        /// Why it does not parse.
        message: String,
    },

    // ---- names and types ---------------------------------------------------
    /// A key that is not in the parameter table.
    #[error("unknown parameter {key}{}", suggestion_text(suggestion))]
    UnknownKey {
        /// The key as given.
        key: String,
        /// The closest known key, if one is close.
        suggestion: Option<String>,
    },

    /// A value of the wrong ROS 2 type for its key (its type is declared in the table).
    #[error("{key} must be {expected}, found {found}")]
    WrongType {
        /// The parameter.
        key: String,
        /// The declared type.
        expected: &'static str,
        /// The type given.
        found: String,
    },

    /// A boundary condition other than `free`, `supported`, `clamped` or `supported_soft`.
    #[error("{key} = {value} is not a boundary condition; use one of: free, supported, clamped, supported_soft (the last with plate.theory: mindlin)")]
    UnknownBoundary {
        /// The parameter.
        key: String,
        /// The value given.
        value: String,
    },

    /// `supported_soft` (a Mindlin edge) on a Kirchhoff plate.
    #[error("{key} = supported_soft is an edge of Mindlin plate theory (w = 0 with the normal free to twist), but plate.theory = kirchhoff; set plate.theory: mindlin or use supported")]
    SoftSupportNeedsMindlin {
        /// The edge key (`plate.inner_boundary` or `plate.outer_boundary`).
        key: &'static str,
    },

    /// `plate.residual_patch_radius` set on a Kirchhoff plate.
    #[error("plate.residual_patch_radius is the half-width of a node's load patch under Mindlin theory (a Kirchhoff node's force is a point force), but plate.theory = kirchhoff; set plate.theory: mindlin or leave the key at auto")]
    PatchRadiusNeedsMindlin,

    /// `plate.residual_patch_radius` neither `auto` nor a number.
    #[error("plate.residual_patch_radius = {found} must be `auto` or a number of metres")]
    PatchRadiusNotAutoOrNumber {
        /// The value given, as text.
        found: String,
    },

    /// A string value outside its key's declared choices.
    #[error("{key} = {value} is not one of: {}", allowed.join(", "))]
    UnknownChoice {
        /// The parameter.
        key: String,
        /// The value given.
        value: String,
        /// The declared choices.
        allowed: &'static [&'static str],
    },

    // ---- single values -----------------------------------------------------
    /// A number that is NaN or infinite; every value must be finite.
    #[error("{key} must be a finite number (got NaN or infinity)")]
    NonFinite {
        /// The parameter.
        key: String,
    },

    /// A value that must be greater than zero is not.
    #[error("{key} = {} must be greater than zero", num(*value))]
    NotPositive {
        /// The parameter.
        key: String,
        /// The value given, in the key's unit.
        value: f64,
    },

    /// A value that must not be negative is.
    #[error("{key} = {} must not be negative", num(*value))]
    Negative {
        /// The parameter.
        key: String,
        /// The value given, in the key's unit.
        value: f64,
    },

    /// A value above its key's maximum.
    #[error("{key} = {} exceeds its maximum of {}", num(*value), num(*max))]
    AboveMaximum {
        /// The parameter.
        key: String,
        /// The value given, in the key's unit.
        value: f64,
        /// The maximum, in the same unit.
        max: f64,
    },

    /// A value outside the range its key declares in the table.
    #[error("{key} = {} is out of its declared range: it must be {rule}", num(*value))]
    OutOfRange {
        /// The parameter.
        key: String,
        /// The value given, in the key's unit.
        value: f64,
        /// The declared range, as text.
        rule: String,
    },

    /// A list or string that must not be empty is.
    #[error("{key} must not be empty")]
    Empty {
        /// The parameter.
        key: String,
    },
    /// A caliper key against its geometric rule (`calipers.*`, docs/scenes.md).
    #[error("{key} = {} breaks its rule: {rule}", num(*value))]
    CaliperRule {
        /// The parameter.
        key: String,
        /// The value given, in the key's unit.
        value: f64,
        /// The geometric rule it breaks.
        rule: String,
    },
    /// A key the calipers need (the pads' radial extent) is missing while `calipers.angles_deg` is given.
    #[error("{key} is required with calipers.angles_deg (the pads' radial extent, m)")]
    CaliperKeyMissing {
        /// The missing parameter.
        key: &'static str,
    },

    /// A list whose entries must be distinct (nodal numbers, node indices) repeats one.
    #[error("{key} lists {value} more than once; each entry must be distinct")]
    Duplicate {
        /// The parameter.
        key: String,
        /// The repeated entry.
        value: i64,
    },

    /// A list of a fixed length has another.
    #[error("{key} must have {expected} elements, found {len}")]
    WrongLength {
        /// The parameter.
        key: String,
        /// Its length as given.
        len: usize,
        /// The length required.
        expected: usize,
    },

    // ---- the plate ---------------------------------------------------------
    /// r_i ≥ r_a: no annulus (paper section 4.2).
    #[error("plate.inner_radius = {} must be smaller than plate.outer_radius = {} (an annulus with r_i ≥ r_a does not exist; paper section 4.2)", num(*inner), num(*outer))]
    InnerRadiusNotBelowOuter {
        /// plate.inner_radius r_i, m.
        inner: f64,
        /// plate.outer_radius r_a, m.
        outer: f64,
    },

    /// One of the paper's two degenerate geometries (section 4.2), by [`Degeneracy`].
    #[error("{}", degenerate_text(*kind, *inner, *outer))]
    DegenerateGeometry {
        /// Which one.
        kind: Degeneracy,
        /// plate.inner_radius r_i, m.
        inner: f64,
        /// plate.outer_radius r_a, m.
        outer: f64,
    },

    /// Both plate.poisson_ratio and plate.shear_modulus are given; exactly one is allowed.
    #[error("give exactly one of plate.poisson_ratio (= {}) and plate.shear_modulus (= {}), not both", num(*poisson_ratio), num(*shear_modulus))]
    PoissonAndShearModulus {
        /// plate.poisson_ratio ν as given.
        poisson_ratio: f64,
        /// plate.shear_modulus G as given, Pa.
        shear_modulus: f64,
    },

    /// ν outside the open interval (−1, 0.5), given or derived as ν = E/(2G) − 1.
    #[error("{}", poisson_text(*nu, *from_shear_modulus))]
    PoissonRatioOutOfRange {
        /// The Poisson ratio ν.
        nu: f64,
        /// Whether ν was derived from plate.shear_modulus.
        from_shear_modulus: bool,
    },

    /// plate.radial_splines leaves fewer free B-spline coefficients than the highest requested nodal circle l needs (l + 4).
    #[error("plate.radial_splines = {splines}: the {inner}–{outer} boundaries remove {removed} B-splines, leaving {free} free coefficients, but nodal circles up to l = {max_l} need at least {} (use plate.radial_splines ≥ {needed})", max_l + 4)]
    TooFewRadialSplines {
        /// plate.radial_splines as given.
        splines: usize,
        /// The smallest count that suffices.
        needed: usize,
        /// Free coefficients left after the boundary conditions.
        free: usize,
        /// B-splines the two edges' essential conditions remove.
        removed: usize,
        /// The highest requested nodal-circle number l.
        max_l: u32,
        /// The inner edge's boundary condition, by name.
        inner: &'static str,
        /// The outer edge's boundary condition, by name.
        outer: &'static str,
    },

    /// plate.radial_splines is neither `auto` nor an integer count up to 400.
    #[error("plate.radial_splines = {found}: give `auto` (the count per nodal-diameter number that reaches plate.frequency_tolerance) or an integer count ≤ 400")]
    RadialSplinesNotAutoOrCount {
        /// The value given, as text.
        found: String,
    },

    /// plate.frequency_tolerance outside its range.
    #[error("plate.frequency_tolerance = {} must lie in [{}, {}] (a relative frequency error; below ~1e-8 double precision limits the radial discretisation, docs/convergence.md)", num(*value), num(*low), num(*high))]
    FrequencyToleranceOutOfRange {
        /// The value given (a relative frequency error).
        value: f64,
        /// The smallest allowed.
        low: f64,
        /// The largest allowed.
        high: f64,
    },

    /// A modal damping ratio ζ outside [0, 1).
    #[error("plate.damping[{index}] = {value} must lie in [0, 1) (a modal damping ratio)")]
    DampingOutOfRange {
        /// Its index in plate.damping (from 0).
        index: usize,
        /// The value given.
        value: f64,
    },

    /// plate.damping has neither 1 value nor one per mode.
    #[error("plate.damping has {len} values; give 1 (for all modes) or exactly {n_modes} (one per mode)")]
    DampingLength {
        /// Its length as given.
        len: usize,
        /// The number of modes selected.
        n_modes: usize,
    },

    /// The selection holds only rigid-body modes of a free–free plate, which the floating frame carries.
    #[error("plate.nodal_diameters × plate.nodal_circles select only the rigid-body modes {skipped:?} of a free–free plate, which the floating frame carries; select at least one elastic mode")]
    NoElasticModes {
        /// The rigid-body ⟨k, l⟩ pairs that were selected.
        skipped: Vec<(u32, u32)>,
    },

    // ---- nodes and loads ---------------------------------------------------
    /// A node coordinate ξ outside [0, 1] (paper section 4.1).
    #[error("{key}[{index}] = {value} must lie in [0, 1] (the paper's ξ coordinate, section 4.1)")]
    NodeOutOfUnitInterval {
        /// The parameter.
        key: String,
        /// Its index in the list (from 0).
        index: usize,
        /// The value given.
        value: f64,
    },

    /// Two lists that pair up element by element differ in length.
    #[error("{key_a} has {len_a} values but {key_b} has {len_b}; they must have the same length")]
    LengthMismatch {
        /// The first parameter.
        key_a: String,
        /// Its length.
        len_a: usize,
        /// The second parameter.
        key_b: String,
        /// Its length.
        len_b: usize,
    },

    /// A wrench list whose length is not 6 per node (or 0).
    #[error("{}", wrench_length_text(key, *len, *nodes))]
    WrenchLength {
        /// The parameter.
        key: String,
        /// Its length as given.
        len: usize,
        /// The nodes of its kind in the scene.
        nodes: usize,
    },

    /// A force or moment above its limit (`limits.max_force` / `limits.max_moment`).
    #[error("{key}: the {what} of node {node} (from 1) has magnitude {}, above {limit_key} = {}", num(*value), num(*limit))]
    WrenchAboveLimit {
        /// The parameter.
        key: String,
        /// The node, counted from 1.
        node: usize,
        /// `force` or `moment`.
        what: &'static str,
        /// Its magnitude, N or N m.
        value: f64,
        /// The limit's key.
        limit_key: &'static str,
        /// The limit, N or N m.
        limit: f64,
    },

    // ---- joint, reference --------------------------------------------------
    /// |joint.speed| above limits.max_speed.
    #[error("joint.speed = {} rad/s exceeds limits.max_speed = {} rad/s in magnitude", num(*speed), num(*max_speed))]
    SpeedAboveLimit {
        /// joint.speed, rad/s.
        speed: f64,
        /// limits.max_speed, rad/s.
        max_speed: f64,
    },

    /// reference.tilt with |tilt| ≥ π/2.
    #[error("reference.tilt = {tilt} rad must satisfy |tilt| < π/2")]
    TiltOutOfRange {
        /// reference.tilt, rad.
        tilt: f64,
    },

    // ---- load models (pads, tool, links) and initial state ------------------
    /// A load model names a node (counted from 1) the scene does not have.
    #[error("{key} names {kind} node {node} (nodes count from 1), but the scene has {} {kind} node(s) (nodes.{kind}_radial / nodes.{kind}_angular)", count)]
    NoSuchNode {
        /// The parameter.
        key: String,
        /// The node number given.
        node: i64,
        /// `lagrange` or `ale`.
        kind: &'static str,
        /// The nodes of that kind in the scene.
        count: usize,
    },

    /// A load model's key is given while its enabling key is empty or missing, so the model is off.
    #[error("{key} is given but {enabling_key} is empty or missing, so this load model is off; give {enabling_key} or remove {key}")]
    KeyWithoutSection {
        /// The parameter given.
        key: String,
        /// The key that switches the model on.
        enabling_key: &'static str,
    },

    /// Pads are numbered from 1 without gaps; one has no contact point.
    #[error("pads.contact_pad: pads are numbered from 1 without gaps, but pad {pad} has no contact point (pads used: 1..={pads})")]
    PadWithoutContacts {
        /// The pad without contact points (from 1).
        pad: usize,
        /// The highest pad number used.
        pads: usize,
    },

    /// pads.clamp_force has neither 1 value nor one per pad.
    #[error("pads.clamp_force has {len} values; give 1 (for every pad) or one per pad ({pads})")]
    ClampForceLength {
        /// Its length as given.
        len: usize,
        /// The number of pads.
        pads: usize,
    },

    /// pads.static_friction_coefficient with pads.contact_surface = mid_plane: μ(v) needs the faces' sliding velocity.
    #[error("pads.static_friction_coefficient is given but pads.contact_surface is mid_plane: the speed-dependent μ(v) needs the sliding velocity of the faces; set pads.contact_surface: faces or remove it")]
    StaticFrictionNeedsFaces,

    /// The pads' mass keys break one of their rules.
    #[error("{rule}")]
    PadMass {
        /// The rule broken, naming the keys.
        rule: &'static str,
    },

    /// The pads' shear keys break one of their rules.
    #[error("{rule}")]
    PadShear {
        /// The rule broken, naming the keys.
        rule: &'static str,
    },

    /// tool.ale_node is not on the rim (ξ_r ≠ 1).
    #[error("tool.ale_node = {node} is at ξ_r = {radial} (nodes.ale_radial[{}]); the tool cuts the rim, so its ALE node must be at ξ_r = 1", node - 1)]
    ToolNotOnRim {
        /// tool.ale_node (from 1).
        node: usize,
        /// Its ξ_r.
        radial: f64,
    },

    /// tool.depth_of_cut is not smaller than the annulus width r_a − r_i.
    #[error("tool.depth_of_cut = {} m reaches beyond the annulus: it must be smaller than plate.outer_radius − plate.inner_radius = {} m", num(*depth), num(*width))]
    DepthOfCutBeyondPlate {
        /// tool.depth_of_cut, m.
        depth: f64,
        /// r_a − r_i, m.
        width: f64,
    },
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
