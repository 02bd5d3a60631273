"""An independent ROS 2 peer for the integration tests: Eclipse Cyclone DDS
(Python binding) speaking the node's topics and services under their ROS 2
wire names, with the QoS an rclpy user would use.

    python peer.py SCENARIO --domain D [--node /annular_plate] [--args JSON]

Each scenario talks to a running node and prints one JSON object (its
observations) as the last line of stdout; the Rust tests
(tests/ros_node_on_the_wire.rs) make the assertions. Every wait is bounded.
Discovery is loopback-only (CYCLONEDDS_URI, see harness.rs).
"""

import argparse
import dataclasses
import json
import math
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from cyclonedds.builtin import BuiltinDataReader, BuiltinTopicDcpsPublication, BuiltinTopicDcpsSubscription  # noqa: E402
from cyclonedds.core import Policy, Qos  # noqa: E402
from cyclonedds.domain import DomainParticipant  # noqa: E402
from cyclonedds.pub import DataWriter  # noqa: E402
from cyclonedds.sub import DataReader  # noqa: E402
from cyclonedds.topic import Topic  # noqa: E402
from cyclonedds.util import duration  # noqa: E402

import ros_types as T  # noqa: E402


def qos(reliable=True, depth=10, transient_local=False):
    policies = [
        Policy.Reliability.Reliable(duration(milliseconds=100)) if reliable else Policy.Reliability.BestEffort,
        Policy.History.KeepLast(depth),
        Policy.Durability.TransientLocal if transient_local else Policy.Durability.Volatile,
    ]
    return Qos(*policies)


def todict(x):
    return dataclasses.asdict(x)


class Timeout(Exception):
    pass


class Peer:
    """One participant; readers and writers by ROS name (`/a/b`)."""

    def __init__(self, domain, node="/annular_plate"):
        self.dp = DomainParticipant(domain)
        self.node = node.rstrip("/")
        self.topics = {}
        self.services = {}

    def topic(self, dds_name, typ):
        key = (dds_name, typ.__name__)
        if key not in self.topics:
            self.topics[key] = Topic(self.dp, dds_name, typ)
        return self.topics[key]

    def reader(self, ros_name, typ, **q):
        return DataReader(self.dp, self.topic("rt" + ros_name, typ), qos=qos(**q))

    def writer(self, ros_name, typ, **q):
        return DataWriter(self.dp, self.topic("rt" + ros_name, typ), qos=qos(**q))

    def private(self, name):
        return f"{self.node}/{name}"

    @staticmethod
    def wait_matched(entity, timeout=15.0):
        deadline = time.time() + timeout
        get = entity.get_matched_subscriptions if isinstance(entity, DataWriter) else entity.get_matched_publications
        while time.time() < deadline:
            if len(get()) > 0:
                # We see the node's endpoint; give the node a moment to see
                # ours too (a volatile writer sends only to readers it knows).
                time.sleep(0.25)
                return
            time.sleep(0.01)
        raise Timeout(f"no match for {entity.topic.name} within {timeout} s")

    @staticmethod
    def take(reader, n=10000):
        return list(reader.take(n))

    @staticmethod
    def wait_for(reader, predicate=lambda s: True, timeout=15.0, keep=None):
        """Take samples until one satisfies `predicate`; returns it. `keep`
        (a list) collects every sample seen."""
        deadline = time.time() + timeout
        while time.time() < deadline:
            for s in reader.take(1000):
                if keep is not None:
                    keep.append(s)
                if predicate(s):
                    return s
            time.sleep(0.002)
        raise Timeout(f"no matching sample on {reader.topic.name} within {timeout} s")

    # ---- services (default "enhanced" mapping: bare payloads) -------------------

    def call(self, name, req_type, resp_type, request, timeout=15.0):
        fq = self.private(name) if not name.startswith("/") else name
        if fq not in self.services:
            w = DataWriter(self.dp, self.topic("rq" + fq + "Request", req_type), qos=qos(depth=10))
            r = DataReader(self.dp, self.topic("rr" + fq + "Reply", resp_type), qos=qos(depth=10))
            self.wait_matched(w, timeout)
            self.wait_matched(r, timeout)
            # Matching is seen from our side first; give the node's side a moment.
            time.sleep(0.2)
            self.services[fq] = (w, r)
        w, r = self.services[fq]
        r.take(100)  # stale replies
        w.write(request)
        return self.wait_for(r, timeout=timeout)

    def set_paused(self, paused):
        return self.call("set_paused", T.SetBoolRequest, T.SetBoolResponse, T.SetBoolRequest(data=paused))

    def step(self, n):
        return self.call("step", T.StepRequest, T.StepResponse, T.StepRequest(steps=n), timeout=60.0)

    def reset(self):
        return self.call("reset", T.TriggerRequest, T.TriggerResponse, T.TriggerRequest())

    # ---- diagnostics ---------------------------------------------------------

    def diagnostics_reader(self):
        if not hasattr(self, "_diag"):
            self._diag = self.reader("/diagnostics", T.DiagnosticArray, depth=100)
        return self._diag

    @staticmethod
    def diag_values(msg):
        out = {}
        for st in msg.status:
            for kv in st.values:
                out[kv.key] = kv.value
        return out

    def wait_diag(self, predicate, timeout=15.0):
        """Wait for a /diagnostics message whose values satisfy `predicate`."""
        r = self.diagnostics_reader()
        msg = self.wait_for(r, lambda m: predicate(self.diag_values(m)), timeout=timeout)
        return self.diag_values(msg), msg

    # ---- discovery -------------------------------------------------------------

    def endpoints(self, seconds=1.0):
        """(kind, topic, type) of every endpoint discovered (the stand-in for `ros2 topic list -v`)."""
        pubs = BuiltinDataReader(self.dp, BuiltinTopicDcpsPublication)
        subs = BuiltinDataReader(self.dp, BuiltinTopicDcpsSubscription)
        seen = set()
        deadline = time.time() + seconds
        while time.time() < deadline:
            for kind, r in (("pub", pubs), ("sub", subs)):
                for s in r.take(1000):
                    seen.add((kind, s.topic_name, s.type_name))
            time.sleep(0.05)
        return sorted(seen)


def first_joint_state(p, timeout=15.0):
    r = p.reader("/joint_states", T.JointState, depth=100)
    return todict(p.wait_for(r, timeout=timeout))


# ---- scenarios -----------------------------------------------------------------------


def scenario_joint_states(p, a):
    """First joint states; then (paused) a speed command and N steps."""
    js = p.reader("/joint_states", T.JointState, depth=5000)
    first = p.wait_for(js)
    p.set_paused(True)
    cmd = p.writer(p.private("speed_command"), T.Float64)
    p.wait_matched(cmd)
    cmd.write(T.Float64(data=a["speed"]))
    p.wait_diag(lambda v: int(v.get("accepted_speed_command", 0)) >= 1)
    before = p.step(0)
    p.take(js)
    resp = p.step(a["steps"])
    target = resp.step
    seen = []
    last = p.wait_for(js, lambda s: len(seen) >= a["steps"], keep=seen)
    return {"first": todict(first), "before": todict(before), "step": todict(resp), "last": todict(last),
            "received_after_step": len(seen), "target_step": target}


def scenario_ale_wrench(p, a):
    """Paused: a WrenchStamped on ~/ale_<j>/wrench, N steps; the state at step N."""
    tf = p.reader("/tf", T.TFMessage, depth=10000)
    modal = p.reader(p.private("modal_amplitudes"), T.ModalAmplitudes, depth=10000)
    p.wait_matched(tf)
    p.wait_matched(modal)
    p.set_paused(True)
    start = p.step(0)
    # The state before the load: ask for it by stepping 0 and reading the latest published.
    w = p.writer(p.private(f"ale_{a['node']}/wrench"), T.WrenchStamped)
    p.wait_matched(w)
    f = a["wrench"]
    msg = T.WrenchStamped(
        header=T.Header(stamp=T.Time(sec=7, nanosec=123), frame_id=a.get("frame_id", "")),
        wrench=T.Wrench(force=T.Vector3(*f[:3]), torque=T.Vector3(*f[3:])),
    )
    w.write(msg)
    p.wait_diag(lambda v: int(v.get("accepted_node_wrench", 0)) >= 1)
    p.take(tf)
    p.take(modal)
    resp = p.step(a["steps"])
    n_total = start.step + a["steps"]
    m = p.wait_for(modal, lambda s: s.step == resp.step)
    # /tf of the same step: sim-time stamps are total steps x dt.
    stamp_ns = round(n_total * a["dt"] * 1e9)
    t = p.wait_for(tf, lambda s: s.transforms and s.transforms[0].header.stamp.to_nanos() == stamp_ns)
    return {"step": todict(resp), "modal": todict(m), "tf": todict(t)}


def scenario_tf(p, a):
    """One /tf message and the joint state of the same stamp (sim time, paused)."""
    tf = p.reader("/tf", T.TFMessage, depth=1000)
    js = p.reader("/joint_states", T.JointState, depth=1000)
    p.wait_matched(tf)
    p.wait_matched(js)
    p.set_paused(True)
    resp = p.step(a["steps"])
    stamp_ns = round(resp.step * a["dt"] * 1e9)
    t = p.wait_for(tf, lambda s: s.transforms[0].header.stamp.to_nanos() == stamp_ns)
    j = p.wait_for(js, lambda s: s.header.stamp.to_nanos() == stamp_ns)
    return {"step": todict(resp), "tf": todict(t), "joint_state": todict(j)}


def scenario_tf_static(p, a):
    """A late joiner's transient-local reader gets the one /tf_static message."""
    r = p.reader("/tf_static", T.TFMessage, depth=1, transient_local=True)
    msg = p.wait_for(r, timeout=15.0)
    time.sleep(0.3)
    more = p.take(r)
    return {"tf_static": todict(msg), "more": len(more)}


def scenario_critical_speeds(p, a):
    """A late joiner's transient-local reader gets the one ~/critical_speeds
    message; then the `<node>: critical speeds` status of /diagnostics."""
    r = p.reader(p.private("critical_speeds"), T.CriticalSpeeds, depth=1, transient_local=True)
    msg = p.wait_for(r, timeout=30.0)
    time.sleep(0.3)
    more = p.take(r)
    d = p.reader("/diagnostics", T.DiagnosticArray, depth=10)
    name = p.node + ": critical speeds"
    diag = p.wait_for(d, lambda s: any(st.name == name for st in s.status), timeout=30.0)
    status = next(st for st in diag.status if st.name == name)
    return {"critical_speeds": todict(msg), "more": len(more), "status": todict(status)}


def scenario_clock(p, a):
    """/clock samples across a reset; the types seen on rt/clock."""
    r = p.reader("/clock", T.Clock, depth=100000)
    p.wait_matched(r)
    stamps = []
    deadline = time.time() + a["seconds"]
    reset_done = None
    while time.time() < deadline:
        for s in r.take(10000):
            stamps.append(s.clock.to_nanos())
        if reset_done is None and time.time() > deadline - a["seconds"] / 2:
            reset_done = todict(p.reset())
        time.sleep(0.01)
    endpoints = [e for e in p.endpoints(1.0) if e[1] == "rt/clock"]
    return {"stamps": stamps, "reset": reset_done, "endpoints": endpoints}


def scenario_services(p, a):
    """Pause, step N, step while running, resume, reset."""
    out = {}
    modal = p.reader(p.private("modal_amplitudes"), T.ModalAmplitudes, depth=10000)
    p.wait_matched(modal)
    out["initial"] = todict(p.step(0))  # started paused: step 0 answers with the state
    out["step5"] = todict(p.step(5))
    out["step0"] = todict(p.step(0))
    seen = []
    p.wait_for(modal, lambda s: s.step == 5, keep=seen)
    out["published_steps"] = [s.step for s in seen]
    out["resume"] = todict(p.set_paused(False))
    # Running: wait until it has stepped well past the 5 requested steps (on a
    # loaded machine 0.3 s of wall time may hold fewer than 100 steps).
    p.wait_for(modal, lambda s: s.step > 110, timeout=30.0)
    out["step_while_running"] = todict(p.step(3))
    out["pause"] = todict(p.set_paused(True))
    paused_at = p.step(0).step
    time.sleep(0.3)
    out["paused_at"] = paused_at
    out["still_paused_at"] = p.step(0).step
    out["reset"] = todict(p.reset())
    out["after_reset"] = todict(p.step(0))
    out["after_reset_step3"] = todict(p.step(3))
    return out


def wrench(fx=0.0, fy=0.0, fz=0.0, mx=0.0, my=0.0, mz=0.0):
    return T.Wrench(force=T.Vector3(fx, fy, fz), torque=T.Vector3(mx, my, mz))


def scenario_bad_inputs(p, a):
    """Every kind of bad input; the counters; the node keeps publishing; the state is untouched."""
    js = p.reader("/joint_states", T.JointState, depth=10000)
    rosout = p.reader("/rosout", T.Log, depth=1000, transient_local=True)
    modal = p.reader(p.private("modal_amplitudes"), T.ModalAmplitudes, depth=10)
    # Subscribe to /diagnostics before sending anything: with a 50 ms period the
    # one message that reports the new rejections (level WARN) must not pass
    # before this reader is matched.
    diag_reader = p.diagnostics_reader()
    p.wait_for(js)
    p.wait_matched(modal)
    p.wait_matched(rosout)
    p.wait_for(diag_reader)
    p.set_paused(True)
    nan, inf = float("nan"), float("inf")
    w1 = p.writer(p.private("ale_1/wrench"), T.WrenchStamped)
    bad_type = p.writer(p.private("ale_2/wrench"), T.TruncatedWrenchStamped)
    batch = p.writer(p.private("wrenches"), T.NodeWrenchArray)
    speed = p.writer(p.private("speed_command"), T.Float64)
    clamp = p.writer(p.private("pad_1/clamp_force"), T.Float64)
    clamps = p.writer(p.private("pad_clamp_forces"), T.PadClampForces)
    states = p.reader(p.private("pad_states"), T.PadStates, depth=10)
    for w in (w1, bad_type, batch, speed, clamp, clamps, states):
        p.wait_matched(w)
    sent = {}

    def ws(frame="", **kw):
        return T.WrenchStamped(header=T.Header(frame_id=frame), wrench=wrench(**kw))

    def nw(kind, index, **kw):
        return T.NodeWrench(kind=kind, index=index, wrench=wrench(**kw))

    w1.write(ws(fz=nan)); sent["non_finite"] = 1
    w1.write(ws(mx=-inf)); sent["non_finite"] += 1
    w1.write(ws(fz=1e12)); sent["absurd"] = 1
    w1.write(ws(frame="map", fz=-10.0)); sent["unknown_frame"] = 1
    w1.write(ws(frame="plate_ale_2", fz=-10.0)); sent["unknown_frame"] += 1
    batch.write(T.NodeWrenchArray(wrenches=[nw(T.NODE_WRENCH_ALE, 1, fz=-10.0), nw(T.NODE_WRENCH_ALE, 99, fz=-10.0)])); sent["no_such_node"] = 1
    batch.write(T.NodeWrenchArray(wrenches=[nw(T.NODE_WRENCH_LAGRANGE, 0, fz=-1.0)])); sent["no_such_node"] += 1
    batch.write(T.NodeWrenchArray(wrenches=[nw(7, 1, fz=-10.0)])); sent["malformed_batch"] = 1
    batch.write(T.NodeWrenchArray(wrenches=[nw(T.NODE_WRENCH_ALE, 2, fz=-1.0), nw(T.NODE_WRENCH_ALE, 2, fz=-2.0)])); sent["malformed_batch"] += 1
    batch.write(T.NodeWrenchArray(wrenches=[nw(T.NODE_WRENCH_ALE, 1, fz=-1.0), nw(T.NODE_WRENCH_ALE, 3, fz=nan)])); sent["non_finite"] += 1
    speed.write(T.Float64(data=nan)); sent["non_finite"] += 1
    speed.write(T.Float64(data=1e9)); sent["absurd"] += 1
    bad_type.write(T.TruncatedWrenchStamped(header=T.Header(frame_id="plate_ale_2"))); sent["undecodable"] = 1
    # The pad's clamp force (the brake bench has one pad): per-pad topic and array.
    clamp.write(T.Float64(data=nan)); sent["non_finite"] += 1
    clamp.write(T.Float64(data=-inf)); sent["non_finite"] += 1
    clamp.write(T.Float64(data=-5.0)); sent["absurd"] += 1
    clamp.write(T.Float64(data=1e12)); sent["absurd"] += 1
    clamps.write(T.PadClampForces(pad=[1, 2], clamp_force=[100.0, 100.0])); sent["no_such_node"] += 1
    clamps.write(T.PadClampForces(pad=[0], clamp_force=[100.0])); sent["no_such_node"] += 1
    clamps.write(T.PadClampForces(pad=[1, 1], clamp_force=[100.0, 200.0])); sent["malformed_batch"] += 1
    clamps.write(T.PadClampForces(pad=[1], clamp_force=[100.0, 200.0])); sent["malformed_batch"] += 1
    clamps.write(T.PadClampForces(pad=[1], clamp_force=[nan])); sent["non_finite"] += 1
    clamps.write(T.PadClampForces(pad=[1], clamp_force=[-1.0])); sent["absurd"] += 1
    total = sum(sent.values())
    values, diag = p.wait_diag(lambda v: int(v.get("rejected_total", 0)) >= total, timeout=20.0)
    inputs_status = [s for s in diag.status if s.name.endswith("inputs")][0]
    # Still publishing: step and watch joint states arrive.
    p.take(js)
    resp = p.step(10)
    seen = []
    p.wait_for(js, lambda s: len(seen) >= 10, keep=seen)
    p.take(modal)
    p.take(states)
    last = p.step(1)
    m = p.wait_for(modal)
    ps = p.wait_for(states, lambda s: s.step == last.step)
    logs = [l.msg for l in p.take(rosout) if "rejected" in l.msg]
    return {"sent": sent, "diag": values, "inputs_level": inputs_status.level, "inputs_message": inputs_status.message,
            "step": todict(resp), "joint_states_after": len(seen), "last_joint_state": todict(seen[-1]),
            "modal": todict(m), "pad_states": todict(ps), "rosout_rejections": logs}


def scenario_wrench_timeout(p, a):
    """Paused: one wrench, then more steps than ros.wrench_timeout allows; the counters."""
    modal = p.reader(p.private("modal_amplitudes"), T.ModalAmplitudes, depth=10000)
    p.wait_matched(modal)
    p.set_paused(True)
    w = p.writer(p.private("ale_1/wrench"), T.WrenchStamped)
    p.wait_matched(w)
    w.write(T.WrenchStamped(wrench=wrench(fz=a["fz"])))
    p.wait_diag(lambda v: int(v.get("accepted_node_wrench", 0)) >= 1)
    resp = p.step(a["steps"])
    m = p.wait_for(modal, lambda s: s.step == resp.step)
    values, _ = p.wait_diag(lambda v: int(v.get("expired_wrenches", 0)) >= 1)
    return {"step": todict(resp), "modal": todict(m), "diag": values}


def scenario_cyclone_services(p, a):
    """~/step with the rmw_cyclonedds request/reply framing (ros.service_mapping: cyclone)."""
    out = []
    for seq, steps in ((11, 4), (12, 0), (13, 2)):
        r = p.call("step", T.CycloneStepRequest, T.CycloneStepResponse,
                   T.CycloneStepRequest(client=0x1122334455667788, seq=seq, steps=steps))
        out.append(todict(r))
    return {"replies": out}


def scenario_first_message(p, a):
    """Wait for the first joint state (the node is up); print it."""
    return {"joint_state": first_joint_state(p)}


def param_value(v):
    return {"type": v.type, "bool": v.bool_value, "integer": v.integer_value, "double": v.double_value,
            "string": v.string_value, "double_array": list(v.double_array_value), "integer_array": list(v.integer_array_value)}


def scenario_params(p, a):
    names = a["names"]
    lst = p.call("list_parameters", T.ListParametersRequest, T.ListParametersResponse, T.ListParametersRequest())
    get = p.call("get_parameters", T.GetParametersRequest, T.GetParametersResponse, T.GetParametersRequest(names=names))
    types = p.call("get_parameter_types", T.GetParameterTypesRequest, T.GetParameterTypesResponse,
                   T.GetParameterTypesRequest(names=names))
    desc = p.call("describe_parameters", T.DescribeParametersRequest, T.DescribeParametersResponse,
                  T.DescribeParametersRequest(names=names))

    def dparam(name, x):
        return T.Parameter(name=name, value=T.ParameterValue(type=T.PARAMETER_DOUBLE, double_value=x))

    setr = p.call("set_parameters", T.SetParametersRequest, T.SetParametersResponse,
                  T.SetParametersRequest(parameters=[dparam("plate.thickness", 0.02), dparam("simulation.realtime_factor", 2.0)]))
    after = p.call("get_parameters", T.GetParametersRequest, T.GetParametersResponse,
                   T.GetParametersRequest(names=["plate.thickness", "simulation.realtime_factor"]))
    values, _ = p.wait_diag(lambda v: v.get("realtime_factor") == "2")
    return {"list": list(lst.result.names), "prefixes": list(lst.result.prefixes),
            "get": {n: param_value(v) for n, v in zip(names, get.values)},
            "types": dict(zip(names, list(types.types))),
            "describe": {d.name: {"read_only": d.read_only, "description": d.description,
                                  "constraints": d.additional_constraints} for d in desc.descriptors},
            "set": [{"ok": r.successful, "reason": r.reason} for r in setr.results],
            "after": [param_value(v) for v in after.values],
            "diag_realtime_factor": values.get("realtime_factor")}


def scenario_names(p, a):
    """Which endpoints the node has, by DDS name and type (after remapping)."""
    js = p.reader(a["joint_states"], T.JointState, depth=10)
    msg = p.wait_for(js)
    return {"endpoints": p.endpoints(1.5), "joint_state": todict(msg)}


def brake_force(t, peak, ramp, hold, release):
    """The clamp force of launch-scripts/brake_load_example.py at time t (its `force`)."""
    if t < ramp:
        return peak * t / ramp
    if t < ramp + hold:
        return peak
    if t < ramp + hold + release:
        return peak * (1.0 - (t - ramp - hold) / release)
    return 0.0


def scenario_brake_example(p, a):
    """The part of launch-scripts/brake_load_example.py, on the wire: the same
    topics, types and QoS as the rclpy script (a PadClampForces on
    ~/pad_clamp_forces per tick; reading ~/pad_states, ~/modal_amplitudes and
    /joint_states), with the script's force profile. Deterministic: the node
    is paused (ros.start_paused) in simulated time, and each tick is the
    script's tick period of simulated time — the command, its acceptance
    (/diagnostics), then ~/step for the tick's steps — so the Rust side can
    replay the same commands at the same steps in-process."""
    pads = a["pads"]
    peak, ramp, hold, release, after = a["peak_force"], a["ramp_s"], a["hold_s"], a["release_s"], a["after_s"]
    rate, dt = a["rate_hz"], a["dt"]
    steps_per_tick = round(1.0 / (rate * dt))
    pub = p.writer(p.private("pad_clamp_forces"), T.PadClampForces)     # rclpy: create_publisher(PadClampForces, '~/pad_clamp_forces', 10)
    states = p.reader(p.private("pad_states"), T.PadStates, depth=10)    # rclpy default: reliable, volatile, depth 10
    modal = p.reader(p.private("modal_amplitudes"), T.ModalAmplitudes, depth=10)
    js = p.reader("/joint_states", T.JointState, depth=10)
    for e in (pub, states, modal, js):
        p.wait_matched(e)
    p.set_paused(True)  # already paused: a no-op that makes sure the services are up
    log = []
    accepted = 0
    ticks = int(round((ramp + hold + release + after) * rate))
    for tick in range(ticks + 1):
        t = tick / rate
        f = brake_force(t, peak, ramp, hold, release)
        stamp = T.Time(sec=1000 + tick, nanosec=tick)  # distinct per tick: echoed as input_stamp
        pub.write(T.PadClampForces(header=T.Header(stamp=stamp), pad=list(pads), clamp_force=[f] * len(pads)))
        accepted += 1
        p.wait_diag(lambda v: int(v.get("accepted_pad_clamp_forces", 0)) >= accepted)
        resp = p.step(steps_per_tick)
        st = p.wait_for(states, lambda s: s.step == resp.step)
        m = p.wait_for(modal, lambda s: s.step == resp.step)
        stamp_ns = round(resp.step * dt * 1e9)
        j = p.wait_for(js, lambda s: s.header.stamp.to_nanos() == stamp_ns)
        log.append({"t": t, "force": f, "step": resp.step, "input_stamp": m.input_stamp.to_nanos(), "sent_stamp": stamp.to_nanos(),
                    "speed": j.velocity[0], "effort": j.effort[0], "position": j.position[0],
                    "pad_states": todict(st), "q_ale": list(m.q_ale), "q_dot_ale": list(m.q_dot_ale),
                    "max_abs_q_ale": max((abs(x) for x in m.q_ale), default=0.0)})
    values, _ = p.wait_diag(lambda v: int(v.get("accepted_pad_clamp_forces", 0)) >= accepted)
    return {"sent": accepted, "steps_per_tick": steps_per_tick, "log": log, "diag": values}


def scenario_pad_clamp_force(p, a):
    """Paused, simulated time: one std_msgs/Float64 on ~/pad_<j>/clamp_force,
    N steps; the pad states, joint state and modal amplitudes at step N."""
    states = p.reader(p.private("pad_states"), T.PadStates, depth=10000)
    modal = p.reader(p.private("modal_amplitudes"), T.ModalAmplitudes, depth=10000)
    js = p.reader("/joint_states", T.JointState, depth=10000)
    for r in (states, modal, js):
        p.wait_matched(r)
    p.set_paused(True)
    w = p.writer(p.private(f"pad_{a['pad']}/clamp_force"), T.Float64)
    p.wait_matched(w)
    w.write(T.Float64(data=a["force"]))
    p.wait_diag(lambda v: int(v.get("accepted_pad_clamp_force", 0)) >= 1)
    resp = p.step(a["steps"])
    st = p.wait_for(states, lambda s: s.step == resp.step)
    m = p.wait_for(modal, lambda s: s.step == resp.step)
    j = p.wait_for(js, lambda s: s.header.stamp.to_nanos() == round(resp.step * a["dt"] * 1e9))
    values, _ = p.wait_diag(lambda v: True)
    return {"step": todict(resp), "pad_states": todict(st), "modal": todict(m),
            "joint_state": todict(j), "diag": values}


def scenario_tool_feed(p, a):
    """Paused, simulated time, a scene with a tool: bad feeds (rejected,
    counted), then one good feed on ~/tool_feed and N steps; the tool state
    and modal amplitudes at step N; the endpoints."""
    tool = p.reader(p.private("tool_state"), T.ToolState, depth=10000)
    modal = p.reader(p.private("modal_amplitudes"), T.ModalAmplitudes, depth=10000)
    for r in (tool, modal):
        p.wait_matched(r)
    p.set_paused(True)
    w = p.writer(p.private("tool_feed"), T.Float64)
    p.wait_matched(w)
    bad = a["bad"]
    for x in bad:
        w.write(T.Float64(data=float(x)))
    p.wait_diag(lambda v: int(v.get("rejected_total", 0)) >= len(bad))
    w.write(T.Float64(data=a["feed"]))
    p.wait_diag(lambda v: int(v.get("accepted_tool_feed", 0)) >= 1)
    resp = p.step(a["steps"])
    t = p.wait_for(tool, lambda s: s.step == resp.step)
    m = p.wait_for(modal, lambda s: s.step == resp.step)
    values, _ = p.wait_diag(lambda v: True)
    return {"step": todict(resp), "tool_state": todict(t), "modal": todict(m), "diag": values,
            "endpoints": p.endpoints(1.0)}


def scenario_record_bag(p, a):
    """Record the node's topics into a rosbag2 bag (MCAP) with rosbags' writer,
    as `ros2 bag record` would: the serialized samples exactly as received
    (raw CDR from the wire, never decoded here), logged at their source
    timestamp. Runs for a["seconds"] after every reader matched."""
    from cyclonedds._clayer import ddspy_take
    from cyclonedds.core import InstanceState, SampleState, ViewState
    from rosbags.rosbag2 import StoragePlugin, Writer
    from rosbags.typesys import Stores, get_typestore, get_types_from_msg

    store = get_typestore(Stores.ROS2_JAZZY)
    msg_dir = a["msg_dir"]
    for name in ("ModalAmplitudes", "PadStates"):
        with open(os.path.join(msg_dir, name + ".msg")) as f:
            store.register(get_types_from_msg(f.read(), f"annular_plate/msg/{name}"))
    topics = [
        ("/joint_states", T.JointState, "sensor_msgs/msg/JointState", {}),
        ("/tf", T.TFMessage, "tf2_msgs/msg/TFMessage", {}),
        ("/tf_static", T.TFMessage, "tf2_msgs/msg/TFMessage", {"transient_local": True}),
        (p.private("modal_amplitudes"), T.ModalAmplitudes, "annular_plate/msg/ModalAmplitudes", {}),
        (p.private("pad_states"), T.PadStates, "annular_plate/msg/PadStates", {}),
        ("/diagnostics", T.DiagnosticArray, "diagnostic_msgs/msg/DiagnosticArray", {}),
        ("/clock", T.Clock, "rosgraph_msgs/msg/Clock", {}),
    ]
    readers = []
    for name, typ, _, q in topics:
        # Reliable and deep: nothing may be lost on our side while Python is busy.
        readers.append(p.reader(name, typ, depth=q.get("depth", 1000000), **{k: v for k, v in q.items() if k != "depth"}))
    for r in readers:
        p.wait_matched(r)
    writer = Writer(a["dir"], version=9, storage_plugin=StoragePlugin.MCAP)
    writer.open()
    conns = [writer.add_connection(name, msgtype, typestore=store) for name, _, msgtype, _ in topics]
    mask = SampleState.Any | ViewState.Any | InstanceState.Any
    counts = [0] * len(topics)
    takes = 0
    t0 = time.time()
    deadline = t0 + a["seconds"]
    while True:
        last_round = time.time() >= deadline
        for i, r in enumerate(readers):
            for data, info in ddspy_take(r._ref, mask, 100000):
                if not info.valid_data:
                    continue
                ts = info.source_timestamp if info.source_timestamp > 0 else time.time_ns()
                writer.write(conns[i], ts, bytes(data))
                counts[i] += 1
            takes += 1
        if last_round:
            break
        time.sleep(0.01)
    writer.close()
    values, _ = p.wait_diag(lambda v: True)
    return {"dir": a["dir"], "seconds": time.time() - t0, "counts": {t[0]: c for t, c in zip(topics, counts)},
            "diag_after": values}


def scenario_marker(p, a):
    """Paused node: subscribe ~/plate_marker and ~/modal_amplitudes, step N,
    return every marker received (with the modal amplitudes of the same
    stamp) — RViz's view of the plate, decoded by Cyclone DDS."""
    markers = p.reader(p.private("plate_marker"), T.MarkerArray, depth=100)
    modal = p.reader(p.private("modal_amplitudes"), T.ModalAmplitudes, depth=10000)
    p.wait_matched(markers)
    p.wait_matched(modal)
    p.set_paused(True)
    p.step(a["steps"])
    got = []
    p.wait_for(markers, lambda s: len(got) >= a["expect"], timeout=30.0, keep=got)
    q_by_stamp = {}
    deadline = time.time() + 5.0
    while time.time() < deadline and not all(m.markers[1].header.stamp.to_nanos() in q_by_stamp for m in got):
        for s in modal.take(10000):
            q_by_stamp[s.header.stamp.to_nanos()] = list(s.q_lagrange)
        time.sleep(0.01)
    out = []
    for m in got:
        stamp = m.markers[1].header.stamp.to_nanos()
        out.append({"stamp_ns": stamp, "q_lagrange": q_by_stamp.get(stamp), "marker": todict(m)})
    return {"markers": out}


def scenario_churn(p, a):
    """`peers` more participants join, each subscribing /joint_states and /tf
    like an rclpy monitor, until each has a sample; then they leave cleanly
    (`clean`: their entities deleted, goodbyes sent) or vanish without a
    goodbye, as a SIGKILLed process does (their leases must expire)."""
    import gc

    joined = [Peer(a["domain"], p.node) for _ in range(a["peers"])]
    readers = [(q.reader("/joint_states", T.JointState), q.reader("/tf", T.TFMessage, depth=100)) for q in joined]
    for q, (js, tf) in zip(joined, readers):
        q.wait_for(js, timeout=30.0)
        q.wait_for(tf, timeout=30.0)
    if not a["clean"]:
        sys.stdout.write(json.dumps({"joined": len(joined), "left": "killed"}) + "\n")
        sys.stdout.flush()
        os._exit(0)
    readers.clear()
    joined.clear()
    gc.collect()
    time.sleep(0.5)
    return {"joined": a["peers"], "left": "clean"}


def scenario_follow_clock(p, a):
    """use_sim_time: the peer's /clock (a best-effort writer: it matches only a
    best-effort reader, rclcpp's ClockQoS) drives the node's steps and stamps."""
    ms = 1_000_000
    t0 = a["t0_ns"]
    clock = p.writer("/clock", T.Clock, reliable=False, depth=1)
    modal = p.reader(p.private("modal_amplitudes"), T.ModalAmplitudes, depth=100000)
    js = p.reader("/joint_states", T.JointState, depth=100000)
    for e in (clock, modal, js):
        p.wait_matched(e)
    seen, joints, out = [], [], {}

    def collect():
        seen.extend(s for s in modal.take(100000) if s.step > 0)
        joints.extend(js.take(100000))
        return max((s.step for s in seen), default=0)

    def send(t_ns):
        clock.write(T.Clock(clock=T.Time(sec=t_ns // 1_000_000_000, nanosec=t_ns % 1_000_000_000)))

    def clock_until(t_ns, step, timeout=30.0):
        """Publish t until the node has reached `step` (best effort: repeat)."""
        deadline = time.time() + timeout
        while time.time() < deadline:
            send(t_ns)
            if collect() >= step:
                return
            time.sleep(0.02)
        raise Timeout(f"the node did not reach step {step} for /clock {t_ns} ns within {timeout} s (at {collect()})")

    def hold(seconds, t_ns=None):
        """Let `seconds` of wall time pass (re-sending t if given); the newest step then."""
        deadline = time.time() + seconds
        while time.time() < deadline:
            if t_ns is not None:
                send(t_ns)
            collect()
            time.sleep(0.02)
        return collect()

    # No clock yet: the node, running (not paused), does not step.
    out["before_clock"] = hold(1.0)
    out["before_clock_diag_step"] = p.wait_diag(lambda v: "step" in v)[0]["step"]
    # The first /clock is the origin: diagnostics report its time, no step.
    deadline = time.time() + 30.0
    while True:
        send(t0)
        try:
            v, _ = p.wait_diag(lambda v: "ros_time" in v and abs(float(v["ros_time"]) - t0 * 1e-9) < 1e-6, timeout=0.2)
            break
        except Timeout:
            if time.time() > deadline:
                raise
    out["origin_diag_step"] = v["step"]
    out["after_origin"] = collect()
    # Five steps' worth at once.
    clock_until(t0 + 5 * ms, 5)
    # Half a step more: none due.
    out["after_half_step"] = hold(0.5, t0 + 5 * ms + ms // 2)
    clock_until(t0 + 10 * ms, 10)
    # The clock stands still: so does the node.
    out["after_standstill"] = hold(1.0)
    # Twenty ticks of one step each, then the last one until it arrives.
    for k in range(11, 31):
        send(t0 + k * ms)
        time.sleep(0.005)
    clock_until(t0 + 30 * ms, 30)
    out["step_service"] = todict(p.step(1))
    # Paused by its service, the node lets the clock's advance pass unstepped ...
    out["pause"] = todict(p.set_paused(True))
    out["while_paused"] = hold(0.5, t0 + 50 * ms)
    out["resume"] = todict(p.set_paused(False))
    out["after_resume"] = hold(0.3, t0 + 50 * ms)
    # ... and steps again as the clock advances beyond it.
    clock_until(t0 + 53 * ms, 33)
    out["final"] = hold(0.3)
    out["modal"] = [{"step": s.step, "stamp": s.header.stamp.sec * 1_000_000_000 + s.header.stamp.nanosec, "sim_time": s.sim_time} for s in seen]
    last = [j for j in joints if j.header.stamp.sec * 1_000_000_000 + j.header.stamp.nanosec == t0 + 53 * ms]
    out["last_joint_state"] = todict(last[-1]) if last else None
    return out


def scenario_clock_jump(p, a):
    """use_sim_time with a /clock that jumps forward beyond ros.max_clock_jump,
    twice: after each jump the node steps from the new time (it re-anchors;
    it does not work off the gap), and /diagnostics reports each jump as a
    WARN with the count. Every wait polls with a deadline."""
    ms = 1_000_000
    t0, jump = a["t0_ns"], a["jump_ns"]
    clock = p.writer("/clock", T.Clock, reliable=False, depth=1)
    modal = p.reader(p.private("modal_amplitudes"), T.ModalAmplitudes, depth=100000)
    diag = p.diagnostics_reader()
    for e in (clock, modal, diag):
        p.wait_matched(e)
    seen, reports = [], []

    def collect():
        seen.extend(s for s in modal.take(100000) if s.step > 0)
        for m in diag.take(1000):
            for st in m.status:
                if st.name.endswith(": simulation"):
                    reports.append({"level": int(st.level), "message": st.message,
                                    "values": {kv.key: kv.value for kv in st.values}})
        return max((s.step for s in seen), default=0)

    def send(t_ns):
        clock.write(T.Clock(clock=T.Time(sec=t_ns // 1_000_000_000, nanosec=t_ns % 1_000_000_000)))

    def until(what, done, t_ns=None, timeout=60.0):
        """Poll (re-sending t, best effort) until `done()`."""
        deadline = time.time() + timeout
        while time.time() < deadline:
            if t_ns is not None:
                send(t_ns)
            collect()
            if done():
                return
            time.sleep(0.02)
        raise Timeout(f"{what} within {timeout} s (step {collect()}, last report {reports[-1:]})")

    def reported_time(t_ns):
        return lambda: any(abs(float(r["values"].get("ros_time", "nan")) - t_ns * 1e-9) < 1e-6 for r in reports)

    def step_reached(k):
        return lambda: collect() >= k

    out = {}
    until("the origin t0 reported", reported_time(t0), t0)
    until("5 steps after the origin", step_reached(5), t0 + 5 * ms)
    t_start = time.time()
    t1 = t0 + jump
    until("the first jump's time reported", reported_time(t1), t1)
    until("5 steps after the first jump", step_reached(10), t1 + 5 * ms)
    out["seconds_to_step_after_jump"] = time.time() - t_start
    until("a WARN counting the first jump", lambda: any(
        r["level"] == 1 and r["values"].get("clock_jumps_forward") == "1" for r in reports))
    t2 = t1 + jump
    until("the second jump's time reported", reported_time(t2), t2)
    until("3 steps after the second jump", step_reached(13), t2 + 3 * ms)
    until("a WARN counting the second jump", lambda: any(
        r["level"] == 1 and r["values"].get("clock_jumps_forward") == "2" for r in reports))
    # A few more reports: the jump count stays, the level goes back to OK.
    n = len(reports)
    until("two reports after the second jump's WARN", lambda: len(reports) >= n + 2)
    out["modal"] = [{"step": s.step, "stamp": s.header.stamp.sec * 1_000_000_000 + s.header.stamp.nanosec}
                    for s in seen]
    out["warnings"] = [r for r in reports if r["level"] == 1]
    out["last_report"] = reports[-1]
    out["max_step_reported"] = max(int(r["values"].get("step", "0")) for r in reports)
    return out


def scenario_simulation_interfaces(p, a):
    """The simulation_interfaces services as a Gazebo tool calls them: state
    query, step N (with a wrench applied), pause/resume, reset, stop."""
    def get_state():
        return todict(p.call("get_simulation_state", T.GetSimulationStateRequest, T.GetSimulationStateResponse, T.GetSimulationStateRequest()))

    def set_state(s):
        req = T.SetSimulationStateRequest(state=T.SimulationState(state=s))
        return todict(p.call("set_simulation_state", T.SetSimulationStateRequest, T.SetSimulationStateResponse, req))

    def step(n):
        req = T.StepSimulationRequest(steps=n)
        return todict(p.call("step_simulation", T.StepSimulationRequest, T.StepSimulationResponse, req, timeout=60.0))

    def reset(scope):
        req = T.ResetSimulationRequest(scope=scope)
        return todict(p.call("reset_simulation", T.ResetSimulationRequest, T.ResetSimulationResponse, req))

    out = {}
    modal = p.reader(p.private("modal_amplitudes"), T.ModalAmplitudes, depth=10000)
    p.wait_matched(modal)
    out["initial"] = get_state()
    w = p.writer(p.private(f"ale_{a['node']}/wrench"), T.WrenchStamped)
    p.wait_matched(w)
    f = a["wrench"]
    w.write(T.WrenchStamped(header=T.Header(), wrench=T.Wrench(force=T.Vector3(*f[:3]), torque=T.Vector3(*f[3:]))))
    p.wait_diag(lambda v: int(v.get("accepted_node_wrench", 0)) >= 1)
    out["step"] = step(a["steps"])
    out["modal"] = todict(p.wait_for(modal, lambda s: s.step == a["steps"]))
    out["after_step"] = get_state()
    out["play"] = set_state(1)
    out["playing"] = get_state()
    out["step_while_playing"] = step(3)
    out["play_again"] = set_state(1)
    out["pause"] = set_state(2)
    out["paused"] = get_state()
    time.sleep(0.3)
    out["still_paused"] = get_state()
    out["pause_again"] = set_state(2)
    out["reset_time_only"] = reset(1)
    out["reset"] = reset(0)
    out["after_reset"] = get_state()
    out["step_after_reset"] = step(5)
    out["after_reset_step"] = get_state()
    out["play_before_stop"] = set_state(1)
    out["stop"] = set_state(0)
    out["stopped"] = get_state()
    out["quit"] = set_state(3)
    out["bad_state"] = set_state(9)
    return out


def scenario_per_topic_flow(p, a):
    """Running: a WrenchStamped on each of the first `topics` ALE wrench topics
    every millisecond for `seconds` (an rclpy script with one publisher per
    pad). Records what /diagnostics says of the input reception during and
    after the flow, times a service call made while the node reads its inputs
    at step boundaries, and waits until every sample sent is counted."""
    diag = p.diagnostics_reader()
    modal = p.reader(p.private("modal_amplitudes"), T.ModalAmplitudes, depth=10000)
    writers = [p.writer(p.private(f"ale_{j + 1}/wrench"), T.WrenchStamped) for j in range(a["topics"])]
    for w in writers:
        p.wait_matched(w)
    p.wait_matched(modal)
    p.step(0)  # the service client is matched before the flow; the call timed below is a round trip only
    before, _ = p.wait_diag(lambda v: "input_reception" in v)
    accepted0 = int(before["accepted_node_wrench"])
    sent, receptions, service_s = 0, [], None
    end = time.time() + a["seconds"]
    while time.time() < end:
        for j, w in enumerate(writers):
            w.write(T.WrenchStamped(header=T.Header(stamp=T.Time(sec=1, nanosec=sent), frame_id=""),
                                    wrench=T.Wrench(force=T.Vector3(0.0, 0.0, -10.0 * (j + 1)), torque=T.Vector3())))
            sent += 1
        for m in p.take(diag):
            receptions.append(p.diag_values(m).get("input_reception"))
        if service_s is None and "at step boundaries" in receptions:
            t0 = time.time()
            p.step(0)  # running: answered with "pause it first", a round trip all the same
            service_s = time.time() - t0
        time.sleep(0.001)
    during = list(receptions)
    after, _ = p.wait_diag(lambda v: v.get("input_reception") == "on arrival"
                           and int(v["accepted_node_wrench"]) - accepted0 >= sent, timeout=20.0)
    p.take(modal)
    last = p.wait_for(modal)
    return {"before": before["input_reception"], "during": during, "after": after["input_reception"],
            "sent": sent, "accepted": int(after["accepted_node_wrench"]) - accepted0,
            "rejected_total": int(after["rejected_total"]), "service_s": service_s,
            "last_input_stamp": todict(last.input_stamp)}


def scenario_two_nodes(p, a):
    """Two nodes in two namespaces on one domain: each one's joint_states, its
    prefixed tf frames and its commands stay its own."""
    nodes = a["nodes"]  # [{"node": "/left/disc", "ns": "/left", "prefix": "left/"}, ...]
    js = {n["node"]: p.reader(n["ns"] + "/joint_states", T.JointState, depth=10000) for n in nodes}
    modal = {n["node"]: p.reader(n["node"] + "/modal_amplitudes", T.ModalAmplitudes, depth=10000) for n in nodes}
    tf = p.reader("/tf", T.TFMessage, depth=100000)
    for r in list(js.values()) + list(modal.values()) + [tf]:
        p.wait_matched(r)
    first, second = nodes[0]["node"], nodes[1]["node"]
    # Commands to the first node only: a speed and a wrench.
    speed = p.writer(first + "/speed_command", T.Float64)
    w = p.writer(first + "/ale_2/wrench", T.WrenchStamped)
    p.wait_matched(speed)
    p.wait_matched(w)
    speed.write(T.Float64(data=a["speed"]))
    w.write(T.WrenchStamped(header=T.Header(), wrench=wrench(fz=a["fz"])))
    p.wait_diag(lambda v: int(v.get("accepted_node_wrench", 0)) >= 1 and int(v.get("accepted_speed_command", 0)) >= 1)
    for n in nodes:
        p.take(js[n["node"]])
        p.take(modal[n["node"]])
    out = {"step": {}, "joint_state": {}, "modal": {}}
    for n in nodes:
        name = n["node"]
        resp = p.call(name + "/step", T.StepRequest, T.StepResponse, T.StepRequest(steps=a["steps"]), timeout=60.0)
        out["step"][name] = todict(resp)
        out["modal"][name] = todict(p.wait_for(modal[name], lambda s, k=resp.step: s.step == k))
        # One joint state per step (publish_divisor 1): the last of them is the stepped state.
        seen = []
        p.wait_for(js[name], lambda s: len(seen) >= a["steps"], keep=seen)
        assert all(s.name == [n["prefix"] + "plate_joint"] for s in seen), [s.name for s in seen[:3]]
        out["joint_state"][name] = todict(seen[-1])
        out["joint_states_seen"] = out.get("joint_states_seen", {}) | {name: len(seen)}
    frames = set()
    for m in p.take(tf):
        for t in m.transforms:
            frames.add((t.header.frame_id, t.child_frame_id))
    out["tf_frames"] = sorted(frames)
    return out


SCENARIOS = {name[len("scenario_"):]: fn for name, fn in globals().items() if name.startswith("scenario_")}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("scenario", choices=sorted(SCENARIOS))
    ap.add_argument("--domain", type=int, required=True)
    ap.add_argument("--node", default="/annular_plate")
    ap.add_argument("--args", default="{}")
    ns = ap.parse_args()
    p = Peer(ns.domain, ns.node)
    result = SCENARIOS[ns.scenario](p, json.loads(ns.args))

    def clean(x):
        if isinstance(x, float) and not math.isfinite(x):
            return repr(x)
        if isinstance(x, dict):
            return {k: clean(v) for k, v in x.items()}
        if isinstance(x, (list, tuple)):
            return [clean(v) for v in x]
        return x

    sys.stdout.write(json.dumps(clean(result)) + "\n")
    sys.stdout.flush()


if __name__ == "__main__":
    main()
