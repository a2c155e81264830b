// The program of docs/bdi.md's Python example: a robot that backs off from an
// obstacle in front, and goes to a place when asked.
+obstacle(front) <- beep; forward(-0.5).

+!go(Place) : at(Place) <- .print("already at ", Place).
+!go(Place) <- forward(1.0); .print("heading for ", Place).
