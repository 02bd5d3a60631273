#!/usr/bin/env python3
"""Benchmark (not a test): the node's CPU per shipped scene, nobody listening.

For each case the node runs `annular_plate run SCENE` in wall time in a
private network namespace (loopback only, no peer), and after a warm-up the
utime + stime of its simulation thread (`annular_plate-sim`) and of the whole
process are read from /proc over the window. In the same invocation,
alternating with the cases, `ddsperf` (Debian package cyclonedds-tools;
installed with apt-get when missing) publishes 1000 samples/s of 600 bytes
with nobody listening: the floor of Cyclone DDS's C stack for an idle node's
traffic, as in benches/node_loop.py.

    python3 benches/scene_cpu.py --seconds 10 --repeat 2

Run as root from the repository root after `cargo build --release`.
docs/performance.md has the measured numbers.
"""

import argparse
import os
import signal
import subprocess
import sys
import time

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(REPO, "benches"))
from node_loop import ensure_ddsperf, thread_ticks  # noqa: E402

# name: (scene file, extra --ros-args)
CASES = {
    "brake_bench": ("config/brake_bench.yaml", []),
    "brake_bench clamped 8 kN": ("config/brake_bench.yaml", ["-p", "pads.clamp_force:=[8000.0]"]),
    "brake_bench on rk4": ("config/brake_bench.yaml", ["-p", "simulation.integrator:=rk4"]),
    "brake_bench clamped 8 kN on rk4": ("config/brake_bench.yaml",
                                       ["-p", "pads.clamp_force:=[8000.0]", "-p", "simulation.integrator:=rk4"]),
    "lathe": ("config/lathe.yaml", []),
    "swash_plate": ("config/swash_plate.yaml", []),
}
SIM_THREAD = "annular_plate-sim"[:15]  # /proc shows 15 characters of a thread name


def in_netns(argv):
    """argv inside a fresh network namespace with loopback up."""
    return ["unshare", "-n", "--", "sh", "-c", 'ip link set lo up && exec "$0" "$@"'] + argv


def measure(argv, warmup, seconds, env=None):
    """CPU % of one core over the window: {thread name: %} and the process's."""
    proc = subprocess.Popen(in_netns(argv), env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    try:
        time.sleep(warmup)
        pid = child_pid(proc.pid, os.path.basename(argv[0]))
        t0, w0 = thread_ticks(pid), time.monotonic()
        time.sleep(seconds)
        t1, w1 = thread_ticks(pid), time.monotonic()
    finally:
        proc.send_signal(signal.SIGINT)
        try:
            _, err = proc.communicate(timeout=10)
        except subprocess.TimeoutExpired:
            proc.kill()
            _, err = proc.communicate()
    scale = 100.0 / os.sysconf("SC_CLK_TCK") / (w1 - w0)
    per_thread = {name: (t1[name] - t0.get(name, 0)) * scale for name in t1}
    if proc.returncode not in (0, -signal.SIGINT, 130):
        sys.exit(f"{argv} exited {proc.returncode}: {err.decode(errors='replace')[-2000:]}")
    return per_thread, sum(per_thread.values())


def child_pid(pid, comm):
    """The process running `comm` at or below pid (unshare and sh exec into it)."""
    for _ in range(200):
        with open(f"/proc/{pid}/comm") as f:
            if f.read().strip() == comm[:15]:
                return pid
        children = open(f"/proc/{pid}/task/{pid}/children").read().split()
        if children:
            pid = int(children[0])
        else:
            time.sleep(0.01)
    sys.exit(f"no process {comm} under {pid}")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--seconds", type=float, default=10.0)
    ap.add_argument("--warmup", type=float, default=3.0)
    ap.add_argument("--repeat", type=int, default=2)
    ap.add_argument("--node", default=os.path.join(REPO, "target", "release", "annular_plate"))
    args = ap.parse_args()
    ensure_ddsperf()
    with open("/proc/cpuinfo") as f:
        model = next((l.split(":", 1)[1].strip() for l in f if l.startswith("model name")), "?")
    print(f"machine: nproc {os.cpu_count()}, {model}", flush=True)
    env = dict(os.environ, ROS_DOMAIN_ID="43")
    floor_env = dict(os.environ, CYCLONEDDS_URI="file://" + os.path.join(REPO, "tests", "peer", "cyclonedds.xml"))
    floor_cmd = ["ddsperf", "-i", "43", "-T", "KS", "pub", "1000Hz", "size", "600"]
    results = {case: ([], []) for case in CASES}
    floors = []
    for r in range(args.repeat):
        floors.append(measure(floor_cmd, args.warmup, args.seconds, floor_env)[1])
        print(f"[run {r + 1}] ddsperf floor {floors[-1]:.1f} %", flush=True)
        for case, (scene, extra) in CASES.items():
            cmd = [args.node, "run", os.path.join(REPO, scene), "--ros-args", "--log-level", "warn"] + extra
            threads, whole = measure(cmd, args.warmup, args.seconds, env)
            results[case][0].append(threads.get(SIM_THREAD, float("nan")))
            results[case][1].append(whole)
            print(f"[run {r + 1}] {case}: simulation thread {results[case][0][-1]:.1f} %, process {whole:.1f} %",
                  flush=True)
    rng = lambda xs: f"{min(xs):.1f}–{max(xs):.1f}"
    print(f"\nddsperf floor (idle, 1000 samples/s of 600 B): {rng(floors)} %")
    print("\n| scene | simulation thread % | process % | process / floor |")
    print("|---|---|---|---|")
    for case, (sim, whole) in results.items():
        ratios = [w / f for w, f in zip(whole, floors)]
        print(f"| {case} | {rng(sim)} | {rng(whole)} | {min(ratios):.1f}–{max(ratios):.1f} |")


if __name__ == "__main__":
    main()
