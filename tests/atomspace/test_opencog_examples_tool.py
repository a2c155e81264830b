"""tools/opencog_examples.py: how it reads and compares results, and its robocog side."""

from __future__ import annotations

import importlib.util
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def _tool():  # noqa: ANN202 - the module
    spec = importlib.util.spec_from_file_location(
        "opencog_examples", ROOT / "tools" / "opencog_examples.py"
    )
    mod = importlib.util.module_from_spec(spec)
    assert spec.loader is not None
    spec.loader.exec_module(mod)
    return mod


def test_results_compare_as_opencog_prints_them() -> None:
    t = _tool()
    a = '(SetLink\n  (ConceptNode "b")\n  (ConceptNode "a"))\n'
    b = '(SetLink (ConceptNode "a") (ConceptNode "b"))'
    assert t.canon_result(a) == t.canon_result(b)
    assert t.canon_result('(NumberNode "2.000000")') == t.canon_result('(NumberNode "2")')
    assert t.canon_result("(stv 0.5 1)") == t.canon_result("(stv 0.500000 1.000000)")
    assert t.canon_result('(ListLink (ConceptNode "b") (ConceptNode "a"))') != t.canon_result(
        '(ListLink (ConceptNode "a") (ConceptNode "b"))'
    )
    # a Scheme list of atoms (an incoming set) has no order in OpenCog
    assert t.canon_result('((ConceptNode "b") (ConceptNode "a"))') == t.canon_result(
        '((ConceptNode "a")\n (ConceptNode "b")\n)'
    )
    assert t.canon_result("(@@error unbound-variable)") == "error"


def test_the_robocog_side_records_each_form(tmp_path: Path) -> None:
    t = _tool()
    ex = tmp_path / "examples" / "atomspace"
    ex.mkdir(parents=True)
    f = ex / "tiny.scm"
    f.write_text(
        "(use-modules (opencog) (opencog exec))\n"
        '(Inheritance (Concept "a") (Concept "b"))\n'
        '(cog-execute! (Get (Inheritance (Variable "$x") (Concept "b"))))\n'
        "(car '())\n"
    )
    blocks, err = t.run_robocog(f)
    assert blocks[1].strip() == "@@unspecified"
    assert t.canon_result(blocks[3]) == '(SetLink (ConceptNode "a"))'
    assert t.canon_result(blocks[4]) == "error" and "wrong-type-arg" in err
    assert "Traceback" not in err
    assert t.main(["--atomspace", str(tmp_path)]) == 0
