// Turns the key when asked, by the one who wants it that way.
+!locked(door)[source(paranoid)] : ~locked(door) <- lock.
+!~locked(door)[source(claustrophobe)] : locked(door) <- unlock.
