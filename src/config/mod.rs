//! Configuration: one validated struct tree read from a ROS 2 parameter file.
//!
//! Data flows one way: `config` → `model` → `dynamics` → `ros` / `cli`.
//! Every value is in SI units. [`Config::from_params_file`] reads the file
//! (`<node name or /**>: ros__parameters: ...`, nested maps or dotted names,
//! flat arrays only), rejects unknown keys and checks every rule; errors name
//! the key (`plate.inner_radius`) and the rule.

mod centrifugal;
mod check;
mod declarations;
pub(crate) mod defaults;
mod error;
pub mod model_sections;
mod params_file;
mod plate_section;
mod raw;
mod simulation;
pub mod table;
mod text_limits;
mod validate;

pub use centrifugal::{CentrifugalConfig, InPlaneInner, InPlaneOuter};
#[cfg(feature = "ros")] // the ROS settings read them
pub(crate) use check::{declared_value, typed, Declared};
pub use declarations::{ModelParameters, Parameters};
pub use error::{ConfigError, Degeneracy};
pub(crate) use model_sections::SectionContext;
pub use model_sections::{LoadModelSection, LoadModelSections, SectionData};
pub use params_file::{ParamValue, Params};
pub(crate) use raw::Reader;
pub use simulation::{Coordinates, IntegratorKind, SimulationConfig};
pub(crate) use simulation::{MAX_MIDPOINT_STEP_LIMIT, MAX_RK4_STEP_LIMIT, MIN_CONTACT_TOLERANCE};

use serde::Serialize;

/// Boundary condition at one edge of the annulus (paper section 4.1,
/// `boundaryConditionRI` / `boundaryConditionRA`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Boundary {
    /// No essential condition; moment and Kirchhoff shear vanish naturally.
    Free,
    /// Simply supported: w = 0; the radial moment vanishes naturally. Under
    /// Mindlin theory the hard support w = ψ_θ = 0 (docs/mindlin.md).
    Supported,
    /// w = 0 and ∂w/∂r = 0 (Mindlin: w = ψ_r = ψ_θ = 0).
    Clamped,
    /// Mindlin theory only: the soft support w = 0, M_r = M_rθ = 0 (the
    /// normal may twist about it); refused under Kirchhoff theory.
    SupportedSoft,
}

impl Boundary {
    /// Every edge condition.
    pub const ALL: [Boundary; 4] = [
        Boundary::Free,
        Boundary::Supported,
        Boundary::Clamped,
        Boundary::SupportedSoft,
    ];
    /// The edge conditions of Kirchhoff theory (all but `supported_soft`).
    pub const KIRCHHOFF: [Boundary; 3] = [Boundary::Free, Boundary::Supported, Boundary::Clamped];

    /// The parameter value (`free`, `supported`, `clamped`, `supported_soft`).
    pub fn name(self) -> &'static str {
        match self {
            Boundary::Free => "free",
            Boundary::Supported => "supported",
            Boundary::Clamped => "clamped",
            Boundary::SupportedSoft => "supported_soft",
        }
    }

    /// From the parameter value; `None` for any other text.
    pub fn from_name(s: &str) -> Option<Self> {
        Boundary::ALL.into_iter().find(|b| b.name() == s)
    }

    /// B-splines the essential conditions of this edge remove from the radial
    /// basis of w: free 0, supported 1 (w = 0), clamped 2 (w = ∂w/∂r = 0);
    /// `supported_soft` (Mindlin only) 1.
    pub fn essential_conditions(self) -> usize {
        match self {
            Boundary::Free => 0,
            Boundary::Supported | Boundary::SupportedSoft => 1,
            Boundary::Clamped => 2,
        }
    }
}

/// The plate theory of the modes (`plate.theory`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum PlateTheory {
    /// Thin plate (the paper's model): rotations −∇w, no rotary inertia.
    Kirchhoff,
    /// First-order shear deformation with rotary inertia (docs/mindlin.md).
    Mindlin,
}

impl PlateTheory {
    /// The names `plate.theory` takes.
    pub const NAMES: &'static [&'static str] = &["kirchhoff", "mindlin"];

    /// `kirchhoff` or `mindlin`.
    pub fn name(self) -> &'static str {
        match self {
            PlateTheory::Kirchhoff => "kirchhoff",
            PlateTheory::Mindlin => "mindlin",
        }
    }

    /// The theory named `s`, if any.
    pub fn from_name(s: &str) -> Option<Self> {
        [PlateTheory::Kirchhoff, PlateTheory::Mindlin]
            .into_iter()
            .find(|t| t.name() == s)
    }
}

/// The plate: geometry, material and modal discretisation (`plate.*`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PlateConfig {
    /// r_i, m.
    pub inner_radius: f64,
    /// r_a, m.
    pub outer_radius: f64,
    /// h, m.
    pub thickness: f64,
    /// ρ, kg/m³.
    pub density: f64,
    /// E, Pa.
    pub youngs_modulus: f64,
    /// ν (given directly, or from the shear modulus as ν = E/2G − 1).
    pub poisson_ratio: f64,
    /// Boundary condition at r_i (`plate.inner_boundary`).
    pub inner_boundary: Boundary,
    /// Boundary condition at r_a (`plate.outer_boundary`).
    pub outer_boundary: Boundary,
    /// Nodal diameters k, as given (distinct, not sorted).
    pub nodal_diameters: Vec<u32>,
    /// Nodal circles l, as given (distinct, not sorted).
    pub nodal_circles: Vec<u32>,
    /// Modal damping ratios ζ: one for all modes, or one per mode in `modes` order.
    pub damping: Vec<f64>,
    /// Cubic B-splines of the radial discretisation (before boundary
    /// conditions): a fixed count, or chosen per nodal-diameter number k
    /// (`auto`, docs/convergence.md "Radial resolution that follows the request").
    pub radial_splines: RadialSplines,
    /// Relative frequency error the `auto` spline count aims at, for every
    /// requested ⟨k, l⟩ (`plate.frequency_tolerance`).
    pub frequency_tolerance: f64,
    /// Add the truncated modes' static deflection at the node frames
    /// (`plate.residual_flexibility`, docs/residual_flexibility.md).
    pub residual_flexibility: bool,
    /// Half-width c of a node's load patch under Mindlin theory, m
    /// (`plate.residual_patch_radius`; None: `auto`, see
    /// [`PlateConfig::residual_patch_half_width`]).
    pub residual_patch_radius: Option<f64>,
    /// Kirchhoff or Mindlin modes (`plate.theory`).
    pub theory: PlateTheory,
    /// Mindlin's shear correction κ (`plate.shear_correction`; no effect
    /// under Kirchhoff theory).
    pub shear_correction: f64,
    /// Nodal diameters k of the in-plane modes, as given (distinct; empty:
    /// none), `plate.in_plane_nodal_diameters` (docs/in_plane.md).
    pub in_plane_nodal_diameters: Vec<u32>,
    /// Orders l of the in-plane modes per k, as given (distinct, non-empty),
    /// `plate.in_plane_orders`.
    pub in_plane_orders: Vec<u32>,
}

/// Bending rigidity D = E h³ / (12 (1 − ν²)), eq. (2).
pub fn bending_rigidity(youngs_modulus: f64, thickness: f64, poisson_ratio: f64) -> f64 {
    youngs_modulus * thickness.powi(3) / (12.0 * (1.0 - poisson_ratio * poisson_ratio))
}

impl PlateConfig {
    /// The paper's Table 1 / lathe disc: the declared defaults of the
    /// `plate.*` keys ([`table`]).
    pub fn lathe_disc() -> Self {
        use defaults::{default_bool, default_f64, default_f64s, default_i64s, default_str};
        let boundary = |key| {
            Boundary::from_name(default_str(key))
                .expect("a declared boundary default is a boundary")
        };
        let indices = |key| default_i64s(key).iter().map(|&i| i as u32).collect();
        PlateConfig {
            inner_radius: const { default_f64("plate.inner_radius") },
            outer_radius: const { default_f64("plate.outer_radius") },
            thickness: const { default_f64("plate.thickness") },
            density: const { default_f64("plate.density") },
            youngs_modulus: const { default_f64("plate.youngs_modulus") },
            poisson_ratio: const { default_f64("plate.poisson_ratio") },
            inner_boundary: boundary("plate.inner_boundary"),
            outer_boundary: boundary("plate.outer_boundary"),
            nodal_diameters: indices("plate.nodal_diameters"),
            nodal_circles: indices("plate.nodal_circles"),
            damping: default_f64s("plate.damping").to_vec(),
            radial_splines: RadialSplines::from_declared_default(),
            frequency_tolerance: DEFAULT_FREQUENCY_TOLERANCE,
            residual_flexibility: const { default_bool("plate.residual_flexibility") },
            residual_patch_radius: None,
            theory: PlateTheory::from_name(default_str("plate.theory"))
                .expect("the declared default is a theory"),
            shear_correction: const { default_f64("plate.shear_correction") },
            in_plane_nodal_diameters: indices("plate.in_plane_nodal_diameters"),
            in_plane_orders: indices("plate.in_plane_orders"),
        }
    }

    /// The half-width c of a node's load patch under Mindlin theory
    /// (docs/residual_flexibility.md): `plate.residual_patch_radius`, or for
    /// `auto` the thickness h (Mindlin theory does not resolve a load finer
    /// than h: a load spreads about 45° through the thickness), at most half
    /// the annulus' width.
    pub fn residual_patch_half_width(&self) -> f64 {
        self.residual_patch_radius.unwrap_or_else(|| {
            self.thickness
                .min(0.5 * (self.outer_radius - self.inner_radius))
        })
    }

    /// Smallest `radial_splines` that resolves the highest requested nodal
    /// circle: after the essential conditions remove B-splines at each edge
    /// ([`Boundary::essential_conditions`]), at least max(l) + 4 free
    /// coefficients must remain (and at least 4 B-splines in total).
    pub fn min_radial_splines(&self) -> usize {
        let max_l = self.nodal_circles.iter().copied().max().unwrap_or(0) as usize;
        let removed =
            self.inner_boundary.essential_conditions() + self.outer_boundary.essential_conditions();
        (max_l + 4 + removed).max(4)
    }

    /// Number of elastic modes: each ⟨k, l⟩ gives one mode for k = 0 and a
    /// cos/sin pair for k ≥ 1; a free–free plate skips its rigid-body motions
    /// ⟨0, 0⟩ (one) and ⟨1, 0⟩ (two) when requested.
    pub fn mode_count(&self) -> usize {
        let per_circle_set: usize = self
            .nodal_diameters
            .iter()
            .map(|&k| if k == 0 { 1 } else { 2 })
            .sum();
        let mut n = per_circle_set * self.nodal_circles.len();
        if self.inner_boundary == Boundary::Free
            && self.outer_boundary == Boundary::Free
            && self.nodal_circles.contains(&0)
        {
            if self.nodal_diameters.contains(&0) {
                n -= 1;
            }
            if self.nodal_diameters.contains(&1) {
                n -= 2;
            }
        }
        n
    }

    /// Explanations (not errors) of geometries near the degenerate cases of
    /// the paper's section 4.2; empty for an ordinary annulus.
    pub fn geometry_notes(&self) -> Vec<String> {
        let (ri, ra) = (self.inner_radius, self.outer_radius);
        let mut notes = Vec::new();
        if ri / ra < 0.01 {
            notes.push(match self.inner_boundary {
                Boundary::Free => format!(
                    "r_i/r_a = {:.3e} < 0.01 with a free inner edge: the model approaches the solid circular plate, \
                     but the displacements of different points of the inner edge need not coincide, so they do not \
                     satisfy the compatibility conditions exactly (paper section 4.2)",
                    ri / ra
                ),
                b => format!(
                    "r_i/r_a = {:.3e} < 0.01 with a {} inner edge: this is a plate pinned at its centre (a point \
                     support), not a solid circular plate; its k = 1 modes approach their limit only like \
                     1/ln(r_a/r_i) (docs/hard_cases.md). Knots are graded towards the hole to resolve it",
                    ri / ra,
                    b.name()
                ),
            });
        }
        if self.theory == PlateTheory::Kirchhoff && self.thickness > 0.25 * (ra - ri) {
            notes.push(format!(
                "plate.thickness = {} m is more than a quarter of the width r_a − r_i = {} m: outside Kirchhoff plate \
                 theory (shear deformation and rotary inertia would lower the frequencies); the model computes the \
                 Kirchhoff plate exactly",
                self.thickness,
                ra - ri
            ));
        }
        if (ra - ri) / ra < 0.02 {
            notes.push(format!(
                "(r_a − r_i)/r_a = {:.3e} < 0.02: a narrow ring is very stiff and its eigenfrequencies are high \
                 (they go to infinity as r_i → r_a, paper section 4.2); the time step must resolve them",
                (ra - ri) / ra
            ));
        }
        notes
    }
}

/// The count the
/// `auto` search starts from for the first k (`plate.radial_splines`).
pub(crate) const DEFAULT_RADIAL_SPLINES: usize = 32;

/// Default of `plate.frequency_tolerance` (its declaration).
pub(crate) const DEFAULT_FREQUENCY_TOLERANCE: f64 =
    defaults::default_f64("plate.frequency_tolerance");

/// `plate.radial_splines`: `auto` (the default) or a fixed count.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RadialSplines {
    /// Per nodal-diameter number k, the count whose estimated relative
    /// frequency error of the requested l is at most `plate.frequency_tolerance`.
    Auto,
    /// The same count for every k.
    Fixed(usize),
}

impl RadialSplines {
    /// The declared default of `plate.radial_splines` (`auto` or a count).
    pub fn from_declared_default() -> Self {
        match defaults::default_of("plate.radial_splines") {
            table::Value::Integer(n) => RadialSplines::Fixed(n as usize),
            _ => RadialSplines::Auto,
        }
    }

    /// The fixed count, or `None` for `auto`.
    pub fn fixed(self) -> Option<usize> {
        match self {
            RadialSplines::Auto => None,
            RadialSplines::Fixed(n) => Some(n),
        }
    }
}

impl RadialSplines {
    /// A fixed count raised to at least `min`; `auto` unchanged (it starts at the minimum).
    pub fn at_least(self, min: usize) -> Self {
        match self {
            RadialSplines::Auto => RadialSplines::Auto,
            RadialSplines::Fixed(n) => RadialSplines::Fixed(n.max(min)),
        }
    }
}

/// Serialised as the parameter is written: `"auto"` or the count.
impl Serialize for RadialSplines {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self {
            RadialSplines::Auto => s.serialize_str("auto"),
            RadialSplines::Fixed(n) => s.serialize_u64(*n as u64),
        }
    }
}

impl std::fmt::Display for RadialSplines {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            RadialSplines::Auto => write!(f, "auto"),
            RadialSplines::Fixed(n) => write!(f, "{n}"),
        }
    }
}

/// A point on the mid-plane in the paper's ξ coordinates (section 4.1):
/// radial ξ_r ∈ [0, 1] from r_i to r_a, angular ξ_φ ∈ [0, 1] for 0..2π.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct NodePosition {
    /// ξ_r ∈ [0, 1]: r = r_i + ξ_r (r_a − r_i).
    pub radial: f64,
    /// ξ_φ ∈ [0, 1]: φ = 2π ξ_φ.
    pub angular: f64,
}

/// Where through the thickness a node frame sits (`nodes.ale_surface`,
/// `nodes.lagrange_surface`): a Kirchhoff plate's face point at z moves
/// in-plane by −z∇w (docs/dynamics.md, "Node frames on a face").
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Surface {
    /// z = +h/2.
    Top,
    /// z = −h/2.
    Bottom,
    /// z = 0 (the paper's node frames).
    #[default]
    Mid,
}

impl Surface {
    /// The parameter value (`top`, `bottom`, `mid`).
    pub fn name(self) -> &'static str {
        match self {
            Surface::Top => "top",
            Surface::Bottom => "bottom",
            Surface::Mid => "mid",
        }
    }

    /// z of the surface for a plate of thickness `h`, m.
    pub fn z(self, thickness: f64) -> f64 {
        match self {
            Surface::Top => 0.5 * thickness,
            Surface::Bottom => -0.5 * thickness,
            Surface::Mid => 0.0,
        }
    }
}

/// Node frames (`nodes.*`).
#[derive(Debug, Clone, PartialEq, Default, Serialize)]
pub struct NodesConfig {
    /// Material points turning with the plate.
    pub lagrange: Vec<NodePosition>,
    /// Space-fixed points the plate slides under.
    pub ale: Vec<NodePosition>,
    /// The surface of each Lagrangian node (empty or shorter: `mid` for the rest).
    pub lagrange_surface: Vec<Surface>,
    /// The surface of each ALE node (empty or shorter: `mid` for the rest).
    pub ale_surface: Vec<Surface>,
}

impl NodesConfig {
    /// The surface of Lagrangian node `j` (0-based).
    pub fn lagrange_surface(&self, j: usize) -> Surface {
        self.lagrange_surface.get(j).copied().unwrap_or_default()
    }
    /// The surface of ALE node `j` (0-based).
    pub fn ale_surface(&self, j: usize) -> Surface {
        self.ale_surface.get(j).copied().unwrap_or_default()
    }
}

/// A wrench: force (N) and moment (N·m), in the node frame.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct WrenchConfig {
    /// Force (f_x, f_y, f_z), N, in the node frame.
    pub force: [f64; 3],
    /// Moment (m_x, m_y, m_z), N m, in the node frame.
    pub moment: [f64; 3],
}

/// Constant wrenches held from t = 0 (`loads.*`), one per node (zero where not given).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LoadsConfig {
    /// One wrench per ALE node (`loads.ale_wrench`).
    pub ale: Vec<WrenchConfig>,
    /// One wrench per Lagrangian node (`loads.lagrange_wrench`).
    pub lagrange: Vec<WrenchConfig>,
    /// Wrenches turn with the deformed surface (follower loads, paper 5.3).
    pub follower: bool,
}

/// No wrenches; `loads.follower` as declared ([`table`]).
impl Default for LoadsConfig {
    fn default() -> Self {
        LoadsConfig {
            ale: Vec::new(),
            lagrange: Vec::new(),
            follower: const { defaults::default_bool("loads.follower") },
        }
    }
}

/// The rotational joint at the plate axis (`joint.*`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct JointConfig {
    /// Commanded speed Ω, rad/s; held from t = 0 and the plate starts at it.
    pub speed: f64,
    /// Acceleration limit of the drive, rad/s² (> 0).
    pub max_acceleration: f64,
    /// Torque limit of the drive, N·m; `None`: the drive is stiff (kinematic).
    pub max_torque: Option<f64>,
    /// Initial joint angle χ(0), rad.
    pub initial_position: f64,
}

/// The declared defaults of the `joint.*` keys ([`table`]).
impl Default for JointConfig {
    fn default() -> Self {
        use defaults::default_f64;
        JointConfig {
            speed: const { default_f64("joint.speed") },
            max_acceleration: const { default_f64("joint.max_acceleration") },
            max_torque: None,
            initial_position: const { default_f64("joint.initial_position") },
        }
    }
}

/// Prescribed motion of the reference frame (`reference.*`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ReferenceConfig {
    /// Constant tilt of the spin axis about the world x axis, rad.
    pub tilt: f64,
    /// Constant angular velocity of the reference frame, rad/s, in reference-frame axes.
    pub angular_velocity: [f64; 3],
    /// Constant linear acceleration of the reference frame origin, m/s², reference axes.
    pub acceleration: [f64; 3],
}

/// The declared defaults of the `reference.*` keys ([`table`]).
impl Default for ReferenceConfig {
    fn default() -> Self {
        let vec3 = |key| {
            <[f64; 3]>::try_from(defaults::default_f64s(key)).expect("declared with 3 values")
        };
        ReferenceConfig {
            tilt: const { defaults::default_f64("reference.tilt") },
            angular_velocity: vec3("reference.angular_velocity"),
            acceleration: vec3("reference.acceleration"),
        }
    }
}

/// Input plausibility limits (`limits.*`): larger wrenches are rejected as absurd.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LimitsConfig {
    /// N.
    pub max_force: f64,
    /// N·m.
    pub max_moment: f64,
    /// rad/s.
    pub max_speed: f64,
    /// Divergence guard: a modal amplitude beyond this many plate thicknesses stops the run.
    pub max_deflection_thicknesses: f64,
}

/// The declared defaults of the `limits.*` keys ([`table`]).
impl Default for LimitsConfig {
    fn default() -> Self {
        use defaults::default_f64;
        LimitsConfig {
            max_force: const { default_f64("limits.max_force") },
            max_moment: const { default_f64("limits.max_moment") },
            max_speed: const { default_f64("limits.max_speed") },
            max_deflection_thicknesses: const { default_f64("limits.max_deflection_thicknesses") },
        }
    }
}

/// Initial elastic state (`initial.*`): Lagrangian amplitudes and rates at t = 0
/// in `modes` order; empty: at rest.
#[derive(Debug, Clone, PartialEq, Default, Serialize)]
pub struct InitialConfig {
    /// Lagrangian modal amplitudes at t = 0, m (`initial.q`).
    pub q: Vec<f64>,
    /// Their rates at t = 0, m/s (`initial.q_dot`).
    pub q_dot: Vec<f64>,
}

/// The whole validated configuration.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Config {
    /// The plate (`plate.*`).
    pub plate: PlateConfig,
    /// The node frames (`nodes.*`).
    pub nodes: NodesConfig,
    /// The held wrenches (`loads.*`).
    pub loads: LoadsConfig,
    /// The rotational joint at the axis (`joint.*`).
    pub joint: JointConfig,
    /// The motion of the reference frame (`reference.*`).
    pub reference: ReferenceConfig,
    /// m/s², in the world frame (the reference frame before its tilt).
    pub gravity: [f64; 3],
    /// Rate, integrator and coordinates (`simulation.*`).
    pub simulation: SimulationConfig,
    /// The plausibility limits of inputs and state (`limits.*`).
    pub limits: LimitsConfig,
    /// The load models' validated sections (each declared and read in its
    /// model's own file); a model is on when its section is here.
    pub load_models: LoadModelSections,
    /// Initial elastic state (`initial.*`).
    pub initial: InitialConfig,
    /// Centrifugal stiffening and the in-plane edge conditions
    /// (`plate.centrifugal_stiffening`, `plate.in_plane_inner`, `plate.in_plane_outer`).
    pub centrifugal: CentrifugalConfig,
}

/// Reading a parameter file into a `Config` needs every declaration, the
/// load models' too: `Config::from_params` and its companions are defined
/// with the registry (`dynamics::load_models::parameters`), on
/// [`Parameters::config`].
impl Config {
    /// The load model section of type `T`, if the scene has it.
    pub fn section<T: LoadModelSection>(&self) -> Option<&T> {
        self.load_models.get::<T>()
    }

    /// The load model section of type `T`, to change.
    pub fn section_mut<T: LoadModelSection>(&mut self) -> Option<&mut T> {
        self.load_models.get_mut::<T>()
    }

    /// Set (or replace) a load model's section: the scene runs with that model.
    pub fn set_section<T: LoadModelSection>(&mut self, section: T) {
        self.load_models.set(section.boxed());
    }
}

/// The documented defaults (docs/parameters.md): what an empty
/// `ros__parameters: {}` yields.
impl Default for Config {
    fn default() -> Self {
        Config {
            plate: PlateConfig::lathe_disc(),
            nodes: NodesConfig::default(),
            loads: LoadsConfig::default(),
            joint: JointConfig::default(),
            reference: ReferenceConfig::default(),
            gravity: <[f64; 3]>::try_from(defaults::default_f64s("gravity"))
                .expect("gravity is declared with 3 values"),
            simulation: SimulationConfig::default(),
            limits: LimitsConfig::default(),
            load_models: LoadModelSections::default(),
            initial: InitialConfig::default(),
            centrifugal: CentrifugalConfig::default(),
        }
    }
}
