// An unlocked door is unbearable: ask the porter to lock it.
+~locked(door) <- .send(porter, achieve, locked(door)).
