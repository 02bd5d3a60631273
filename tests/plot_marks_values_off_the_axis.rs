//! A plot never draws a value outside its axis as if it were on it.
//!
//! `stability --plot`: a squeal threshold the map only bounds — unstable at
//! the first μ already (so at or below it), stable over the whole range (so
//! above the last), or a value beyond the axis — is an arrow at the edge it
//! lies beyond with the bound written beside it ("≤ 0.2", "> 0.6"), not a
//! dot on the curve at the edge. Thresholds inside the range stay dots.

mod support;

use annular_plate::cli::plot::{placement, stability_map, Placement, Size, StabilityGrid};

fn dir() -> std::path::PathBuf {
    support::cli::scratch_dir("off_axis")
}

#[test]
fn thresholds_outside_the_mu_range_are_arrows_at_the_edge_with_their_bound() {
    let speeds = [5.0, 15.0, 25.0, 35.0, 45.0];
    let mu = [0.2, 0.3, 0.4, 0.5, 0.6];
    let growth_rate = vec![
        vec![3.0, 4.0, 5.0, 6.0, 7.0], // unstable from the first μ: threshold at or below 0.2
        vec![-1.0, 1.0, 2.0, 3.0, 4.0], // threshold between 0.2 and 0.3
        vec![-2.0, -1.0, 1.0, 2.0, 3.0], // between 0.3 and 0.4
        vec![-3.0, -2.0, -1.0, -0.5, -0.1], // stable over the range
        vec![-1.0, -1.0, -1.0, -1.0, 1.0], // between 0.5 and 0.6
    ];
    // As `dynamics::stability_map` reports them: the first μ if unstable there, None if stable throughout.
    let threshold_mu = [Some(0.2), Some(0.27), Some(0.35), None, Some(0.58)];
    let grid = StabilityGrid {
        speeds: &speeds,
        mu: &mu,
        growth_rate: &growth_rate,
        threshold_mu: &threshold_mu,
    };
    let out = dir().join("map.png");
    let g = stability_map(
        &grid,
        &out,
        Size {
            width: 1200,
            height: 800,
        },
    )
    .unwrap();
    assert_eq!(g.thresholds.len(), 5);
    let by_speed = |s: f64| g.thresholds.iter().find(|t| t.speed == s).unwrap();

    let low = by_speed(5.0);
    assert_eq!(
        low.placement,
        Placement::Below,
        "unstable at μ = 0.2 already: not a dot at 0.2"
    );
    assert_eq!(low.label.as_deref(), Some("≤ 0.2"));
    let high = by_speed(35.0);
    assert_eq!(
        high.placement,
        Placement::Above,
        "stable over the range: an arrow at the top"
    );
    assert_eq!(high.label.as_deref(), Some("> 0.6"));
    for s in [15.0, 25.0, 45.0] {
        assert_eq!(by_speed(s).placement, Placement::Within);
        assert_eq!(by_speed(s).label, None);
    }
    // The arrows sit on the edges of the plotted range, the dots strictly between them.
    let dots: Vec<i32> = [15.0, 25.0, 45.0]
        .iter()
        .map(|&s| by_speed(s).pixel.1)
        .collect();
    assert!(
        dots.iter().all(|&y| y < low.pixel.1 && y > high.pixel.1),
        "{dots:?} between {} and {}",
        high.pixel.1,
        low.pixel.1
    );
    // On the picture: the arrow is drawn (black) just inside the lower edge at its speed.
    let img = image::open(&out).unwrap().to_rgb8();
    let (x, y) = low.pixel;
    let black = (y - 12..y)
        .filter(|&yy| img.get_pixel(x as u32, yy as u32).0.iter().all(|&c| c < 60))
        .count();
    assert!(
        black >= 8,
        "no arrow above ({x}, {y}): {black} black pixels"
    );
}

#[test]
fn a_value_beyond_the_axis_is_placed_beyond_it() {
    assert_eq!(placement(0.1, 0.15, 0.65), Placement::Below);
    assert_eq!(placement(0.15, 0.15, 0.65), Placement::Within);
    assert_eq!(placement(0.65, 0.15, 0.65), Placement::Within);
    assert_eq!(placement(0.7, 0.15, 0.65), Placement::Above);
    // A threshold below the plotted range (a map that starts above it) is marked "< edge".
    let speeds = [25.0];
    let mu = [0.4, 0.5, 0.6];
    let growth_rate = vec![vec![-1.0, -1.0, -1.0]];
    let threshold_mu = [Some(0.1)];
    let grid = StabilityGrid {
        speeds: &speeds,
        mu: &mu,
        growth_rate: &growth_rate,
        threshold_mu: &threshold_mu,
    };
    let g = stability_map(
        &grid,
        &dir().join("single.svg"),
        Size {
            width: 800,
            height: 600,
        },
    )
    .unwrap();
    assert_eq!(g.thresholds[0].placement, Placement::Below);
    assert!(
        g.thresholds[0].label.as_deref().unwrap().starts_with("< "),
        "{:?}",
        g.thresholds[0].label
    );
}
