//! What a node frame publishes (docs/dynamics.md, "Node wrenches"; docs/in_plane.md,
//! "Node frames"): its pose in the parent frame, the transverse deflection
//! and rates, and with in-plane modes its in-plane displacement and rates.

use super::in_plane::InPlaneNodeMotion;
use super::node_frame::{NodeFrame, NodeKind};
use nalgebra::{Isometry3, Quaternion, Translation3, UnitQuaternion, Vector3};

/// A rigid transform as the messages carry it: translation (m) and unit
/// quaternion (x, y, z, w). The maths is nalgebra's ([`Pose::isometry`],
/// `From<Isometry3>`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pose {
    /// Translation, m.
    pub translation: [f64; 3],
    /// Unit quaternion (x, y, z, w).
    pub rotation: [f64; 4],
}

impl Pose {
    /// No translation, no rotation.
    pub const IDENTITY: Pose = Pose {
        translation: [0.0; 3],
        rotation: [0.0, 0.0, 0.0, 1.0],
    };

    /// A rotation about z by `angle`.
    pub fn about_z(angle: f64) -> Pose {
        Isometry3::from_parts(
            Translation3::identity(),
            UnitQuaternion::from_axis_angle(&Vector3::z_axis(), angle),
        )
        .into()
    }

    /// As a nalgebra isometry.
    pub fn isometry(&self) -> Isometry3<f64> {
        let [x, y, z, w] = self.rotation;
        let q = UnitQuaternion::new_unchecked(Quaternion::new(w, x, y, z));
        Isometry3::from_parts(Translation3::from(self.translation), q)
    }
}

impl From<Isometry3<f64>> for Pose {
    fn from(iso: Isometry3<f64>) -> Pose {
        let q = iso.rotation.coords;
        Pose {
            translation: iso.translation.vector.into(),
            rotation: [q[0], q[1], q[2], q[3]],
        }
    }
}

/// Kinematics of one node frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NodeOutput {
    /// In the parent frame: plate_base for ALE nodes, plate_rotor for Lagrangian ones.
    pub pose: Pose,
    /// Transverse elastic displacement w, m.
    pub uz: f64,
    /// dw/dt of the frame (for an ALE node: of the space-fixed point), m/s.
    pub uz_dot: f64,
    /// Surface tilt (θ_x, θ_y), rad.
    pub tilt: [f64; 2],
    /// Transverse velocity of the material under the node, m/s (ALE: ∂w/∂t + Ω ∂w/∂θ).
    pub material_uz_dot: f64,
    /// In-plane motion of the mid-plane point under the frame (zero without
    /// in-plane modes): displacement u (in the pose's translation, with the
    /// in-plane residual), the frame's velocity and the material's rate.
    pub in_plane: InPlaneNodeMotion,
}

impl NodeOutput {
    /// The kinematics of `node` for amplitudes in its own description.
    /// `residual` (m) is the truncated modes' static deflection added to w
    /// (the tilt and the rates stay modal). `in_plane` (None without in-plane
    /// modes) moves the frame's point by u.
    pub(super) fn of(
        node: &NodeFrame,
        q: &[f64],
        q_dot: &[f64],
        speed: f64,
        residual: f64,
        in_plane: Option<InPlaneNodeMotion>,
    ) -> NodeOutput {
        let mut d = node.deflection(q);
        d.w += residual;
        let uz_dot: f64 = node.shapes.iter().zip(q_dot).map(|(s, v)| s.w * v).sum();
        let material_uz_dot = match node.kind {
            NodeKind::Lagrange => uz_dot,
            NodeKind::Ale => {
                uz_dot + speed * node.w_phi.iter().zip(q).map(|(w, qi)| w * qi).sum::<f64>()
            }
        };
        let mut p = node.surface_position(&d);
        if let Some(ip) = &in_plane {
            p[0] += ip.u[0];
            p[1] += ip.u[1];
        }
        NodeOutput {
            pose: Isometry3::from_parts(Translation3::new(p[0], p[1], p[2]), tilt_rotation(d.tilt))
                .into(),
            uz: d.w,
            uz_dot,
            tilt: d.tilt,
            material_uz_dot,
            in_plane: in_plane.unwrap_or_default(),
        }
    }
}

/// The rotation of the small-slope rotation vector (θ_x, θ_y, 0): about the
/// axis (θ_x, θ_y, 0)/θ by θ = |(θ_x, θ_y)|. Written out (rather than
/// `UnitQuaternion::from_scaled_axis`, which rounds differently in the last
/// digit) so the published quaternions stay what they were.
pub fn tilt_rotation(tilt: [f64; 2]) -> UnitQuaternion<f64> {
    let angle = (tilt[0] * tilt[0] + tilt[1] * tilt[1]).sqrt();
    if angle < 1e-300 {
        return UnitQuaternion::identity();
    }
    let (s, c) = (0.5 * angle).sin_cos();
    UnitQuaternion::new_unchecked(Quaternion::new(
        c,
        tilt[0] / angle * s,
        tilt[1] / angle * s,
        0.0,
    ))
}
