// docs/bdi.md, several agents: the worker greets whoever asked.
+!greet[source(Boss)] <- .print("hello, ", Boss).
