// The background knowledge of Hammer et al., Section V.C.1,, translated to AgentSpeak as the
// paper's BDI baseline (Section V.D). Percepts arrive as beliefs with source(percept):
//   see(Label)  position(Label, left|center|right)  obstacle(left|front|right|free)
//   at(Place)   gripper(hold|open)
// Environment actions: goto(next), pick(Label), drop, forward, left, right.

// bottles and cups are both trash
trash(bottle).
trash(cup).

!collect.

// If the gripper is holding an object, drop it to the trailer
+!collect : gripper(hold) <- drop; !collect.

// If gripper is open and trash is seen, pick it up to hold it
+!collect : gripper(open) & see(X) & trash(X) <- pick(X); !collect.

// Go to next checkpoint to arrive there
+!collect : gripper(open) <- goto(next); !collect.

// Nothing sensed yet: wait for the next perception
+!collect <- !collect.

// An action that failed (a missed grasp, say) ends the plan; carry on collecting
-!collect <- !collect.
