//! The immutable scene: the plate model plus what a configuration adds —
//! node frames (with their mode shapes evaluated once), the joint drive, the
//! reference-frame motion and the set of effects that motion needs.

use crate::config::{Config, JointConfig, LimitsConfig, NodePosition};
use crate::model::{PlateModel, ShapeValue};
use std::f64::consts::TAU;

use super::load_models::LoadModels;
use super::wrench::NodeKind;

/// A cos/sin mode pair with the same ⟨k, l⟩.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ModePair {
    pub k: u32,
    pub cos: usize,
    pub sin: usize,
}

/// Which modes are axisymmetric and which form pairs (indices into the mode table).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ModeLayout {
    pub axisymmetric: Vec<usize>,
    pub pairs: Vec<ModePair>,
    pub k_max: u32,
}

impl ModeLayout {
    pub fn new(model: &PlateModel) -> ModeLayout {
        let mut layout = ModeLayout::default();
        for (i, m) in model.modes().iter().enumerate() {
            layout.k_max = layout.k_max.max(m.k);
            match (m.k, m.partner) {
                (0, _) => layout.axisymmetric.push(i),
                (_, Some(j)) if m.shape == crate::model::AngularShape::Cos => layout.pairs.push(ModePair { k: m.k, cos: i, sin: j }),
                _ => {}
            }
        }
        layout
    }
}

/// A node frame with the mode shapes evaluated at its point.
#[derive(Debug, Clone, PartialEq)]
pub struct NodeFrame {
    pub kind: NodeKind,
    pub radius: f64,
    /// φ for Lagrangian nodes (plate frame), θ for ALE nodes (ALE frame), rad.
    pub angle: f64,
    /// Per mode: w_i, and the surface tilt (θ_x, θ_y) = (∂w_i/∂y, −∂w_i/∂x).
    pub shapes: Vec<NodeShape>,
    /// Per mode ∂w_i/∂φ (for the material velocity under an ALE point).
    pub w_phi: Vec<f64>,
    /// Undeformed position (r cos, r sin) in the parent frame, m.
    xy: [f64; 2],
}

#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct NodeShape {
    pub w: f64,
    pub tilt: [f64; 2],
}

impl NodeFrame {
    fn new(model: &PlateModel, kind: NodeKind, p: NodePosition) -> NodeFrame {
        let radius = model.radius_at(p.radial);
        let angle = p.angular * TAU;
        let values: Vec<ShapeValue> = (0..model.n_modes()).map(|i| model.mode_shape(i, radius, angle)).collect();
        NodeFrame {
            kind,
            radius,
            angle,
            shapes: values.iter().map(|s| NodeShape { w: s.w, tilt: s.tilt(radius, angle) }).collect(),
            w_phi: values.iter().map(|s| s.w_phi).collect(),
            xy: [radius * angle.cos(), radius * angle.sin()],
        }
    }

    /// Position in the node's parent frame (undeformed).
    pub fn position(&self) -> [f64; 3] {
        [self.xy[0], self.xy[1], 0.0]
    }

    /// Deflection w and tilt at the node for amplitudes `q` in the node's own description.
    pub fn deflection(&self, q: &[f64]) -> NodeShape {
        let mut out = NodeShape::default();
        for (s, &qi) in self.shapes.iter().zip(q) {
            out.w += s.w * qi;
            out.tilt[0] += s.tilt[0] * qi;
            out.tilt[1] += s.tilt[1] * qi;
        }
        out
    }
}

/// The effects the reference motion switches on (DESIGN: only what a scene needs).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Effects {
    /// Axial load on the k = 0 modes: −C_t (a_R − g), from gravity or a translating base.
    pub axial_body_force: bool,
    /// k = 1 excitation −C_r ω̇ − ω_z(ω_x s_x + ω_y s_y) and the centrifugal
    /// softening (ω_x² + ω_y²) M_e: the reference frame turns off-axis.
    pub off_axis_rotation: bool,
    /// Node wrenches follow the deformed surface (paper 5.3).
    pub follower_loads: bool,
}

/// The prescribed reference-frame motion, resolved in the reference frame A.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ReferenceMotion {
    /// ω_A, rad/s.
    pub angular_velocity: [f64; 3],
    /// a_R − g, m/s²: the origin's acceleration less gravity.
    pub specific_force: [f64; 3],
}

/// Everything the stepper needs besides the state and inputs.
#[derive(Debug, Clone)]
pub struct Scene {
    pub model: PlateModel,
    pub layout: ModeLayout,
    pub ale_nodes: Vec<NodeFrame>,
    pub lagrange_nodes: Vec<NodeFrame>,
    pub joint: JointConfig,
    pub limits: LimitsConfig,
    pub reference: ReferenceMotion,
    pub effects: Effects,
    /// Polar inertia J_zz of the plate about the joint axis, kg·m².
    pub polar_inertia: f64,
    /// Pads, tool, pitch links (paper section 5): only those the configuration gives.
    pub load_models: LoadModels,
}

impl Scene {
    pub fn new(config: &Config, model: PlateModel) -> Scene {
        let layout = ModeLayout::new(&model);
        let ale_nodes: Vec<NodeFrame> = config.nodes.ale.iter().map(|&p| NodeFrame::new(&model, NodeKind::Ale, p)).collect();
        let lagrange_nodes: Vec<NodeFrame> = config.nodes.lagrange.iter().map(|&p| NodeFrame::new(&model, NodeKind::Lagrange, p)).collect();
        // Gravity is given in world axes; the reference frame is tilted about world x.
        let (st, ct) = config.reference.tilt.sin_cos();
        let g = config.gravity;
        let g_ref = [g[0], ct * g[1] + st * g[2], -st * g[1] + ct * g[2]];
        let a = config.reference.acceleration;
        let specific_force = [a[0] - g_ref[0], a[1] - g_ref[1], a[2] - g_ref[2]];
        let w = config.reference.angular_velocity;
        let has_k0 = !layout.axisymmetric.is_empty();
        let effects = Effects {
            axial_body_force: has_k0 && specific_force[2] != 0.0,
            off_axis_rotation: w[0] != 0.0 || w[1] != 0.0,
            follower_loads: config.loads.follower,
        };
        let polar_inertia = model.body().inertia[2][2];
        let load_models = LoadModels::new(config, &ale_nodes, &lagrange_nodes, &model.body().modal_mass);
        Scene {
            model,
            layout,
            ale_nodes,
            lagrange_nodes,
            joint: config.joint.clone(),
            limits: config.limits.clone(),
            reference: ReferenceMotion { angular_velocity: w, specific_force },
            effects,
            polar_inertia,
            load_models,
        }
    }

    pub fn n_modes(&self) -> usize {
        self.model.n_modes()
    }

    /// Square of the reference frame's off-axis angular velocity, ω_x² + ω_y²
    /// (invariant under the spin about z).
    pub fn off_axis_rate_squared(&self) -> f64 {
        let w = self.reference.angular_velocity;
        if self.effects.off_axis_rotation {
            w[0] * w[0] + w[1] * w[1]
        } else {
            0.0
        }
    }
}
