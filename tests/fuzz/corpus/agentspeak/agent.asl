// a small agent with annotations, rules, plans, if and while
at(home)[source(self), a, b].
count(3).
safe(X) :- not danger(X) & at(X).
!start.
+!start : count(N) & N > 0 <- .print("n=", N); -+count(N-1); !start.
+!start <- if (at(home)) { .print(home) } else { .print(away) }.
+danger(X)[source(A)] : at(X) <- .send(A, tell, moved); -at(X); +at(elsewhere).
-!start <- while (count(N) & N < 5) { -+count(N+1) }.
