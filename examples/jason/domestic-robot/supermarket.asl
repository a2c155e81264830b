// Delivers what it is asked for, numbering its orders.
last_order_id(1).

+!order(Product, Qtd)[source(A)]
   <- ?last_order_id(N);
      Id = N + 1;
      -+last_order_id(Id);
      deliver(Product, Qtd);
      .send(A, tell, delivered(Product, Qtd, Id)).
