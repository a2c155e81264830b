"""ROS 1 through Debian's rospy: a rospy node run by the system Python (``node.py``),
spoken to over a pipe by ``Ros1Link``, and a stand-in robot with move_base."""
