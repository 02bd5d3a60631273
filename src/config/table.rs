//! Every parameter, declared once: name, ROS type, unit, default, rule and
//! meaning, section by section. This file holds the declaration types and the
//! configuration's own sections; each load model declares its sections with
//! the same types in its own file (`dynamics::load_models`), and
//! [`super::Parameters`] joins them. The known keys and their types, the
//! effective-parameter dump of the node's parameter service, its
//! descriptions and the reference in docs/parameters.md (and the key index in
//! the README) come from these declarations; `validate` (and each model's
//! reader) implements each section's rules as the `rule` text states them,
//! and the tests check that the declared defaults are what an empty
//! parameter file yields.

use super::ParamValue;

/// The ROS 2 parameter type of a key.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Ty {
    /// `bool`.
    Bool,
    /// `integer` (i64).
    Integer,
    /// `double` (a finite f64).
    Double,
    /// `string`.
    String,
    /// `integer[]`.
    IntegerArray,
    /// `double[]`.
    DoubleArray,
    /// `string[]`.
    StringArray,
    /// The string `auto` or an integer (`plate.radial_splines`).
    AutoOrInteger,
    /// The string `auto` or a double (`ros.marker_scale`).
    AutoOrDouble,
}

impl Ty {
    /// As an error message states what the key takes.
    pub fn expected(self) -> &'static str {
        match self {
            Ty::Bool => "a bool (true or false)",
            Ty::Integer => "an integer",
            Ty::Double => "a double",
            Ty::String => "a string",
            Ty::IntegerArray => "an integer array",
            Ty::DoubleArray => "a double array",
            Ty::StringArray => "a string array",
            Ty::AutoOrInteger => "`auto` or an integer",
            Ty::AutoOrDouble => "`auto` or a double",
        }
    }
}

/// One end of a declared numeric range.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Bound {
    /// No bound at this end.
    Open,
    /// `≥ x` (or `≤ x` as the upper end).
    Inclusive(f64),
    /// `> x` (or `< x`).
    Exclusive(f64),
}

/// The range every number of a key (each element of an array) must lie in,
/// checked by `config::check` for every source of a value; doubles must be
/// finite whatever the range. `or_zero`: 0 is accepted besides the range
/// (`simulation.realtime_factor`: 0 = as fast as possible).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Range {
    /// The lower end.
    pub min: Bound,
    /// The upper end.
    pub max: Bound,
    /// Whether 0 is accepted besides the range.
    pub or_zero: bool,
}

impl Range {
    /// Any finite number.
    pub const ANY: Range = Range {
        min: Bound::Open,
        max: Bound::Open,
        or_zero: false,
    };

    /// Whether `x` lies in the range.
    pub fn contains(&self, x: f64) -> bool {
        let low = match self.min {
            Bound::Open => true,
            Bound::Inclusive(m) => x >= m,
            Bound::Exclusive(m) => x > m,
        };
        let high = match self.max {
            Bound::Open => true,
            Bound::Inclusive(m) => x <= m,
            Bound::Exclusive(m) => x < m,
        };
        (low && high) || (self.or_zero && x == 0.0)
    }

    /// The range as an error message states it (`> 0`, `in (0, 2.5]`, `0 or in [1e-6, 1e6]`).
    pub fn text(&self) -> String {
        let n = |x: f64| {
            if x != 0.0 && (x.abs() >= 1e6 || x.abs() < 1e-4) {
                format!("{x:e}")
            } else {
                format!("{x}")
            }
        };
        let range = match (self.min, self.max) {
            (Bound::Open, Bound::Open) => "finite".to_string(),
            (Bound::Inclusive(a), Bound::Open) => format!(">= {}", n(a)),
            (Bound::Exclusive(a), Bound::Open) => format!("> {}", n(a)),
            (Bound::Open, Bound::Inclusive(b)) => format!("<= {}", n(b)),
            (Bound::Open, Bound::Exclusive(b)) => format!("< {}", n(b)),
            (lo, hi) => {
                let (l, a) = match lo {
                    Bound::Inclusive(a) => ('[', a),
                    Bound::Exclusive(a) => ('(', a),
                    Bound::Open => ('(', f64::NEG_INFINITY),
                };
                let (h, b) = match hi {
                    Bound::Inclusive(b) => (']', b),
                    Bound::Exclusive(b) => (')', b),
                    Bound::Open => (')', f64::INFINITY),
                };
                format!("in {l}{}, {}{h}", n(a), n(b))
            }
        };
        if self.or_zero {
            format!("0 or {range}")
        } else {
            range
        }
    }
}

/// A declared default value (`None`: the key has no value unless given).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Value {
    /// No default: the key has no value unless given.
    None,
    /// A bool.
    Bool(bool),
    /// An integer.
    Integer(i64),
    /// A double.
    Double(f64),
    /// A string.
    Str(&'static str),
    /// An integer array.
    Integers(&'static [i64]),
    /// A double array.
    Doubles(&'static [f64]),
}

impl Value {
    /// As a parameter value (`None` has none).
    pub fn to_param(self) -> Option<ParamValue> {
        Some(match self {
            Value::None => return None,
            Value::Bool(b) => ParamValue::Bool(b),
            Value::Integer(i) => ParamValue::Integer(i),
            Value::Double(x) => ParamValue::Double(x),
            Value::Str(s) => ParamValue::String(s.to_string()),
            Value::Integers(a) => ParamValue::IntegerArray(a.to_vec()),
            Value::Doubles(a) => ParamValue::DoubleArray(a.to_vec()),
        })
    }
}

/// One parameter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Param {
    /// The full key (`plate.inner_radius`).
    pub key: &'static str,
    /// Its ROS 2 type.
    pub ty: Ty,
    /// The type as the reference shows it (`double array (3)`).
    pub type_text: &'static str,
    /// Its SI unit (`m`, `N`; `—` for none).
    pub unit: &'static str,
    /// Its default value.
    pub default: Value,
    /// The default as the reference shows it (`0.3 (when neither is given)`).
    pub default_text: &'static str,
    /// The rule a value must satisfy, as the reference states it.
    pub rule: &'static str,
    /// What the key sets, as the reference states it.
    pub meaning: &'static str,
    /// The numeric range the rule states (`Range::ANY`: none beyond finite).
    pub range: Range,
}

impl Param {
    /// `≥ x`.
    pub const fn min(mut self, x: f64) -> Param {
        self.range.min = Bound::Inclusive(x);
        self
    }

    /// `> x`.
    pub const fn above(mut self, x: f64) -> Param {
        self.range.min = Bound::Exclusive(x);
        self
    }

    /// `≤ x`.
    pub const fn max(mut self, x: f64) -> Param {
        self.range.max = Bound::Inclusive(x);
        self
    }

    /// `< x`.
    pub const fn below(mut self, x: f64) -> Param {
        self.range.max = Bound::Exclusive(x);
        self
    }

    /// 0 is accepted besides the range.
    pub const fn or_zero(mut self) -> Param {
        self.range.or_zero = true;
        self
    }
}

/// One section of keys (`plate.*`; `""`: the top-level keys).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Section {
    /// The section's prefix (`plate`; `""` for the top-level keys).
    pub name: &'static str,
    /// The section's heading in the reference.
    pub title: &'static str,
    /// Text before the section's table in the reference.
    pub before: &'static str,
    /// Text after the section's table in the reference.
    pub after: &'static str,
    /// Its keys, in the reference's order.
    pub params: &'static [Param],
}

use self::param as p;

/// A table row: key, type, type as shown, unit, default, default as shown,
/// rule, meaning (the load models declare theirs with it in their own files).
#[allow(clippy::too_many_arguments)]
pub const fn param(
    key: &'static str,
    ty: Ty,
    type_text: &'static str,
    unit: &'static str,
    default: Value,
    default_text: &'static str,
    rule: &'static str,
    meaning: &'static str,
) -> Param {
    Param {
        key,
        ty,
        type_text,
        unit,
        default,
        default_text,
        rule,
        meaning,
        range: Range::ANY,
    }
}

/// The sections before the load models' (in the reference's order).
pub(crate) const BEFORE_LOAD_MODELS: &[Section] = &[
    Section {
        name: "plate",
        title: "`plate` — geometry, material, modal discretisation",
        before: "",
        after: "",
        params: &[
            p("plate.inner_radius", Ty::Double, "double", "m", Value::Double(0.075), "0.075", "> 0, < `plate.outer_radius`; r_i/r_a ≥ 1e-6; (r_a − r_i)/r_a ≥ 1e-3", "inner radius r_i"),
            p("plate.outer_radius", Ty::Double, "double", "m", Value::Double(0.15), "0.15", "> 0", "outer radius r_a").above(0.0),
            p("plate.thickness", Ty::Double, "double", "m", Value::Double(0.01), "0.01", "> 0", "thickness h").above(0.0),
            p("plate.density", Ty::Double, "double", "kg/m³", Value::Double(7850.0), "7850", "> 0", "mass density ρ").above(0.0),
            p("plate.youngs_modulus", Ty::Double, "double", "Pa", Value::Double(210000000000.0), "2.1e11", "> 0", "Young's modulus E").above(0.0),
            p("plate.shear_modulus", Ty::Double, "double", "Pa", Value::None, "—", "> 0; gives ν = E/(2G) − 1 (paper 4.1), which must lie in (−1, 0.5), i.e. G > E/3; not together with `plate.poisson_ratio`", "shear modulus G, as the paper's parameter").above(0.0),
            p("plate.poisson_ratio", Ty::Double, "double", "—", Value::Double(0.3), "0.3 (when neither is given)", "in (−1, 0.5) exclusive; not together with `plate.shear_modulus`", "Poisson ratio ν"),
            p("plate.inner_boundary", Ty::String, "string", "—", Value::Str("clamped"), "`clamped`", "`free`, `supported`, `clamped`, or `supported_soft` with `plate.theory: mindlin`", "boundary condition at r_i (`boundaryConditionRI`); under Mindlin theory `supported` is the hard support w = ψ_θ = 0 and `supported_soft` the soft one w = 0 (docs/mindlin.md)"),
            p("plate.outer_boundary", Ty::String, "string", "—", Value::Str("free"), "`free`", "`free`, `supported`, `clamped`, or `supported_soft` with `plate.theory: mindlin`", "boundary condition at r_a (`boundaryConditionRA`), as `plate.inner_boundary`"),
            p("plate.theory", Ty::String, "string", "—", Value::Str("kirchhoff"), "`kirchhoff`", "`kirchhoff` or `mindlin`", "plate theory of the modes: `kirchhoff` (the paper's thin plate) or `mindlin` (shear deformation and rotary inertia, for thick discs; `modes`, `simulate`, `campbell`, `stability` and the node use Mindlin modes with every load model, the pads with face kinematics z ψ; `plot` draws their deflection w, `study` measures them and compares the theories; residual flexibility at nodes acts over load patches (`plate.residual_patch_radius`), centrifugal stiffening on w; follower loads are refused naming their key — docs/mindlin.md)"),
            p("plate.shear_correction", Ty::Double, "double", "—", Value::Double(5.0 / 6.0), "5/6", "in (0, 1]", "Mindlin's shear correction κ (no effect with `plate.theory: kirchhoff`)").above(0.0).max(1.0),
            p("plate.nodal_diameters", Ty::IntegerArray, "integer array", "—", Value::Integers(&[0, 1, 2, 3, 4, 5, 6, 7]), "[0, 1, 2, 3, 4, 5, 6, 7]", "non-empty, each 0 ≤ k ≤ 200, distinct", "nodal diameter numbers k to include"),
            p("plate.nodal_circles", Ty::IntegerArray, "integer array", "—", Value::Integers(&[0, 1]), "[0, 1]", "non-empty, each 0 ≤ l ≤ 50, distinct", "nodal circle numbers l to include"),
            p("plate.damping", Ty::DoubleArray, "double array", "—", Value::Doubles(&[0.0]), "[0.0]", "each in [0, 1); length 1 (all modes) or n (one per mode, in `modes` order)", "modal damping ratios ζ"),
            p("plate.radial_splines", Ty::AutoOrInteger, "`auto` or integer", "—", Value::Str("auto"), "`auto`", "`auto`, or an integer ≤ 400 and at least `min_radial_splines` (below)", "cubic B-splines of the radial discretisation, before boundary conditions: `auto` chooses per nodal-diameter number k the count whose estimated relative frequency error of the requested l is at most `plate.frequency_tolerance` (docs/convergence.md; `modes --json` reports it per k); an integer fixes the count for every k"),
            p("plate.frequency_tolerance", Ty::Double, "double", "—", Value::Double(1e-6), "1e-6", "in [1e-9, 1e-2]", "relative frequency error the `auto` radial spline count reaches for every requested ⟨k, l⟩ (estimated by Richardson extrapolation; a count above 400 needed is an error naming this key)"),
            p("plate.centrifugal_stiffening", Ty::Bool, "bool", "—", Value::Bool(false), "false", "—", "the membrane prestress of the spinning annulus (Lamé, ∝ Ω²) stiffens the plate: geometric stiffness Ω(t)²G_k in the time integration (every integrator, `stability`) and in `campbell`, critical speeds (docs/rotor_dynamics.md)"),
            p("plate.in_plane_inner", Ty::String, "string", "—", Value::Str("auto"), "`auto`", "`auto`, `fixed` or `free`", "in-plane condition at r_i for the prestress and the in-plane modes: `fixed` u = 0 (hub), `free` σ_rr = σ_rθ = 0; `auto`: fixed when `plate.inner_boundary` is clamped or supported, free when free"),
            p("plate.in_plane_outer", Ty::String, "string", "—", Value::Str("free"), "`free`", "`fixed` or `free`", "in-plane condition at r_a for the prestress and the in-plane modes: `fixed` u = 0, `free` σ_rr = σ_rθ = 0"),
            p("plate.in_plane_nodal_diameters", Ty::IntegerArray, "integer array", "—", Value::Integers(&[]), "[]", "each 0 ≤ k ≤ 200, distinct; empty: no in-plane modes", "nodal diameter numbers k of the in-plane (plane-stress) modes that `modes` lists beside the bending modes (k = 0: a torsional and a radial family); `simulate` and `run` carry them at any joint speed with their spin terms (Coriolis coupling, centrifugal softening, prestress) on the exponential, contact_exponential and RK4 integrators, with every load model; `campbell` adds their spinning waves and critical speeds; `stability` takes them (their spin terms and the pads' friction on them; the lining's patches refused); `campbell --plot` draws them; `plot` draws the bending of a scene with them (the in-plane shapes and deformation not drawn); `study` adds their frequency axis, their static response axis and their own trajectory error (docs/in_plane.md, docs/study.md)"),
            p("plate.in_plane_orders", Ty::IntegerArray, "integer array", "—", Value::Integers(&[0, 1, 2]), "[0, 1, 2]", "non-empty, each 0 ≤ l ≤ 50, distinct", "orders l of the in-plane modes per k (and per family at k = 0), numbered by ascending frequency; radial resolution: `plate.radial_splines` per field, `auto` = 60 (docs/in_plane.md)"),
            p("plate.residual_flexibility", Ty::Bool, "bool", "—", Value::Bool(true), "true", "—", "add the truncated modes' static deflection (residual flexibility) of the transverse node forces at the node frames' outputs (docs/residual_flexibility.md)"),
            p("plate.residual_patch_radius", Ty::AutoOrDouble, "`auto` or double", "m", Value::Str("auto"), "`auto`", "`auto`, or > 0 and ≤ (`plate.outer_radius` − `plate.inner_radius`)/2; a number only with `plate.theory: mindlin`", "under Mindlin theory with residual flexibility, the half-width c of the load patch a node stands for: its force is spread uniformly over the sector |r − r₀| ≤ c, |θ − θ₀| ≤ c/r₀ and its deflection is the patch mean (a point force's Mindlin deflection is infinite); `auto` = the thickness h, Mindlin theory resolving no load finer than h (docs/residual_flexibility.md)").above(0.0),
        ],
    },
    Section {
        name: "nodes",
        title: "`nodes` — node frames (the paper's ξ, section 4.1)",
        before: "",
        after: "Nodes are numbered from 1 in the order given (`~/ale_1/wrench`, …).",
        params: &[
            p("nodes.lagrange_radial", Ty::DoubleArray, "double array", "—", Value::Doubles(&[]), "[]", "each in [0, 1]; same length as `nodes.lagrange_angular`", "ξ_r of material points turning with the plate (0 at r_i, 1 at r_a)"),
            p("nodes.lagrange_angular", Ty::DoubleArray, "double array", "—", Value::Doubles(&[]), "[]", "each in [0, 1]; same length as `nodes.lagrange_radial`", "ξ_φ of those points (0..1 for 0..2π)"),
            p("nodes.ale_radial", Ty::DoubleArray, "double array", "—", Value::Doubles(&[]), "[]", "each in [0, 1]; same length as `nodes.ale_angular`", "ξ_r of space-fixed points the plate slides under"),
            p("nodes.ale_angular", Ty::DoubleArray, "double array", "—", Value::Doubles(&[]), "[]", "each in [0, 1]; same length as `nodes.ale_radial`", "ξ_φ of those points"),
            p("nodes.lagrange_surface", Ty::StringArray, "string array", "—", Value::None, "all `mid`", "each `top`, `bottom` or `mid`; same length as `nodes.lagrange_radial`", "the face each Lagrangian node sits on: z = +h/2, −h/2 or the mid-plane; a wrench there acts through the face kinematics (an in-plane force F at z adds −z F·∇w_i) and its /tf pose is on the face"),
            p("nodes.ale_surface", Ty::StringArray, "string array", "—", Value::None, "all `mid`", "each `top`, `bottom` or `mid`; same length as `nodes.ale_radial`", "the face each ALE node sits on (as `nodes.lagrange_surface`)"),
        ],
    },
    Section {
        name: "loads",
        title: "`loads` — constant wrenches held from t = 0",
        before: "",
        after: "",
        params: &[
            p("loads.ale_wrench", Ty::DoubleArray, "double array", "N, N·m", Value::Doubles(&[]), "[]", "empty or 6 × (number of ALE nodes); finite; per node ‖f‖ ≤ `limits.max_force`, ‖m‖ ≤ `limits.max_moment`", "`fx fy fz mx my mz` per ALE node, in the node frame; empty: zero"),
            p("loads.lagrange_wrench", Ty::DoubleArray, "double array", "N, N·m", Value::Doubles(&[]), "[]", "as above, per Lagrangian node", "`fx fy fz mx my mz` per Lagrangian node"),
            p("loads.follower", Ty::Bool, "bool", "—", Value::Bool(false), "false", "—", "wrenches turn with the deformed surface (follower loads, paper 5.3)"),
        ],
    },
    Section {
        name: "joint",
        title: "`joint` — the rotational joint at the plate axis",
        before: "",
        after: "",
        params: &[
            p("joint.speed", Ty::Double, "double", "rad/s", Value::Double(0.0), "0", "finite, \\|Ω\\| ≤ `limits.max_speed`", "commanded speed Ω; held from t = 0 and the plate starts at it"),
            p("joint.max_acceleration", Ty::Double, "double", "rad/s²", Value::Double(50.0), "50", "> 0", "acceleration limit of the drive").above(0.0),
            p("joint.max_torque", Ty::Double, "double", "N·m", Value::None, "none (stiff drive)", "> 0 when given", "torque limit of the drive; omitted: the joint follows its command kinematically").above(0.0),
            p("joint.initial_position", Ty::Double, "double", "rad", Value::Double(0.0), "0", "finite", "initial joint angle χ(0)"),
        ],
    },
    Section {
        name: "reference",
        title: "`reference` — prescribed motion of the reference frame",
        before: "",
        after: "",
        params: &[
            p("reference.tilt", Ty::Double, "double", "rad", Value::Double(0.0), "0", "\\|tilt\\| < π/2", "constant tilt of the spin axis about the world x axis"),
            p("reference.angular_velocity", Ty::DoubleArray, "double array (3)", "rad/s", Value::Doubles(&[0.0, 0.0, 0.0]), "[0, 0, 0]", "3 finite values", "constant angular velocity of the reference frame, reference axes"),
            p("reference.acceleration", Ty::DoubleArray, "double array (3)", "m/s²", Value::Doubles(&[0.0, 0.0, 0.0]), "[0, 0, 0]", "3 finite values", "constant linear acceleration of the reference origin, reference axes"),
        ],
    },
    Section {
        name: "",
        title: "Top level",
        before: "",
        after: "",
        params: &[
            p("gravity", Ty::DoubleArray, "double array (3)", "m/s²", Value::Doubles(&[0.0, 0.0, 0.0]), "[0, 0, 0]", "3 finite values", "gravity in the world frame (the reference frame before its tilt)"),
            p("use_sim_time", Ty::Bool, "bool", "—", Value::Bool(false), "false", "bool", "the standard ROS 2 parameter every node has (often set for all nodes under `/**`): the node follows an external /clock — stamps from it, one step of dt per dt it advances, no step while it stands still (docs/ros.md, Time); accepted here, used by the node only"),
        ],
    },
    Section {
        name: "simulation",
        title: "`simulation`",
        before: "",
        after: "",
        params: &[
            p("simulation.rate_hz", Ty::Double, "double", "Hz", Value::Double(1000.0), "1000", "≥ 1e-3, ≤ 1e6", "fixed step and output rate").min(1e-3).max(1e6),
            p("simulation.substeps", Ty::Integer, "integer", "—", Value::Integer(1), "1", "1 ..= 10000", "integration sub-steps per output step").min(1.0).max(10000.0),
            p("simulation.integrator", Ty::String, "string", "—", Value::Str("exponential"), "`exponential`", "`exponential`, `implicit_midpoint`, `rk4` or `contact_exponential`", "time integration scheme (exact exponential per mode for held loads; A-stable energy-conserving implicit midpoint; classical Runge–Kutta 4, sub-stepping below its stability limit; the exponential of the stiff contacts' linearisation on their active set, switches located inside the step: docs/dynamics.md, \"Stiff contacts\")"),
            p("simulation.coordinates", Ty::String, "string", "—", Value::Str("ale"), "`ale`", "`ale` or `lagrangian`", "modal amplitudes integrated in the non-rotating frame (ALE, eq. 20) or in the rotating plate frame"),
            p("simulation.realtime_factor", Ty::Double, "double", "—", Value::Double(1.0), "1", "0, or in [1e-6, 1e6]", "1 = wall clock, 0 = as fast as possible (the node only; can be set while it runs)").min(1e-6).max(1e6).or_zero(),
            p("simulation.publish_divisor", Ty::Integer, "integer", "—", Value::Integer(1), "1", "≥ 1", "publish every n-th step (the node only)").min(1.0).max(4294967295.0),
            p("simulation.rk4_step_limit", Ty::Double, "double", "—", Value::Double(0.2), "0.2", "> 0, ≤ 2.5", "`rk4` sub-steps itself so that h·λ_max stays below this; its amplitude error per step is (hω)⁶/144 (config/brake_squeal_paper.yaml uses 0.1, config/brake_squeal.yaml 0.0425: a growing squeal amplifies it)").above(0.0).max(super::MAX_RK4_STEP_LIMIT),
            p("simulation.midpoint_step_limit", Ty::Double, "double", "—", Value::Double(0.5), "0.5", "> 0, ≤ 1e6", "`implicit_midpoint` sub-steps itself so that h·λ_max stays below this: the fastest mode's frequency is then within 1 − 2·atan(x/2)/x (2.0 % at 0.5), slower ones within (hω)²/12; a huge value accepts unresolved modes (A-stable, they ring without numerical damping)").above(0.0).max(super::MAX_MIDPOINT_STEP_LIMIT),
            p("simulation.contact_tolerance", Ty::Double, "double", "—", Value::Double(1.0e-9), "1e-9", "≥ 1e-14, ≤ 1", "`contact_exponential`: the local error allowed per span for what the step holds beyond the contacts' linearisation (friction direction, follower terms, the law's curvature), relative to the largest amplitude (rate) of the state; spans are halved until it holds (docs/dynamics.md, \"Stiff contacts\")").min(super::MIN_CONTACT_TOLERANCE).max(1.0),
        ],
    },
    Section {
        name: "limits",
        title: "`limits` — plausibility limits",
        before: "",
        after: "",
        params: &[
            p("limits.max_force", Ty::Double, "double", "N", Value::Double(10000000.0), "1e7", "> 0", "larger forces (per node, magnitude) are rejected as absurd").above(0.0),
            p("limits.max_moment", Ty::Double, "double", "N·m", Value::Double(1000000.0), "1e6", "> 0", "larger moments (per node, magnitude) are rejected as absurd").above(0.0),
            p("limits.max_speed", Ty::Double, "double", "rad/s", Value::Double(10000.0), "1e4", "> 0, ≤ 1e6", "larger joint speeds are rejected (also the speeds of `stability`)").above(0.0).max(1e6),
            p("limits.max_deflection_thicknesses", Ty::Double, "double", "—", Value::Double(1000.0), "1e3", "> 0", "divergence guard: a modal amplitude beyond this many plate thicknesses stops the run").above(0.0),
        ],
    },
];

/// The sections after the load models'.
pub(crate) const AFTER_LOAD_MODELS: &[Section] = &[
    Section {
        name: "initial",
        title: "`initial` — initial elastic state",
        before: "",
        after: "",
        params: &[
            p("initial.q", Ty::DoubleArray, "double array", "m", Value::Doubles(&[]), "[] (at rest)", "empty or one per mode; \\|q\\| ≤ `limits.max_deflection_thicknesses` × thickness", "Lagrangian modal amplitudes at t = 0, in `modes` order"),
            p("initial.q_dot", Ty::DoubleArray, "double array", "m/s", Value::Doubles(&[]), "[]", "empty or one per mode", "their rates at t = 0"),
        ],
    },
    Section {
        name: "ros",
        title: "`ros` — the node's own keys (checked by the node; accepted by `modes`/`simulate`)",
        before: "",
        after: "Also the standard `use_sim_time` (see above). Topics, services and QoS: [docs/ros.md](ros.md).",
        params: &[
            p("ros.frame_prefix", Ty::String, "string", "—", Value::Str(""), "\"\"", "prefix of every frame and joint name; letters, digits, `_`, `/`, `-`, `.`; not starting with `/`", ""),
            p("ros.world_frame", Ty::String, "string", "—", Value::Str("world"), "\"world\"", "parent of plate_base in /tf_static (not prefixed); non-empty, same characters", ""),
            p("ros.publish_clock", Ty::Bool, "bool", "—", Value::Bool(false), "false", "publish /clock and stamp outputs with the node's own simulated time; refused together with use_sim_time: true (that node follows another clock)", ""),
            p("ros.wrench_timeout", Ty::Double, "double", "s", Value::Double(0.0), "0.0", "s of simulated time after which a wrench not renewed drops to zero; 0 = hold forever; finite, >= 0", "").min(0.0),
            p("ros.max_clock_jump", Ty::Double, "double", "s", Value::Double(1.0), "1.0", "with use_sim_time: a /clock message more than this many s of simulated time ahead of the previous one is a jump: the node re-anchors its stamps at the new time instead of stepping through the gap (logged and counted, WARN on /diagnostics; docs/ros.md, Time); finite, > 0, <= 1e9", "").above(0.0).max(1e9),
            p("ros.start_paused", Ty::Bool, "bool", "—", Value::Bool(false), "false", "start paused (resume with ~/set_paused, advance with ~/step)", ""),
            p("ros.diagnostics_period", Ty::Double, "double", "s", Value::Double(1.0), "1.0", "s of wall time between /diagnostics messages; finite, > 0, <= 1e6", "").above(0.0).max(1e6),
            p("ros.reject_log_period", Ty::Double, "double", "s", Value::Double(1.0), "1.0", "s of wall time between log lines about rejected inputs of one kind; finite, >= 0, <= 1e6", "").min(0.0).max(1e6),
            p("ros.service_mapping", Ty::String, "string", "—", Value::Str("enhanced"), "\"enhanced\"", "request/reply mapping of all services: enhanced (rmw_fastrtps, the Jazzy default), cyclone (rmw_cyclonedds_cpp) or basic", ""),
            p("ros.input_reception", Ty::String, "string", "—", Value::Str("on_arrival"), "\"on_arrival\"", "how the node reads input datagrams: `on_arrival` (as they come), or `step_aligned` (at step boundaries while the input topics bring more than 2.5 samples a step: less CPU with many per-topic inputs, more step-period jitter; docs/ros.md)", ""),
            p("ros.marker_rate_hz", Ty::Double, "double", "Hz", Value::Double(30.0), "30.0", "`~/plate_marker` (the deformed plate for RViz/Foxglove) per second, decimated from the loop (every round(rate_hz / this) steps); 0 = off; finite, >= 0, <= simulation.rate_hz", "").min(0.0),
            p("ros.marker_rings", Ty::Integer, "integer", "—", Value::Integer(8), "8", "radial cells of the marker's mesh; 1 ..= 200, rings × sectors <= 20000", "").min(1.0).max(200.0),
            p("ros.marker_sectors", Ty::Integer, "integer", "—", Value::Integer(128), "128", "angular cells of the marker's mesh (2 triangles each); 8 ..= 4096", "").min(8.0).max(4096.0),
            p("ros.marker_scale", Ty::AutoOrDouble, "string or double", "—", Value::Str("auto"), "\"auto\"", "magnification of the drawn deflection: `auto` (the largest of the last second drawn as 5 % of the outer radius) or a finite number > 0", "").above(0.0),
        ],
    },
];
