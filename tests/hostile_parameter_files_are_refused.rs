//! Parameter files an attacker (or a slip of the units) would write are
//! refused before any work, naming the limit or the keys: deep nesting is
//! stopped before the YAML parser (whose time grows with the square of the
//! depth), an oversized file before it is read, and extreme but finite
//! material values by the derived quantities the model is built from.

use annular_plate::config::{Config, ConfigError, Params};
use annular_plate::model::PlateModel;

const NODE: &str = "annular_plate";

fn with_plate(lines: &str) -> Result<Config, ConfigError> {
    Config::from_yaml_str(
        &format!("annular_plate:\n  ros__parameters:\n    plate:\n{lines}"),
        NODE,
    )
}

#[test]
fn nesting_a_hundred_thousand_deep_is_refused_before_parsing_naming_the_line() {
    let d = 100_000;
    let text = format!(
        "annular_plate:\n  ros__parameters:\n    plate:\n      damping: {}{}\n",
        "[".repeat(d),
        "]".repeat(d)
    );
    let e = Config::from_yaml_str(&text, NODE).unwrap_err();
    assert!(matches!(e, ConfigError::TooDeep { line: 4, .. }), "{e:?}");
    assert!(
        e.to_string().contains("line 4") && e.to_string().contains("32 levels"),
        "{e}"
    );
    // Block nesting and `-p` overrides too.
    let mut block = String::from("annular_plate:\n  ros__parameters:\n");
    for level in 0..2_000 {
        block.push_str(&format!("{}k{level}:\n", " ".repeat(4 + 2 * level)));
    }
    assert!(matches!(
        Config::from_yaml_str(&block, NODE),
        Err(ConfigError::TooDeep { .. })
    ));
    let mut p = Params::new();
    assert!(matches!(
        p.set_override("plate.damping", &"[".repeat(5_000)),
        Err(ConfigError::TooDeep { .. })
    ));
    // What a real file nests is far from the limit.
    assert!(with_plate("      damping: [0.02]\n      nodal_circles: [0, 1]\n").is_ok());
}

#[test]
fn a_file_beyond_the_size_limit_is_refused_before_it_is_read() {
    let path = std::env::temp_dir().join(format!("annular_plate_big_{}.yaml", std::process::id()));
    let mut text =
        String::from("annular_plate:\n  ros__parameters:\n    plate:\n      thickness: 0.01\n");
    text.push_str(&"# padding\n".repeat(120_000));
    std::fs::write(&path, &text).unwrap();
    let e = Config::from_params_file(&path, NODE).unwrap_err();
    std::fs::remove_file(&path).unwrap();
    assert!(
        matches!(
            e,
            ConfigError::TooLarge {
                limit: 1_048_576,
                ..
            }
        ),
        "{e:?}"
    );
}

#[test]
fn extreme_finite_material_values_are_refused_naming_their_keys() {
    let cases = [
        ("density: 1.0e-308", "plate.density"),
        ("density: 1.0e+300", "plate.density"),
        ("youngs_modulus: 1.0e+308", "plate.youngs_modulus"),
        ("youngs_modulus: 1.0e-308", "plate.youngs_modulus"),
        ("thickness: 5.0e-324", "plate.thickness"),
        ("thickness: 1.0e+100", "plate.thickness"),
        (
            "outer_radius: 1.0e+200\n      inner_radius: 1.0e+199",
            "plate.outer_radius",
        ),
        (
            "outer_radius: 1.0e-200\n      inner_radius: 1.0e-201",
            "plate.outer_radius",
        ),
    ];
    for (line, key) in cases {
        let e = with_plate(&format!("      {line}\n")).expect_err(line);
        let text = e.to_string();
        assert!(
            text.contains(key),
            "{line}: the refusal does not name {key}: {text}"
        );
        assert!(
            !text.contains("Pivot") && !text.contains("NaN"),
            "{line}: internal text in {text}"
        );
    }
}

#[test]
fn accepted_materials_build_a_model() {
    // The derived ranges leave every real plate in: a rubber membrane, a
    // tungsten slab, a micro-machined silicon ring, a steel disc of 10 m.
    let plates = [
        "      youngs_modulus: 1.0e6\n      density: 1100.0\n      thickness: 1.0e-4\n",
        "      youngs_modulus: 4.1e11\n      density: 19300.0\n      thickness: 0.05\n",
        "      youngs_modulus: 1.6e11\n      density: 2330.0\n      thickness: 2.0e-6\n      inner_radius: 1.0e-4\n      outer_radius: 2.0e-4\n",
        "      outer_radius: 10.0\n      inner_radius: 1.0\n      thickness: 0.05\n",
    ];
    for plate in plates {
        let c = with_plate(plate).unwrap_or_else(|e| panic!("{plate}: {e}"));
        let m = PlateModel::new(&c.plate).unwrap_or_else(|e| panic!("{plate}: {e}"));
        assert!(
            m.modes()
                .iter()
                .all(|m| m.omega.is_finite() && m.omega > 0.0),
            "{plate}"
        );
    }
}
