#!/usr/bin/env python3
"""Side-by-side benchmark (not a test): the lathe case in `annular_plate
simulate` and in Exudyn (PyPI), both at a 10 kHz step for 5.5 s with 1 kHz
output.

  annular_plate, full scene: `simulate config/lathe.yaml` with
      simulation.rate_hz 10 kHz, `--output-rate 1000 --csv` — the full lathe
      scene (30 ALE modes, the regenerative tool model with its surface memory
      in series with the residual flexibility, node outputs), timed as a whole
      process (user + system CPU of the child, and wall).
  annular_plate, same equations: Exudyn's equations below and nothing else —
      lathe.yaml without the tool and without the Lagrangian node, the rim load
      as a held ALE wrench (0, 0, −F, 0, 0, 0) at the ALE node on the rim at
      θ = 0 (`loads.ale_wrench`), `plate.residual_flexibility: false` (Exudyn's
      model has no residual correction), 10 kHz, 5.5 s, `--output-rate 1000
      --csv`. Its CSV row: time, joint angle and speed, the 30 Lagrangian and
      the 30 ALE amplitudes and the ALE node's uz (64 values, shortest
      round-trip text); Exudyn's coordinates file row: time and the 30
      coordinates, velocities and accelerations (91 values, 10 significant
      digits). Timed as a whole process (model build from the plate data
      included; Exudyn is given the modes).
  Exudyn: the 30 ALE modal equations of the same disc at the same spin
      (docs/dynamics.md, "The ALE equations"; frequencies, modal masses and
      damping from `annular_plate modes --json`) as one ObjectGenericODE2
      (mass-normalised: M = I, D = 2ζω I − 2kΩ J per pair, K = (ω² − k²Ω²) I −
      2ζωkΩ J), under a constant space-fixed rim load of the size of the steady
      cut's feed force F (the mean tool_feed_force of the full-scene run over
      2–5 s) along −z, as the tool pushes: −F/m on every cos and axisymmetric
      mode (the shapes are 1 at the rim at θ = 0), the sin modes unloaded,
      integrated with Exudyn's implicit generalized-α solver (SolveDynamic,
      default settings, 55 000 steps), solution written every 1 ms. Timed solver only (process
      CPU around SolveDynamic) and as a whole process.

Two ratios: Exudyn's solver against annular_plate on the same equations (the
headline comparison), and against the full scene (Exudyn does less work). The
script checks that both solved those equations: Exudyn's and annular_plate's
ALE amplitudes at 5.5 s against the closed-form steady state
[(ω² − k²Ω²) I − 2ζωkΩ J] q̄ = f̄ (docs/dynamics.md) and against each other
(largest difference relative to the largest steady amplitude).

Exudyn is installed by the script into target/exudyn-venv (like the tests'
peer in target/peer-venv):

    cargo build --release
    python3 benches/exudyn_lathe.py [--repeat 3]
"""

import argparse
import json
import os
import subprocess
import sys
import time

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
VENV = os.path.join(REPO, "target", "exudyn-venv")
EXUDYN = "exudyn==1.13.6"
OUT = os.path.join(REPO, "target", "exudyn_lathe")
RATE_HZ = 10_000
OUTPUT_HZ = 1_000
DURATION = 5.5


def ensure_venv():
    python = os.path.join(VENV, "bin", "python")
    ok = os.path.exists(python) and subprocess.call(
        [python, "-c", "import exudyn, numpy"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL) == 0
    if not ok:
        print(f"installing {EXUDYN} into {VENV}", flush=True)
        subprocess.check_call([sys.executable, "-m", "venv", VENV])
        subprocess.check_call([python, "-m", "pip", "install", "--disable-pip-version-check", "-q", EXUDYN, "numpy"])
    return python


def child_cpu(cmd, **kw):
    """Run cmd; (user + system CPU s, wall s) of the child."""
    t0 = time.perf_counter()
    p = subprocess.Popen(cmd, **kw)
    _, status, usage = os.wait4(p.pid, 0)
    wall = time.perf_counter() - t0
    if status != 0:
        sys.exit(f"{cmd[0]} failed ({status})")
    return usage.ru_utime + usage.ru_stime, wall


def annular_plate_run(node):
    scene = os.path.join(OUT, "lathe_10khz.yaml")
    with open(os.path.join(REPO, "config", "lathe.yaml")) as f:
        text = f.read()
    assert "rate_hz: 1000.0" in text
    with open(scene, "w") as f:
        f.write(text.replace("rate_hz: 1000.0", f"rate_hz: {RATE_HZ:.1f}"))
    csv = os.path.join(OUT, "annular_plate.csv")
    cpu, wall = child_cpu([node, "simulate", scene, "--duration", str(DURATION), "--output-rate", str(OUTPUT_HZ),
                           "--csv", csv, "--quiet"], stderr=subprocess.DEVNULL)
    return cpu, wall, csv


def same_equations_run(node, force):
    """annular_plate on Exudyn's equations (module docstring): (CPU s, wall s, q̄ at the last row)."""
    with open(os.path.join(REPO, "config", "lathe.yaml")) as f:
        text = f.read()
    for old, new in [
        ("rate_hz: 1000.0", f"rate_hz: {RATE_HZ:.1f}"),
        ("      damping: [0.02]\n", "      damping: [0.02]\n      residual_flexibility: false\n"),
        ("      lagrange_radial: [1.0]     # a material point on the rim (turns with the disc)\n"
         "      lagrange_angular: [0.0]\n", ""),
    ]:
        assert old in text, old
        text = text.replace(old, new)
    tool, sim = text.index("    tool:\n"), text.index("    simulation:\n")
    text = text[:tool] + f"    loads:\n      ale_wrench: [0.0, 0.0, {-force!r}, 0.0, 0.0, 0.0]\n" + text[sim:]
    scene = os.path.join(OUT, "same_equations.yaml")
    with open(scene, "w") as f:
        f.write(text)
    csv = os.path.join(OUT, "same_equations.csv")
    cpu, wall = child_cpu([node, "simulate", scene, "--duration", str(DURATION), "--output-rate", str(OUTPUT_HZ),
                           "--csv", csv, "--quiet"], stderr=subprocess.DEVNULL)
    with open(csv) as f:
        cols = f.readline().strip().split(",")
        last = None
        for last in f:
            pass
    row = dict(zip(cols, last.strip().split(",")))
    assert abs(float(row["time"]) - DURATION) < 1e-9, row["time"]
    q_ale = [float(row[f"qale{i}"]) for i in range(1, sum(c.startswith("qale") for c in cols) + 1)]
    return cpu, wall, q_ale


def steady_feed_force(csv):
    with open(csv) as f:
        cols = f.readline().strip().split(",")
        i_t, i_f = cols.index("time"), cols.index("tool_feed_force")
        values = [float(r[i_f]) for r in (line.split(",") for line in f) if 2.0 <= float(r[i_t]) <= 5.0]
    return sum(values) / len(values)


def exudyn_side(args):
    """Runs in the Exudyn venv: build, solve, check; prints JSON."""
    import numpy as np
    import warnings
    warnings.simplefilter("ignore", DeprecationWarning)
    import exudyn as exu
    from exudyn.itemInterface import NodeGenericODE2, ObjectGenericODE2

    t_start = time.process_time()
    with open(args.modes_json) as f:
        modes = json.load(f)["modes"]
    omega_spin = args.spin
    n = len(modes)
    M, D, K, f = np.eye(n), np.zeros((n, n)), np.zeros((n, n)), np.zeros(n)
    # Pair each cos mode with its sin partner (same k, l).
    index = {(m["k"], m["l"], m["shape"]): i for i, m in enumerate(modes)}
    for i, m in enumerate(modes):
        w = 2 * np.pi * m["frequency_hz"]
        z = m["damping"]
        D[i, i] = 2 * z * w
        K[i, i] = w * w - (m["k"] * omega_spin) ** 2
        if m["shape"] in ("cos", "axisymmetric"):
            f[i] = args.force / m["modal_mass_kg"]
        if m["shape"] == "cos":
            s = index[(m["k"], m["l"], "sin")]
            kO = m["k"] * omega_spin
            # J = [[0, -1], [1, 0]] on (c, s): −2kΩ J q̄̇ and −2ζωkΩ J q̄.
            D[i, s], D[s, i] = 2 * kO, -2 * kO
            K[i, s], K[s, i] = 2 * z * w * kO, -2 * z * w * kO
    SC = exu.SystemContainer()
    mbs = SC.AddSystem()
    node = mbs.AddNode(NodeGenericODE2(numberOfODE2Coordinates=n, referenceCoordinates=[0.0] * n,
                                       initialCoordinates=[0.0] * n, initialCoordinates_t=[0.0] * n))
    mbs.AddObject(ObjectGenericODE2(nodeNumbers=[node], massMatrix=M, stiffnessMatrix=K, dampingMatrix=D,
                                    forceVector=f.tolist()))
    mbs.Assemble()
    settings = exu.SimulationSettings()
    settings.timeIntegration.numberOfSteps = int(round(DURATION * RATE_HZ))
    settings.timeIntegration.endTime = DURATION
    settings.timeIntegration.verboseMode = 0
    settings.solutionSettings.writeSolutionToFile = True
    settings.solutionSettings.solutionWritePeriod = 1.0 / OUTPUT_HZ
    settings.solutionSettings.coordinatesSolutionFileName = os.path.join(OUT, "exudyn_solution.txt")
    settings.displayStatistics = False
    settings.displayComputationTime = False
    t0 = time.process_time()
    w0 = time.perf_counter()
    exu.SolveDynamic(mbs, settings)
    solver_cpu = time.process_time() - t0
    solver_wall = time.perf_counter() - w0
    q_end = np.array(mbs.GetNodeOutput(node, exu.OutputVariableType.Coordinates))
    steady = np.linalg.solve(K, f)
    scale = np.max(np.abs(steady))
    error = np.max(np.abs(q_end - steady)) / scale
    with open(args.annular_plate_q) as fh:
        q_ap = np.array(json.load(fh))
    ap_error = np.max(np.abs(q_ap - steady)) / scale
    ap_vs_exudyn = np.max(np.abs(q_ap - q_end)) / scale
    with open(settings.solutionSettings.coordinatesSolutionFileName) as fh:
        rows = sum(1 for line in fh if line and line[0] not in "#\n")
    print(json.dumps({"solver_cpu": solver_cpu, "solver_wall": solver_wall, "steady_error": error, "rows": rows,
                      "annular_plate_steady_error": ap_error, "annular_plate_vs_exudyn": ap_vs_exudyn,
                      "steady_amplitude": scale, "modes": n, "setup_cpu": t0 - t_start}))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--node", default=os.path.join(REPO, "target", "release", "annular_plate"))
    ap.add_argument("--exudyn-side", action="store_true", help=argparse.SUPPRESS)
    ap.add_argument("--modes-json", help=argparse.SUPPRESS)
    ap.add_argument("--spin", type=float, help=argparse.SUPPRESS)
    ap.add_argument("--force", type=float, help=argparse.SUPPRESS)
    ap.add_argument("--annular-plate-q", help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.exudyn_side:
        exudyn_side(args)
        return
    os.makedirs(OUT, exist_ok=True)
    python = ensure_venv()
    with open("/proc/cpuinfo") as f:
        model = next((l.split(":", 1)[1].strip() for l in f if l.startswith("model name")), "?")
    version = subprocess.check_output([python, "-c", "import exudyn; print(exudyn.__version__)"], text=True).strip()
    print(f"machine: nproc {os.cpu_count()}, {model}; Exudyn {version}")
    modes_json = os.path.join(OUT, "modes.json")
    with open(modes_json, "w") as f:
        subprocess.check_call([args.node, "modes", os.path.join(REPO, "config", "lathe.yaml"), "--json"], stdout=f,
                              stderr=subprocess.DEVNULL)
    spin = 100.0 / 60.0 / 0.15
    rows = []
    force = None
    for r in range(args.repeat):
        ap_cpu, ap_wall, csv = annular_plate_run(args.node)
        if force is None:
            force = steady_feed_force(csv)  # from the first run: every run then solves the same equations
        same_cpu, same_wall, q_ale = same_equations_run(args.node, force)
        q_file = os.path.join(OUT, "annular_plate_q_ale.json")
        with open(q_file, "w") as f:
            json.dump(q_ale, f)
        t0 = time.perf_counter()
        p = subprocess.Popen([python, os.path.abspath(__file__), "--exudyn-side", "--modes-json", modes_json,
                              "--spin", repr(spin), "--force", repr(-force), "--annular-plate-q", q_file],
                             stdout=subprocess.PIPE, text=True)
        out = p.stdout.read()
        _, status, usage = os.wait4(p.pid, 0)
        exu_wall = time.perf_counter() - t0
        exu_cpu = usage.ru_utime + usage.ru_stime
        if status != 0:
            sys.exit("the Exudyn side failed")
        e = json.loads(out)
        rows.append((ap_cpu, same_cpu, e["solver_cpu"], exu_cpu))
        print(f"[run {r + 1}] annular_plate whole process: full scene {ap_cpu:.3f} s CPU ({ap_wall:.3f} s wall), "
              f"same equations {same_cpu:.3f} s CPU ({same_wall:.3f} s wall); "
              f"Exudyn solver {e['solver_cpu']:.3f} s CPU ({e['solver_wall']:.3f} s wall), whole process "
              f"{exu_cpu:.3f} s CPU ({exu_wall:.3f} s wall); {e['rows']} solution rows; feed force {force:.1f} N", flush=True)
        print(f"        q̄ at 5.5 s (largest |difference| / largest steady |q̄| = {e['steady_amplitude']:.3e} m): "
              f"Exudyn vs closed form {e['steady_error']:.1e}, annular_plate vs closed form "
              f"{e['annular_plate_steady_error']:.1e}, annular_plate vs Exudyn {e['annular_plate_vs_exudyn']:.1e}", flush=True)
    rng = lambda xs: f"{min(xs):.3f}–{max(xs):.3f}"
    same = [ex / s for _, s, ex, _ in rows]
    full = [ex / ap for ap, _, ex, _ in rows]
    print(f"\nannular_plate whole process: same equations {rng([r[1] for r in rows])} s CPU, full scene "
          f"{rng([r[0] for r in rows])} s CPU; Exudyn solver only {rng([r[2] for r in rows])} s CPU, Exudyn whole "
          f"process {rng([r[3] for r in rows])} s CPU.\nExudyn solver / annular_plate process (run by run): "
          f"same equations {min(same):.1f}–{max(same):.1f}, full scene {min(full):.1f}–{max(full):.1f}")


if __name__ == "__main__":
    main()
