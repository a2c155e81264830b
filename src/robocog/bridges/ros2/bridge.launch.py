"""A ROS 2 launch file for machines that have ROS 2: robocog's bridge beside your robot.

The bridge is not an rclpy node (it speaks DDS itself, so that robocog needs no ROS
installation), so the launch file starts it as a process with the launch arguments
turned into its command line:

    LAUNCH=$(python -c "import robocog.bridges.ros2 as r; print(r.__path__[0])")/bridge.launch.py
    ros2 launch "$LAUNCH" mind:=bdi
    ros2 launch "$LAUNCH" mind:=nars robot:=garbage namespace:=robot1
    ros2 launch "$LAUNCH" mind:=nars config:=/path/to/my_robot.toml

It uses the robot's ROS_DOMAIN_ID and the Cyclone DDS settings of the environment, so
the bridge joins the same graph as the robot's nodes. This file is read only by
``ros2 launch``; robocog itself never imports it.
"""

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, ExecuteProcess, OpaqueFunction
from launch.substitutions import LaunchConfiguration

ARGUMENTS = {
    "mind": ("nars", "nars, bdi, or module:factory for a mind of your own"),
    "robot": ("garbage", "a robot configuration shipped with robocog (ignored with config)"),
    "config": ("", "a TOML file with your robot's topics, places, speeds and limits"),
    "knowledge": ("", "a Narsese file for a NARS mind, or an AgentSpeak file for a BDI mind"),
    "namespace": ("", "prefix of every topic and action, for several robots on one domain"),
    "watchdog": ("1.0", "seconds without percepts before the robot is stopped"),
    "record": ("", "an MCAP file to record every message into"),
}


def _bridge(context: object) -> list[ExecuteProcess]:
    def value(name: str) -> str:
        return LaunchConfiguration(name).perform(context)

    cmd = ["robocog", "bridge", "ros2", "--mind", value("mind"), "--watchdog", value("watchdog")]
    if value("config"):
        cmd += ["--config", value("config")]
    else:
        cmd += ["--robot", value("robot")]
    if value("knowledge"):
        flag = "--knowledge" if value("mind") == "nars" else "--program"
        cmd += [flag, value("knowledge")]
    if value("namespace"):
        cmd += ["--namespace", value("namespace")]
    if value("record"):
        cmd += ["--record", value("record")]
    return [ExecuteProcess(cmd=cmd, output="screen", name="robocog_bridge")]


def generate_launch_description() -> LaunchDescription:
    """The launch description ``ros2 launch`` asks for."""
    declared = [
        DeclareLaunchArgument(name, default_value=default, description=text)
        for name, (default, text) in ARGUMENTS.items()
    ]
    return LaunchDescription([*declared, OpaqueFunction(function=_bridge)])
