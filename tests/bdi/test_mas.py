"""Several agents in one run: tell, untell, achieve, askOne, askAll, broadcast."""

from __future__ import annotations

from robocog.bdi import MultiAgentSystem


def _mas(**sources: str) -> tuple[MultiAgentSystem, list[str]]:
    out: list[str] = []
    mas = MultiAgentSystem()
    for name, src in sources.items():
        mas.create(name, src, printer=lambda n, t: out.append(f"{n}: {t}"))
    return mas, out


def test_tell_and_untell_change_the_receivers_beliefs_with_the_sender_as_source() -> None:
    mas, out = _mas(
        bob="!s.\n+!s <- .send(alice, tell, hot(30)); .wait(10); .send(alice, untell, hot(30)).",
        alice='+hot(T)[source(S)] <- .print(S, " says ", T).\n-hot(T)[source(S)] <- .print(S, " retracts").',
    )
    mas.run()
    assert out == ["alice: bob says 30", "alice: bob retracts"]
    assert mas.agents["alice"].beliefs() == []


def test_achieve_starts_a_goal_in_the_receiver() -> None:
    mas, out = _mas(
        boss="!s.\n+!s <- .send(worker, achieve, clean(room1)).",
        worker='+!clean(R)[source(A)] <- .print("cleaning ", R, " for ", A).',
    )
    mas.run()
    assert out == ["worker: cleaning room1 for boss"]


def test_ask_one_waits_for_the_answer() -> None:
    mas, out = _mas(
        asker="!s.\n+!s <- .send(oracle, askOne, value(X), A); .print(A); "
        ".send(oracle, askOne, missing(Y), B); .print(B).",
        oracle="value(42).",
    )
    mas.run()
    assert out == ["asker: value(42)[source(oracle)]", "asker: false"]


def test_ask_all_and_broadcast() -> None:
    mas, out = _mas(
        a="!s.\n+!s <- .send(b, askAll, n(X), L); .print(L); .broadcast(tell, done).",
        b="n(1). n(2).\n+done[source(S)] <- .print(done_from, S).",
        c="+done[source(S)] <- .print(done_from, S).",
    )
    mas.run()
    assert out[0] == "a: [n(1)[source(b)],n(2)[source(b)]]"
    assert sorted(out[1:]) == ["b: done_froma", "c: done_froma"]


def test_my_name_and_all_names() -> None:
    mas, out = _mas(x="!s.\n+!s <- .my_name(N); .all_names(L); .print(N, L).", y="")
    mas.run()
    assert out == ["x: x[x,y]"]


def test_ask_all_answers_carry_the_beliefs_sources_nested_under_the_answerer() -> None:
    # as Jason 3.3 prints it: b believes p(1) told by c; a asks b
    mas, out = _mas(
        c="!s.\n+!s <- .send(b, tell, p(1)).",
        b="p(2)[x].",
        a="!s.\n+!s <- .wait(50); .send(b, askAll, p(X), L); .print(L).",
    )
    mas.run()
    assert out == ["a: [p(1)[source(b)[source(c)]],p(2)[source(b),x]]"]


def test_a_sleeping_agent_wakes_for_a_message_and_for_news_from_outside() -> None:
    mas, out = _mas(
        a="+!ping[source(S)] <- .print(ping, S).\n+hot <- .print(hot).",
        b="!s.\n+!s <- .wait(20); .send(a, achieve, ping).",
    )
    mas.run()
    assert out == ["a: pingb"]
    mas.agents["a"].add_belief("hot")  # the system idles; news from outside wakes it
    mas.run()
    assert out[-1] == "a: hot"


def test_run_takes_as_many_rounds_as_stepping_until_idle() -> None:
    """run() skips asking every agent whether it is idle while one is known to have
    work: the rounds and what is printed must be those of the plain loop."""
    sources = {
        "a": "+!t(K) : K <= 0 <- .print(end).\n+!t(K) <- .send(c, achieve, t(K - 1)).",
        "b": "!s.\n+!s <- .send(a, achieve, t(5)); .print(b1); .print(b2).",
        "c": "+!t(K) <- .print(c, K); .send(a, achieve, t(K - 1)).",
    }
    mas, out = _mas(**sources)
    rounds = mas.run()
    ref, ref_out = _mas(**sources)
    n = 0
    while not ref.is_idle():
        ref.step()
        n += 1
    assert out == ref_out and rounds == n
    assert out[-1] == "a: end" and "c: c4" in out
