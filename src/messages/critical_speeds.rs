//! `~/critical_speeds` and the near-critical /diagnostics status
//! (docs/ros.md): the critical speeds of the retained modes as `campbell`
//! computes them (honouring `plate.centrifugal_stiffening`), as a message
//! published once at start, and the `<node>: critical speeds` status — WARN
//! while the joint speed is within [`NEAR_FRACTION`] of one of them.

use super::types::{CriticalSpeeds, DiagnosticStatus, KeyValue};
use crate::model::campbell::CriticalSpeed;

/// |Ω| within this fraction of a critical speed Ω_c (|​|Ω| − Ω_c| ≤ 0.05 Ω_c) warns.
pub const NEAR_FRACTION: f64 = 0.05;

/// The `~/critical_speeds` message.
pub fn message(speeds: &[CriticalSpeed], stiffening: bool) -> CriticalSpeeds {
    CriticalSpeeds {
        centrifugal_stiffening: stiffening,
        k: speeds.iter().map(|s| s.k).collect(),
        l: speeds.iter().map(|s| s.l).collect(),
        rad_s: speeds.iter().map(|s| s.rad_s).collect(),
    }
}

/// The critical speed nearest to |Ω| in relative terms, if within [`NEAR_FRACTION`].
pub fn near(speeds: &[CriticalSpeed], joint_speed: f64) -> Option<&CriticalSpeed> {
    let w = joint_speed.abs();
    speeds
        .iter()
        .map(|s| (s, (w - s.rad_s).abs() / s.rad_s))
        .filter(|&(_, gap)| gap <= NEAR_FRACTION)
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(s, _)| s)
}

/// `<node>: critical speeds`: WARN naming the mode ⟨k, l⟩, the joint speed
/// and the critical speed while |Ω| is within 5 % of one; OK otherwise.
pub fn status(node_name: &str, speeds: &[CriticalSpeed], joint_speed: f64) -> DiagnosticStatus {
    let kv = |k: &str, v: String| KeyValue {
        key: k.to_string(),
        value: v,
    };
    let mut values = vec![
        kv("joint_speed_rad_s", format!("{joint_speed}")),
        kv("critical_speeds", speeds.len().to_string()),
    ];
    let (level, message) = match near(speeds, joint_speed) {
        Some(s) => {
            values.extend([
                kv("near_k", s.k.to_string()),
                kv("near_l", s.l.to_string()),
                kv("near_rad_s", format!("{}", s.rad_s)),
            ]);
            (
                DiagnosticStatus::WARN,
                format!(
                    "joint speed {:.1} rad/s is within {:.1} % of the critical speed {:.1} rad/s of mode <{}, {}> (5 % warns)",
                    joint_speed.abs(),
                    100.0 * (joint_speed.abs() - s.rad_s).abs() / s.rad_s,
                    s.rad_s,
                    s.k,
                    s.l
                ),
            )
        }
        None if speeds.is_empty() => (
            DiagnosticStatus::OK,
            "no critical speeds in the mode set".to_string(),
        ),
        None => (
            DiagnosticStatus::OK,
            "joint speed more than 5 % from every critical speed".to_string(),
        ),
    };
    DiagnosticStatus {
        level,
        name: format!("{node_name}: critical speeds"),
        message,
        hardware_id: node_name.to_string(),
        values,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn speeds() -> Vec<CriticalSpeed> {
        vec![
            CriticalSpeed {
                k: 2,
                l: 0,
                rad_s: 458.0,
            },
            CriticalSpeed {
                k: 3,
                l: 0,
                rad_s: 480.0,
            },
            CriticalSpeed {
                k: 2,
                l: 1,
                rad_s: 2000.0,
            },
        ]
    }

    #[test]
    fn warns_within_five_percent_of_a_critical_speed_naming_the_nearest_mode_and_both_speeds() {
        let s = speeds();
        // 458 · 0.95 = 435.1 and 458 · 1.05 = 480.9: the band's edges.
        for (w, expected) in [
            (0.0, None),
            (435.0, None),
            (435.2, Some((2, 0))),
            (458.0, Some((2, 0))),
            (-460.0, Some((2, 0))),
            (470.0, Some((3, 0))),
            (505.0, None),
            (505.9, None),
            (1900.5, Some((2, 1))),
            (2100.1, None),
        ] {
            let st = status("/n", &s, w);
            let got = near(&s, w).map(|c| (c.k, c.l));
            assert_eq!(got, expected, "Ω = {w}");
            if let Some((k, l)) = expected {
                assert_eq!(st.level, DiagnosticStatus::WARN, "Ω = {w}");
                let c = s.iter().find(|c| c.k == k && c.l == l).unwrap();
                assert!(
                    st.message.contains(&format!("<{k}, {l}>"))
                        && st.message.contains(&format!("{:.1}", c.rad_s))
                        && st.message.contains(&format!("{:.1}", w.abs())),
                    "{}",
                    st.message
                );
            } else {
                assert_eq!(st.level, DiagnosticStatus::OK, "Ω = {w}: {}", st.message);
            }
            assert_eq!(st.name, "/n: critical speeds");
        }
        // 480 · 1.05 = 504: above it nothing warns until 2000 · 0.95 = 1900.
        assert!(near(&s, 503.9).is_some() && near(&s, 504.1).is_none());
        assert_eq!(status("/n", &[], 100.0).level, DiagnosticStatus::OK);
    }

    #[test]
    fn the_message_lists_every_critical_speed_in_order() {
        let m = message(&speeds(), true);
        assert!(m.centrifugal_stiffening);
        assert_eq!(
            (m.k, m.l, m.rad_s),
            (vec![2, 3, 2], vec![0, 0, 1], vec![458.0, 480.0, 2000.0])
        );
    }
}
