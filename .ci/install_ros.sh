#!/usr/bin/env bash
# Debian's ROS 1 packages for the ROS 1 bridge tests: rospy, the master (the tests start
# `rosmaster --core`, which is what roscore runs, so roslaunch and its C++ rosout logger
# with Boost and ICU are not needed), actionlib, and the message packages the bridge and
# its stand-in robot use. Not python3-nav-msgs, which brings the C++ message headers and
# Boost's: the bridge makes nav_msgs/Odometry from its definition when it is missing.
# They are installed for /usr/bin/python3 only; robocog reaches them through a child
# process. Only what is missing is installed, and nothing upgraded
# (see apt_install.sh).
set -euo pipefail

exec bash "$(dirname "$0")/apt_install.sh" \
    python3-rospy \
    python3-rosmaster \
    python3-actionlib \
    python3-actionlib-msgs \
    python3-std-msgs \
    python3-geometry-msgs \
    python3-sensor-msgs \
    python3-move-base-msgs
