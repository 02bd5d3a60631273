//! package.xml and CMakeLists.txt name every interface of the package: each
//! `msg/*.msg` and `srv/*.srv` is in package.xml's description and in
//! CMakeLists.txt's `rosidl_generate_interfaces`, and every standard package whose types the node
//! speaks is an exec_depend.

use std::path::PathBuf;

fn repo() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn interfaces() -> Vec<(String, String)> {
    let mut out = Vec::new();
    for dir in ["msg", "srv"] {
        for entry in std::fs::read_dir(repo().join(dir)).unwrap() {
            let path = entry.unwrap().path();
            if path.extension().is_some_and(|e| e == dir) {
                out.push((
                    dir.to_string(),
                    path.file_stem().unwrap().to_string_lossy().to_string(),
                ));
            }
        }
    }
    out.sort();
    out
}

#[test]
fn every_msg_and_srv_file_is_described_and_built() {
    let package = std::fs::read_to_string(repo().join("package.xml")).unwrap();
    let description =
        &package[package.find("<description>").unwrap()..package.find("</description>").unwrap()];
    let cmake = std::fs::read_to_string(repo().join("CMakeLists.txt")).unwrap();
    let all = interfaces();
    assert!(all.len() >= 7, "{all:?}");
    for (dir, name) in &all {
        let word = |text: &str| {
            text.split(|c: char| !c.is_alphanumeric() && c != '_')
                .any(|w| w == name)
        };
        assert!(
            word(description),
            "package.xml's description does not name {dir}/{name}"
        );
        assert!(
            cmake.contains(&format!("\"{dir}/{name}.{dir}\"")),
            "CMakeLists.txt does not build {dir}/{name}.{dir}"
        );
    }
}

#[test]
fn every_standard_package_the_node_speaks_is_a_dependency() {
    let package = std::fs::read_to_string(repo().join("package.xml")).unwrap();
    for pkg in [
        "std_msgs",
        "geometry_msgs",
        "sensor_msgs",
        "std_srvs",
        "tf2_msgs",
        "rosgraph_msgs",
        "diagnostic_msgs",
        "visualization_msgs",
        "simulation_interfaces",
    ] {
        assert!(
            package.contains(&format!("depend>{pkg}</")),
            "package.xml lacks a dependency on {pkg}"
        );
    }
}
