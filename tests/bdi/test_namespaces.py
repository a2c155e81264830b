"""Jason's modules and namespaces: ``::b``, ``this_ns``, ``Ns::b`` with a variable
namespace, local namespaces, ``.include`` at run time, ``+{ plan }``.

Each program here was run on Jason 3.3 and on robocog; the expected lines are Jason's.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from robocog.bdi import Agent, ParseError
from robocog.bdi.nsterm import NsLiteral, split_ns, with_ns
from robocog.bdi.parser import parse_program, read_source
from robocog.bdi.terms import Literal, Var

MODULE = """\
{namespace(priv,local)}
count(0).
priv::secret(1).
+!start(X) <- .print("start ", X, " in ", this_ns); ?priv::secret(S); .print(S); +::got(X); !priv::inner(this_ns).
{begin namespace(priv)}
+!inner(N) <- .print("inner ", N); .print(this_ns); .print(::k(1), " ", k(2), " ", default::k(3)).
{end}
+got(X) <- .print("got ", X, " ", ::j, " ", j).
"""  # noqa: E501 - the program as it was run on Jason

MAIN = """\
{include("mod.asl", a)}
!a::start(1).
!go.
+!go <- .include("mod.asl", b); !b::start(2); N = c; .include("mod.asl", N); !N::start(3);
   +N::val(5); +b::val(6); ?N::val(V); .print(V); .findall(f(M,X), M::val(X), L); .print(L);
   .send(self, tell, N::msg(hi)); .print(N::foo(1), " ", ::bar, " ", this_ns);
   .wait(200); .print(done).
+M::msg(X)[source(S)] <- .print("msg ", M, " ", X, " ", S).
+!M::start(X) : M == zz <- .print(never).
"""

#: what Jason 3.3 printed for MAIN
JASON = """\
start 1 in a
1
start 2 in b
got 1 a::j j
1
inner a
priv
got 2 b::j j
#1priv::k(1) k(2) k(3)
inner b
priv
#2priv::k(1) k(2) k(3)
start 3 in c
1
got 3 c::j j
inner c
priv
#3priv::k(1) k(2) k(3)
5
[f(b,6),f(c,5)]
c::foo(1) bar default
msg c hi self
done"""


def run(tmp_path: Path, files: dict[str, str], main: str = "main.asl") -> list[str]:
    for name, text in files.items():
        (tmp_path / name).write_text(text, encoding="utf-8")
    out: list[str] = []
    path = tmp_path / main
    Agent(read_source(path), "main", file=str(path), printer=lambda n, t: out.append(t)).run()
    return out


def test_modules_in_namespaces_print_what_jason_prints(tmp_path: Path) -> None:
    got = run(tmp_path, {"mod.asl": MODULE, "main.asl": MAIN})
    # the local namespaces' numbers are a counter of the reader (Jason's too)
    got = [ln.replace(ln[ln.find("#") : ln.find("priv")], "#N") if "#" in ln else ln for ln in got]
    want = [
        ln.replace(ln[ln.find("#") : ln.find("priv")], "#N") if "#" in ln else ln
        for ln in JASON.split("\n")
    ]
    assert got == want


def test_a_label_is_in_the_namespace_of_its_file(tmp_path: Path) -> None:
    files = {
        "lab.asl": '@p1 +!hi <- .print("hi from ", this_ns).\n',
        "main.asl": '{include("lab.asl", x)}\n{include("lab.asl", y)}\n!go.\n'
        '+!go <- !x::hi; !y::hi; .include("lab.asl", V); .print(V); !V::hi; '
        ".plan_label(P, x::p1); .print(P).\n",
    }
    got = run(tmp_path, files)
    assert got[:4] == ["hi from x", "hi from y", got[2], f"hi from {got[2]}"]
    assert got[2].startswith("ns")  # a new namespace for a free variable, as Jason's ns1
    assert got[4].startswith("{ @x::p1[source(self),url(") and "+!x::hi <-" in got[4]


def test_a_plan_added_as_a_term_takes_its_variables_values(tmp_path: Path) -> None:
    prog = (
        '!g.\n+!g <- T = tv; +{+T::winner(W) <- .print("Winner to fix ",T," is ",W)}; '
        "+tv::winner(bob); X = 5; +{+b(Y) : Y > X <- .print(big, Y)}; "
        "+>{+b(Y) <- .print(small, Y)}; +b(7); +b(2).\n"
    )
    assert run(tmp_path, {"main.asl": prog}) == ["Winner to fix tv is bob", "big7", "small2"]


def test_a_variable_namespace_unifies_with_any_namespace() -> None:
    n = Var("N")
    lit = NsLiteral(n, Literal("b", (1,)))
    assert str(lit) == "N::b(1)"
    assert split_ns(Literal("hall::b")) == ("hall", Literal("b"))
    assert split_ns(Literal("b")) == ("default", Literal("b"))
    assert with_ns("default", Literal("b")) == Literal("b")
    ag = Agent("hall::b(1).\nb(2).\n", "t")
    assert sorted(str(a["N"]) for a in ag.query("N::b(_)")) == ["default", "hall"]
    assert [str(a["X"]) for a in ag.query("N = hall & N::b(X)")] == ["1"]


def test_an_include_reads_its_file_into_the_namespace_it_stands_in(tmp_path: Path) -> None:
    (tmp_path / "inner.asl").write_text("k(1).\n")
    (tmp_path / "outer.asl").write_text('{ include("inner.asl") }\n')
    prog = parse_program('{ include("outer.asl", m) }\n', str(tmp_path / "main.asl"))
    assert [str(b) for b in prog.beliefs] == ["m::k(1)"]


@pytest.mark.parametrize("text", ["{ begin namespace(a) }\n{ begin namespace(b) }\n", "{ end }\n"])
def test_a_namespace_block_out_of_place_is_an_error(text: str) -> None:
    with pytest.raises(ParseError):
        parse_program(text)
