#!/usr/bin/env python3
"""Benchmark of the node's loop (not a test): at 1 kHz with 18 ALE wrenches
updated at 1 kHz, measure

  - the node's CPU use (utime + stime of the process over the window),
  - the step-period jitter p50 / p99 (the node's own measurement, reported on
    /diagnostics over the whole window: |actual period - 1 ms|),
  - the latency from a published wrench to the first published state that
    includes it (the peer stamps each command with its wall clock; the node
    echoes the stamp of the newest applied input in ModalAmplitudes.input_stamp;
    latency = arrival of the first state carrying it - the stamp),

with the wrenches sent either as one annular_plate/msg/NodeWrenchArray of 18
per millisecond (`--mode batch`) or as 18 geometry_msgs/WrenchStamped per
millisecond on the 18 per-node topics (`--mode topics`), and idle (`--mode idle`);
with `--input-reception step_aligned` the node reads its input datagrams at
step boundaries while they are many (`ros.input_reception`); with
`--marker-rate HZ` the node also publishes ~/plate_marker at that rate (0 =
off, the default here) and the peer subscribes to it as RViz would.
`--wrench-topics N` sends on the first N of the 18 per-node topics only.

`--compare` runs, in one invocation and alternating, the node and the Cyclone
DDS C floor for the same sample traffic in the four cases — idle, 3 wrench
topics, 18 wrench topics, the batch topic — `--repeat` times each, and prints
the node's CPU, the floor's and their ratio with ranges. The floor is
`ddsperf` (Debian package cyclonedds-tools; installed with apt-get when
missing): one ddsperf process in the node's role publishes 1000 samples/s of
600 bytes (the size of the ModalAmplitudes the peer subscribes to) to a
second ddsperf and subscribes to what that one publishes: nothing (idle),
bursts of 3 or 18 samples of 80 bytes (WrenchStamped), or samples of 1100
bytes (the NodeWrenchArray of 18), at the update rate the Python peer
reached in the node's run just before (1000/s when it keeps up); the CPU of
the first process over the same window is the floor:

    target/peer-venv/bin/python benches/node_loop.py --compare --seconds 10 --repeat 3

Run as root from the repository root after `cargo build --release` and one
`cargo test --release` (which creates target/peer-venv):

    target/peer-venv/bin/python benches/node_loop.py --mode batch --seconds 10

Node and peer run in a private network namespace (loopback only). The peer
is Python (Cyclone DDS) on the same two cores, so the latency is an upper
bound of what a C++ client would see. docs/ros.md has the measured numbers.
"""

import argparse
import os
import statistics
import struct
import subprocess
import sys
import tempfile
import threading
import time

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(REPO, "tests", "peer"))

N_ALE = 18


def scene_text():
    radial = ", ".join(["0.6"] * N_ALE)
    angular = ", ".join(f"{j / N_ALE:.6f}" for j in range(N_ALE))
    return f"""/**:
  ros__parameters:
    plate:
      inner_radius: 0.07
      outer_radius: 0.153
      thickness: 0.0181
      density: 7850.0
      youngs_modulus: 2.1e11
      poisson_ratio: 0.3
      inner_boundary: supported
      outer_boundary: free
      nodal_diameters: [0, 1, 2, 3, 4]
      nodal_circles: [0]
      damping: [0.005]
    nodes:
      ale_radial: [{radial}]
      ale_angular: [{angular}]
      lagrange_radial: [1.0]
      lagrange_angular: [0.0]
    joint:
      speed: 25.0
    simulation:
      rate_hz: 1000.0
      realtime_factor: 1.0
"""


def in_netns_main(args):
    """Runs inside the network namespace: node + driver."""
    from cyclonedds.core import Policy, Qos
    from cyclonedds.domain import DomainParticipant
    from cyclonedds.pub import DataWriter
    from cyclonedds.sub import DataReader
    from cyclonedds.topic import Topic
    from cyclonedds.util import duration
    import ros_types as T

    os.environ["CYCLONEDDS_URI"] = "file://" + os.path.join(REPO, "tests", "peer", "cyclonedds.xml")
    with tempfile.NamedTemporaryFile("w", suffix=".yaml", delete=False) as f:
        f.write(scene_text())
        scene = f.name
    window = args.seconds
    env = dict(os.environ, ROS_DOMAIN_ID="42")
    node = subprocess.Popen(
        [args.node, "run", scene, "--ros-args", "-p", "ros.diagnostics_period:=1.0",
         "-p", f"ros.marker_rate_hz:={args.marker_rate}", "--log-level", "warn"]
        # (the default is left out, so the script also runs builds that predate the key)
        + (["-p", "ros.input_reception:=step_aligned"] if args.input_reception == "step_aligned" else []),
        env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    try:
        dp = DomainParticipant(42)
        q = Qos(Policy.Reliability.Reliable(duration(milliseconds=100)), Policy.History.KeepLast(10))
        modal = DataReader(dp, Topic(dp, "rt/annular_plate/modal_amplitudes", T.ModalAmplitudes), qos=q)
        diag = DataReader(dp, Topic(dp, "rt/diagnostics", T.DiagnosticArray),
                          qos=Qos(Policy.Reliability.Reliable(duration(milliseconds=100)), Policy.History.KeepLast(100)))
        markers = []
        if args.marker_rate > 0:
            markers.append(DataReader(dp, Topic(dp, "rt/annular_plate/plate_marker", T.MarkerArray),
                                      qos=Qos(Policy.Reliability.Reliable(duration(milliseconds=100)), Policy.History.KeepLast(1))))
        writers = []
        if args.mode == "batch":
            writers = [DataWriter(dp, Topic(dp, "rt/annular_plate/wrenches", T.NodeWrenchArray), qos=q)]
        elif args.mode == "topics":
            writers = [DataWriter(dp, Topic(dp, f"rt/annular_plate/ale_{j}/wrench", T.WrenchStamped), qos=q)
                       for j in range(1, args.wrench_topics + 1)]
        deadline = time.time() + 20
        time.sleep(0.5)
        if node.poll() is not None:
            sys.exit(f"the node exited at once: {node.stderr.read().decode(errors='replace')}")
        while time.time() < deadline and (len(modal.get_matched_publications()) == 0
                                          or any(len(w.get_matched_subscriptions()) == 0 for w in writers)):
            time.sleep(0.01)
        # The diagnostics window starts at the node's first report (t = 0); wait for it.
        latencies = []
        seen_stamps = set()
        stop = threading.Event()

        received_markers = [0]

        def read_markers():
            # Raw samples, not decoded (as `ros2 bag record` takes them): a
            # Python decode of 12,000 points per message would starve the
            # two cores the node runs on; RViz decodes in C++.
            from cyclonedds._clayer import ddspy_take
            from cyclonedds.core import InstanceState, SampleState, ViewState
            mask = SampleState.Any | ViewState.Any | InstanceState.Any
            while not stop.is_set():
                for r in markers:
                    received_markers[0] += sum(1 for _, info in ddspy_take(r._ref, mask, 100) if info.valid_data)
                time.sleep(0.005)

        def read_states():
            last = None
            while not stop.is_set():
                for m in modal.take_iter(timeout=duration(milliseconds=200)):
                    now = time.time_ns()
                    s = m.input_stamp.sec * 1_000_000_000 + m.input_stamp.nanosec
                    if s and s != last:
                        last = s
                        if s in seen_stamps:
                            latencies.append((now - s) / 1e3)
                    if stop.is_set():
                        break

        reader = threading.Thread(target=read_states, daemon=True)
        reader.start()
        marker_reader = threading.Thread(target=read_markers, daemon=True)
        marker_reader.start()
        # The samples of each of the ten force levels, serialized once: the
        # loop only writes the stamp into them (see write_stamped).
        batch_cdr = [cdr(batch_message(-100.0 - 10.0 * i, 0)) for i in range(10)]
        wrench_cdr = [cdr(wrench_message(-100.0 - 10.0 * i, 0)) for i in range(10)]
        t_end = time.time() + args.warmup + window
        t_measure = time.time() + args.warmup
        stat0 = None
        sent = 0
        period = 1e-3
        next_t = time.perf_counter()
        k = 0
        while time.time() < t_end:
            if stat0 is None and time.time() >= t_measure:
                stat0 = (cpu_ticks(node.pid), time.time())
                threads0 = thread_ticks(node.pid)
                latencies.clear()
                received_markers[0] = 0
                sent = 0
            k += 1
            fz = -100.0 - 10.0 * (k % 10)
            stamp = time.time_ns()
            if args.mode == "batch":
                if args.python_serialize:
                    writers[0].write(batch_message(fz, stamp))
                else:
                    write_stamped(writers[0], batch_cdr[k % 10], stamp)
                seen_stamps.add(stamp)
                sent += 1
            elif args.mode == "topics":
                for j, w in enumerate(writers):
                    s = time.time_ns()
                    seen_stamps.add(s)
                    if args.python_serialize:
                        w.write(wrench_message(fz, s))
                    else:
                        write_stamped(w, wrench_cdr[k % 10], s)
                sent += 1
            next_t += period
            delay = next_t - time.perf_counter()
            if delay > 0:
                time.sleep(delay)
            else:
                next_t = time.perf_counter()
        stat1 = (cpu_ticks(node.pid), time.time())
        threads1 = thread_ticks(node.pid)
        markers_in_window = received_markers[0]
        # The node's per-second reports inside the window.
        time.sleep(1.2)
        reports = []
        for m in diag.take(1000):
            t = m.header.stamp.sec + m.header.stamp.nanosec * 1e-9
            if stat0[1] + 1.0 <= t <= stat1[1] + 0.2:
                for st in m.status:
                    if st.name.endswith("simulation"):
                        reports.append({kv.key: float(kv.value) for kv in st.values
                                        if kv.key not in ("state",)})
        med = lambda k: statistics.median(r[k] for r in reports) if reports else float("nan")
        mx = lambda k: max(r[k] for r in reports) if reports else float("nan")
        stop.set()
        reader.join(timeout=2)
        hz = os.sysconf("SC_CLK_TCK")
        cpu = (stat1[0] - stat0[0]) / hz / (stat1[1] - stat0[1]) * 100.0
        lat = sorted(latencies)

        def pct(p):
            return lat[min(len(lat) - 1, int(round(p * (len(lat) - 1))))] if lat else float("nan")

        n_in = {"batch": N_ALE, "topics": args.wrench_topics, "idle": 0}[args.mode]
        print(f"mode {args.mode}: {n_in} of {N_ALE} ALE wrenches, {sent / (stat1[1] - stat0[1]):.0f} updates/s sent over {stat1[1] - stat0[1]:.1f} s")
        print(f"RESULT node_cpu {cpu:.3f}")
        print(f"RESULT sent_rate {sent / (stat1[1] - stat0[1]):.1f}")
        print(f"  node CPU: {cpu:.1f} % of one core (~/plate_marker at {args.marker_rate} Hz, {markers_in_window / (stat1[1] - stat0[1]):.1f}/s received)")
        span = stat1[1] - stat0[1]
        per_thread = {n: (threads1[n] - threads0.get(n, 0)) / hz / span * 100.0 for n in threads1}
        print("  threads: " + ", ".join(f"{n} {c:.1f} %" for n, c in sorted(per_thread.items(), key=lambda x: -x[1]) if c >= 0.05))
        print(f"  node loop ({len(reports)} one-second /diagnostics reports): achieved {med('achieved_rate_hz'):.1f} Hz, "
              f"step+publish mean {med('step_time_mean_us'):.1f} us (max {mx('step_time_max_us'):.0f} us), "
              f"period jitter p50 {med('period_jitter_p50_us'):.1f} us, p99 {med('period_jitter_p99_us'):.1f} us "
              f"(worst second {mx('period_jitter_p99_us'):.1f} us), lateness p99 {med('lateness_p99_us'):.1f} us, "
              f"overruns {mx('overruns'):.0f}")
        if args.mode != "idle":
            print(f"  wrench -> first state including it: n={len(lat)} p50 {pct(0.5) / 1e3:.3f} ms "
                  f"p90 {pct(0.9) / 1e3:.3f} ms p99 {pct(0.99) / 1e3:.3f} ms max {pct(1.0) / 1e3:.3f} ms")
    finally:
        node.send_signal(2)
        try:
            node.wait(timeout=5)
        except subprocess.TimeoutExpired:
            node.kill()


def batch_message(fz, stamp):
    import ros_types as T
    return T.NodeWrenchArray(
        header=T.Header(stamp=T.Time.from_nanos(stamp)),
        wrenches=[T.NodeWrench(kind=0, index=j, wrench=T.Wrench(force=T.Vector3(0.0, 0.0, fz)))
                  for j in range(1, N_ALE + 1)])


def wrench_message(fz, stamp):
    import ros_types as T
    return T.WrenchStamped(header=T.Header(stamp=T.Time.from_nanos(stamp)),
                           wrench=T.Wrench(force=T.Vector3(0.0, 0.0, fz)))


def cdr(msg):
    """The sample as DataWriter.write sends it (XCDR1 little-endian, padded to 4)."""
    ser = msg.serialize()
    assert ser[:2] == b"\x00\x01", "CDR_LE encapsulation expected"
    return bytearray(ser.ljust((len(ser) + 3) & ~3, b"\0"))


def write_stamped(writer, sample, stamp_ns):
    """Write a pre-serialized sample whose header stamp (the first field, right
    after the 4-byte encapsulation header) is set to stamp_ns: about 1.5 µs a
    sample against ~17 µs for DataWriter.write, whose Python serialization
    spread 18 writes over ~1 ms; now they leave in a burst, as from a compiled
    client (and as ddsperf's bursts in the floor)."""
    from cyclonedds._clayer import ddspy_write
    struct.pack_into("<iI", sample, 4, stamp_ns // 1_000_000_000, stamp_ns % 1_000_000_000)
    if ddspy_write(writer._ref, bytes(sample)) < 0:
        raise RuntimeError("ddspy_write failed")


def thread_ticks(pid):
    """utime + stime per thread name of the process."""
    out = {}
    for tid in os.listdir(f"/proc/{pid}/task"):
        try:
            with open(f"/proc/{pid}/task/{tid}/stat") as f:
                text = f.read()
        except OSError:
            continue
        name = text[text.index("(") + 1:text.rindex(")")]
        fields = text.rsplit(")", 1)[1].split()
        out[name] = out.get(name, 0) + int(fields[11]) + int(fields[12])
    return out


def cpu_ticks(pid):
    with open(f"/proc/{pid}/stat") as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return int(fields[11]) + int(fields[12])  # utime + stime


# The floor's traffic per case: (samples per burst at 1 kHz, bytes per sample) the
# node receives; it publishes 1000 samples/s of FLOOR_OUT_BYTES in every case.
FLOOR_OUT_BYTES = 600
FLOOR_CASES = {
    "idle": None,
    "topics3": (3, 80),
    "topics18": (18, 80),
    "batch": (1, 1100),
}
# The node's run for each case.
NODE_CASES = {
    "idle": ["--mode", "idle"],
    "topics3": ["--mode", "topics", "--wrench-topics", "3"],
    "topics18": ["--mode", "topics", "--wrench-topics", "18"],
    "batch": ["--mode", "batch"],
}


def floor_main(args):
    """Runs inside the network namespace: the ddsperf pair of one case."""
    env = dict(os.environ, CYCLONEDDS_URI="file://" + os.path.join(REPO, "tests", "peer", "cyclonedds.xml"))
    run_for = args.warmup + args.seconds + 2
    base = ["ddsperf", "-i", "43", "-D", f"{run_for:.0f}", "-T", "KS"]
    node_role = subprocess.Popen(base + ["pub", "1000Hz", "size", str(FLOOR_OUT_BYTES), "sub"],
                                 env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    case = FLOOR_CASES[args.floor]
    rate = f"{args.floor_rate:.0f}Hz"
    peer_modes = ["sub"] if case is None else ["pub", rate, "burst", str(case[0]), "size", str(case[1]), "sub"]
    peer = subprocess.Popen(base + peer_modes, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        time.sleep(args.warmup)
        c0, t0 = cpu_ticks(node_role.pid), time.time()
        time.sleep(args.seconds)
        c1, t1 = cpu_ticks(node_role.pid), time.time()
        cpu = (c1 - c0) / os.sysconf("SC_CLK_TCK") / (t1 - t0) * 100.0
        print(f"RESULT floor_cpu {cpu:.3f}")
    finally:
        for p in (node_role, peer):
            p.send_signal(2)
        for p in (node_role, peer):
            try:
                p.wait(timeout=5)
            except subprocess.TimeoutExpired:
                p.kill()


def ensure_ddsperf():
    if subprocess.call(["sh", "-c", "command -v ddsperf >/dev/null"]) == 0:
        return
    print("ddsperf missing: apt-get install -y cyclonedds-tools", flush=True)
    if subprocess.call(["apt-get", "install", "-y", "-q", "cyclonedds-tools"], stdout=subprocess.DEVNULL) != 0:
        subprocess.check_call(["apt-get", "update", "-q"], stdout=subprocess.DEVNULL)
        subprocess.check_call(["apt-get", "install", "-y", "-q", "cyclonedds-tools"], stdout=subprocess.DEVNULL)


def serialize_flag(args):
    return ["--python-serialize"] if args.python_serialize else []


def netns_run(args, extra):
    """This script inside a private network namespace; its RESULT value and output."""
    cmd = ["unshare", "-n", "--", "sh", "-c",
           'ip link set lo up && exec "$0" "$@"', sys.executable, os.path.abspath(__file__), "--in-netns",
           "--seconds", str(args.seconds), "--warmup", str(args.warmup), "--node", args.node,
           "--marker-rate", str(args.marker_rate), "--floor-rate", str(args.floor_rate),
           "--input-reception", args.input_reception] + serialize_flag(args) + extra
    out = subprocess.run(cmd, stdout=subprocess.PIPE, text=True).stdout
    values = {l.split()[1]: float(l.split()[2]) for l in out.splitlines() if l.startswith("RESULT")}
    return values, "\n".join(l for l in out.splitlines() if not l.startswith("RESULT"))


def compare(args):
    ensure_ddsperf()
    results = {case: ([], []) for case in NODE_CASES}
    for r in range(args.repeat):
        for case in NODE_CASES:
            values, text = netns_run(args, NODE_CASES[case])
            node, sent = values.get("node_cpu", float("nan")), values.get("sent_rate", 0.0)
            # The floor carries the wrench rate the Python peer reached in the node's run.
            floor = netns_run(args, ["--floor", case, "--floor-rate", str(max(sent, 1.0))])[0].get("floor_cpu", float("nan"))
            results[case][0].append(node)
            results[case][1].append(floor)
            print(f"[run {r + 1}/{args.repeat}] {case}: wrench updates {sent:.0f}/s, node {node:.1f} %, floor {floor:.1f} %, "
                  f"ratio {node / floor:.2f}")
            if args.verbose:
                print(text)
            sys.stdout.flush()
    rng = lambda xs: f"{min(xs):.1f}–{max(xs):.1f}"
    print("\n| case | node CPU % | ddsperf floor % | node / floor |")
    print("|---|---|---|---|")
    for case, (node, floor) in results.items():
        ratios = [n / f for n, f in zip(node, floor)]
        print(f"| {case} | {rng(node)} | {rng(floor)} | {min(ratios):.1f}–{max(ratios):.1f} |")
    t18, batch = results["topics18"][0], results["batch"][0]
    print(f"\n18 topics / batch (node CPU, run by run): " + ", ".join(f"{a / b:.2f}" for a, b in zip(t18, batch)))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--mode", choices=["batch", "topics", "idle"], default="batch")
    ap.add_argument("--wrench-topics", type=int, default=N_ALE, help="with --mode topics: send on the first N per-node topics")
    ap.add_argument("--seconds", type=float, default=10.0)
    ap.add_argument("--warmup", type=float, default=2.0)
    ap.add_argument("--marker-rate", type=float, default=0.0)
    ap.add_argument("--python-serialize", action="store_true",
                    help="the peer serializes every sample in Python (DataWriter.write, ~17 µs each: "
                         "18 topics' writes spread over the millisecond) instead of writing pre-serialized bursts")
    ap.add_argument("--input-reception", choices=["on_arrival", "step_aligned"], default="on_arrival",
                    help="the node's ros.input_reception (step_aligned: input datagrams read at step boundaries)")
    ap.add_argument("--node", default=os.path.join(REPO, "target", "release", "annular_plate"))
    ap.add_argument("--compare", action="store_true", help="node against the ddsperf floor in the four cases")
    ap.add_argument("--repeat", type=int, default=3, help="with --compare: runs per case")
    ap.add_argument("--verbose", action="store_true", help="with --compare: the node runs' full output")
    ap.add_argument("--floor", choices=list(FLOOR_CASES), help=argparse.SUPPRESS)
    ap.add_argument("--floor-rate", type=float, default=1000.0, help=argparse.SUPPRESS)
    ap.add_argument("--in-netns", action="store_true", help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.in_netns:
        if args.floor:
            floor_main(args)
        else:
            in_netns_main(args)
        return
    with open("/proc/cpuinfo") as f:
        model = next((l.split(":", 1)[1].strip() for l in f if l.startswith("model name")), "?")
    print(f"machine: nproc {os.cpu_count()}, {model}")
    if args.compare:
        compare(args)
        return
    cmd = ["unshare", "-n", "--", "sh", "-c",
           'ip link set lo up && exec "$0" "$@"', sys.executable, os.path.abspath(__file__), "--in-netns",
           "--mode", args.mode, "--wrench-topics", str(args.wrench_topics), "--marker-rate", str(args.marker_rate),
           *serialize_flag(args),
           "--seconds", str(args.seconds), "--warmup", str(args.warmup), "--node", args.node]
    sys.exit(subprocess.call(cmd))


if __name__ == "__main__":
    main()
