"""Test doubles that tests and users share: stand-in robots for the bridges.

``ros2_standin`` (a ROS 2 robot on Cyclone DDS that publishes a scripted scene and
records what it is told; ``python -m robocog.testing.ros2_standin``) and
``ros1_standin`` (the same for ROS 1, a script for the system Python that has rospy).
They let a mind be tried on the bridge before a robot is at hand.
"""
