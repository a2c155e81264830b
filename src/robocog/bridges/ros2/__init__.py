"""ROS 2 without a ROS installation: the ROS 2 wire types over Cyclone DDS
(the optional ``ros2`` extra)."""
