#!/usr/bin/env python3
"""Brake the disc of the annular_plate node: ramp the clamp force of the
caliper's pads up (the normal force each face of the disc is pressed with),
hold it, release it, and print how the plate responds — the joint speed
dropping under the brake torque, the drive's effort, the pad forces and the
modal amplitudes.

Needs the interfaces of this package (colcon build, see docs/ros.md) and a
running node on the brake-bench scene (config/brake_bench.yaml, the default):

    annular_plate                                   # terminal 1: the node
    python3 launch-scripts/brake_load_example.py    # terminal 2: this script
    # or both at once:
    ros2 launch launch-scripts/brake_bench.launch.py run_example:=true

The pads are a load model inside the simulator (a spring-damper per contact
point and face, floating caliper, lift-off, friction mu N against the
sliding), evaluated at the integration rate; this script only commands their
clamp force. Their friction torque 2 mu N r brakes the joint. The bench's
drive holds 25 rad/s with at most joint.max_torque = 1500 N m, so up to
N = 1500 / (2 * 0.4 * 0.1198 m) = 15.65 kN the speed holds and the drive's
effort equals the brake torque; above it the bare disc (polar inertia
0.117 kg m^2) decelerates at (2 mu N r - 1500 N m) / J — 285 rad/s^2 at
16 kN, so the default 30 ms hold takes about 13 rad/s off. Released, the
drive speeds it up again at joint.max_acceleration = 50 rad/s^2. (A hold long
enough to stop the disc ends at the friction's stick point, which the
1-ms joint step does not resolve: the speed then jitters about zero.) A flat
disc squeezed by floating pads is not bent — friction acts in its plane and
the two faces' forces cancel — so the modal amplitudes stay at zero unless
something else disturbs the plate (a wrench on a node, ~/ale_<j>/wrench).

Parameters (--ros-args -p name:=value):
    target       the node, default /annular_plate
    pads         pad numbers to command (from 1), default [1]
    peak_force   N per face at full clamp, default 16000.0
    ramp, hold, release   s, default 1.0, 0.03, 0.5
    rate         Hz at which the clamp forces are sent, default 100.0
    print_period s between printed lines, default 0.05 (and whenever the
                 speed moved by more than 0.5 rad/s since the last line)

All commanded pads are one annular_plate/msg/PadClampForces on
<target>/pad_clamp_forces per tick, so they change together before one step
of the simulation; its header stamp comes back as ModalAmplitudes.input_stamp
(the command-to-state latency printed). Topics and QoS (reliable, volatile;
the two whose every sample counts for the summary with depth 1000, one
second of the node's 1-kHz states, so that none is dropped while Python
catches up; the others rclpy's default depth 10):
    <target>/pad_clamp_forces  annular_plate/msg/PadClampForces    (published)
    <target>/pad_states        annular_plate/msg/PadStates         (subscribed)
    <target>/modal_amplitudes  annular_plate/msg/ModalAmplitudes   (subscribed)
    /joint_states              sensor_msgs/msg/JointState          (subscribed)
(One pad can also be commanded alone with a std_msgs/Float64 on
<target>/pad_<j>/clamp_force.) The integration test
`the_brake_load_example_works_on_the_wire` plays this script's part against
the real node with an independent DDS implementation, with this force profile
stepped in simulated time, and checks the response against the simulator.
"""

import rclpy
from rclpy.node import Node

from annular_plate.msg import ModalAmplitudes, PadClampForces, PadStates
from sensor_msgs.msg import JointState


class BrakeLoad(Node):
    def __init__(self):
        super().__init__("brake_load_example")
        p = self.declare_parameter
        self.target = p("target", "/annular_plate").value.rstrip("/")
        self.pads = [int(j) for j in p("pads", [1]).value]
        self.peak = float(p("peak_force", 16000.0).value)
        self.ramp = float(p("ramp", 1.0).value)
        self.hold = float(p("hold", 0.03).value)
        self.release = float(p("release", 0.5).value)
        self.print_period = float(p("print_period", 0.05).value)
        rate = float(p("rate", 100.0).value)

        self.pub = self.create_publisher(PadClampForces, f"{self.target}/pad_clamp_forces", 10)
        self.create_subscription(PadStates, f"{self.target}/pad_states", self.on_pads, 1000)
        self.create_subscription(ModalAmplitudes, f"{self.target}/modal_amplitudes", self.on_modal, 10)
        self.create_subscription(JointState, "/joint_states", self.on_joint, 1000)
        self.pad_states = None
        self.modal = None
        self.speed = float("nan")
        self.effort = float("nan")
        self.start = None
        self.last_print = None
        self.printed_speed = None
        self.min_speed = (float("inf"), 0.0)
        self.max_brake = 0.0
        self.max_q = 0.0
        self.done = False
        self.timer = self.create_timer(1.0 / rate, self.tick)
        self.get_logger().info(
            f"braking {self.target}: pads {self.pads}, {self.peak} N, "
            f"ramp {self.ramp} s, hold {self.hold} s, release {self.release} s")

    def elapsed(self):
        return 0.0 if self.start is None else (self.get_clock().now() - self.start).nanoseconds * 1e-9

    def on_pads(self, msg):
        # The summary's largest brake torque is over every state, not the ticks.
        self.pad_states = msg
        self.max_brake = max(self.max_brake, -sum(msg.friction_torque))

    def on_modal(self, msg):
        self.modal = msg

    def on_joint(self, msg):
        if msg.velocity:
            self.speed = msg.velocity[0]
            if self.speed < self.min_speed[0]:  # the minimum over every state
                self.min_speed = (self.speed, self.elapsed())
        if msg.effort:
            self.effort = msg.effort[0]

    def force(self, t):
        if t < self.ramp:
            return self.peak * t / self.ramp
        if t < self.ramp + self.hold:
            return self.peak
        if t < self.ramp + self.hold + self.release:
            return self.peak * (1.0 - (t - self.ramp - self.hold) / self.release)
        return 0.0

    def command(self, force):
        msg = PadClampForces()
        msg.header.stamp = self.get_clock().now().to_msg()
        msg.pad = self.pads
        msg.clamp_force = [float(force)] * len(self.pads)
        self.pub.publish(msg)

    def report(self, t, f, now):
        line = f"t={t:5.2f} s  clamp {f:8.1f} N  speed {self.speed:7.3f} rad/s  effort {self.effort:7.1f} N m"
        ps = self.pad_states
        if ps is not None and ps.clamp_force:
            line += (f"  pad normal {sum(ps.normal_force):8.1f} N  friction torque {sum(ps.friction_torque):8.1f} N m")
        m = self.modal
        if m is not None and m.q_ale:
            peak_q = max(abs(q) for q in m.q_ale)
            stamp = m.input_stamp.sec * 10**9 + m.input_stamp.nanosec
            line += f"  max|q_ale| {peak_q * 1e6:8.3f} um  step {m.step}"
            if stamp > 0:
                line += f"  command->state {(now.nanoseconds - stamp) * 1e-6:6.2f} ms"
        print(line, flush=True)

    def tick(self):
        now = self.get_clock().now()
        if self.start is None:
            if self.pub.get_subscription_count() == 0:
                return  # wait for the node
            self.start = now
        t = (now - self.start).nanoseconds * 1e-9
        f = self.force(t)
        self.command(f)
        if self.modal is not None and self.modal.q_ale:
            self.max_q = max(self.max_q, max(abs(q) for q in self.modal.q_ale))
        moved = self.printed_speed is None or abs(self.speed - self.printed_speed) > 0.5
        if self.last_print is None or t - self.last_print >= self.print_period or moved:
            self.last_print = t
            self.printed_speed = self.speed
            self.report(t, f, now)
        if t > self.ramp + self.hold + self.release + 1.0 and not self.done:
            self.command(0.0)
            self.done = True
            print(f"minimum speed {self.min_speed[0]:.3f} rad/s at t = {self.min_speed[1]:.2f} s; "
                  f"largest brake torque {self.max_brake:.1f} N m; largest |q_ale| {self.max_q * 1e6:.3f} um",
                  flush=True)
            self.get_logger().info("released; done")
            raise SystemExit


def main():
    rclpy.init()
    node = BrakeLoad()
    try:
        rclpy.spin(node)
    except (SystemExit, KeyboardInterrupt):
        pass
    finally:
        node.destroy_node()
        if rclpy.ok():
            rclpy.shutdown()


if __name__ == "__main__":
    main()
