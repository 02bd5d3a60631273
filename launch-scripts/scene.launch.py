"""Launch the annular_plate node on a scene (a ROS 2 parameter file).

    ros2 launch launch-scripts/scene.launch.py scene:=config/brake_bench.yaml
    ros2 launch launch-scripts/scene.launch.py scene:=config/brake_bench.yaml \
        publish_clock:=true frame_prefix:=left/ namespace:=/bench run_example:=true

`publish_clock:=true`: the node runs on its own simulated time and publishes
/clock (the example follows it). `use_sim_time:=true`: the node follows an
external /clock (Gazebo, `ros2 bag play --clock`) and steps with it.

The node is the Rust program `annular_plate` (docs/ros.md): found as
$ANNULAR_PLATE_EXECUTABLE, else in this package's lib/ (colcon install),
else target/release/annular_plate of the source tree, else on PATH. The
other launch files of this folder include this one with a fixed scene.
"""

import os
import shutil

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterValue

HERE = os.path.dirname(os.path.abspath(__file__))


def node_executable():
    candidates = [
        os.environ.get("ANNULAR_PLATE_EXECUTABLE"),
        # colcon install: <prefix>/share/annular_plate/launch-scripts -> <prefix>/lib/annular_plate
        os.path.join(HERE, "..", "..", "..", "lib", "annular_plate", "annular_plate"),
        # source tree after `cargo build --release`
        os.path.join(HERE, "..", "target", "release", "annular_plate"),
        shutil.which("annular_plate"),
    ]
    for c in candidates:
        if c and os.path.isfile(c) and os.access(c, os.X_OK):
            return os.path.abspath(c)
    raise RuntimeError(
        "annular_plate executable not found: build it with `cargo build --release` "
        "or set ANNULAR_PLATE_EXECUTABLE"
    )


def example_script():
    for c in (os.path.join(HERE, "..", "..", "..", "lib", "annular_plate", "brake_load_example.py"),
              os.path.join(HERE, "brake_load_example.py")):
        if os.path.isfile(c):
            return os.path.abspath(c)
    raise RuntimeError("brake_load_example.py not found")


def default_scene():
    for c in (os.path.join(HERE, "..", "config", "brake_bench.yaml"),):
        if os.path.isfile(c):
            return os.path.abspath(c)
    return ""


def launch_setup(context, *args, **kwargs):
    scene = LaunchConfiguration("scene").perform(context)
    name = LaunchConfiguration("node_name").perform(context)
    namespace = LaunchConfiguration("namespace").perform(context)
    publish_clock = LaunchConfiguration("publish_clock").perform(context).lower() == "true"
    use_sim_time = LaunchConfiguration("use_sim_time").perform(context).lower() == "true"
    node = Node(
        executable=node_executable(),
        name=name,
        namespace=namespace,
        arguments=["run", os.path.abspath(scene)] if scene else ["run"],
        parameters=[{
            "use_sim_time": use_sim_time,
            "ros.publish_clock": publish_clock,
            "ros.frame_prefix": LaunchConfiguration("frame_prefix"),
            "ros.start_paused": ParameterValue(LaunchConfiguration("start_paused"), value_type=bool),
        }],
        ros_arguments=["--log-level", LaunchConfiguration("log_level")],
        output="screen",
        emulate_tty=True,
    )
    target = (namespace.rstrip("/") + "/" + name) if namespace else "/" + name
    if not target.startswith("/"):
        target = "/" + target
    example = Node(
        executable=example_script(),
        name="brake_load_example",
        # The example runs on the clock the node runs on.
        parameters=[{"target": target, "use_sim_time": publish_clock or use_sim_time}],
        output="screen",
        condition=IfCondition(LaunchConfiguration("run_example")),
    )
    return [node, example]


def generate_launch_description(scene=None):
    return LaunchDescription([
        DeclareLaunchArgument("scene", default_value=scene or default_scene(),
                              description="ROS 2 parameter file of the scene (config/*.yaml)"),
        DeclareLaunchArgument("node_name", default_value="annular_plate"),
        DeclareLaunchArgument("namespace", default_value=""),
        DeclareLaunchArgument("use_sim_time", default_value="false",
                              description="follow an external /clock and step with it (docs/ros.md, Time)"),
        DeclareLaunchArgument("publish_clock", default_value="false",
                              description="ros.publish_clock: the node's own simulated time, published on /clock"),
        DeclareLaunchArgument("frame_prefix", default_value="", description="ros.frame_prefix"),
        DeclareLaunchArgument("start_paused", default_value="false", description="ros.start_paused"),
        DeclareLaunchArgument("log_level", default_value="info"),
        DeclareLaunchArgument("run_example", default_value="false",
                              description="also run brake_load_example.py against the node"),
        OpaqueFunction(function=launch_setup),
    ])
