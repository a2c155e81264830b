"""Real middleware behind the Body protocol: ROS 2 over Cyclone DDS and ROS 1
over rospy. Know no engine.
"""
