#!/usr/bin/env python3
"""Run OpenCog's own AtomSpace examples on robocog (and on OpenCog) and compare.

    python tools/opencog_examples.py --atomspace CHECKOUT [--opencog PREFIX] [-k NAME] [-v]

CHECKOUT is an OpenCog AtomSpace source tree (the examples of June 2021, commit
3fc9758, are the reference); its ``examples/pattern-matcher/*.scm`` and
``examples/atomspace/*.scm`` are run one file at a time, each in a fresh process, form
by form: every top-level form is evaluated and what it returns is recorded (an error
is recorded as an error; output the program prints is not compared). With ``--opencog``
(the install prefix that ``build-opencog.sh`` prints, holding ``bin/opencog-guile``)
each file also runs on OpenCog's Guile, and the results of the forms are compared:
printed forms are read as s-expressions, numbers compared to six decimals, NumberNode
names as numbers, and the members of unordered links (SetLink, AndLink...) and of
QueueValue/LinkValue compared as sets. A form counts when OpenCog returns something
(not an unspecified value, not a definition); an example agrees when every counted form
gives OpenCog's result. The last line reads ``N of M examples agree``.
"""

from __future__ import annotations

import argparse
import json
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
SRC = HERE.parent / "src"
TIMEOUT = 300  # gperf.scm builds 10^6 atoms

_GUILE_DRIVER = r"""
(use-modules (ice-9 rdelim))
(define (robocog-run file)
  (define port (open-input-file file))
  (let loop ()
    (let* ((form (catch #t (lambda () (read port)) (lambda (k . a) (eof-object)))))
      (unless (eof-object? form)
        (let* ((line (if (pair? form) (or (source-property form 'line) -1) -1))
               (result
                 (catch #t
                   (lambda () (call-with-values
                                (lambda () (eval form (interaction-environment)))
                                (lambda vals (if (null? vals) *unspecified* (car vals)))))
                   (lambda (key . args)
                     (format (current-error-port) "@@ERROR ~a: ~a ~s\n" (+ 1 line) key args)
                     (list '@@error key)))))
          (display "\n@@RESULT ") (display (+ 1 line)) (newline)
          (if (unspecified? result) (display "@@unspecified") (write result))
          (display "\n@@END\n")
          (force-output))
        (loop)))))
"""


# ---------------------------------------------------------------------- reading results
_TOK = re.compile(r'\s+|(?P<o>\()|(?P<c>\))|(?P<s>"(?:[^"\\]|\\.)*")|(?P<a>[^\s()"]+)', re.S)
UNORDERED = {
    "SetLink",
    "AndLink",
    "OrLink",
    "ChoiceLink",
    "PresentLink",
    "SimilarityLink",
    "EquivalenceLink",
    "UnorderedLink",
    "EqualLink",
    "IdenticalLink",
    "VariableSet",
    "ExclusiveLink",
    "AlwaysLink",
    "QueueValue",
    "LinkValue",
}


def read_sexprs(text: str) -> list:
    """Every s-expression of ``text`` (strings kept with their quotes)."""
    stack: list[list] = [[]]
    for m in _TOK.finditer(text):
        if m.group("o"):
            stack.append([])
        elif m.group("c"):
            if len(stack) > 1:
                done = stack.pop()
                stack[-1].append(done)
        elif m.group("s") is not None:
            stack[-1].append(m.group("s"))
        elif m.group("a") is not None:
            stack[-1].append(m.group("a"))
    while len(stack) > 1:
        done = stack.pop()
        stack[-1].append(done)
    return stack[0]


def _num(tok: str) -> str | None:
    try:
        return f"{float(tok):.6f}"
    except ValueError:
        return None


def canon(x: object) -> str:
    """A canonical text of one read s-expression."""
    if isinstance(x, str):
        if x.startswith("#<"):
            return "#<" + re.split(r"[\s>]", x[2:], maxsplit=1)[0] + ">"
        n = _num(x)
        return n if n is not None else x
    assert isinstance(x, list)
    if len(x) == 2 and x[0] == "NumberNode" and isinstance(x[1], str) and x[1].startswith('"'):
        parts = [(_num(p) or p) for p in x[1][1:-1].split()]
        return f'(NumberNode "{" ".join(parts)}")'
    items = [canon(y) for y in x]
    if items and items[0] in UNORDERED:
        items = [items[0], *sorted(items[1:])]
    return "(" + " ".join(items) + ")"


def canon_result(text: str) -> str:
    """A recorded result as canonical text (errors: just ``error``)."""
    text = text.strip()
    if text.startswith("(@@error") or text.startswith("@@error"):
        return "error"
    if text.startswith("#<atomspace") or text.startswith("#<procedure"):
        return text.split()[0].rstrip(">") + ">"
    data = read_sexprs(text)
    if (
        len(data) == 1
        and isinstance(data[0], list)
        and data[0]
        and all(isinstance(x, list) and x and _is_atom_head(x[0]) for x in data[0])
    ):
        # a Scheme list of atoms (cog-incoming-set, cog-keys...): OpenCog gives no order
        return "(" + " ".join(sorted(canon(x) for x in data[0])) + ")"
    return " ".join(canon(d) for d in data)


def _is_atom_head(x: object) -> bool:
    return isinstance(x, str) and (x.endswith("Node") or x.endswith("Link"))


# ---------------------------------------------------------------------- running
def _parse_blocks(out: str) -> dict[int, str]:
    blocks: dict[int, str] = {}
    for m in re.finditer(r"@@RESULT (-?\d+)\n(.*?)\n@@END", out, re.S):
        line = int(m.group(1))
        blocks.setdefault(line, m.group(2))
    return blocks


def run_opencog(prefix: Path, path: Path) -> tuple[dict[int, str], str]:
    """Run one example on OpenCog's Guile; {form line: printed result}, stderr."""
    guile = prefix / "bin" / "opencog-guile"
    script = _GUILE_DRIVER + f"\n(robocog-run {json.dumps(str(path))})\n"
    with tempfile.TemporaryDirectory() as tmp:
        try:
            proc = subprocess.run(
                [str(guile), "--no-auto-compile", "-c", script],
                capture_output=True,
                text=True,
                errors="replace",
                cwd=str(path.parent) if os.access(path.parent, os.W_OK) else tmp,
                timeout=TIMEOUT,
                stdin=subprocess.DEVNULL,
            )
        except subprocess.TimeoutExpired:
            return {}, "timeout"
    return _parse_blocks(proc.stdout), proc.stderr


def run_robocog(path: Path) -> tuple[dict[int, str], str]:
    """Run one example on robocog in a fresh process; {form line: printed result}."""
    env = dict(os.environ)
    env["PYTHONPATH"] = str(SRC) + os.pathsep + env.get("PYTHONPATH", "")
    try:
        proc = subprocess.run(
            [sys.executable, str(Path(__file__).resolve()), "--one", str(path)],
            capture_output=True,
            text=True,
            errors="replace",
            timeout=TIMEOUT,
            env=env,
            cwd=str(path.parent),
            stdin=subprocess.DEVNULL,
        )
    except subprocess.TimeoutExpired:
        return {}, "timeout"
    return _parse_blocks(proc.stdout), proc.stderr


def one(path: str) -> int:
    """(internal) Run one file on robocog, printing each form's result as the driver does."""
    from robocog.atomspace.cogscm import make_scheme
    from robocog.atomspace.scheme import UNSPECIFIED, SchemeError, read, to_text

    scheme = make_scheme(out=sys.stdout, preload=False)
    text = Path(path).read_text(encoding="utf-8")
    try:
        forms = list(read(text, path))
    except SchemeError as exc:
        print(f"@@READ-ERROR {exc}", file=sys.stderr)
        return 1
    scheme.source = path
    for form in forms:
        line = getattr(form, "line", 0)
        try:
            value = scheme.eval_top(form)
            shown = "@@unspecified" if value is UNSPECIFIED else _write(value, scheme)
        except SchemeError as exc:
            print(str(exc), file=sys.stderr)
            shown = f"(@@error {exc.key})"
        except (TypeError, ValueError, RecursionError) as exc:  # a value that cannot print
            print(f"{path}:{line}: cannot print the result: {exc}", file=sys.stderr)
            shown = "(@@error print)"
        sys.stdout.write(f"\n@@RESULT {line}\n{shown}\n@@END\n")
        sys.stdout.flush()
    _ = to_text
    return 0


def _write(value: object, scheme: object) -> str:
    from robocog.atomspace.atomese import write_pretty
    from robocog.atomspace.atoms import Atom
    from robocog.atomspace.scheme import to_text
    from robocog.atomspace.values import Value

    space = scheme.cog.space  # type: ignore[attr-defined]
    if isinstance(value, Atom):
        return write_pretty(value, space)
    if isinstance(value, Value):
        return value.to_atomese()
    if isinstance(value, list):
        return "(" + "\n".join(_write(v, scheme) for v in value) + ")"
    return to_text(value)


_SKIP_HEADS = ("(define ", "(use-modules", "(load ", "(define-public")


def compare(path: Path, prefix: Path | None, verbose: bool) -> tuple[bool, int, int, list[str]]:
    """(agrees, forms compared, forms agreeing, notes) for one example."""
    mine, err = run_robocog(path)
    notes: list[str] = []
    if prefix is None:
        errors = sum(1 for v in mine.values() if "@@error" in v)
        if errors:
            notes.append(f"{errors} forms raised errors: {err.strip().splitlines()[:1]}")
        return errors == 0, len(mine), len(mine) - errors, notes
    theirs, oerr = run_opencog(prefix, path)
    if verbose:
        notes.extend(ln[:300] for ln in oerr.splitlines() if ln.startswith("@@ERROR"))
    text = path.read_text(encoding="utf-8", errors="replace").split("\n")
    n = ok = 0
    for line, got in sorted(theirs.items()):
        src = text[line - 1].strip() if 0 < line <= len(text) else ""
        if line <= 0 or got.strip() == "@@unspecified" or src.startswith(_SKIP_HEADS):
            continue
        n += 1
        want_c = canon_result(got)
        have = mine.get(line)
        have_c = canon_result(have) if have is not None else "(missing)"
        if want_c == have_c:
            ok += 1
        else:
            notes.append(f"line {line}: OpenCog {want_c[:160]} | robocog {have_c[:160]}")
    if verbose and err.strip():
        notes.append("robocog stderr: " + err.strip().splitlines()[0][:200])
    return ok == n, n, ok, notes


def main(argv: list[str] | None = None) -> int:
    """Run the examples; print one line per example and the count that agree."""
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--atomspace", help="an OpenCog AtomSpace checkout (holds examples/)")
    ap.add_argument("--opencog", help="OpenCog install prefix (bin/opencog-guile)")
    ap.add_argument("-k", default="", help="only examples whose path contains this")
    ap.add_argument("-v", action="store_true", help="show every differing form")
    ap.add_argument("--one", help=argparse.SUPPRESS)
    args = ap.parse_args(argv)
    if args.one:
        return one(args.one)
    if not args.atomspace:
        ap.error("--atomspace CHECKOUT is required")
    root = Path(args.atomspace)
    files = sorted(root.glob("examples/pattern-matcher/*.scm")) + sorted(
        root.glob("examples/atomspace/*.scm")
    )
    if not files:
        print(f"opencog_examples: no examples under {root}/examples", file=sys.stderr)
        return 1
    prefix = Path(args.opencog) if args.opencog else None
    if prefix is not None and not (prefix / "bin" / "opencog-guile").exists():
        print(f"opencog_examples: no bin/opencog-guile under {prefix}", file=sys.stderr)
        return 1
    good = total = 0
    for f in files:
        rel = f.relative_to(root)
        if args.k not in str(rel):
            continue
        total += 1
        agrees, n, ok, notes = compare(f, prefix, args.v)
        good += agrees
        print(f"{'ok  ' if agrees else 'DIFF'} {rel}  {ok}/{n} forms", flush=True)
        if not agrees or args.v:
            for note in notes[: (50 if args.v else 3)]:
                print(f"      {note}")
    print(f"{good} of {total} examples agree")
    return 0


if __name__ == "__main__":
    sys.exit(main())
