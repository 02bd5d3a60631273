"""Launch the annular_plate node on config/design_example.yaml (see scene.launch.py for the arguments).

    ros2 launch launch-scripts/design_example.launch.py [publish_clock:=true | use_sim_time:=true] [run_example:=true]
"""

import importlib.util
import os

HERE = os.path.dirname(os.path.abspath(__file__))


def generate_launch_description():
    spec = importlib.util.spec_from_file_location("annular_plate_scene_launch", os.path.join(HERE, "scene.launch.py"))
    scene_launch = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(scene_launch)
    return scene_launch.generate_launch_description(os.path.abspath(os.path.join(HERE, "..", "config", "design_example.yaml")))
