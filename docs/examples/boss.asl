// docs/bdi.md, several agents: the boss asks the worker to greet it.
!start.
+!start <- .send(worker, achieve, greet).
