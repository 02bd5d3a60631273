#!/usr/bin/env bash
# Regenerate the README's pictures (docs/img/*.png) from a release build:
#   cargo build --release && bash docs/img/regenerate.sh
# The study picture's timings are this machine's (see docs/study.md); everything
# else is deterministic.
set -euo pipefail
cd "$(dirname "$0")/../.."
B=${ANNULAR_PLATE:-target/release/annular_plate}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT

# Mode shapes (paper Figs. 2 and 3).
$B plot modes config/lathe.yaml --l 0,1,2 \
  --title "The lathe disc (config/lathe.yaml, paper 5.1): r_i = 75 mm, r_a = 150 mm, h = 10 mm, steel, clamped inside, free outside — ⟨k, l⟩ from above, nodal lines black" \
  --out docs/img/modes_lathe.png
$B plot mode config/lathe.yaml -p plate.inner_boundary:=supported --k 2 --l 2 --out docs/img/mode_k2_l2_supported.png

# The three scenes of the paper's section 5 (Figs. 9, 15, 17).
$B simulate config/lathe.yaml --duration 5.5 --csv "$T/lathe.csv" --quiet
$B plot csv "$T/lathe.csv" --columns q2,q3 --panel qale2,qale3 --panel tool_feed_force \
  --ylabel "Lagrangian q, ⟨1,0⟩ pair (m)" --ylabel "ALE q, ⟨1,0⟩ pair (m)" --ylabel "feed force (N)" \
  --title "config/lathe.yaml (paper Fig. 9): the ⟨k = 1, l = 0⟩ pair while the tool cuts — Lagrangian, ALE; feed force" \
  --size 1200x950 --out docs/img/scene_lathe.png
$B simulate config/swash_plate.yaml --duration 5 --csv "$T/swash.csv" --quiet
$B plot csv "$T/swash.csv" --columns lagrange1_uz,lagrange2_uz --panel q3,q1 \
  --ylabel "deflection at the links (m)" --ylabel "q3 = ⟨0,0⟩, q1 = ⟨1,0⟩ cos (m)" \
  --title "config/swash_plate.yaml (paper Fig. 15): deflection at the two linkage points; modal amplitudes" \
  --out docs/img/scene_swash_plate.png
$B simulate config/brake_squeal_paper.yaml --duration 5 --csv "$T/squeal.csv" --quiet
$B plot csv "$T/squeal.csv" --columns q1,q2 --panel q3,q4 \
  --ylabel "⟨1,0⟩ pair, Lagrangian (m)" --ylabel "⟨2,0⟩ pair, Lagrangian (m)" \
  --title "config/brake_squeal_paper.yaml (paper Fig. 17): modal amplitudes at μ = 0.6, above the flutter threshold 0.300 (sampled at 1 kHz)" \
  --out docs/img/scene_brake_squeal.png

# The plate as RViz/Foxglove get it (docs/ros.md): a marker drawn from a bag,
# and an animation of a run (from its CSV).
$B simulate config/swash_plate.yaml --duration 0.3 --bag "$T/swash_bag" --csv "$T/swash_short.csv" --quiet
$B plot marker "$T/swash_bag" --out docs/img/plate_marker_bag.png
$B plot animate "$T/swash_short.csv" --params config/swash_plate.yaml --fps 20 --slowdown 2 --size 720x360 --quiet \
  --out docs/img/swash_plate.gif

# Accuracy against cost (docs/study.md).
$B study --quiet --plot docs/img/study_pareto.png > "$T/study.txt"
cat "$T/study.txt"
