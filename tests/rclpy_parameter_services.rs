//! The six parameter services as rclpy (ROS 2 Jazzy wheels, rmw_fastrtps_cpp)
//! calls them — the requests of the `ros2 param` verbs, each on a fresh
//! client as every `ros2 param` command makes one — at loopback's default MTU
//! (65536) and at 1500 bytes (what an Ethernet link between two machines
//! gives: DDS fragments every reply larger than about 1.2 kB). Then 200
//! consecutive describe_parameters calls on one client with replies from
//! ~100 B to ~70 KB (past 64 KiB, where a reply no longer fits one UDP
//! datagram whatever the MTU): none may be lost (no reply within 10 s), and the
//! latency distribution is printed (not asserted); so is the first reply of
//! fresh clients.
//!
//! The expected names are the node's own: the in-process setup of the same
//! arguments (`NodeSetup::load`, `effective_parameters`).

#![cfg(feature = "ros")]

#[path = "peer/harness.rs"]
mod harness;
#[path = "peer/rclpy.rs"]
mod rclpy;

use annular_plate::ros::params_service::effective_parameters;
use annular_plate::ros::NodeSetup;
use harness::{scene, start_node, Netns};
use rclpy::{quantiles, rclpy_peer};
use serde_json::{json, Value};

/// Every parameter name the node declares with these ROS arguments.
fn declared_names(ros_args: &[&str]) -> Vec<String> {
    let args: Vec<String> = std::iter::once("--ros-args")
        .chain(ros_args.iter().copied())
        .map(String::from)
        .collect();
    let setup = NodeSetup::load(Some(&scene()), &args).expect("the scene loads in-process");
    effective_parameters(&setup.params, &setup.settings)
        .into_keys()
        .collect()
}

fn strings(v: &Value) -> Vec<String> {
    v.as_array()
        .map(|a| {
            a.iter()
                .map(|x| x.as_str().unwrap_or_default().to_string())
                .collect()
        })
        .unwrap_or_default()
}

fn sorted(mut v: Vec<String>) -> Vec<String> {
    v.sort();
    v
}

/// What rclcpp's list_parameters returns for `prefixes` at `depth`.
fn listed(names: &[String], prefixes: &[&str], depth: usize) -> Vec<String> {
    sorted(
        names
            .iter()
            .filter(|n| {
                prefixes.iter().any(|p| {
                    n.as_str() == *p
                        || (n.starts_with(&format!("{p}."))
                            && (depth == 0 || n[p.len()..].matches('.').count() < depth))
                })
            })
            .cloned()
            .collect(),
    )
}

fn ms(s: f64) -> String {
    format!("{:.2} ms", s * 1e3)
}

/// Print the series' latency distribution, overall and by reply size.
fn print_latencies(mtu: u32, out: &Value) {
    let series = out["series"].as_array().expect("series");
    let got: Vec<(f64, f64)> = series
        .iter()
        .filter(|c| !c["lost"].as_bool().unwrap_or(true))
        .map(|c| {
            (
                c["reply_bytes"].as_f64().unwrap(),
                c["seconds"].as_f64().unwrap(),
            )
        })
        .collect();
    println!(
        "--- MTU {mtu}: {} describe_parameters calls on one client, {} replies, {} lost",
        series.len(),
        got.len(),
        series.len() - got.len()
    );
    let bands = [
        (0.0, 1024.0, "< 1 KiB"),
        (1024.0, 8192.0, "1-8 KiB"),
        (8192.0, 32768.0, "8-32 KiB"),
        (32768.0, 1e9, ">= 32 KiB"),
        (0.0, 1e9, "all"),
    ];
    for (lo, hi, label) in bands {
        let xs: Vec<f64> = got
            .iter()
            .filter(|(b, _)| *b >= lo && *b < hi)
            .map(|(_, s)| *s)
            .collect();
        match quantiles(&xs) {
            Some((n, min, p50, p90, p99, max)) => println!(
                "    reply {label:>9}: n {n:3}  min {}  p50 {}  p90 {}  p99 {}  max {}",
                ms(min),
                ms(p50),
                ms(p90),
                ms(p99),
                ms(max)
            ),
            None => println!("    reply {label:>9}: none"),
        }
    }
    if let (Some(first), Some(last)) = (got.first(), got.last()) {
        println!("    replies from {} B to {} B", first.0, last.0);
    }
    if let Some(c) = series.iter().find(|c| c["lost"].as_bool().unwrap_or(false)) {
        println!(
            "    first loss: call {} ({} descriptors asked, ~{} B expected)",
            c["i"], c["names"], c["target_bytes"]
        );
    }
    let firsts: Vec<String> = out["fresh_first"]
        .as_array()
        .expect("fresh_first")
        .iter()
        .map(|m| {
            if m["lost"].as_bool().unwrap_or(true) {
                "lost".to_string()
            } else {
                ms(m["reply_s"].as_f64().unwrap())
            }
        })
        .collect();
    println!(
        "    first reply on a fresh client (get_parameter_types, 9 B): {}",
        firsts.join(", ")
    );
    let verbs: Vec<String> = out["verbs"]
        .as_object()
        .expect("verbs")
        .iter()
        .map(|(k, m)| {
            if m["lost"].as_bool().unwrap_or(true) {
                format!("{k} lost")
            } else {
                format!(
                    "{k} {} B {}",
                    m["reply_bytes"],
                    ms(m["reply_s"].as_f64().unwrap())
                )
            }
        })
        .collect();
    println!(
        "    ros2 param verbs (fresh client each): {}",
        verbs.join("; ")
    );
}

fn parameter_services_at(mtu: u32, domain: u16) {
    let ros_args = ["-p", "ros.diagnostics_period:=0.2"];
    let names = declared_names(&ros_args);
    let ns = if mtu == 65536 {
        Netns::new()
    } else {
        Netns::with_lo_mtu(mtu)
    };
    let node = start_node(&ns, domain, &ros_args);
    let out = rclpy_peer(
        &ns,
        &node,
        "params",
        "/annular_plate",
        json!({"names": names, "calls": 200, "timeout": 10.0, "min_bytes": 100, "max_bytes": 70000}),
    );
    print_latencies(mtu, &out);

    // Collect every failure first: one run shows all of them.
    let mut problems: Vec<String> = Vec::new();
    let mut check = |ok: bool, what: String| {
        if !ok {
            problems.push(what);
        }
    };
    for (verb, m) in out["verbs"].as_object().expect("verbs") {
        check(
            !m["lost"].as_bool().unwrap_or(true),
            format!("`{verb}`: no reply within 10 s on a fresh client"),
        );
    }
    // ros2 param list: every declared name, depth 0 (recursive).
    check(
        sorted(strings(&out["list"]["names"])) == names,
        format!(
            "list depth 0: {:?} != the {} declared names",
            out["list"]["names"],
            names.len()
        ),
    );
    for (key, prefixes, depth) in [
        ("list_plate", vec!["plate"], 0),
        ("list_ros_depth2", vec!["ros"], 2),
        ("list_two", vec!["joint", "pads"], 0),
    ] {
        let want = listed(&names, &prefixes, depth);
        check(
            !want.is_empty(),
            format!("{key}: the scene declares no such names"),
        );
        check(
            sorted(strings(&out[key]["names"])) == want,
            format!("{key}: {:?} != {want:?}", out[key]["names"]),
        );
    }
    // get / get_parameter_types / describe of every name in one call each.
    match out["get_all"].as_object() {
        Some(get) => {
            check(
                get.len() == names.len(),
                format!(
                    "get_parameters of all {} names: {} values",
                    names.len(),
                    get.len()
                ),
            );
            for n in &names {
                check(
                    get.get(n).map(|v| v["type"] != 0).unwrap_or(false),
                    format!("get_parameters: `{n}` not set: {:?}", get.get(n)),
                );
            }
            check(
                get.get("joint.speed")
                    .map(|v| v["value"] == 25.0)
                    .unwrap_or(false),
                "get_parameters: joint.speed != 25".into(),
            );
            check(
                get.get("simulation.rate_hz")
                    .map(|v| v["value"] == 1000.0)
                    .unwrap_or(false),
                "get_parameters: simulation.rate_hz != 1000".into(),
            );
            check(
                get.get("use_sim_time")
                    .map(|v| v["value"] == false)
                    .unwrap_or(false),
                "get_parameters: use_sim_time != false".into(),
            );
            if let Some(types) = out["types_all"].as_object() {
                for n in &names {
                    check(
                        types.get(n) == get.get(n).map(|v| &v["type"]),
                        format!(
                            "get_parameter_types `{n}`: {:?} vs get's {:?}",
                            types.get(n),
                            get.get(n)
                        ),
                    );
                }
            }
        }
        None => check(
            false,
            format!("get_parameters of all {} names: no reply", names.len()),
        ),
    }
    match out["describe_all"].as_object() {
        Some(desc) => {
            check(
                out["describe_all_count"] == names.len(),
                format!(
                    "describe_parameters: {} descriptors for {} names",
                    out["describe_all_count"],
                    names.len()
                ),
            );
            for n in &names {
                let d = desc.get(n);
                check(
                    d.map(|d| !d["description"].as_str().unwrap_or_default().is_empty())
                        .unwrap_or(false),
                    format!("describe_parameters: `{n}` has no description: {d:?}"),
                );
            }
            check(
                desc.get("plate.thickness")
                    .map(|d| d["read_only"] == true)
                    .unwrap_or(false),
                "plate.thickness is read only".into(),
            );
            check(
                desc.get("simulation.realtime_factor")
                    .map(|d| d["read_only"] == false)
                    .unwrap_or(false),
                "simulation.realtime_factor is not read only".into(),
            );
        }
        None => check(
            false,
            format!("describe_parameters of all {} names: no reply", names.len()),
        ),
    }
    check(
        out["get_one"] == json!([{"type": 3, "value": 25.0}, {"type": 0, "value": null}]),
        format!(
            "ros2 param get joint.speed / an unknown name: {}",
            out["get_one"]
        ),
    );
    // ros2 param set: accepted and refused, with the reasons.
    check(
        out["set_good"] == json!([{"ok": true, "reason": ""}, {"ok": true, "reason": ""}]),
        format!("set_parameters of the run-time keys: {}", out["set_good"]),
    );
    let refused = out["set_refused"].as_array().cloned().unwrap_or_default();
    // Each refusal names the key and the rule it breaks.
    let reasons = [
        "read only",
        "simulation.realtime_factor = -1 must not be negative",
        "ros.wrench_timeout must be a double",
        "not declared",
    ];
    check(
        refused.len() == 4,
        format!("set_parameters of four bad values: {refused:?}"),
    );
    for (r, why) in refused.iter().zip(reasons) {
        check(
            r["ok"] == false && r["reason"].as_str().unwrap_or_default().contains(why),
            format!("set_parameters refused with `{why}`: {r}"),
        );
    }
    check(
        out["set_atomic_good"]["ok"] == true,
        format!(
            "set_parameters_atomically of the run-time keys: {}",
            out["set_atomic_good"]
        ),
    );
    check(
        out["set_atomic_refused"]["ok"] == false
            && out["set_atomic_refused"]["reason"]
                .as_str()
                .unwrap_or_default()
                .contains("plate.thickness"),
        format!(
            "set_parameters_atomically with a read-only key: {}",
            out["set_atomic_refused"]
        ),
    );
    check(
        out["get_after"]
            == json!([{"type": 3, "value": 1.0}, {"type": 3, "value": 0.5}, {"type": 3, "value": 0.0181}]),
        format!(
            "after the sets (the atomic refusal changed nothing): {}",
            out["get_after"]
        ),
    );
    // 200 consecutive calls on one client, replies ~100 B .. ~70 KB, none lost.
    let series = out["series"].as_array().expect("series");
    check(
        series.len() == 200,
        format!("{} calls, not 200", series.len()),
    );
    let lost: Vec<String> = series
        .iter()
        .filter(|c| c["lost"].as_bool().unwrap_or(true))
        .map(|c| format!("{}(~{} B)", c["i"], c["target_bytes"]))
        .collect();
    check(
        lost.is_empty(),
        format!(
            "{} of 200 describe_parameters replies lost (not there within 10 s; after 3 in a row the rest are not sent), from call {}",
            lost.len(),
            lost.iter().take(3).cloned().collect::<Vec<_>>().join(" ")
        ),
    );
    let incomplete = series
        .iter()
        .filter(|c| c["lost"] == false && c["complete"] != true)
        .count();
    check(
        incomplete == 0,
        format!("{incomplete} replies with fewer descriptors than names asked"),
    );
    let sizes: Vec<f64> = series
        .iter()
        .filter_map(|c| c["reply_bytes"].as_f64())
        .collect();
    let (smallest, largest) = (
        sizes.iter().cloned().fold(f64::INFINITY, f64::min),
        sizes.iter().cloned().fold(0.0, f64::max),
    );
    let aimed = series
        .last()
        .and_then(|c| c["target_bytes"].as_f64())
        .unwrap_or(0.0);
    check(
        smallest <= 150.0 && aimed >= 66000.0,
        format!("the replies asked for span {smallest} .. {aimed} B, not ~100 B .. 70 KB"),
    );
    if lost.is_empty() {
        check(
            largest >= 66000.0,
            format!("the largest reply is {largest} B, not ~70 KB"),
        );
    }
    for (i, m) in out["fresh_first"]
        .as_array()
        .expect("fresh_first")
        .iter()
        .enumerate()
    {
        check(
            m["lost"] == false,
            format!("fresh client {i}: first reply lost"),
        );
    }
    assert!(
        problems.is_empty(),
        "MTU {mtu}: {} problems:\n  {}",
        problems.len(),
        problems.join("\n  ")
    );
}

#[test]
fn parameter_services_answer_the_ros2_param_verbs_and_200_calls_up_to_70_kb_at_mtu_65536() {
    parameter_services_at(65536, 151);
}

#[test]
fn parameter_services_answer_the_ros2_param_verbs_and_200_calls_up_to_70_kb_at_mtu_1500() {
    parameter_services_at(1500, 152);
}
