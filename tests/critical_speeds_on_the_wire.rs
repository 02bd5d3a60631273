//! `~/critical_speeds` and the near-critical /diagnostics status on the wire
//! against the Cyclone DDS peer (`tests/peer/peer.py`).
//!
//! The node starts paused on the brake bench with
//! `plate.centrifugal_stiffening:=true` and its joint speed 2 % above the
//! lowest stiffened critical speed. A reader that joins ~1 s after the node
//! started (transient local) receives the one latched message; its list
//! equals the critical speeds the in-process model computes for the same
//! configuration (`annular_plate campbell`'s computation), and differs from
//! the unstiffened ω/k — the node honours the key. Then /diagnostics carries
//! `<node>: critical speeds` at WARN naming that mode and both speeds.
//! No timing is asserted: the peer waits (up to 30 s) for what it reads.

#![cfg(feature = "ros")]

#[path = "peer/harness.rs"]
mod harness;

use annular_plate::model::campbell::critical_speeds;
use annular_plate::model::PlateModel;
use annular_plate::ros::NodeSetup;
use harness::{peer, scene, start_node, Netns};
use serde_json::json;
use std::time::Duration;

/// The critical speeds the node's own configuration gives, computed in-process.
fn expected(ros_args: &[&str]) -> (Vec<(u32, u32, f64)>, bool) {
    let args: Vec<String> = std::iter::once("--ros-args")
        .chain(ros_args.iter().copied())
        .map(String::from)
        .collect();
    let setup = NodeSetup::load(Some(&scene()), &args).expect("the scene loads in-process");
    let model = PlateModel::new(&setup.config.plate).unwrap();
    let list = critical_speeds(&model, &setup.config.centrifugal)
        .unwrap()
        .into_iter()
        .map(|c| (c.k, c.l, c.rad_s))
        .collect();
    (list, setup.config.centrifugal.stiffening)
}

#[test]
fn critical_speeds_reach_a_late_joiner_and_a_near_critical_speed_warns() {
    let stiffened = ["-p", "plate.centrifugal_stiffening:=true"];
    let (list, stiffening) = expected(&stiffened);
    let (unstiffened, _) = expected(&[]);
    assert!(stiffening && !list.is_empty());
    let lowest = list
        .iter()
        .cloned()
        .min_by(|a, b| a.2.total_cmp(&b.2))
        .unwrap();
    let speed = 1.02 * lowest.2;
    let speed_arg = format!("joint.speed:={speed}");
    let args = [
        &stiffened[..],
        &[
            "-p",
            "ros.start_paused:=true",
            "-p",
            "ros.diagnostics_period:=0.2",
            "-p",
            &speed_arg,
        ],
    ]
    .concat();

    let ns = Netns::new();
    let node = start_node(&ns, 41, &args);
    std::thread::sleep(Duration::from_millis(1000));
    let out = peer(&ns, &node, "critical_speeds", "/annular_plate", json!({}));

    let m = &out["critical_speeds"];
    assert_eq!(m["centrifugal_stiffening"], true);
    let got: Vec<(u32, u32, f64)> = (0..m["k"].as_array().unwrap().len())
        .map(|i| {
            (
                m["k"][i].as_u64().unwrap() as u32,
                m["l"][i].as_u64().unwrap() as u32,
                m["rad_s"][i].as_f64().unwrap(),
            )
        })
        .collect();
    println!("~/critical_speeds: {got:?}\nunstiffened ω/k: {unstiffened:?}");
    assert_eq!(got.len(), list.len(), "{got:?} vs {list:?}");
    for (g, e) in got.iter().zip(&list) {
        assert_eq!((g.0, g.1), (e.0, e.1));
        assert!(
            (g.2 - e.2).abs() <= 1e-12 * e.2,
            "⟨{}, {}⟩: {} vs {}",
            e.0,
            e.1,
            g.2,
            e.2
        );
    }
    // Honours the key: every stiffened speed lies above its ω/k.
    for (k, l, rad_s) in &got {
        let off = unstiffened
            .iter()
            .find(|u| u.0 == *k && u.1 == *l)
            .map(|u| u.2);
        if let Some(off) = off {
            assert!(
                *rad_s > 1.01 * off,
                "⟨{k}, {l}⟩: stiffened {rad_s} vs ω/k {off}"
            );
        }
    }
    assert_eq!(out["more"], 0, "one message only");

    let st = &out["status"];
    println!("status: {st}");
    assert_eq!(
        st["level"], 1,
        "WARN within 5 % of ⟨{}, {}⟩ at {} rad/s",
        lowest.0, lowest.1, lowest.2
    );
    let text = st["message"].as_str().unwrap();
    assert!(
        text.contains(&format!("<{}, {}>", lowest.0, lowest.1)),
        "{text}"
    );
    assert!(
        text.contains(&format!("{:.1}", lowest.2)) && text.contains(&format!("{speed:.1}")),
        "{text}"
    );
}
