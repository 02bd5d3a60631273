#!/usr/bin/env python3
"""Brake the disc of the annular_plate node: ramp the pad normal forces on the
caliper's ALE nodes up, hold them, release them, and print how the plate
responds.

Needs the interfaces of this package (colcon build, see docs/ros.md) and a
running node on the brake-bench scene:

    annular_plate                                   # terminal 1: the node
    python3 launch-scripts/brake_load_example.py    # terminal 2: this script
    # or both at once:
    ros2 launch launch-scripts/brake_bench.launch.py run_example:=true

Parameters (--ros-args -p name:=value):
    target       the node, default /annular_plate
    inboard      ALE node numbers of the inboard pad  (push along -z), default [1, 2, 3]
    outboard     ALE node numbers of the outboard pad (push along +z), default [4, 5, 6]
    peak_force   N per pad at full clamp, default 2000.0
    friction     pad friction coefficient mu (tangential force mu*N along -x), default 0.4
    ramp, hold, release   s, default 0.5, 1.0, 0.5
    rate         Hz at which the forces are sent, default 100.0

The whole caliper is one annular_plate/msg/NodeWrenchArray on <target>/wrenches
per tick, so the pads change together in one step of the simulation. Topics
and QoS (all rclpy defaults: reliable, volatile, depth 10):
    <target>/wrenches          annular_plate/msg/NodeWrenchArray   (published)
    <target>/modal_amplitudes  annular_plate/msg/ModalAmplitudes   (subscribed)
    /joint_states              sensor_msgs/msg/JointState          (subscribed)
The integration test `the_brake_load_example_works_on_the_wire` plays this
script's part against the real node with an independent DDS implementation.
"""

import rclpy
from rclpy.node import Node

from annular_plate.msg import ModalAmplitudes, NodeWrench, NodeWrenchArray
from sensor_msgs.msg import JointState


class BrakeLoad(Node):
    def __init__(self):
        super().__init__("brake_load_example")
        p = self.declare_parameter
        self.target = p("target", "/annular_plate").value.rstrip("/")
        self.inboard = list(p("inboard", [1, 2, 3]).value)
        self.outboard = list(p("outboard", [4, 5, 6]).value)
        self.peak = float(p("peak_force", 2000.0).value)
        self.mu = float(p("friction", 0.4).value)
        self.ramp = float(p("ramp", 0.5).value)
        self.hold = float(p("hold", 1.0).value)
        self.release = float(p("release", 0.5).value)
        rate = float(p("rate", 100.0).value)

        self.pub = self.create_publisher(NodeWrenchArray, f"{self.target}/wrenches", 10)
        self.create_subscription(ModalAmplitudes, f"{self.target}/modal_amplitudes", self.on_modal, 10)
        self.create_subscription(JointState, "/joint_states", self.on_joint, 10)
        self.modal = None
        self.speed = float("nan")
        self.start = None
        self.last_print = -1.0
        self.done = False
        self.timer = self.create_timer(1.0 / rate, self.tick)
        self.get_logger().info(
            f"braking {self.target}: pads {self.inboard} / {self.outboard}, {self.peak} N, "
            f"ramp {self.ramp} s, hold {self.hold} s, release {self.release} s")

    def on_modal(self, msg):
        self.modal = msg

    def on_joint(self, msg):
        if msg.velocity:
            self.speed = msg.velocity[0]

    def force(self, t):
        if t < self.ramp:
            return self.peak * t / self.ramp
        if t < self.ramp + self.hold:
            return self.peak
        if t < self.ramp + self.hold + self.release:
            return self.peak * (1.0 - (t - self.ramp - self.hold) / self.release)
        return 0.0

    def batch(self, force):
        msg = NodeWrenchArray()
        msg.header.stamp = self.get_clock().now().to_msg()
        share_in = force / max(len(self.inboard), 1)
        share_out = force / max(len(self.outboard), 1)
        for nodes, share, sign in ((self.inboard, share_in, -1.0), (self.outboard, share_out, 1.0)):
            for j in nodes:
                w = NodeWrench(kind=NodeWrench.ALE, index=int(j))
                w.wrench.force.z = sign * share      # pad pressure, normal to the disc
                w.wrench.force.x = -self.mu * share  # friction, against the rotation
                msg.wrenches.append(w)
        return msg

    def tick(self):
        now = self.get_clock().now()
        if self.start is None:
            if self.pub.get_subscription_count() == 0:
                return  # wait for the node
            self.start = now
        t = (now - self.start).nanoseconds * 1e-9
        f = self.force(t)
        self.pub.publish(self.batch(f))
        if t - self.last_print >= 0.1:
            self.last_print = t
            if self.modal is not None and self.modal.q_ale:
                peak_q = max(abs(q) for q in self.modal.q_ale)
                lag_ms = (now.nanoseconds - (self.modal.input_stamp.sec * 10**9 + self.modal.input_stamp.nanosec)) * 1e-6
                print(f"t={t:5.2f} s  pad force {f:7.1f} N  max|q_ale| {peak_q * 1e6:9.3f} um  "
                      f"speed {self.speed:7.3f} rad/s  step {self.modal.step}  command->state {lag_ms:6.2f} ms",
                      flush=True)
            else:
                print(f"t={t:5.2f} s  pad force {f:7.1f} N  (no modal amplitudes yet)", flush=True)
        if t > self.ramp + self.hold + self.release + 0.5 and not self.done:
            self.pub.publish(self.batch(0.0))
            self.done = True
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
