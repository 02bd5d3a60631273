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
//! thickness). The drilling moment M_z acts on the joint only. Residual
//! flexibility (`plate.residual_flexibility`) stays the bending modes':
//! in-plane loads have none.

use super::error::SimulationError;
use super::in_plane_spin::{InPlaneSpinBlock, InPlaneSpinTerms};
use super::integrators::exponential::ModePropagator;
use super::layout::{ModeLayout, ModePair};
use super::node_frame::NodeFrame;
use crate::config::{Config, IntegratorKind};
use crate::model::in_plane::{
    in_plane_plate, InPlaneDiscretisation, InPlaneFamily, InPlaneMode, InPlaneShape, InPlaneTable,
};
use crate::model::prestress::LamePrestress;
use crate::model::ModelError;

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
    /// The spin terms (Coriolis, centrifugal softening, prestress) per k.
    pub spin: InPlaneSpinTerms,
    /// The largest |Ω| the step accepts: 10⁻³ ω_min / 2 rad/s where the spin
    /// terms are not built (the implicit midpoint rule; a torque-limited
    /// drive with torsional modes), otherwise unbounded.
    pub speed_bound: f64,
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
            let coupling = if family == InPlaneFamily::Torsional {
                torsional_coupling(&m, plate.density * plate.thickness)
            } else {
                0.0
            };
            modes.push(InPlaneModeDyn {
                k: e.k,
                l: e.l,
                shape: e.shape,
                omega: e.omega,
                modal_mass: e.modal_mass,
                damping,
                coupling,
            });
            radial.push(m);
        }
        let at_nodes = |nodes: &[NodeFrame]| -> Vec<Vec<[f64; 2]>> {
            nodes
                .iter()
                .map(|n| {
                    modes
                        .iter()
                        .zip(&radial)
                        .map(|(m, r)| displacement(m, r, n.radius, n.angle))
                        .collect()
                })
                .collect()
        };
        let omega_min = modes.iter().map(|m| m.omega).fold(f64::INFINITY, f64::min);
        let spin = spin_terms(
            &disc,
            &LamePrestress::new(plate, &config.centrifugal),
            offset,
            &modes,
            &radial,
        );
        let spin_built = config.simulation.integrator != IntegratorKind::ImplicitMidpoint
            && !(config.joint.max_torque.is_some()
                && modes.iter().any(|m| m.shape == InPlaneShape::Torsional));
        Ok(Some(InPlaneDynamics {
            offset,
            torsional: (0..modes.len())
                .filter(|&j| modes[j].shape == InPlaneShape::Torsional)
                .collect(),
            ale_nodes: at_nodes(ale),
            lagrange_nodes: at_nodes(lagrange),
            spin,
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

    /// The exact propagator of the one torsional mode with the joint free
    /// under a held torque: mass m − s²/J, the same c and k.
    pub fn free_joint_propagator(&self, polar_inertia: f64, h: f64) -> ModePropagator {
        let j = self.torsional[0];
        let m = &self.modes[j];
        let (c, k) = self.damping_stiffness(j);
        let reduced = m.modal_mass - m.coupling * m.coupling / polar_inertia;
        let omega = (k / reduced).sqrt();
        ModePropagator::new(reduced, c / (2.0 * reduced * omega), omega, 0.0, h, 0.0)
    }

    /// Refuse what the in-plane modes do not carry yet, naming the key: load
    /// models, follower loads, centrifugal stiffening, an off-axis reference
    /// rotation, a start above the speed bound (where the spin terms are not
    /// built), and a torque-limited drive unless it is one torsional mode on
    /// the exponential integrator.
    pub fn check(&self, config: &Config, has_load_models: bool) -> Result<(), SimulationError> {
        let refuse = |key: &'static str, why: &'static str| {
            Err(SimulationError::InPlaneKeyNotWired { key, why })
        };
        if has_load_models {
            return refuse(
                "pads / tool / links",
                "their forces do not carry in-plane modes yet",
            );
        }
        if config.loads.follower {
            return refuse(
                "loads.follower",
                "the follower turn of an in-plane force is not built for the in-plane modes",
            );
        }
        if config.centrifugal.stiffening {
            return refuse(
                "plate.centrifugal_stiffening",
                "the bending modes' stiffening is not stepped together with the in-plane modes yet",
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
        let exponential = matches!(
            config.simulation.integrator,
            IntegratorKind::Exponential | IntegratorKind::ContactExponential
        );
        if config.joint.max_torque.is_some()
            && !self.torsional.is_empty()
            && !(self.torsional.len() == 1 && exponential)
        {
            return refuse(
                "joint.max_torque",
                "a torque-limited drive with in-plane torsional modes is built for one torsional mode (plate.in_plane_orders) on simulation.integrator: exponential",
            );
        }
        Ok(())
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
    InPlaneSpinTerms { blocks }
}

/// s = 2π ∫ ρh V r² dr over the mode's B-spline spans (3-point Gauss per
/// span: exact for the cubic V times r²).
fn torsional_coupling(mode: &InPlaneMode, areal_density: f64) -> f64 {
    const X: [f64; 3] = [-0.774_596_669_241_483_4, 0.0, 0.774_596_669_241_483_4];
    const W: [f64; 3] = [5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0];
    let basis = &mode.basis;
    let mut sum = 0.0;
    for s in 0..basis.spans() {
        let (a, b) = basis.span_bounds(s);
        let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
        for (x, w) in X.iter().zip(W) {
            let r = mid + half * x;
            sum += w * half * mode.eval(r).v * r * r;
        }
    }
    std::f64::consts::TAU * areal_density * sum
}

/// (u_x, u_y) of mode `m` (radial functions `r`) at radius ρ and angle a.
fn displacement(m: &InPlaneModeDyn, r: &InPlaneMode, rho: f64, a: f64) -> [f64; 2] {
    let value = r.eval(rho);
    let (fu, fv) = m.shape.angular(m.k, a);
    let (ur, ut) = (value.u * fu, value.v * fv);
    let (s, c) = a.sin_cos();
    [ur * c - ut * s, ur * s + ut * c]
}
