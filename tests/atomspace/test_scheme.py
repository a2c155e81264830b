"""The Scheme under Atomese: the language, OpenCog's cog- API, errors and the REPL."""

from __future__ import annotations

import io
import os
import pty
import select
import subprocess
import sys
import time
from pathlib import Path

import pytest

from robocog.atomspace import AtomeseError, AtomSpace, Link, Node, stv
from robocog.atomspace.cogscm import make_scheme, run_text
from robocog.atomspace.scheme import SchemeError, to_text

SRC = Path(__file__).resolve().parents[2] / "src"


def ev(text: str, space: AtomSpace | None = None) -> str:
    """The written form of the last value of ``text``."""
    return to_text(make_scheme(space, out=io.StringIO()).eval_text(text))


def test_core_forms() -> None:
    assert ev("(define (sq x) (* x x)) (map sq (list 1 2 3))") == "(1 4 9)"
    assert ev("(let* ((a 1) (b (+ a 1))) (list a b))") == "(1 2)"
    assert (
        ev(
            "(letrec ((ev? (lambda (n) (if (= n 0) #t (od? (- n 1))))) "
            "(od? (lambda (n) (if (= n 0) #f (ev? (- n 1)))))) (ev? 10))"
        )
        == "#t"
    )
    assert ev("(define x 1) (set! x (+ x 41)) x") == "42"
    assert ev("(cond ((> 1 2) 'a) ((assv 2 '((1 . one) (2 . two))) => cdr) (else 'c))") == "two"
    assert ev("(case (* 2 3) ((2 3 5 7) 'prime) ((1 4 6 8 9) 'composite))") == "composite"
    assert ev("(when #f 1) (unless #f 'yes)") == "yes"
    assert ev("`(1 ,(+ 1 1) ,@(list 3 4))") == "(1 2 3 4)"
    assert ev("(fold + 0 (filter odd? (iota 10)))") == "25"
    assert ev('(string-append "a" (number->string 12) (symbol->string \'b))') == '"a12b"'
    assert ev('(format #f "~a and ~s~%" "x" "y")') == '"x and \\"y\\"\\n"'
    assert ev("(catch 'oops (lambda () (throw 'oops 1 2)) (lambda (k . args) (cons k args)))") == (
        "(oops 1 2)"
    )
    assert ev("(catch #t (lambda () (car '())) (lambda (k . rest) k))") == "wrong-type-arg"
    assert ev("(define (f . args) (length args)) (f 1 2 3)") == "3"
    assert ev("(use-modules (ice-9 format) (srfi srfi-1)) (delete-duplicates '(1 2 1))") == "(1 2)"
    assert ev("(/ 1 3)") == "1/3" and ev("(exact->inexact 1/4)") == "0.25"


def test_named_let_loops_run_in_constant_stack() -> None:
    assert ev("(let loop ((i 0) (acc 0)) (if (< i 20000) (loop (+ i 1) (+ acc i)) acc))") == (
        str(sum(range(20000)))
    )
    # a procedure calling itself in tail position through cond and begin, too
    text = "(define (count n) (cond ((= n 0) 'done) (else (begin (count (- n 1))))))"
    assert ev(text + " (count 15000)") == "done"


def test_errors_name_the_place_and_the_name() -> None:
    s = make_scheme(out=io.StringIO())
    with pytest.raises(SchemeError) as info:
        s.eval_text("(define (f x)\n  (+ x (g x)))\n(f 1)", source="prog.scm")
    e = info.value
    assert (e.key, e.source, e.line, e.column) == ("unbound-variable", "prog.scm", 2, 8)
    assert "g" in e.message and str(e).startswith("prog.scm:2:8: unbound-variable")
    with pytest.raises(SchemeError) as info:
        s.eval_text('\n(+ 1 "a")', source="t.scm")
    assert (info.value.key, info.value.line) == ("wrong-type-arg", 2)
    with pytest.raises(SchemeError) as info:
        s.eval_text("(5 1)")
    assert "Wrong type to apply" in info.value.message
    with pytest.raises(SchemeError) as info:  # non-tail recursion past the limit
        s.eval_text("(define (deep n) (+ 1 (deep (+ n 1)))) (deep 0)")
    assert info.value.key == "stack-overflow"
    with pytest.raises(SchemeError) as info:
        s.eval_text("(use-modules (no such))")
    assert "no code for module" in info.value.message
    # the documented error type, for every reader entry point
    assert issubclass(SchemeError, AtomeseError)
    with pytest.raises(AtomeseError):
        run_text("(let loop () (loop))", max_steps=10_000)
    with pytest.raises(AtomeseError, match="nesting deeper"):
        run_text("(" * 5000)
    with pytest.raises(AtomeseError, match="unterminated block comment"):
        run_text("#| (display 1)\n" * 20000)  # refused at once, not backtracked over
    assert run_text("#| a\n b |# (display 1) #!x\n!# (display 2)") == "12"


def test_constructors_and_the_cog_api() -> None:
    space = AtomSpace()
    out = ev(
        """
        (define a (Concept "a" (stv 0.9 0.8)))
        (define l (Inheritance a (Concept "b")))
        (cog-set-tv! (Concept "b") (stv 0.5 0.25))
        (list (cog-name a) (cog-type l) (cog-mean a) (cog-confidence (Concept "b"))
              (length (cog-incoming-set a)) (cog-outgoing-set l)
              (cog-node 'ConceptNode "a") (cog-node 'ConceptNode "zz"))
        """,
        space,
    )
    assert out == (
        '("a" InheritanceLink 0.9 0.25 1 ((ConceptNode "a") (ConceptNode "b")) '
        '(ConceptNode "a") ())'
    )
    a = Node("ConceptNode", "a")
    assert space.get_tv(a) == stv(0.9, 0.8)
    assert Link("InheritanceLink", a, Node("ConceptNode", "b")) in space
    # values
    assert (
        ev(
            '(define k (Predicate "k")) (cog-set-value! (Concept "x") k (FloatValue 1 2 3))'
            '(list (cog-value (Concept "x") k) (cog-value->list (cog-value (Concept "x") k)))'
        )
        == "((FloatValue 1 2 3) (1.0 2.0 3.0))"
    )
    # several atomspaces
    assert (
        ev(
            "(define base (cog-atomspace)) (define kid (cog-new-atomspace base))"
            '(cog-set-atomspace! kid) (Concept "only-in-kid") (cog-set-atomspace! base)'
            '(cog-node \'ConceptNode "only-in-kid")'
        )
        == "()"
    )


def test_queries_evaluation_and_grounded_scheme() -> None:
    space = AtomSpace()
    s = make_scheme(space, out=io.StringIO())
    s.eval_text(
        """
        (Evaluation (Predicate "on") (List (Concept "B") (Concept "C")))
        (Evaluation (Predicate "on") (List (Concept "A") (Concept "B")))
        (define calls 0)
        (define (heavy? x) (set! calls (+ calls 1))
          (if (equal? (cog-name x) "A") (stv 1 1) (stv 0 1)))
        """
    )
    got = s.eval_text(
        '(cog-execute! (Get (And (Evaluation (Predicate "on") (List (Variable "$x") (Variable "$y")))'
        '  (Evaluation (GroundedPredicate "scm: heavy?") (List (Variable "$x"))))))'
    )
    assert to_text(got) == '(SetLink (ListLink (ConceptNode "A") (ConceptNode "B")))'
    assert s.lookup("calls") == 2  # once per candidate, never on the pattern itself
    assert (
        to_text(
            s.eval_text(
                '(cog-evaluate! (Evaluation (GroundedPredicate "scm: heavy?") '
                '(List (Concept "A"))))'
            )
        )
        == "(stv 1 1)"
    )
    assert to_text(s.eval_text('(cog-evaluate! (Equal (Concept "q") (Concept "q")))')) == (
        "(stv 1 1)"
    )


def test_put_over_delete_gives_false_and_deletes() -> None:
    space = AtomSpace()
    s = make_scheme(space, out=io.StringIO())
    s.eval_text('(Evaluation (Predicate "p") (Concept "a"))')
    v = s.eval_text(
        '(cog-execute! (Put (Delete (Evaluation (Predicate "p") (Variable "$x"))) (Concept "a")))'
    )
    assert v is False  # OpenCog 2021 answers #f
    assert Link("EvaluationLink", Node("PredicateNode", "p"), Node("ConceptNode", "a")) not in space


def test_get_over_or_of_branches_with_different_variables() -> None:
    # OpenCog 2021's answers (checked on the real AtomSpace): every variable must be
    # ground, the present clauses in any branch are sought, the absent ones refused
    s = make_scheme(out=io.StringIO())
    s.eval_text(
        '(Evaluation (Predicate "p") (Concept "a")) (Evaluation (Predicate "q") (Concept "b"))'
    )
    p = '(Present (Evaluation (Predicate "p") (Variable "$x")))'
    q = '(Present (Evaluation (Predicate "q") (Variable "$y")))'
    assert to_text(s.eval_text(f"(cog-execute! (Get (Or {p} {q})))")) == (
        '(SetLink (ListLink (ConceptNode "a") (ConceptNode "b")))'
    )
    absent_q = '(Absent (Evaluation (Predicate "q") (Variable "$y")))'
    assert to_text(s.eval_text(f"(cog-execute! (Get (Or {p} {absent_q})))")) == "(SetLink)"
    assert to_text(s.eval_text(f"(cog-execute! (Get (Or (And {p} (Not {q})) {q})))")) == "(SetLink)"


def test_arithmetic_and_value_flows() -> None:
    assert ev("(cog-execute! (Plus (Number 2) (Times (Number 3) (Number 4))))") == (
        '(NumberNode "14")'
    )
    assert (
        ev(
            '(Concept "foo" (stv 0.3 0.7)) (cog-execute! (SetTV (Concept "bar") '
            '(TruthValueOf (Concept "foo")))) (cog-tv (Concept "bar"))'
        )
        == "(stv 0.3 0.7)"
    )
    assert (
        ev(
            '(define k (Predicate "k")) (cog-set-value! (Concept "f") k (FloatValue 1 2 3))'
            '(DefineLink (DefinedSchema "tri") (Lambda (Variable "$X") (Divide (Times (Variable "$X")'
            ' (Plus (Variable "$X") (Number 1))) (Number 2))))'
            '(cog-execute! (SetValue (Concept "g") k (DefinedSchema "tri") (ValueOf (Concept "f") k)))'
        )
        == "(FloatValue 1 3 6)"
    )
    assert ev("(cog-evaluate! (PredicateFormula (Number 0.25) (Number 0.5)))") == "(stv 0.25 0.5)"


def test_modules_bind_opencog_names_as_guile_does() -> None:
    s = make_scheme(out=io.StringIO(), preload=False)
    with pytest.raises(SchemeError, match="Concept"):
        s.eval_text('(Concept "a")')
    s.eval_text("(use-modules (opencog))")
    s.eval_text('(Concept "a")')
    with pytest.raises(SchemeError, match="cog-execute!"):
        s.eval_text('(cog-execute! (Get (Variable "$x")))')
    s.eval_text("(use-modules (opencog exec))")
    s.eval_text('(cog-execute! (Get (Variable "$x")))')


def test_the_command_runs_scheme_and_reports_errors_without_traceback(tmp_path: Path) -> None:
    prog = tmp_path / "p.scm"
    prog.write_text(
        "(use-modules (opencog) (opencog exec))\n"
        '(define (mk name) (Evaluation (Predicate "p") (Concept name)))\n'
        '(for-each mk (list "a" "b"))\n'
        '(cog-execute! (Get (Evaluation (Predicate "p") (Variable "$x"))))\n'
        '(cog-execute! (Put (Delete (Evaluation (Predicate "p") (Variable "$x"))) (Concept "a")))\n'
        "(undefined-thing 1)\n"
    )
    env = {**os.environ, "PYTHONPATH": str(SRC)}
    proc = subprocess.run(
        [sys.executable, "-m", "robocog", "atomese", str(prog)],
        capture_output=True,
        text=True,
        env=env,
        timeout=60,
    )
    assert proc.returncode == 1
    assert '(ConceptNode "a")' in proc.stdout and '(ConceptNode "b")' in proc.stdout
    assert "#f" in proc.stdout
    assert f"{prog}:6:1: unbound-variable: Unbound variable: undefined-thing" in proc.stderr
    assert "Traceback" not in proc.stderr


def _read_until(fd: int, marker: bytes, timeout: float = 30.0) -> bytes:
    buf = b""
    end = time.monotonic() + timeout
    while marker not in buf:
        left = end - time.monotonic()
        if left <= 0:
            raise AssertionError(f"no {marker!r} in {buf[-500:]!r}")
        ready, _, _ = select.select([fd], [], [], left)
        if ready:
            try:
                chunk = os.read(fd, 4096)
            except OSError:
                break
            if not chunk:
                break
            buf += chunk
    return buf


def test_repl_session_through_a_terminal() -> None:
    env = {**os.environ, "PYTHONPATH": str(SRC), "TERM": "dumb"}
    master, slave = pty.openpty()
    proc = subprocess.Popen(
        [sys.executable, "-m", "robocog", "atomese"],
        stdin=slave,
        stdout=slave,
        stderr=slave,
        env=env,
        close_fds=True,
    )
    os.close(slave)
    prompt = b"scheme@(guile-user)> "
    try:
        _read_until(master, prompt)
        for line in (
            "(define (on a b)",
            '  (Evaluation (Predicate "on") (List (Concept a) (Concept b))))',
        ):
            os.write(master, line.encode() + b"\n")
        _read_until(master, prompt)
        os.write(master, b'(on "B" "C")\n')
        out = _read_until(master, prompt)
        assert b"$1 =" in out and b"EvaluationLink" in out
        os.write(master, b'(cog-set-tv! (on "A" "B") (stv 0.7 0.9))\n')
        _read_until(master, prompt)
        os.write(
            master,
            b'(cog-execute! (Get (Evaluation (Predicate "on") '
            b'(List (Variable "$x") (Concept "B")))))\n',
        )
        out = _read_until(master, prompt)
        assert b'(ConceptNode "A")' in out and b"SetLink" in out
        os.write(master, b'(cog-tv (on "A" "B"))\n')
        out = _read_until(master, prompt)
        assert b"(stv 0.7 0.9)" in out
        os.write(master, b"(car '())\n")
        out = _read_until(master, prompt)
        assert b"wrong-type-arg" in out and b"Traceback" not in out
        os.write(master, b"\x04")  # Ctrl-D ends the session
        assert proc.wait(timeout=30) == 0
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
        os.close(master)


def test_shared_parts_cannot_blow_up_an_atom() -> None:
    # each level holds the previous one twice: 2^n atoms once unfolded; atoms are hashed
    # by content, so this is refused early, with a clear error, instead of hanging
    tree = "(define (tree a n) (if (> n 0) (tree (List a a) (- n 1)) a))"
    assert ev(tree + ' (cog-arity (tree (Concept "nil") 12))') == "2"
    with pytest.raises(SchemeError, match="unfolded"):
        run_text(tree + ' (tree (Concept "nil") 250000)')
    text = '(define a0 (Concept "x"))' + "".join(
        f"(define a{i + 1} (List a{i} a{i}))" for i in range(40)
    )
    from robocog.atomspace import parse

    with pytest.raises(AtomeseError, match="unfolded"):
        parse(text)


def test_programs_export_and_load_atoms_but_untrusted_text_touches_no_file(
    tmp_path: Path,
) -> None:
    path = tmp_path / "x.scm"
    s = make_scheme(out=io.StringIO())
    s.eval_text(f'(List (Concept "cat") (Concept "dog")) (export-all-atoms "{path}") (clear)')
    assert s.eval_text('(cog-node \'ConceptNode "cat")') == []
    assert to_text(s.eval_text(f'(primitive-load "{path}")')) == (
        '(ListLink (ConceptNode "cat") (ConceptNode "dog"))'
    )
    with pytest.raises(SchemeError, match="files are not available"):
        run_text(f'(export-all-atoms "{tmp_path / "y.scm"}")')
    assert not (tmp_path / "y.scm").exists()


def test_map_dual_threads_and_missing_values() -> None:
    # MapLink: one argument gives its grounding; a set gives the set of them, typed
    assert (
        ev(
            '(cog-execute! (Map (Lambda (Variable "$x") (Evaluation (Predicate "k") (Variable "$x")))'
            ' (Evaluation (Predicate "k") (Concept "v"))))'
        )
        == '(ConceptNode "v")'
    )
    assert (
        ev(
            '(cog-execute! (Map (ImplicationScope (VariableList (TypedVariable (Variable "$x")'
            ' (Type "NumberNode")) (TypedVariable (Variable "$y") (Type "NumberNode")))'
            ' (List (Variable "$x") (Variable "$y")) (Plus (Variable "$x") (Variable "$y")))'
            ' (Set (List (Number 2) (Number 3)) (List (Concept "a") (Number 1))'
            " (List (Number 10) (Times (Number 3) (Number 2))))))"
        )
        == '(SetLink (NumberNode "16") (NumberNode "5"))'
    )
    # DualLink: the stored patterns a ground term matches
    assert (
        ev(
            '(Get (Inheritance (Variable "$x") (Concept "animal")))'
            '(cog-execute! (Dual (Inheritance (Concept "cat") (Concept "animal"))))'
        )
        == '(SetLink (InheritanceLink (VariableNode "$x") (ConceptNode "animal")))'
    )
    # ExecuteThreadedLink: each result in its own queue
    assert (
        ev(
            '(Inheritance (Concept "rock") (Concept "thing"))'
            '(cog-execute! (ExecuteThreaded (Set (Meet (Inheritance (Variable "$x") (Concept "thing"))))))'
        )
        == '(QueueValue (QueueValue (ConceptNode "rock")))'
    )
    # a comparison over a value that is not there is false, not an error
    assert (
        ev(
            '(define k (Predicate "k")) (cog-set-value! (Concept "a") k (FloatValue 42))'
            '(Concept "b")'
            '(cog-execute! (Bind (TypedVariable (Variable "$X") (Type "ConceptNode"))'
            ' (And (Present (Variable "$X")) (GreaterThan (Divide (ValueOf (Variable "$X") k)'
            ' (Number 12)) (Number 3))) (Variable "$X")))'
        )
        == '(SetLink (ConceptNode "a"))'
    )


def test_recursive_defined_schema_with_cond() -> None:
    # OpenCog's factorial.scm, run: OpenCog 2021 answers (NumberNode "120") and 9
    text = Path(__file__).with_name("data").joinpath("factorial.scm").read_text()
    assert ev(text + '(cog-execute! (ExecutionOutput (DefinedSchema "factorial") (Number 5)))') == (
        '(NumberNode "120")'
    )
    assert ev(
        "(cog-execute! (Cond (GreaterThan (Number 1) (Number 2)) (Number 7) (Number 9)))"
    ) == ('(NumberNode "9")')
