//! In-plane modes in the dynamics (docs/in_plane.md, "In the dynamics"): the
//! plane-stress modes of `plate.in_plane_nodal_diameters` carried by the
//! elastic state after the bending modes, with their modal mass, stiffness
//! and damping, the node wrenches' in-plane forces and the coupling of the
//! k = 0 torsional modes with the joint.
//!
//! # Layout
//!
//! State index `offset + j` is in-plane entry j of the table
//! ([`crate::model::in_plane::InPlaneTable`], ascending in frequency); cos/sin
//! partners form pairs of the [`ModeLayout`], the k = 0 families are
//! axisymmetric. The sin partner is the cos partner turned by a quarter wave,
//! so eq. (20) transforms the pair between the descriptions unchanged.
//!
//! # Joint
//!
//! The hub turns by χ and a torsional mode adds u_θ = V(r) q, so the kinetic
//! energy ½∫ρh (rΩ + V q̇)² dA couples them through
//! s = 2π ∫ ρh V r² dr:
//!
//! J Ω̇ + Σ s_i q̈_i = τ_drive + τ_loads,  m_i q̈_i + s_i Ω̇ + c_i q̇_i + k_i q_i = f_i.
//!
//! Eliminating q̈ gives the joint's equation with the reduced inertia
//! J* = J − Σ s_i²/m_i and the load torque τ* = τ_loads − Σ (s_i/m_i)(f_i − c_i q̇_i − k_i q_i)
//! at the substep's start ([`InPlaneDynamics::reduced_joint`]): the drive's
//! law decides with those. A drive that follows its speed profile imposes Ω̇ = α:
//! each torsional mode sees the Euler force −s_i α, and the effort is the
//! step's mean J α − τ_loads + Σ s_i Δq̇_i / h. A torque-limited drive at its
//! limit holds τ = τ_drive + τ_loads: the torsional mode then obeys
//! (m − s²/J) q̈ + c q̇ + k q = f − s τ/J exactly, and Ω₁ = Ω₀ + (τ h − s Δq̇)/J.
//!
//! # Loads
//!
//! A node's in-plane force (F_x, F_y), in its frame's axes, does the virtual
//! work u_x,i F_x + u_y,i F_y on in-plane mode i, with (u_x, u_y) the mode's
//! displacement at the node (the same at a face: u does not vary through the
//! thickness). The load models' wrenches act the same way: the pads' friction
//! on the faces, whose sliding velocity includes the in-plane rate
//! (`load_models/pad_in_plane.rs`, with [`InPlaneDynamics::ale_contacts`]).
//! The drilling moment M_z acts on the joint only.
//!
//! # Node frames
//!
//! A node frame moves with u: its in-plane displacement is Σ (u_x, u_y)_i q_i
//! and its rate Σ (u_x, u_y)_i q̇_i in its own description's amplitudes
//! ([`InPlaneDynamics::node_motion`]). Under an ALE node the material's
//! displacement, in the plate's turning polar axes, changes at
//! ∂u/∂t + Ω ∂(u_r, u_θ)/∂θ (the transport term; [`InPlaneDynamics::ale_turn`]).
//! With `plate.residual_flexibility` a node stands for a load patch of
//! half-width [`crate::config::PlateConfig::residual_patch_half_width`]: the
//! modes' (u_r, u_θ) there are the patch means (work-conjugate with the
//! force spread over the patch), and the held in-plane forces add the
//! residual displacement of the modes left out ([`InPlaneResidual`]).

use super::error::SimulationError;
use super::in_plane_residual::InPlaneResidual;
use super::in_plane_spin::{InPlaneSpinBlock, InPlaneSpinTerms};
use super::layout::{ModeLayout, ModePair};
use super::node_frame::NodeFrame;
use crate::config::{Config, IntegratorKind};
use crate::model::in_plane::{
    in_plane_plate, patch_means, InPlaneDiscretisation, InPlaneFamily, InPlaneMode,
    InPlaneRadialValue, InPlaneShape, InPlaneTable, LoadPatch,
};
use crate::model::prestress::LamePrestress;
use crate::model::ModelError;
use nalgebra::DMatrix;
use std::f64::consts::{PI, TAU};

/// One in-plane mode as the dynamics carry it.
#[derive(Debug, Clone, PartialEq)]
pub struct InPlaneModeDyn {
    /// Nodal diameters.
    pub k: u32,
    /// Order per k (and family at k = 0).
    pub l: u32,
    /// Angular form.
    pub shape: InPlaneShape,
    /// ω, rad/s.
    pub omega: f64,
    /// Modal mass c_k ∫ ρh (U² + V²) r dr, kg.
    pub modal_mass: f64,
    /// Modal damping ratio ζ (`plate.damping` when it is one ratio; 0 when it
    /// is a list, which is of the bending modes).
    pub damping: f64,
    /// Torsional modes: s = 2π ∫ ρh V r² dr, kg·m; 0 otherwise.
    pub coupling: f64,
    /// ∫ ρh u dA in the plate's axes at χ = 0, kg·m: (C, 0) for a k = 1 cos
    /// mode and (0, C) for its sin partner, C = π ∫ ρh (U − V) r dr (u_r =
    /// U cos θ, u_θ = V sin θ); 0 otherwise. The work of a uniform body force.
    pub first_moment: [f64; 2],
}

/// The in-plane modes of a scene and what the stepper needs of them.
#[derive(Debug, Clone, PartialEq)]
pub struct InPlaneDynamics {
    /// State index of the first in-plane mode (the number of bending modes).
    pub offset: usize,
    /// The modes, in the table's order.
    pub modes: Vec<InPlaneModeDyn>,
    /// Local indices of the torsional modes.
    pub torsional: Vec<usize>,
    /// Per ALE node, per in-plane mode: (u_x, u_y) in the ALE frame's axes, m per m.
    pub ale_nodes: Vec<Vec<[f64; 2]>>,
    /// Per Lagrangian node, per in-plane mode: (u_x, u_y) in the plate frame's axes.
    pub lagrange_nodes: Vec<Vec<[f64; 2]>>,
    /// Per ALE node, per in-plane mode: ∂(u_r, u_θ)/∂θ in the ALE frame's
    /// axes (the transport term of the material's rate, module docs).
    pub ale_turn: Vec<Vec<[f64; 2]>>,
    /// Per ALE node, per in-plane mode: (u_x, u_y) and ∂(u_x, u_y)/∂θ (the
    /// transport term [`InPlaneDynamics::ale_turn`] plus e_z × u, the turn of
    /// the polar basis), for contacts at the node. With
    /// `plate.residual_flexibility` these are the patch means of the node
    /// frames: the pads' friction is spread over the node's load patch, so
    /// the modes and the in-plane residual of the node frames see the same
    /// force (docs/in_plane.md, "Pads").
    pub ale_contacts: Vec<Vec<[[f64; 2]; 2]>>,
    /// The residual compliance between the node frames
    /// (`plate.residual_flexibility`; None when off or without nodes).
    pub residual: Option<InPlaneResidual>,
    /// The spin terms (Coriolis, centrifugal softening, prestress) per k.
    pub spin: InPlaneSpinTerms,
    /// The largest |Ω| the step accepts: 10⁻³ ω_min / 2 rad/s where the spin
    /// terms are not built (the implicit midpoint rule), otherwise unbounded.
    pub speed_bound: f64,
    /// With a torque-limited drive, the free joint's fastest torsional rate
    /// ω* ([`InPlaneDynamics::free_joint_rate`], set with the scene's polar
    /// inertia); 0 otherwise.
    pub free_joint_omega: f64,
}

/// A node frame's in-plane motion, in its parent frame's axes.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct InPlaneNodeMotion {
    /// Displacement (u_x, u_y) of the mid-plane point, m.
    pub u: [f64; 2],
    /// Its rate: the frame's in-plane velocity, m/s.
    pub u_dot: [f64; 2],
    /// Rate of the displacement of the material under the node, in the
    /// plate's turning axes (ALE: with the transport term Ω ∂u/∂θ; a
    /// Lagrangian node's [`InPlaneNodeMotion::u_dot`]), m/s.
    pub material_u_dot: [f64; 2],
}

/// Relative size 2|Ω|/ω_min of the neglected Coriolis coupling accepted.
const SPIN_TOLERANCE: f64 = 1e-3;

impl InPlaneDynamics {
    /// The in-plane modes of `config` after `offset` bending modes, with
    /// their displacements at the scene's node frames; `None` without
    /// `plate.in_plane_nodal_diameters`.
    pub fn new(
        config: &Config,
        offset: usize,
        ale: &[NodeFrame],
        lagrange: &[NodeFrame],
    ) -> Result<Option<InPlaneDynamics>, ModelError> {
        let plate = &config.plate;
        if plate.in_plane_nodal_diameters.is_empty() {
            return Ok(None);
        }
        let table = InPlaneTable::new(plate, &config.centrifugal)?;
        let ip = in_plane_plate(plate, &config.centrifugal);
        let disc = InPlaneDiscretisation::new(&ip, table.splines)?;
        let orders = plate
            .in_plane_orders
            .iter()
            .max()
            .map_or(1, |&l| l as usize + 1);
        let damping = match plate.damping.as_slice() {
            [zeta] => *zeta,
            _ => 0.0,
        };
        let mut radial: Vec<InPlaneMode> = Vec::with_capacity(table.entries.len());
        let mut modes = Vec::with_capacity(table.entries.len());
        for e in &table.entries {
            let family = match e.shape {
                InPlaneShape::Torsional => InPlaneFamily::Torsional,
                InPlaneShape::Radial => InPlaneFamily::Radial,
                InPlaneShape::Cos | InPlaneShape::Sin => InPlaneFamily::Coupled,
            };
            let all = disc.modes(e.k, family, orders)?;
            let Some(m) = all.into_iter().find(|m| m.l == e.l) else {
                unreachable!("the table lists only computed modes")
            };
            let areal_density = plate.density * plate.thickness;
            let coupling = if family == InPlaneFamily::Torsional {
                TAU * areal_density * radial_integral(&m, |value, r| value.v * r * r)
            } else {
                0.0
            };
            let translation =
                PI * areal_density * radial_integral(&m, |value, r| (value.u - value.v) * r);
            let first_moment = match (e.k, e.shape) {
                (1, InPlaneShape::Cos) => [translation, 0.0],
                (1, InPlaneShape::Sin) => [0.0, translation],
                _ => [0.0; 2],
            };
            modes.push(InPlaneModeDyn {
                k: e.k,
                l: e.l,
                shape: e.shape,
                omega: e.omega,
                modal_mass: e.modal_mass,
                damping,
                coupling,
                first_moment,
            });
            radial.push(m);
        }
        let patch = plate
            .residual_flexibility
            .then(|| plate.residual_patch_half_width());
        let (ri, ra) = (plate.inner_radius, plate.outer_radius);
        let at_nodes =
            |nodes: &[NodeFrame], patch: Option<f64>| -> Vec<Vec<([f64; 2], [f64; 2])>> {
                nodes
                    .iter()
                    .map(|n| {
                        let patch = patch.map(|c| LoadPatch::new(ri, ra, n.radius, c));
                        modes
                            .iter()
                            .zip(&radial)
                            .map(|(m, r)| node_shape(m, r, n.radius, patch.as_ref(), n.angle))
                            .collect()
                    })
                    .collect()
            };
        let (ale_shapes, lagrange_shapes) = (at_nodes(ale, patch), at_nodes(lagrange, patch));
        let firsts = |shapes: &[Vec<([f64; 2], [f64; 2])>]| -> Vec<Vec<[f64; 2]>> {
            shapes
                .iter()
                .map(|n| n.iter().map(|s| s.0).collect())
                .collect()
        };
        let residual = patch
            .filter(|_| !(ale.is_empty() && lagrange.is_empty()))
            .map(|c| {
                let nodes: Vec<&NodeFrame> = ale.iter().chain(lagrange).collect();
                // One entry per ⟨k, l⟩ and family: the cos partner stands for the pair.
                let retained: Vec<InPlaneMode> = modes
                    .iter()
                    .zip(&radial)
                    .filter(|(m, _)| m.shape != InPlaneShape::Sin)
                    .map(|(_, r)| r.clone())
                    .collect();
                InPlaneResidual::new(&disc, &retained, &nodes, c)
            });
        let omega_min = modes.iter().map(|m| m.omega).fold(f64::INFINITY, f64::min);
        let spin = spin_terms(
            &disc,
            &LamePrestress::new(plate, &config.centrifugal),
            offset,
            &modes,
            &radial,
        );
        let spin_built = config.simulation.integrator != IntegratorKind::ImplicitMidpoint;
        Ok(Some(InPlaneDynamics {
            offset,
            torsional: (0..modes.len())
                .filter(|&j| modes[j].shape == InPlaneShape::Torsional)
                .collect(),
            ale_nodes: firsts(&ale_shapes),
            lagrange_nodes: firsts(&lagrange_shapes),
            ale_turn: ale_shapes
                .iter()
                .map(|n| n.iter().map(|s| s.1).collect())
                .collect(),
            ale_contacts: ale_shapes
                .iter()
                .map(|n| {
                    n.iter()
                        .map(|&(u, t)| [u, [t[0] - u[1], t[1] + u[0]]])
                        .collect()
                })
                .collect(),
            residual,
            spin,
            free_joint_omega: 0.0,
            speed_bound: if spin_built {
                f64::INFINITY
            } else {
                0.5 * SPIN_TOLERANCE * omega_min
            },
            modes,
        }))
    }

    /// The number of in-plane modes.
    pub fn len(&self) -> usize {
        self.modes.len()
    }

    /// Whether there are none.
    pub fn is_empty(&self) -> bool {
        self.modes.is_empty()
    }

    /// Add the in-plane modes to `layout`: k = 0 axisymmetric, cos/sin pairs.
    pub fn extend_layout(&self, layout: &mut ModeLayout) {
        for (j, m) in self.modes.iter().enumerate() {
            let i = self.offset + j;
            layout.k_max = layout.k_max.max(m.k);
            match m.shape {
                InPlaneShape::Torsional | InPlaneShape::Radial => layout.axisymmetric.push(i),
                InPlaneShape::Cos => {
                    let Some(s) = self
                        .modes
                        .iter()
                        .position(|p| p.shape == InPlaneShape::Sin && p.k == m.k && p.l == m.l)
                    else {
                        unreachable!("the table lists a sin partner with every cos mode")
                    };
                    layout.pairs.push(ModePair {
                        k: m.k,
                        cos: i,
                        sin: self.offset + s,
                    });
                }
                InPlaneShape::Sin => {}
            }
        }
    }

    /// Add the in-plane generalized forces of `force` (in the node frame's
    /// axes) at a node whose in-plane mode displacements are `shapes`.
    pub fn add_node_force(&self, shapes: &[[f64; 2]], force: &[f64; 3], out: &mut [f64]) {
        for (o, u) in out[self.offset..].iter_mut().zip(shapes) {
            *o += u[0] * force[0] + u[1] * force[1];
        }
    }

    /// The same for a load model's force at an ALE node, through
    /// [`InPlaneDynamics::ale_contacts`] (point values, or patch means with
    /// `plate.residual_flexibility`).
    pub fn add_contact_force(&self, shapes: &[[[f64; 2]; 2]], force: &[f64; 3], out: &mut [f64]) {
        for (o, [u, _]) in out[self.offset..].iter_mut().zip(shapes) {
            *o += u[0] * force[0] + u[1] * force[1];
        }
    }

    /// The in-plane motion of a node frame with mode displacements `shapes`
    /// for amplitudes and rates in its own description (module docs,
    /// "Node frames"); `turn` ([`InPlaneDynamics::ale_turn`]) for an ALE node
    /// turning at `speed` under the material. Without the residual.
    pub fn node_motion(
        &self,
        shapes: &[[f64; 2]],
        turn: Option<&[[f64; 2]]>,
        q: &[f64],
        q_dot: &[f64],
        speed: f64,
    ) -> InPlaneNodeMotion {
        let sum = |shapes: &[[f64; 2]], x: &[f64]| {
            shapes
                .iter()
                .zip(&x[self.offset..])
                .fold([0.0; 2], |acc, (u, xi)| {
                    [acc[0] + u[0] * xi, acc[1] + u[1] * xi]
                })
        };
        let u_dot = sum(shapes, q_dot);
        let material_u_dot = match turn {
            None => u_dot,
            Some(t) => {
                let d = sum(t, q);
                [u_dot[0] + speed * d[0], u_dot[1] + speed * d[1]]
            }
        };
        InPlaneNodeMotion {
            u: sum(shapes, q),
            u_dot,
            material_u_dot,
        }
    }

    /// The joint's reduced inertia J* and load torque τ* at the substep's
    /// start (module docs) from the torsional modes' forces `f` (state
    /// indices, the k = 0 force in one place), their amplitudes and rates and
    /// their spin terms at the joint speed (Lagrangian amplitudes).
    pub fn reduced_joint(
        &self,
        polar_inertia: f64,
        load_torque: f64,
        speed: f64,
        f: &[f64],
        q: &[f64],
        q_dot: &[f64],
    ) -> (f64, f64) {
        let (mut inertia, mut torque) = (polar_inertia, load_torque);
        for &j in &self.torsional {
            let m = &self.modes[j];
            let i = self.offset + j;
            let (c, k) = self.damping_stiffness(j);
            let ratio = m.coupling / m.modal_mass;
            let spin = m.modal_mass * self.spin.acceleration_of(i, speed, q, q_dot);
            inertia -= ratio * m.coupling;
            torque -= ratio * (f[i] - c * q_dot[i] - k * q[i] - spin);
        }
        (inertia, torque)
    }

    /// c = 2ζωm and k = ω²m of local mode j.
    fn damping_stiffness(&self, j: usize) -> (f64, f64) {
        let m = &self.modes[j];
        (
            2.0 * m.damping * m.omega * m.modal_mass,
            m.omega * m.omega * m.modal_mass,
        )
    }

    /// The Euler force −s α of a joint acceleration α on the torsional modes.
    pub fn add_euler_force(&self, alpha: f64, f: &mut [f64]) {
        for &j in &self.torsional {
            f[self.offset + j] -= self.modes[j].coupling * alpha;
        }
    }

    /// Σ s_i q̇_i of the torsional modes (the angular momentum the twist adds).
    pub fn twist_momentum(&self, q_dot: &[f64]) -> f64 {
        self.torsional
            .iter()
            .map(|&j| self.modes[j].coupling * q_dot[self.offset + j])
            .sum()
    }

    /// The free joint's fastest torsional rate ω*, rad/s: the largest
    /// eigenvalue of K ψ = ω² (M − s sᵀ/J) ψ over the torsional modes (0
    /// without them).
    pub fn free_joint_rate(&self, polar_inertia: f64) -> f64 {
        let n = self.torsional.len();
        if n == 0 {
            return 0.0;
        }
        let mode = |a: usize| &self.modes[self.torsional[a]];
        let mass = DMatrix::from_fn(n, n, |a, b| {
            let diagonal = if a == b { mode(a).modal_mass } else { 0.0 };
            diagonal - mode(a).coupling * mode(b).coupling / polar_inertia
        });
        let Some(chol) = mass.cholesky() else {
            return f64::INFINITY;
        };
        let l_inv = chol
            .l()
            .try_inverse()
            .unwrap_or_else(|| DMatrix::zeros(n, n));
        let stiffness = DMatrix::from_fn(n, n, |a, b| {
            if a == b {
                self.damping_stiffness(self.torsional[a]).1
            } else {
                0.0
            }
        });
        let reduced = &l_inv * stiffness * l_inv.transpose();
        reduced
            .symmetric_eigenvalues()
            .iter()
            .fold(0.0f64, |m, &w2| m.max(w2))
            .sqrt()
    }

    /// The coupling s of the mode at state index i with the joint (zero but
    /// for the torsional modes).
    pub fn coupling_of(&self, i: usize) -> f64 {
        i.checked_sub(self.offset)
            .and_then(|j| self.modes.get(j))
            .map_or(0.0, |m| m.coupling)
    }

    /// Refuse what the in-plane modes do not carry yet, naming the key
    /// (the load models refuse for themselves,
    /// `LoadModel::attach_in_plane`): follower loads, centrifugal stiffening
    /// on the implicit midpoint rule, an off-axis reference
    /// rotation, a start above the speed bound (where the spin terms are not
    /// built), and a torque-limited drive with torsional modes on the
    /// implicit midpoint rule or on `contact_exponential` with
    /// `stage_dependent_loads` (the pads, the tool). There the joint would
    /// ride in the step's unknowns: free at the drive's limit, the hub rings
    /// with the torsional modes far above the step (ω* = 4.6e5 rad/s on
    /// config/brake_bench.yaml with the k = 0 modes,
    /// [`InPlaneDynamics::free_joint_rate`]) and the limit switches within
    /// each ring; the step's results there did not converge with h (1e-3 to
    /// 1e-2 of the speed off converged RK4 at 16–36 kHz).
    pub fn check(
        &self,
        config: &Config,
        stage_dependent_loads: bool,
    ) -> Result<(), SimulationError> {
        let refuse = |key: &'static str, why: &'static str| {
            Err(SimulationError::InPlaneKeyNotWired { key, why })
        };
        if config.loads.follower {
            return refuse(
                "loads.follower",
                "the follower turn of an in-plane force is not built for the in-plane modes",
            );
        }
        if config.centrifugal.stiffening
            && config.simulation.integrator == IntegratorKind::ImplicitMidpoint
        {
            return refuse(
                "plate.centrifugal_stiffening",
                "the stiffened implicit midpoint rule steps the bending modes' blocks only (simulation.integrator: exponential, contact_exponential or rk4 step both)",
            );
        }
        let w = config.reference.angular_velocity;
        if w[0] != 0.0 || w[1] != 0.0 {
            return refuse(
                "reference.angular_velocity",
                "the off-axis rotation's terms are built for the bending modes",
            );
        }
        if config.joint.speed.abs() > self.speed_bound {
            return Err(SimulationError::InPlaneSpin {
                speed: config.joint.speed,
                limit: self.speed_bound,
            });
        }
        if config.joint.max_torque.is_none() || self.torsional.is_empty() {
            return Ok(());
        }
        match config.simulation.integrator {
            IntegratorKind::ImplicitMidpoint => refuse(
                "joint.max_torque",
                "a torque-limited drive with in-plane torsional modes is built for simulation.integrator: exponential, rk4 and contact_exponential (without pads or tool)",
            ),
            IntegratorKind::ContactExponential if stage_dependent_loads => refuse(
                "joint.max_torque",
                "with torsional modes and stage-dependent loads (pads, tool) on simulation.integrator: contact_exponential the joint is free at the drive's limit and rings with the torsional modes far above the step, where the located switches of the limit do not converge; simulation.integrator: rk4 (or exponential without such loads) steps it, or drop joint.max_torque",
            ),
            _ => Ok(()),
        }
    }
}

/// The spin blocks of every k among `modes` (state index = `offset` + table index).
fn spin_terms(
    disc: &InPlaneDiscretisation,
    prestress: &LamePrestress,
    offset: usize,
    modes: &[InPlaneModeDyn],
    radial: &[InPlaneMode],
) -> InPlaneSpinTerms {
    let mut ks: Vec<u32> = modes.iter().map(|m| m.k).collect();
    ks.sort_unstable();
    ks.dedup();
    let blocks = ks
        .into_iter()
        .filter_map(|k| {
            let entries: Vec<_> = modes
                .iter()
                .zip(radial)
                .enumerate()
                .filter(|(_, (m, _))| m.k == k)
                .map(|(j, (m, r))| (offset + j, m.shape, r, m.modal_mass))
                .collect();
            InPlaneSpinBlock::new(disc, prestress, k, &entries)
        })
        .collect();
    InPlaneSpinTerms::new(blocks)
}

/// ∫ g(U, U', V, V'; r) dr over the annulus (three-point Gauss per B-spline
/// span: exact for the polynomials of a cubic spline times r²).
fn radial_integral(mode: &InPlaneMode, g: impl Fn(InPlaneRadialValue, f64) -> f64) -> f64 {
    const X: [f64; 3] = [-0.774_596_669_241_483_4, 0.0, 0.774_596_669_241_483_4];
    const W: [f64; 3] = [5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0];
    let basis = &mode.basis;
    let mut sum = 0.0;
    for s in 0..basis.spans() {
        let (a, b) = basis.span_bounds(s);
        let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
        for (x, w) in X.iter().zip(W) {
            let r = mid + half * x;
            sum += w * half * g(mode.eval(r), r);
        }
    }
    sum
}

/// (u_x, u_y) of mode `m` (radial functions `r`) at radius ρ and angle a,
/// and ∂(u_r, u_θ)/∂θ there in the same axes: point values, or with a
/// `patch` its means Ū sinc kβ, V̄ sinc kβ (docs/in_plane.md, "Node frames").
fn node_shape(
    m: &InPlaneModeDyn,
    r: &InPlaneMode,
    rho: f64,
    patch: Option<&LoadPatch>,
    a: f64,
) -> ([f64; 2], [f64; 2]) {
    let [u, v] = match patch {
        None => {
            let value = r.eval(rho);
            [value.u, value.v]
        }
        Some(p) => patch_means(r, p).map(|x| x * p.angular_factor(m.k)),
    };
    let (fu, fv) = m.shape.angular(m.k, a);
    let (dfu, dfv) = angular_slope(m.shape, m.k, a);
    let (s, c) = a.sin_cos();
    let cartesian = |ur: f64, ut: f64| [ur * c - ut * s, ur * s + ut * c];
    (cartesian(u * fu, v * fv), cartesian(u * dfu, v * dfv))
}

/// d/dθ of [`InPlaneShape::angular`].
fn angular_slope(shape: InPlaneShape, k: u32, theta: f64) -> (f64, f64) {
    let kf = k as f64;
    let (s, c) = (kf * theta).sin_cos();
    match shape {
        InPlaneShape::Torsional | InPlaneShape::Radial => (0.0, 0.0),
        InPlaneShape::Cos => (-kf * s, kf * c),
        InPlaneShape::Sin => (kf * c, kf * s),
    }
}
