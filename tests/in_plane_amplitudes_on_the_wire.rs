//! `~/modal_amplitudes` (and the bags, which record the same message) carry
//! the in-plane amplitudes after the bending ones (docs/ros.md,
//! ModalAmplitudes): with in-plane modes selected every array equals the
//! simulation's state, and the in-plane entries' k, l, shape and frequency are
//! the in-plane table's; without them the message is byte for byte the one
//! built from the bending modes alone, as before the in-plane entries existed.

use annular_plate::config::{Boundary, Config, IntegratorKind, NodePosition, WrenchConfig};
use annular_plate::dynamics::Simulation;
use annular_plate::messages::outputs::{FrameNames, OutputMessages};
use annular_plate::messages::types::ModalAmplitudes;
use annular_plate::model::in_plane::{InPlaneShape, InPlaneTable};
use annular_plate::model::AngularShape;
use byteorder::LittleEndian;
use ros2_client::dds::rustdds::cdr_encoding;

/// The brake bench disc (clamped hub, free rim) with bending modes k = 0, 1
/// and the in-plane modes `in_plane` × l = 0, 1, pushed at two rim nodes by
/// forces with radial, tangential and transverse parts, turning slowly.
fn pushed_disc(in_plane: &[u32]) -> Config {
    let mut c = Config::default();
    let p = &mut c.plate;
    (p.inner_radius, p.outer_radius, p.thickness) = (0.07, 0.153, 0.0181);
    (p.density, p.youngs_modulus, p.poisson_ratio) = (7850.0, 2.1e11, 0.3);
    (p.inner_boundary, p.outer_boundary) = (Boundary::Clamped, Boundary::Free);
    p.nodal_diameters = vec![0, 1];
    p.nodal_circles = vec![0];
    p.damping = vec![0.02];
    p.in_plane_nodal_diameters = in_plane.to_vec();
    p.in_plane_orders = vec![0, 1];
    c.gravity = [0.0; 3];
    c.joint.speed = 5.0;
    c.simulation.rate_hz = 20_000.0;
    c.simulation.substeps = 1;
    c.simulation.integrator = IntegratorKind::Exponential;
    for (angular, force) in [(0.1, [300.0, -500.0, 40.0]), (0.6, [-200.0, 100.0, -25.0])] {
        c.nodes.lagrange.push(NodePosition {
            radial: 1.0,
            angular,
        });
        c.loads.lagrange.push(WrenchConfig {
            force,
            moment: [0.0; 3],
        });
    }
    c
}

fn stepped(config: Config, steps: usize) -> Simulation {
    let mut sim = Simulation::new(config).expect("scene builds");
    for _ in 0..steps {
        sim.step().unwrap();
    }
    sim
}

fn message(sim: &Simulation) -> ModalAmplitudes {
    let names = FrameNames::new("", "world", sim.n_ale_nodes(), sim.n_lagrange_nodes());
    OutputMessages::new(sim, &names).modal.0.as_ref().clone()
}

fn cdr(m: &ModalAmplitudes) -> Vec<u8> {
    let mut buf = Vec::new();
    cdr_encoding::to_writer::<_, LittleEndian, _>(&mut buf, m).unwrap();
    buf
}

#[test]
fn the_message_carries_the_in_plane_amplitudes_after_the_bending_ones() {
    let config = pushed_disc(&[0, 1]);
    let table = InPlaneTable::new(&config.plate, &config.centrifugal).unwrap();
    let sim = stepped(config, 40);
    let m = message(&sim);
    let bending = sim.model().modes().len();
    let n = bending + table.entries.len();
    // 3 bending (⟨0,0⟩, ⟨1,0⟩ cos/sin) and 2 torsional + 2 radial + 2 × 2 k = 1.
    assert_eq!((bending, n), (3, 11));
    for (name, got, want) in [
        ("q_lagrange", &m.q_lagrange, sim.q_lagrange()),
        ("q_dot_lagrange", &m.q_dot_lagrange, sim.q_dot_lagrange()),
        ("q_ale", &m.q_ale, sim.q_ale()),
        ("q_dot_ale", &m.q_dot_ale, sim.q_dot_ale()),
    ] {
        assert_eq!(got.len(), n, "{name}");
        assert_eq!(got.as_slice(), want, "{name} is the state's");
        // Every in-plane amplitude moved: the entries are not zeros that match.
        assert!(
            want[bending..].iter().all(|&q| q != 0.0),
            "{name}: {:?}",
            &want[bending..]
        );
    }
    let code = |s: InPlaneShape| match s {
        InPlaneShape::Torsional => 3,
        InPlaneShape::Radial => 4,
        InPlaneShape::Cos => 5,
        InPlaneShape::Sin => 6,
    };
    for (j, e) in table.entries.iter().enumerate() {
        let i = bending + j;
        assert_eq!(
            (m.k[i], m.l[i], m.shape[i], m.frequency_hz[i]),
            (e.k, e.l, code(e.shape), e.frequency_hz),
            "in-plane entry {j}"
        );
    }
    println!(
        "11 entries; in-plane q_lagrange {:?}",
        &m.q_lagrange[bending..]
    );
}

#[test]
fn without_in_plane_modes_the_message_is_the_bending_one_byte_for_byte() {
    let sim = stepped(pushed_disc(&[]), 40);
    let modes = sim.model().modes();
    let code = |s: AngularShape| match s {
        AngularShape::Axisymmetric => 0,
        AngularShape::Cos => 1,
        AngularShape::Sin => 2,
    };
    let built = message(&sim);
    // The message as it was built before the in-plane entries.
    let before = ModalAmplitudes {
        header: built.header.clone(),
        step: sim.step_count(),
        sim_time: sim.time(),
        input_stamp: Default::default(),
        k: modes.iter().map(|m| m.k).collect(),
        l: modes.iter().map(|m| m.l).collect(),
        shape: modes.iter().map(|m| code(m.shape)).collect(),
        frequency_hz: modes.iter().map(|m| m.frequency_hz).collect(),
        q_lagrange: sim.q_lagrange()[..modes.len()].to_vec(),
        q_dot_lagrange: sim.q_dot_lagrange()[..modes.len()].to_vec(),
        q_ale: sim.q_ale()[..modes.len()].to_vec(),
        q_dot_ale: sim.q_dot_ale()[..modes.len()].to_vec(),
    };
    assert_eq!(built.header.frame_id, "plate_base");
    assert_eq!(cdr(&built), cdr(&before));
    assert!(built.q_lagrange.iter().all(|&q| q != 0.0));
}
