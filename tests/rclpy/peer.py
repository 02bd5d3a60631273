"""A real ROS 2 peer for the wire tests: rclpy (ROS 2 Jazzy wheels from PyPI,
rmw_fastrtps_cpp) with the interfaces built by scripts/rclpy_env.sh — the
node's topics and services as a ROS 2 user reaches them, with the QoS users
pick (rclpy's defaults, qos_profile_sensor_data, transient-local late joiners)
and the requests the `ros2 param` verbs make.

    python peer.py SCENARIO [--node /annular_plate] [--args JSON]

Runs in the node's network namespace on its ROS_DOMAIN_ID (the harness,
tests/peer/rclpy.rs, sets both). Each scenario prints one JSON object, its
observations, as the last line of stdout; the Rust tests make the
assertions. Every wait is bounded; no timing is asserted here.
"""

import argparse
import json
import math
import sys
import time

import rclpy
from rclpy.node import Node, NodeNameNonExistentError
from rclpy.parameter import Parameter
from rclpy.qos import (DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy,
                       qos_profile_sensor_data)
from rclpy.serialization import serialize_message

from diagnostic_msgs.msg import DiagnosticArray
from geometry_msgs.msg import WrenchStamped
from rcl_interfaces.msg import Log, ParameterType, ParameterValue
from rcl_interfaces.msg import Parameter as ParameterMsg
from rcl_interfaces.srv import (DescribeParameters, GetParameters, GetParameterTypes, ListParameters,
                                SetParameters, SetParametersAtomically)
from rosgraph_msgs.msg import Clock
from sensor_msgs.msg import JointState
from std_msgs.msg import Float64
from std_srvs.srv import SetBool, Trigger
from tf2_msgs.msg import TFMessage
from visualization_msgs.msg import MarkerArray
from simulation_interfaces.msg import SimulationState
from simulation_interfaces.srv import GetSimulationState, ResetSimulation, SetSimulationState, StepSimulation

from annular_plate.msg import (CriticalSpeeds, ModalAmplitudes, NodeWrench, NodeWrenchArray, PadClampForces,
                               PadStates)
from annular_plate.srv import Step

LATCHED = QoSProfile(depth=1, reliability=ReliabilityPolicy.RELIABLE, durability=DurabilityPolicy.TRANSIENT_LOCAL,
                     history=HistoryPolicy.KEEP_LAST)
# rcl's /rosout publisher: reliable, transient local, depth 1000.
ROSOUT = QoSProfile(depth=1000, reliability=ReliabilityPolicy.RELIABLE, durability=DurabilityPolicy.TRANSIENT_LOCAL)
BEST_EFFORT_1 = QoSProfile(depth=1, reliability=ReliabilityPolicy.BEST_EFFORT)


class Timeout(Exception):
    pass


def stamp_ns(t):
    return t.sec * 10**9 + t.nanosec


class Peer:
    def __init__(self, target, name="rclpy_peer", **node_kw):
        self.node = Node(name, **node_kw)
        self.target = target.rstrip("/")

    def private(self, name):
        return f"{self.target}/{name}"

    def spin_until(self, cond, timeout, what="a condition"):
        deadline = time.monotonic() + timeout
        while not cond():
            if time.monotonic() > deadline:
                raise Timeout(f"{what}: not within {timeout} s")
            rclpy.spin_once(self.node, timeout_sec=0.01)

    def node_publishes(self, name, namespace):
        """The node's publishers as `ros2 node info` lists them; empty while
        the node's name has not reached the graph (its ros_discovery_info
        sample may come after its endpoints)."""
        try:
            return dict(self.node.get_publisher_names_and_types_by_node(name, namespace))
        except NodeNameNonExistentError:
            return {}

    def spin_for(self, seconds):
        end = time.monotonic() + seconds
        while time.monotonic() < end:
            rclpy.spin_once(self.node, timeout_sec=0.01)

    def collect(self, typ, topic, qos=10, keep=None):
        """Subscribe; every message goes into the returned list (only the last `keep` if given)."""
        box = []

        def cb(msg):
            box.append(msg)
            if keep is not None and len(box) > keep:
                del box[0]
        self.node.create_subscription(typ, topic, cb, qos)
        return box

    def publisher(self, typ, topic, qos=10, timeout=20.0):
        pub = self.node.create_publisher(typ, topic, qos)
        self.spin_until(lambda: pub.get_subscription_count() > 0, timeout, f"a subscriber of {topic}")
        return pub

    def client(self, typ, name, timeout=20.0):
        c = self.node.create_client(typ, name)
        t0 = time.monotonic()
        if not c.wait_for_service(timeout_sec=timeout):
            raise Timeout(f"service {name} not available within {timeout} s")
        return c, time.monotonic() - t0

    def call(self, client, request, timeout=10.0):
        """(response or None if none came within `timeout`, seconds waited)."""
        t0 = time.monotonic()
        fut = client.call_async(request)
        deadline = t0 + timeout
        while not fut.done() and time.monotonic() < deadline:
            rclpy.spin_once(self.node, timeout_sec=0.005)
        dt = time.monotonic() - t0
        if not fut.done():
            client.remove_pending_request(fut)
            return None, dt
        return fut.result(), dt

    def call_fresh(self, typ, name, request, timeout=10.0):
        """As `ros2 service call` and `ros2 param` do: a new client for one call."""
        c, waited = self.client(typ, name)
        resp, dt = self.call(c, request, timeout)
        self.node.destroy_client(c)
        return resp, {"wait_for_service_s": waited, "reply_s": dt, "lost": resp is None,
                      "reply_bytes": len(serialize_message(resp)) if resp is not None else None}

    # ---- diagnostics -----------------------------------------------------------
    def diagnostics(self):
        if not hasattr(self, "_diag"):
            self._diag = self.collect(DiagnosticArray, "/diagnostics", 10, keep=50)
        return self._diag

    @staticmethod
    def status_values(msg, suffix):
        for st in msg.status:
            if st.name.endswith(suffix):
                return {kv.key: kv.value for kv in st.values}, st
        return None, None

    def wait_status(self, suffix, predicate, timeout=20.0):
        box = self.diagnostics()
        found = {}

        def cond():
            for m in reversed(box):
                v, st = self.status_values(m, suffix)
                if v is not None and predicate(v):
                    found["v"], found["st"] = v, st
                    return True
            return False
        self.spin_until(cond, timeout, f"/diagnostics status '*{suffix}' as expected (last: {self.last_status(suffix)})")
        return found["v"], found["st"]

    def last_status(self, suffix):
        for m in reversed(self.diagnostics()):
            v, _ = self.status_values(m, suffix)
            if v is not None:
                return v
        return None


# ---- scenarios ----------------------------------------------------------------------


def scenario_topics(p, a):
    """Every output topic with rclpy's default QoS (reliable, volatile, depth 10)
    and with qos_profile_sensor_data (best effort, depth 5); /tf_static and
    ~/critical_speeds as transient-local late joiners; /rosout; the graph as
    `ros2 topic list -t` sees it."""
    n = a.get("messages", 20)
    reliable = {
        "joint_states": p.collect(JointState, "/joint_states", 10, keep=n + 5),
        "tf": p.collect(TFMessage, "/tf", 10, keep=n + 5),
        "modal_amplitudes": p.collect(ModalAmplitudes, p.private("modal_amplitudes"), 10, keep=n + 5),
        "pad_states": p.collect(PadStates, p.private("pad_states"), 10, keep=n + 5),
        "diagnostics": p.collect(DiagnosticArray, "/diagnostics", 10, keep=n + 5),
        "plate_marker": p.collect(MarkerArray, p.private("plate_marker"), 10, keep=2),
    }
    sensor = {
        "joint_states": p.collect(JointState, "/joint_states", qos_profile_sensor_data, keep=n + 5),
        "tf": p.collect(TFMessage, "/tf", qos_profile_sensor_data, keep=n + 5),
        "modal_amplitudes": p.collect(ModalAmplitudes, p.private("modal_amplitudes"), qos_profile_sensor_data, keep=n + 5),
        "pad_states": p.collect(PadStates, p.private("pad_states"), qos_profile_sensor_data, keep=n + 5),
    }
    start = time.monotonic()
    need = {k: (2 if k in ("diagnostics", "plate_marker") else n) for k in reliable}

    def enough():
        return all(len(reliable[k]) >= need[k] for k in reliable) and all(len(sensor[k]) >= n for k in sensor)
    p.spin_until(enough, a.get("timeout", 60.0), "messages on every topic")
    waited = time.monotonic() - start
    # Late joiners: the node has been up for a while; transient local brings the latched samples.
    p.spin_for(1.0)
    tf_static = p.collect(TFMessage, "/tf_static", LATCHED)
    critical = p.collect(CriticalSpeeds, p.private("critical_speeds"), LATCHED)
    rosout = p.collect(Log, "/rosout", ROSOUT)
    t_late = time.monotonic()
    p.spin_until(lambda: tf_static and critical and rosout, 30.0, "/tf_static, ~/critical_speeds and /rosout for a late joiner")
    late_s = time.monotonic() - t_late
    p.spin_for(1.0)  # one message each, no more
    node_name, node_ns = a.get("node_name", "annular_plate"), a.get("node_namespace", "/")
    p.spin_until(lambda: "/joint_states" in p.node_publishes(node_name, node_ns), 30.0,
                 f"{node_ns}{node_name} in the graph")
    topics = {name: types for name, types in p.node.get_topic_names_and_types()}
    js = reliable["joint_states"][-1]
    tf = reliable["tf"][-1]
    ma = reliable["modal_amplitudes"][-1]
    ps = reliable["pad_states"][-1]
    steps = [m.step for m in reliable["modal_amplitudes"]]
    diag_names = sorted({st.name for m in reliable["diagnostics"] for st in m.status})
    marker = reliable["plate_marker"][-1]
    return {
        "received": {"reliable": {k: len(v) for k, v in reliable.items()},
                     "sensor_data": {k: len(v) for k, v in sensor.items()}},
        "seconds_to_receive": waited,
        "joint_state": {"name": list(js.name), "velocity": list(js.velocity), "effort": list(js.effort),
                        "frame_id": js.header.frame_id},
        "sensor_joint_state_name": list(sensor["joint_states"][-1].name),
        "tf_children": sorted(t.child_frame_id for t in tf.transforms),
        "tf_parents": sorted({t.header.frame_id for t in tf.transforms}),
        "modal": {"modes": len(ma.k), "frame_id": ma.header.frame_id, "steps_increasing": all(b > a_ for a_, b in zip(steps, steps[1:]))},
        "pad_states": {"clamp_force": list(ps.clamp_force), "frame_id": ps.header.frame_id},
        "diagnostics": diag_names,
        "marker": {"markers": len(marker.markers), "bytes": len(serialize_message(marker))},
        "tf_static": {"messages": len(tf_static), "children": sorted(t.child_frame_id for t in tf_static[0].transforms),
                      "parents": sorted({t.header.frame_id for t in tf_static[0].transforms})},
        "critical_speeds": {"messages": len(critical), "k": list(critical[0].k), "l": list(critical[0].l),
                            "rad_s": list(critical[0].rad_s), "stiffening": critical[0].centrifugal_stiffening},
        "late_joiner_s": late_s,
        "rosout": {"messages": len(rosout), "names": sorted({m.name for m in rosout})},
        "graph_topics": topics,
        "graph_nodes": [list(x) for x in p.node.get_node_names_and_namespaces()],
        "node_publishes": p.node_publishes(node_name, node_ns),
        "node_subscribes": dict(p.node.get_subscriber_names_and_types_by_node(node_name, node_ns)),
    }


def wrench_msg(frame="", fx=0.0, fz=0.0):
    m = WrenchStamped()
    m.header.frame_id = frame
    m.wrench.force.x = fx
    m.wrench.force.z = fz
    return m


def scenario_inputs(p, a):
    """Paused node: each input topic once with a good sample (rclpy's default
    publisher QoS), then the bad ones the docs list (NaN, wrong frame, unknown
    pad, absurd clamp force); the /diagnostics counters after each phase."""
    setp, _ = p.client(SetBool, p.private("set_paused"))
    resp, _ = p.call(setp, SetBool.Request(data=True), 20.0)
    assert resp is not None and resp.success, f"set_paused: {resp}"
    pubs = {
        "speed": p.publisher(Float64, p.private("speed_command")),
        "ale_1": p.publisher(WrenchStamped, p.private("ale_1/wrench")),
        "wrenches": p.publisher(NodeWrenchArray, p.private("wrenches")),
        "pad_1": p.publisher(Float64, p.private("pad_1/clamp_force")),
        "pads": p.publisher(PadClampForces, p.private("pad_clamp_forces")),
    }
    p.diagnostics()
    p.wait_status(": inputs", lambda v: True)
    pubs["speed"].publish(Float64(data=26.0))
    pubs["ale_1"].publish(wrench_msg(a.get("ale_1_frame", "plate_ale_1"), fz=10.0))
    arr = NodeWrenchArray()
    arr.wrenches = [NodeWrench(kind=NodeWrench.ALE, index=2, wrench=wrench_msg().wrench)]
    pubs["wrenches"].publish(arr)
    pubs["pad_1"].publish(Float64(data=1000.0))
    p.wait_status(": inputs", lambda v: int(v.get("accepted_total", 0)) >= 4)
    pc = PadClampForces()
    pc.pad = [1]
    pc.clamp_force = [2000.0]
    pubs["pads"].publish(pc)  # after the Float64 on pad_1: this one holds
    good, _ = p.wait_status(": inputs", lambda v: int(v.get("accepted_total", 0)) >= 5)
    # The bad ones.
    pubs["speed"].publish(Float64(data=float("nan")))
    pubs["ale_1"].publish(wrench_msg("", fx=float("nan")))
    pubs["ale_1"].publish(wrench_msg("not_a_frame_of_this_node", fz=1.0))
    bad_pad = PadClampForces()
    bad_pad.pad = [9]
    bad_pad.clamp_force = [100.0]
    pubs["pads"].publish(bad_pad)
    pubs["pad_1"].publish(Float64(data=-5.0))
    p.wait_status(": inputs", lambda v: int(v.get("rejected_total", 0)) >= 5)
    p.spin_for(0.5)
    bad, st = p.wait_status(": inputs", lambda v: int(v.get("rejected_total", 0)) >= 5)
    p.spin_for(0.5)  # and a report or more with no new rejection

    def level(st):
        return st.level[0] if isinstance(st.level, (bytes, bytearray)) else int(st.level)
    # (rejected_total, level) of every inputs status kept, oldest first.
    reports = []
    for m in p.diagnostics():
        v, st = p.status_values(m, ": inputs")
        if v is not None:
            reports.append([int(v["rejected_total"]), level(st)])
    # The node still runs: a step goes through and the state carries the good inputs.
    step, _ = p.client(Step, p.private("step"))
    states = p.collect(PadStates, p.private("pad_states"), 10, keep=5)
    r, _ = p.call(step, Step.Request(steps=3), 20.0)
    p.spin_until(lambda: states and states[-1].step == r.step, 20.0, "the pad state of the last step")
    return {"after_good": good, "after_bad": bad, "reports": reports, "step": {"success": r.success, "step": r.step},
            "clamp_force": list(states[-1].clamp_force)}


def scenario_services(p, a):
    """The node's own services and the simulation_interfaces ones, each call on
    a fresh client as `ros2 service call` makes it."""
    out = {}

    def call(key, typ, name, req):
        r, meta = p.call_fresh(typ, p.private(name), req, timeout=a.get("timeout", 20.0))
        if r is None:
            raise Timeout(f"{key}: no reply to {name} within the timeout ({meta})")
        out.setdefault("_latency", {})[key] = meta["reply_s"]
        return r

    def res(r):
        return {"result": r.result.result, "message": r.result.error_message}
    st = call("get_state_running", GetSimulationState, "get_simulation_state", GetSimulationState.Request())
    out["get_state_running"] = {"state": st.state.state, **res(st)}
    r = call("step_running", Step, "step", Step.Request(steps=5))
    out["step_running"] = {"success": r.success, "message": r.message}
    r = call("step_simulation_running", StepSimulation, "step_simulation", StepSimulation.Request(steps=5))
    out["step_simulation_running"] = res(r)
    r = call("pause", SetBool, "set_paused", SetBool.Request(data=True))
    out["pause"] = {"success": r.success, "message": r.message}
    st = call("get_state_paused", GetSimulationState, "get_simulation_state", GetSimulationState.Request())
    out["get_state_paused"] = {"state": st.state.state, **res(st)}
    r = call("step", Step, "step", Step.Request(steps=10))
    out["step"] = {"success": r.success, "step": r.step, "sim_time": r.sim_time}
    r = call("step_simulation", StepSimulation, "step_simulation", StepSimulation.Request(steps=15))
    out["step_simulation"] = res(r)
    r = call("step_after", Step, "step", Step.Request(steps=0))
    out["step_after"] = {"success": r.success, "step": r.step, "sim_time": r.sim_time}
    r = call("set_paused_again", SetSimulationState, "set_simulation_state",
             SetSimulationState.Request(state=SimulationState(state=SimulationState.STATE_PAUSED)))
    out["set_paused_again"] = res(r)
    r = call("reset", Trigger, "reset", Trigger.Request())
    out["reset"] = {"success": r.success, "message": r.message}
    r = call("step_after_reset", Step, "step", Step.Request(steps=0))
    out["step_after_reset"] = {"success": r.success, "step": r.step}
    r = call("step_simulation_2", StepSimulation, "step_simulation", StepSimulation.Request(steps=7))
    out["step_simulation_2"] = res(r)
    r = call("reset_time_only", ResetSimulation, "reset_simulation", ResetSimulation.Request(scope=ResetSimulation.Request.SCOPE_TIME))
    out["reset_time_only"] = res(r)
    r = call("reset_simulation", ResetSimulation, "reset_simulation", ResetSimulation.Request(scope=ResetSimulation.Request.SCOPE_ALL))
    out["reset_simulation"] = res(r)
    r = call("step_after_reset_simulation", Step, "step", Step.Request(steps=0))
    out["step_after_reset_simulation"] = {"step": r.step}
    r = call("play", SetSimulationState, "set_simulation_state",
             SetSimulationState.Request(state=SimulationState(state=SimulationState.STATE_PLAYING)))
    out["play"] = res(r)
    st = call("get_state_playing", GetSimulationState, "get_simulation_state", GetSimulationState.Request())
    out["get_state_playing"] = {"state": st.state.state, **res(st)}
    r = call("stop", SetSimulationState, "set_simulation_state",
             SetSimulationState.Request(state=SimulationState(state=SimulationState.STATE_STOPPED)))
    out["stop"] = res(r)
    st = call("get_state_stopped", GetSimulationState, "get_simulation_state", GetSimulationState.Request())
    out["get_state_stopped"] = {"state": st.state.state, **res(st)}
    r = call("quit", SetSimulationState, "set_simulation_state",
             SetSimulationState.Request(state=SimulationState(state=SimulationState.STATE_QUITTING)))
    out["quit"] = res(r)
    r = call("resume", SetBool, "set_paused", SetBool.Request(data=False))
    out["resume"] = {"success": r.success, "message": r.message}
    return out


# ---- parameters -------------------------------------------------------------------


def pvalue(v):
    t = v.type
    if t == ParameterType.PARAMETER_BOOL:
        x = v.bool_value
    elif t == ParameterType.PARAMETER_INTEGER:
        x = v.integer_value
    elif t == ParameterType.PARAMETER_DOUBLE:
        x = v.double_value
    elif t == ParameterType.PARAMETER_STRING:
        x = v.string_value
    elif t == ParameterType.PARAMETER_DOUBLE_ARRAY:
        x = list(v.double_array_value)
    elif t == ParameterType.PARAMETER_INTEGER_ARRAY:
        x = list(v.integer_array_value)
    elif t == ParameterType.PARAMETER_STRING_ARRAY:
        x = list(v.string_array_value)
    elif t == ParameterType.PARAMETER_BOOL_ARRAY:
        x = list(v.bool_array_value)
    else:
        x = None
    return {"type": t, "value": x}


def dparam(name, x):
    return ParameterMsg(name=name, value=ParameterValue(type=ParameterType.PARAMETER_DOUBLE, double_value=x))


def sparam(name, s):
    return ParameterMsg(name=name, value=ParameterValue(type=ParameterType.PARAMETER_STRING, string_value=s))


def scenario_params(p, a):
    """The six parameter services as the `ros2 param` verbs call them (one fresh
    client per verb), then `calls` consecutive describe_parameters calls on one
    client with replies from ~100 B to ~70 KB, then the first reply of fresh
    clients. A reply not there within `timeout` s counts as lost (and the
    scenario goes on)."""
    timeout = a.get("timeout", 10.0)
    out = {"verbs": {}}
    verbs = out["verbs"]

    def verb(key, typ, name, req):
        r, meta = p.call_fresh(typ, p.private(name), req, timeout)
        verbs[key] = meta
        print(f"{key}: {meta}", file=sys.stderr, flush=True)
        return r

    # ros2 param list: ListParameters, depth 0 (DEPTH_RECURSIVE), no prefix.
    lst = verb("list", ListParameters, "list_parameters", ListParameters.Request(depth=0))
    names = list(lst.result.names) if lst else []
    out["list"] = {"names": names, "prefixes": list(lst.result.prefixes) if lst else None}
    # ros2 param list --filter / a prefix: ListParameters with prefixes.
    for key, prefixes, depth in (("list_plate", ["plate"], 0), ("list_ros_depth2", ["ros"], 2), ("list_two", ["joint", "pads"], 0)):
        r = verb(key, ListParameters, "list_parameters", ListParameters.Request(prefixes=prefixes, depth=depth))
        out[key] = {"names": list(r.result.names), "prefixes": list(r.result.prefixes)} if r else None
    # Every declared name (the test knows them from the in-process setup; else the list).
    all_names = a.get("names") or names
    # ros2 param dump / get: GetParameters of every name in one call.
    r = verb("get_all", GetParameters, "get_parameters", GetParameters.Request(names=all_names))
    out["get_all"] = {n: pvalue(v) for n, v in zip(all_names, r.values)} if r else None
    # ros2 param list --param-type: GetParameterTypes of every name.
    r = verb("types_all", GetParameterTypes, "get_parameter_types", GetParameterTypes.Request(names=all_names))
    out["types_all"] = dict(zip(all_names, list(r.types))) if r else None
    # ros2 param describe NODE every name.
    r = verb("describe_all", DescribeParameters, "describe_parameters", DescribeParameters.Request(names=all_names))
    out["describe_all"] = {d.name: {"type": d.type, "read_only": d.read_only, "description": d.description,
                                    "constraints": d.additional_constraints} for d in r.descriptors} if r else None
    out["describe_all_count"] = len(r.descriptors) if r else None
    # ros2 param get of one name, unknown name.
    r = verb("get_one", GetParameters, "get_parameters", GetParameters.Request(names=["joint.speed", "no.such.name"]))
    out["get_one"] = [pvalue(v) for v in r.values] if r else None
    # ros2 param set: SetParameters, one accepted (run-time key), refused ones.
    r = verb("set_good", SetParameters, "set_parameters",
             SetParameters.Request(parameters=[dparam("simulation.realtime_factor", 1.0), dparam("ros.wrench_timeout", 0.25)]))
    out["set_good"] = [{"ok": x.successful, "reason": x.reason} for x in r.results] if r else None
    r = verb("set_refused", SetParameters, "set_parameters",
             SetParameters.Request(parameters=[dparam("plate.thickness", 0.02), dparam("simulation.realtime_factor", -1.0),
                                               sparam("ros.wrench_timeout", "soon"), dparam("no.such.name", 1.0)]))
    out["set_refused"] = [{"ok": x.successful, "reason": x.reason} for x in r.results] if r else None
    # ros2 param load --no-use-wildcard ... atomically: SetParametersAtomically.
    r = verb("set_atomic_good", SetParametersAtomically, "set_parameters_atomically",
             SetParametersAtomically.Request(parameters=[dparam("simulation.realtime_factor", 1.0), dparam("ros.wrench_timeout", 0.5)]))
    out["set_atomic_good"] = {"ok": r.result.successful, "reason": r.result.reason} if r else None
    r = verb("set_atomic_refused", SetParametersAtomically, "set_parameters_atomically",
             SetParametersAtomically.Request(parameters=[dparam("ros.wrench_timeout", 0.75), dparam("plate.thickness", 0.02)]))
    out["set_atomic_refused"] = {"ok": r.result.successful, "reason": r.result.reason} if r else None
    r = verb("get_after", GetParameters, "get_parameters",
             GetParameters.Request(names=["simulation.realtime_factor", "ros.wrench_timeout", "plate.thickness"]))
    out["get_after"] = [pvalue(v) for v in r.values] if r else None

    # `calls` consecutive calls on one client, replies from ~100 B to ~70 KB:
    # describe_parameters of the first n names of the declared list repeated
    # (a descriptor per name asked, duplicates included); n grows
    # geometrically, aimed with the bytes per descriptor seen so far.
    calls = a.get("calls", 200)
    lo, hi = a.get("min_bytes", 100), a.get("max_bytes", 70000)
    client, _ = p.client(DescribeParameters, p.private("describe_parameters"))
    cycle = all_names or ["plate.thickness"]
    per_name = 300.0  # first guess of a descriptor's CDR bytes; refined by every reply
    series = []
    give_up = a.get("give_up_after", 3)
    consecutive_losses = 0
    for i in range(calls):
        target = lo * (hi / lo) ** (i / max(1, calls - 1))
        if consecutive_losses >= give_up:
            # A client whose reply was lost gets no later reply either: the
            # rest are counted as lost without waiting `timeout` for each.
            series.append({"i": i, "target_bytes": int(target), "reply_bytes": None, "seconds": None,
                           "lost": True, "not_sent": True})
            continue
        if i == 0:
            req_names = ["x"]  # an undeclared name: the smallest descriptor
        else:
            n = max(1, int(round((target - 8) / per_name)))
            req_names = [cycle[j % len(cycle)] for j in range(n)]
        r, dt = p.call(client, DescribeParameters.Request(names=req_names), timeout)
        size = len(serialize_message(r)) if r is not None else None
        if r is not None and i > 0:
            per_name = max(20.0, (size - 8) / len(req_names))
        consecutive_losses = consecutive_losses + 1 if r is None else 0
        print(f"describe_parameters call {i}: {len(req_names)} names -> "
              f"{'LOST' if r is None else str(size) + ' B'} after {dt:.4f} s", file=sys.stderr, flush=True)
        series.append({"i": i, "names": len(req_names), "target_bytes": int(target),
                       "request_bytes": len(serialize_message(DescribeParameters.Request(names=req_names))),
                       "reply_bytes": size, "seconds": dt, "lost": r is None,
                       "complete": r is not None and len(r.descriptors) == len(req_names)})
    out["series"] = series

    # The first reply on fresh clients (what every `ros2 param` command sees).
    firsts = []
    for i in range(a.get("fresh_clients", 5)):
        r, meta = p.call_fresh(GetParameterTypes, p.private("get_parameter_types"),
                               GetParameterTypes.Request(names=["joint.speed"]), timeout)
        firsts.append(meta)
    out["fresh_first"] = firsts
    return out


# ---- time ---------------------------------------------------------------------------


def scenario_clock_out(p, a):
    """Node with ros.publish_clock: /clock (rosgraph_msgs/Clock) with a reliable
    and a best-effort subscriber, and an rclpy node on use_sim_time following it."""
    n = a.get("messages", 50)
    rel = p.collect(Clock, "/clock", 10, keep=n + 50)
    be = p.collect(Clock, "/clock", BEST_EFFORT_1, keep=n + 50)
    follower = Node("sim_time_follower", parameter_overrides=[Parameter("use_sim_time", Parameter.Type.BOOL, True)])
    ma = p.collect(ModalAmplitudes, p.private("modal_amplitudes"), 10, keep=20)
    ex = rclpy.executors.SingleThreadedExecutor()
    ex.add_node(p.node)
    ex.add_node(follower)
    deadline = time.monotonic() + a.get("timeout", 60.0)
    while (len(rel) < n or len(be) < 5 or len(ma) < 5) and time.monotonic() < deadline:
        ex.spin_once(timeout_sec=0.01)
    if len(rel) < n or len(be) < 5 or len(ma) < 5:
        raise Timeout(f"/clock: {len(rel)} reliable, {len(be)} best-effort, {len(ma)} modal amplitudes")
    ex.spin_once(timeout_sec=0.01)
    follower_now = follower.get_clock().now().nanoseconds
    last_clock = stamp_ns(rel[-1].clock)
    stamps = [stamp_ns(c.clock) for c in rel]
    # The node's outputs are stamped with its simulated time: the modal amplitudes'
    # stamp against sim_time (both from the node's own simulated clock).
    m = ma[-1]
    types = dict(p.node.get_topic_names_and_types()).get("/clock")
    return {"reliable": len(rel), "best_effort": len(be), "monotonic": all(b > a_ for a_, b in zip(stamps, stamps[1:])),
            "first_clock_ns": stamps[0], "last_clock_ns": last_clock, "follower_now_ns": follower_now,
            "follower_minus_clock_s": (follower_now - last_clock) * 1e-9,
            "modal_stamp_ns": stamp_ns(m.header.stamp), "modal_sim_time": m.sim_time, "modal_step": m.step,
            "clock_types": types}


def scenario_clock_in(p, a):
    """Node with use_sim_time: rclpy publishes /clock, first reliable (rclpy's
    default, as Gazebo's bridge) and then best effort (rclcpp's ClockQoS, as
    `ros2 bag play --clock`); the node steps as far as the clock advanced and
    stamps its outputs with it."""
    dt = a.get("dt", 1e-3)
    origin = a.get("origin", 100.0)
    ma = p.collect(ModalAmplitudes, p.private("modal_amplitudes"), 10, keep=200)
    rel = p.publisher(Clock, "/clock", 10)
    be = p.node.create_publisher(Clock, "/clock", BEST_EFFORT_1)
    p.spin_until(lambda: be.get_subscription_count() > 0, 20.0, "the node's /clock reader for the best-effort writer")

    def clock(t):
        c = Clock()
        c.clock.sec = int(math.floor(t))
        c.clock.nanosec = int(round((t - math.floor(t)) * 1e9))
        return c
    seen = []

    def drive(pub, t, expect_step, timeout=20.0):
        """Publish t (again every 0.2 s: best effort may drop one) until a state of `expect_step` arrives."""
        deadline = time.monotonic() + timeout
        last = 0.0
        while time.monotonic() < deadline:
            if time.monotonic() - last > 0.2:
                pub.publish(clock(t))
                last = time.monotonic()
            rclpy.spin_once(p.node, timeout_sec=0.01)
            for m in ma:
                if m.step == expect_step:
                    return m
        raise Timeout(f"no modal amplitudes of step {expect_step} after /clock = {t} (last step {ma[-1].step if ma else None})")

    # The origin: no step yet; then 5 steps' worth reliable, 10 more best effort.
    # Several times over a second: the node's reader may match the writer a
    # moment after the writer saw it; the first that arrives is the origin,
    # the others stand still.
    for _ in range(10):
        rel.publish(clock(origin))
        p.spin_for(0.1)
    p.spin_for(0.5)
    before = [m.step for m in ma]
    m5 = drive(rel, origin + 5 * dt, 5)
    m15 = drive(be, origin + 15 * dt, 15)
    p.spin_for(0.5)
    steps = sorted({m.step for m in ma})
    return {"steps_before_advance": before, "steps": steps,
            "stamp5_ns": stamp_ns(m5.header.stamp), "stamp15_ns": stamp_ns(m15.header.stamp),
            "origin_ns": int(round(origin * 1e9)), "sim_time15": m15.sim_time}


# ---- names --------------------------------------------------------------------------


def scenario_names(p, a):
    """A renamed, namespaced node (-r __ns:=/bench -r __node:=disc): the graph
    as `ros2 node list`, `ros2 topic list -t` and `ros2 service list -t` see it;
    a message and a service call under the new names."""
    js = p.collect(JointState, a["joint_states"], 10, keep=2)
    p.spin_until(lambda: js, 30.0, f"a joint state on {a['joint_states']}")

    def node_topics():
        return p.node_publishes(a["node_name"], a["node_namespace"])

    # Endpoints are seen by DDS discovery, the node's name by its
    # ros_discovery_info sample: either can come first, so wait for both.
    def graph_complete():
        services = dict(p.node.get_service_names_and_types())
        return (all(s in services for s in a.get("expect_services", []))
                and a["joint_states"] in node_topics())
    p.spin_until(graph_complete, 30.0, "the node's services and its name in the graph")
    r, meta = p.call_fresh(GetSimulationState, p.private("get_simulation_state"), GetSimulationState.Request(), 20.0)
    return {"nodes": sorted([list(x) for x in p.node.get_node_names_and_namespaces()]),
            "topics": dict(p.node.get_topic_names_and_types()),
            "services": dict(p.node.get_service_names_and_types()),
            "node_topics": node_topics(),
            "joint_name": list(js[-1].name),
            "state": r.state.state if r else None, "state_meta": meta}


SCENARIOS = {name[len("scenario_"):]: fn for name, fn in globals().items() if name.startswith("scenario_")}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("scenario", choices=sorted(SCENARIOS))
    ap.add_argument("--node", default="/annular_plate")
    ap.add_argument("--args", default="{}")
    ns = ap.parse_args()
    rclpy.init()
    p = Peer(ns.node)
    try:
        result = SCENARIOS[ns.scenario](p, json.loads(ns.args))
    finally:
        p.node.destroy_node()
        rclpy.try_shutdown()
    print(json.dumps(result), flush=True)


if __name__ == "__main__":
    sys.exit(main())
