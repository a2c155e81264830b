// Wants beer, drinks it sip by sip, and now and then asks the robot the time.
!get(beer).
!check_bored.

+!get(beer) <- .send(robot, achieve, has(owner, beer)).

+has(owner, beer) <- !drink(beer).
-has(owner, beer) <- !get(beer).

+!drink(beer) : has(owner, beer) <- sip(beer); !drink(beer).
+!drink(beer) : not has(owner, beer).

+!check_bored
   <- .random(R); .wait(R * 5000 + 2000);
      .send(robot, askOne, time(_), Answer);
      .print(Answer);
      !check_bored.

+msg(M)[source(A)] <- .print("Message from ", A, ": ", M); -msg(M).
