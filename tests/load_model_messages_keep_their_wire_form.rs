//! The load models' state messages are built from the models' declared
//! channels (`messages::model_states`), yet they are the package's
//! `PadStates` and `ToolState` field for field: written out here as the
//! structs the `.msg` files describe, filled through the models' typed views
//! (`PadOutputs`, `ToolOutputs`), they serialize to the same JSON (names,
//! order, integer or float) as the node's messages after a few steps — on the
//! massless and the massive brake, with and without the lining's patches, and
//! on the lathe.

#![cfg(feature = "ros")]

mod support;

use annular_plate::config::{Config, Params};
use annular_plate::dynamics::load_models::pad::PadScratch;
use annular_plate::dynamics::load_models::pad_config::PadsConfig;
use annular_plate::dynamics::load_models::pad_outputs::PadOutputs;
use annular_plate::dynamics::load_models::tool::ToolOutputs;
use annular_plate::dynamics::Simulation;
use annular_plate::messages::outputs::{FrameNames, OutputMessages};
use annular_plate::messages::types::{Header, Time};
use serde::Serialize;
use support::scene_files;

/// `msg/PadStates.msg`, as the old hand-written struct.
#[derive(Serialize)]
struct PadStates {
    header: Header,
    step: u64,
    sim_time: f64,
    clamp_force: Vec<f64>,
    normal_force: Vec<f64>,
    friction_force: Vec<f64>,
    friction_torque: Vec<f64>,
    contact_pad: Vec<u32>,
    contact_ale_node: Vec<u32>,
    contact_normal_top: Vec<f64>,
    contact_normal_bottom: Vec<f64>,
    contact_friction: Vec<f64>,
    pad_compression_top: Vec<f64>,
    pad_compression_bottom: Vec<f64>,
    contact_patch_top_radial: Vec<f64>,
    contact_patch_top_tangential: Vec<f64>,
    contact_patch_bottom_radial: Vec<f64>,
    contact_patch_bottom_tangential: Vec<f64>,
    contact_slip_top: Vec<f64>,
    contact_slip_bottom: Vec<f64>,
}

/// `msg/ToolState.msg`.
#[derive(Serialize)]
struct ToolState {
    header: Header,
    step: u64,
    sim_time: f64,
    feed_rate: f64,
    tip_z: f64,
    chip_thickness: f64,
    feed_force: f64,
}

fn header(names: &FrameNames, stamp: Time) -> Header {
    Header {
        stamp,
        frame_id: names.base.clone(),
    }
}

fn pad_states(sim: &Simulation, names: &FrameNames, stamp: Time) -> PadStates {
    let n = sim.pad_count();
    let pads: Vec<_> = (0..n).map(|p| sim.pad_output(p)).collect();
    let compressions: Vec<[f64; 2]> = (0..n).filter_map(|p| sim.pad_compression(p)).collect();
    let contacts = &sim.config().section::<PadsConfig>().unwrap().contacts;
    let forces = sim.pad_contact_forces();
    let patches = sim.pad_patch_deflections();
    let patch = |a: usize| patches.iter().map(|x| x[a]).collect();
    let slip: &[[f64; 2]] = sim
        .model_wrenches()
        .scratch::<PadScratch>(0)
        .map_or(&[], |s| &s.slip);
    PadStates {
        header: header(names, stamp),
        step: sim.step_count(),
        sim_time: sim.time(),
        clamp_force: pads.iter().map(|o| o.clamp_force).collect(),
        normal_force: pads.iter().map(|o| o.normal_force).collect(),
        friction_force: pads.iter().map(|o| o.friction_force).collect(),
        friction_torque: pads.iter().map(|o| o.friction_torque).collect(),
        contact_pad: contacts.iter().map(|c| c.pad as u32 + 1).collect(),
        contact_ale_node: contacts.iter().map(|c| c.node as u32 + 1).collect(),
        contact_normal_top: forces.iter().map(|f| f.top).collect(),
        contact_normal_bottom: forces.iter().map(|f| f.bottom).collect(),
        contact_friction: forces.iter().map(|f| f.tangential).collect(),
        pad_compression_top: compressions.iter().map(|c| c[0]).collect(),
        pad_compression_bottom: compressions.iter().map(|c| c[1]).collect(),
        contact_patch_top_radial: patch(0),
        contact_patch_top_tangential: patch(1),
        contact_patch_bottom_radial: patch(2),
        contact_patch_bottom_tangential: patch(3),
        contact_slip_top: slip.iter().map(|s| s[0]).collect(),
        contact_slip_bottom: slip.iter().map(|s| s[1]).collect(),
    }
}

fn tool_state(sim: &Simulation, names: &FrameNames, stamp: Time) -> ToolState {
    let t = sim.tool_output().unwrap();
    ToolState {
        header: header(names, stamp),
        step: sim.step_count(),
        sim_time: sim.time(),
        feed_rate: t.feed_rate,
        tip_z: t.tip,
        chip_thickness: t.chip,
        feed_force: t.feed_force,
    }
}

/// The scene's model messages after `steps` steps, as JSON.
fn published(mut sim: Simulation, steps: usize) -> (Simulation, FrameNames, Time, Vec<String>) {
    for _ in 0..steps {
        sim.step().unwrap();
    }
    let names = FrameNames::new("p/", "world", sim.n_ale_nodes(), sim.n_lagrange_nodes());
    let stamp = Time { sec: 3, nanosec: 7 };
    let mut out = OutputMessages::new(&sim, &names);
    out.update(&sim, stamp);
    let json = out
        .models
        .iter()
        .map(|(_, m)| serde_json::to_string(&*m.0).unwrap())
        .collect();
    (sim, names, stamp, json)
}

#[test]
fn pad_states_are_the_msg_struct_massless_and_massive() {
    // brake_squeal carries the lining's shear, the bench a rigid lining.
    for (file, mass, shear) in [
        ("brake_squeal.yaml", "0", true),
        ("brake_squeal.yaml", "0.3", true),
        ("brake_bench.yaml", "0", false),
        ("brake_bench.yaml", "0.3", false),
    ] {
        let mut params = Params::from_file(&scene_files::path(file), scene_files::NODE).unwrap();
        params.set_override("pads.mass", mass).unwrap();
        params.set_override("simulation.integrator", "rk4").unwrap();
        params.set_override("pads.clamp_force", "[5000.0]").unwrap();
        params
            .set_override("plate.residual_flexibility", "false")
            .unwrap();
        let config = Config::from_params(&params).unwrap();
        let (sim, names, stamp, json) = published(Simulation::new(config).unwrap(), 20);
        assert_eq!(json.len(), 1, "one pad topic");
        let want = serde_json::to_string(&pad_states(&sim, &names, stamp)).unwrap();
        assert_eq!(json[0], want, "{file}, pads.mass {mass}");
        assert_eq!(json[0].contains("\"pad_compression_top\":[]"), mass == "0");
        assert_eq!(json[0].contains("\"contact_patch_top_radial\":[]"), !shear);
        assert_eq!(json[0].contains("\"contact_slip_bottom\":[]"), !shear);
    }
}

#[test]
fn tool_state_is_the_msg_struct() {
    let sim = Simulation::new(scene_files::load("lathe.yaml")).unwrap();
    let (sim, names, stamp, json) = published(sim, 50);
    assert_eq!(json.len(), 1, "one tool topic");
    let want = serde_json::to_string(&tool_state(&sim, &names, stamp)).unwrap();
    assert_eq!(json[0], want);
}

#[test]
fn a_scene_without_models_with_topics_has_no_model_messages() {
    let sim = Simulation::new(scene_files::load("swash_plate.yaml")).unwrap();
    let (_, _, _, json) = published(sim, 1);
    assert!(json.is_empty());
}
