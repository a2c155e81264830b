"""Real middleware behind the Body protocol: ROS 2 over Cyclone DDS and ROS 1
over rospy. Know no engine.

``config`` (topics, places, limits), ``perception`` (readings to percepts), ``body``
(``RobotBody``: a Body over a middleware ``Link``), ``runner`` (the cycle and its
watchdog), ``ros2`` (the ROS 2 wire types and link, a stand-in robot, loopback-only
DDS), ``ros1`` (the rospy node run by the system Python, its link, a stand-in robot),
``cli`` (``robocog bridge``).
"""
