// Brings beer while there is some and the day's limit is not reached.
available(beer, fridge).
limit(beer, 10).

too_much(B) :-
   .date(Y, M, D) & .count(consumed(Y, M, D, _, _, _, B), N) & limit(B, L) & N > L.

+!has(owner, beer) : available(beer, fridge) & not too_much(beer)
   <- !at(robot, fridge);
      open(fridge); get(beer); close(fridge);
      !at(robot, owner);
      hand_in(beer);
      ?has(owner, beer);
      .date(Y, M, D); .time(H, Mi, S);
      +consumed(Y, M, D, H, Mi, S, beer).
+!has(owner, beer) : not available(beer, fridge)
   <- .send(supermarket, achieve, order(beer, 5));
      !at(robot, fridge).
+!has(owner, beer) : too_much(beer) & limit(beer, L)
   <- .concat("The Department of Health does not allow me to give you more than ", L,
              " beers a day! I am very sorry about that!", M);
      .send(owner, tell, msg(M)).

-!has(_, _) <- .print("Failed to achieve goal '!has(_,_)'").

+!at(robot, P) : at(robot, P).
+!at(robot, P) : not at(robot, P) <- move_towards(P); !at(robot, P).

+delivered(beer, _, _)[source(supermarket)]
   <- +available(beer, fridge);
      !has(owner, beer).

+stock(beer, 0) : available(beer, fridge) <- -available(beer, fridge).
+stock(beer, N) : N > 0 & not available(beer, fridge) <- -+available(beer, fridge).

+?time(T) <- time.check(T).
