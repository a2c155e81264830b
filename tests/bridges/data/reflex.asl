// Drive a robot through the bridge: turn away from obstacles, pick a bottle that is
// seen. Percepts: obstacle(left|front|right|free), see(Label), gripper(hold|open).
!drive.
+!drive : obstacle(left) <- right; !drive.
+!drive : obstacle(right) <- left; !drive.
+!drive : gripper(open) & see(bottle) <- pick(bottle); !drive.
+!drive <- !drive.
-!drive <- !drive.
