#!/usr/bin/env python3
"""Benchmark (not a test): the node's resident memory over many rounds of
peers joining and leaving.

Each round, `--peers` Cyclone DDS participants join (one process), subscribe
/joint_states and /tf like an rclpy monitor until each has a sample, and
leave cleanly; then as many again join and vanish without a goodbye (the
process exits at once, as a SIGKILLed one would: their leases, 10 s in
Cyclone DDS, must expire). The peer is tests/peer/peer.py's `churn`
scenario, the same as tests/node_memory_under_peer_churn.rs (which runs 4
rounds and asserts the memory comes back once the leases expire).

Printed: the node's VmRSS after every round, then after the last leases
have expired (`--expiry` seconds), and the summary it is run for —
whether the memory stays flat within 10 %: the largest RSS from round
`--warm-rounds` on against the RSS after that warm-up round, and the RSS
after the final expiry against the same.

Run as root from the repository root after `cargo build --release` and one
`cargo test --release` (which creates target/peer-venv):

    target/peer-venv/bin/python benches/peer_churn.py [--rounds 100] [--peers 10]

Node and peers run in a private network namespace (loopback only).
"""

import argparse
import json
import os
import subprocess
import sys
import time

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DOMAIN = 43


def rss_kb(pid):
    with open(f"/proc/{pid}/status") as f:
        return int(next(l for l in f if l.startswith("VmRSS:")).split()[1])


def churn(peers, clean):
    env = dict(os.environ, CYCLONEDDS_URI="file://" + os.path.join(REPO, "tests", "peer", "cyclonedds.xml"))
    out = subprocess.run(
        [sys.executable, os.path.join(REPO, "tests", "peer", "peer.py"), "churn", "--domain", str(DOMAIN),
         "--node", "/annular_plate", "--args", json.dumps({"peers": peers, "clean": clean, "domain": DOMAIN})],
        env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=300)
    line = out.stdout.strip().splitlines()[-1] if out.stdout.strip() else ""
    if not line or json.loads(line).get("joined") != peers:
        sys.exit(f"peer round failed: {out.stdout}\n{out.stderr}")


def in_netns(args):
    env = dict(os.environ, ROS_DOMAIN_ID=str(DOMAIN))
    node = subprocess.Popen([args.node, "run", os.path.join(REPO, "config", "brake_bench.yaml"), "--ros-args", "--log-level", "warn"],
                            env=env, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        time.sleep(1.0)
        start = rss_kb(node.pid)
        print(f"node started: {start} kB", flush=True)
        per_round = []
        t0 = time.time()
        for r in range(1, args.rounds + 1):
            churn(args.peers, True)
            churn(args.peers, False)
            per_round.append(rss_kb(node.pid))
            print(f"round {r}: {per_round[-1]} kB ({time.time() - t0:.0f} s)", flush=True)
        time.sleep(args.expiry)
        after = rss_kb(node.pid)
        warm = per_round[args.warm_rounds - 1]
        peak = max(per_round[args.warm_rounds - 1:])
        last = per_round[-10:]
        print(f"\nnode RSS, {args.rounds} rounds of {args.peers} clean + {args.peers} killed peers:")
        print(f"  started {start} kB; after round {args.warm_rounds} (warm) {warm} kB; "
              f"largest from there {peak} kB ({100.0 * (peak / warm - 1):+.1f} %); "
              f"last 10 rounds {min(last)}–{max(last)} kB ({100.0 * (max(last) / warm - 1):+.1f} %); "
              f"{args.expiry:.0f} s after the last round {after} kB ({100.0 * (after / warm - 1):+.1f} %)")
        print(f"  flat within 10 % of the warm value: {'yes' if peak <= 1.1 * warm else 'no'} (largest), "
              f"{'yes' if after <= 1.1 * warm else 'no'} (after expiry)")
    finally:
        node.terminate()
        node.wait(timeout=10)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--rounds", type=int, default=100)
    ap.add_argument("--peers", type=int, default=10, help="participants per half round (as many again are killed)")
    ap.add_argument("--warm-rounds", type=int, default=10, help="the round whose RSS is the reference")
    ap.add_argument("--expiry", type=float, default=20.0, help="seconds to wait after the last round")
    ap.add_argument("--node", default=os.path.join(REPO, "target", "release", "annular_plate"))
    ap.add_argument("--in-netns", action="store_true", help=argparse.SUPPRESS)
    args = ap.parse_args()
    args.warm_rounds = max(1, min(args.warm_rounds, args.rounds))
    if args.in_netns:
        in_netns(args)
        return
    with open("/proc/cpuinfo") as f:
        model = next((l.split(":", 1)[1].strip() for l in f if l.startswith("model name")), "?")
    print(f"machine: nproc {os.cpu_count()}, {model}", flush=True)
    cmd = ["unshare", "-n", "--", "sh", "-c", 'ip link set lo up && exec "$0" "$@"', sys.executable,
           os.path.abspath(__file__), "--in-netns", "--rounds", str(args.rounds), "--peers", str(args.peers),
           "--warm-rounds", str(args.warm_rounds), "--expiry", str(args.expiry), "--node", args.node]
    sys.exit(subprocess.call(cmd))


if __name__ == "__main__":
    main()
