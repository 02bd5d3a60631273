//! What the node publishes after a step: joint state, transforms, modal
//! amplitudes, the load models' states (one topic per model that declares
//! one, `model_states`), clock; and the static transform and diagnostics.
//!
//! The messages are built once ([`OutputMessages::new`]) and then only
//! overwritten in place each step: no allocation on our side of the per-step
//! path. They are handed to the DDS writer as [`Shared`] (an `Arc` that the
//! writer serializes synchronously and drops), so publishing does not clone
//! the strings and vectors either. With `run --record` the bag writer thread
//! gets a handle too and drops it once written; should it still hold one
//! at the next step, [`Shared::get_mut`] copies (the loop never waits).
//! `simulate --bag` builds its messages with the same [`OutputMessages`].

use super::clock::StepClock;
use super::model_states::{model_topics, ModelStates};
use super::types::{
    Clock, Header, JointState, ModalAmplitudes, Quaternion, TFMessage, Time, Transform,
    TransformStamped, Vector3,
};
use crate::dynamics::{Pose, Simulation};
use crate::model::in_plane::InPlaneShape;
use crate::model::AngularShape;
use serde::{Deserialize, Deserializer, Serialize, Serializer};
use std::sync::Arc;

/// Frame and joint names, with `ros.frame_prefix` applied.
#[derive(Debug, Clone, PartialEq)]
pub struct FrameNames {
    /// The fixed frame the base is placed in (`ros.world_frame`).
    pub world: String,
    /// `<prefix>plate_base`: the base frame, fixed to the bearing (the joint's space-fixed side).
    pub base: String,
    /// `<prefix>plate_rotor`: the floating frame of reference, turned by the joint angle χ.
    pub rotor: String,
    /// `<prefix>plate_joint`: the rotational joint in /joint_states.
    pub joint: String,
    /// `ale[j]` is the frame of ALE node j + 1.
    pub ale: Vec<String>,
    /// `lagrange[j]` is the frame of Lagrangian node j + 1.
    pub lagrange: Vec<String>,
}

impl FrameNames {
    /// The names for `n_ale` ALE and `n_lagrange` Lagrangian nodes, `prefix` prepended
    /// to every frame but `world`.
    pub fn new(prefix: &str, world: &str, n_ale: usize, n_lagrange: usize) -> Self {
        FrameNames {
            world: world.to_string(),
            base: format!("{prefix}plate_base"),
            rotor: format!("{prefix}plate_rotor"),
            joint: format!("{prefix}plate_joint"),
            ale: (1..=n_ale)
                .map(|j| format!("{prefix}plate_ale_{j}"))
                .collect(),
            lagrange: (1..=n_lagrange)
                .map(|j| format!("{prefix}plate_lagrange_{j}"))
                .collect(),
        }
    }
}

/// A message shared with the writer instead of cloned: serializes as `T`.
#[derive(Debug, Clone, PartialEq)]
pub struct Shared<T>(pub Arc<T>);

impl<T: Serialize> Serialize for Shared<T> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        self.0.serialize(s)
    }
}

impl<'de, T: Deserialize<'de>> Deserialize<'de> for Shared<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        T::deserialize(d).map(|t| Shared(Arc::new(t)))
    }
}

impl<T: Serialize + for<'de> Deserialize<'de>> ros2_client::Message for Shared<T> {}

impl<T> Shared<T> {
    /// Share `t`.
    pub fn new(t: T) -> Self {
        Shared(Arc::new(t))
    }
    /// A handle for one `publish` call.
    pub fn handle(&self) -> Self {
        Shared(Arc::clone(&self.0))
    }
}

impl<T: Clone> Shared<T> {
    /// Mutable access; copies only if a writer still holds the last handle.
    pub fn get_mut(&mut self) -> &mut T {
        Arc::make_mut(&mut self.0)
    }
}

fn shape_code(s: AngularShape) -> u8 {
    match s {
        AngularShape::Axisymmetric => ModalAmplitudes::SHAPE_AXISYMMETRIC,
        AngularShape::Cos => ModalAmplitudes::SHAPE_COS,
        AngularShape::Sin => ModalAmplitudes::SHAPE_SIN,
    }
}

fn in_plane_shape_code(s: InPlaneShape) -> u8 {
    match s {
        InPlaneShape::Torsional => ModalAmplitudes::SHAPE_TORSIONAL,
        InPlaneShape::Radial => ModalAmplitudes::SHAPE_RADIAL,
        InPlaneShape::Cos => ModalAmplitudes::SHAPE_IN_PLANE_COS,
        InPlaneShape::Sin => ModalAmplitudes::SHAPE_IN_PLANE_SIN,
    }
}

/// The modal message's per-mode description, state order: the bending modes,
/// then the in-plane modes (docs/in_plane.md, "In the dynamics").
fn modal_entries(sim: &Simulation) -> ModalAmplitudes {
    let mut m = ModalAmplitudes::default();
    for b in sim.model().modes() {
        m.k.push(b.k);
        m.l.push(b.l);
        m.shape.push(shape_code(b.shape));
        m.frequency_hz.push(b.frequency_hz);
    }
    for ip in sim.scene().in_plane.iter().flat_map(|ip| &ip.modes) {
        m.k.push(ip.k);
        m.l.push(ip.l);
        m.shape.push(in_plane_shape_code(ip.shape));
        m.frequency_hz.push(ip.omega / std::f64::consts::TAU);
    }
    let n = m.k.len();
    m.q_lagrange = vec![0.0; n];
    m.q_dot_lagrange = vec![0.0; n];
    m.q_ale = vec![0.0; n];
    m.q_dot_ale = vec![0.0; n];
    m
}

fn transform(p: &Pose) -> Transform {
    Transform {
        translation: Vector3::from_array(p.translation),
        rotation: Quaternion::from_xyzw(p.rotation),
    }
}

/// Rotation by `angle` about z as a quaternion.
pub fn z_rotation(angle: f64) -> Quaternion {
    let (s, c) = (0.5 * angle).sin_cos();
    Quaternion {
        x: 0.0,
        y: 0.0,
        z: s,
        w: c,
    }
}

/// Rotation by `angle` about x as a quaternion.
pub fn x_rotation(angle: f64) -> Quaternion {
    let (s, c) = (0.5 * angle).sin_cos();
    Quaternion {
        x: s,
        y: 0.0,
        z: 0.0,
        w: c,
    }
}

/// The per-step messages, preallocated for one scene.
#[derive(Debug)]
pub struct OutputMessages {
    /// /joint_states: the joint's position, velocity and effort.
    pub joint_state: Shared<JointState>,
    /// `transforms[0]`: base → rotor; then base → ale_j; then rotor → lagrange_j.
    pub tf: Shared<TFMessage>,
    /// `~/modal_amplitudes`: the modal amplitudes and rates, Lagrangian and ALE.
    pub modal: Shared<ModalAmplitudes>,
    /// Per load model with a topic (registry order): its index and message.
    pub models: Vec<(usize, Shared<ModelStates>)>,
    n_ale: usize,
}

impl OutputMessages {
    /// The messages for `sim`'s scene, named by `names`, with zero content.
    pub fn new(sim: &Simulation, names: &FrameNames) -> Self {
        let header = |frame: &str| Header {
            stamp: Time::default(),
            frame_id: frame.to_string(),
        };
        let joint_state = JointState {
            header: header(""),
            name: vec![names.joint.clone()],
            position: vec![0.0],
            velocity: vec![0.0],
            effort: vec![0.0],
        };
        let mut transforms = Vec::with_capacity(1 + sim.n_ale_nodes() + sim.n_lagrange_nodes());
        let ts = |parent: &str, child: &str| TransformStamped {
            header: header(parent),
            child_frame_id: child.to_string(),
            transform: Transform::default(),
        };
        transforms.push(ts(&names.base, &names.rotor));
        for ale in &names.ale {
            transforms.push(ts(&names.base, ale));
        }
        for lag in &names.lagrange {
            transforms.push(ts(&names.rotor, lag));
        }
        let modal = ModalAmplitudes {
            header: header(&names.base),
            ..modal_entries(sim)
        };
        let models = model_topics(sim)
            .into_iter()
            .map(|(i, _)| {
                let (outputs, layout) = sim.scene().load_models.outputs(i);
                (
                    i,
                    Shared::new(ModelStates::new(outputs, layout, &names.base)),
                )
            })
            .collect();
        let mut out = OutputMessages {
            joint_state: Shared::new(joint_state),
            tf: Shared::new(TFMessage { transforms }),
            modal: Shared::new(modal),
            models,
            n_ale: sim.n_ale_nodes(),
        };
        out.update(sim, Time::default());
        out
    }

    /// Overwrite every value from the simulation's current state.
    pub fn update(&mut self, sim: &Simulation, stamp: Time) {
        let j = sim.joint();
        let js = self.joint_state.get_mut();
        js.header.stamp = stamp;
        js.position[0] = j.position;
        js.velocity[0] = j.velocity;
        js.effort[0] = j.effort;

        let n_ale = self.n_ale;
        let tf = self.tf.get_mut();
        for (i, t) in tf.transforms.iter_mut().enumerate() {
            t.header.stamp = stamp;
            t.transform = if i == 0 {
                Transform {
                    translation: Vector3::default(),
                    rotation: z_rotation(sim.rotor_angle()),
                }
            } else if i <= n_ale {
                transform(&sim.ale_node_pose(i - 1))
            } else {
                transform(&sim.lagrange_node_pose(i - 1 - n_ale))
            };
        }

        let m = self.modal.get_mut();
        m.header.stamp = stamp;
        m.step = sim.step_count();
        m.sim_time = sim.time();
        m.q_lagrange.copy_from_slice(sim.q_lagrange());
        m.q_dot_lagrange.copy_from_slice(sim.q_dot_lagrange());
        m.q_ale.copy_from_slice(sim.q_ale());
        m.q_dot_ale.copy_from_slice(sim.q_dot_ale());

        for (i, msg) in &mut self.models {
            let (_, layout) = sim.scene().load_models.outputs(*i);
            let m = msg.get_mut();
            m.update(layout, sim.output_values(*i), stamp);
            m.step = sim.step_count();
            m.sim_time = sim.time();
        }
    }
}

/// The one `/tf_static` message: world → plate_base, turned by `reference.tilt` about x.
pub fn static_transforms(names: &FrameNames, tilt: f64, stamp: Time) -> TFMessage {
    TFMessage {
        transforms: vec![TransformStamped {
            header: Header {
                stamp,
                frame_id: names.world.clone(),
            },
            child_frame_id: names.base.clone(),
            transform: Transform {
                translation: Vector3::default(),
                rotation: x_rotation(tilt),
            },
        }],
    }
}

/// The `/clock` message for the clock's current time.
pub fn clock_message(clock: &StepClock) -> Clock {
    Clock {
        clock: clock.sim_time(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frame_names_use_the_prefix() {
        let n = FrameNames::new("left/", "world", 2, 1);
        assert_eq!(n.base, "left/plate_base");
        assert_eq!(n.rotor, "left/plate_rotor");
        assert_eq!(n.joint, "left/plate_joint");
        assert_eq!(n.ale, vec!["left/plate_ale_1", "left/plate_ale_2"]);
        assert_eq!(n.lagrange, vec!["left/plate_lagrange_1"]);
        assert_eq!(n.world, "world");
    }

    #[test]
    fn quaternions_are_unit_and_right_handed() {
        let q = z_rotation(std::f64::consts::FRAC_PI_2);
        assert!((q.z - 0.5f64.sqrt()).abs() < 1e-15 && (q.w - 0.5f64.sqrt()).abs() < 1e-15);
        let q = x_rotation(0.3);
        assert!((q.x * q.x + q.w * q.w - 1.0).abs() < 1e-15);
        assert!(q.x > 0.0);
    }

    #[test]
    fn shared_serializes_as_its_content() {
        let a = Shared::new(vec![1u32, 2]);
        assert_eq!(serde_json::to_string(&a).unwrap(), "[1,2]");
        let mut b = a.handle();
        // A second holder forces a copy on write; the first is unchanged.
        b.get_mut().push(3);
        assert_eq!(*a.0, vec![1, 2]);
        drop(a);
        let mut c = Shared::new(5u8);
        let p = c.0.as_ref() as *const u8;
        *c.get_mut() = 6;
        assert_eq!(c.0.as_ref() as *const u8, p, "sole owner writes in place");
    }
}
