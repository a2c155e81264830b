"""The embedded worlds served as robots over middleware: ``robocog sim garbage --ros2``.

``ros2`` (a world behind the standard interfaces of a ROS 2 mobile manipulator, on
Cyclone DDS), ``cli`` (``robocog sim``). Imports worlds and the bridges' wire types,
never an engine or a mind.
"""
