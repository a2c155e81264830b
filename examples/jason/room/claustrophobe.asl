// A locked door is unbearable: ask the porter to open it.
+locked(door) <- .send(porter, achieve, ~locked(door)).
