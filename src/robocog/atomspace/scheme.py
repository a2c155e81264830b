"""A small Scheme for Atomese: the part of Guile that OpenCog's programs are written in.

OpenCog users write Atomese inside Guile: ``(define (f x) ...)``, ``let``, ``map``,
``display`` and the ``cog-`` procedures around the atoms. This module is the Scheme
evaluator (the ``cog-`` API over robocog's AtomSpace is in :mod:`robocog.atomspace.cogscm`).
No maintained Scheme on PyPI can call robocog's Python atom constructors directly and be
called back from ``scm:`` grounded atoms at the cost of a Python call, and Guile driven
from Python would cross a process boundary for every atom; so the evaluator is written
here, to Guile's behaviour where the examples of OpenCog depend on it.

Design, for safety and speed:

- the reader is iterative, with a documented nesting limit (:data:`MAX_NESTING`) and a
  size limit (:data:`MAX_TEXT`); every list remembers its line and column;
- the evaluator interprets the read lists directly, with proper tail calls (``if``,
  ``cond``, ``let``, ``begin``, a procedure's last expression loop instead of
  recursing), so a named-let loop runs in constant stack; non-tail recursion deeper
  than :data:`MAX_DEPTH` ends with a clear ``stack-overflow`` error;
- every error is a :class:`SchemeError` (an :class:`AtomeseError`) with Guile's key
  (``unbound-variable``, ``wrong-type-arg``...), the name involved and the place of the
  innermost form; a Python exception never leaves :meth:`Scheme.eval_text`.
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from fractions import Fraction
from typing import Any

from robocog.atomspace.schemedata import (
    MAX_DEPTH,
    MAX_MESSAGE,
    MAX_NESTING,
    MAX_TEXT,
    UNSPECIFIED,
    Char,
    ControlFlow,
    DottedForm,
    Env,
    Form,
    Keyword,
    Pair,
    Primitive,
    Procedure,
    SchemeError,
    Sym,
    Throw,
    Vector,
    is_true,
    read,
    shorten,
    sym,
    to_text,
)

# ---------------------------------------------------------------------- evaluator
S = sym
_QUOTE, _QUASI, _UNQ, _UNQS = S("quote"), S("quasiquote"), S("unquote"), S("unquote-splicing")
_ELSE, _ARROW = S("else"), S("=>")
_DEFINE_FORMS = frozenset({S("define"), S("define-public")})

# special form codes
(
    _IF,
    _DEFINE,
    _LAMBDA,
    _LET,
    _LETSTAR,
    _LETREC,
    _BEGIN,
    _SET,
    _QUOTEF,
    _QUASIF,
    _COND,
    _CASE,
    _AND,
    _OR,
    _WHEN,
    _UNLESS,
    _DO,
    _DELAY,
    _USE_MODULES,
    _DEFINE_MODULE,
    _DEFINE_SYNTAX,
) = range(21)
SPECIAL: dict[Sym, int] = {
    S("if"): _IF,
    S("define"): _DEFINE,
    S("define-public"): _DEFINE,
    S("define*"): _DEFINE,
    S("lambda"): _LAMBDA,
    S("lambda*"): _LAMBDA,
    S("λ"): _LAMBDA,
    S("let"): _LET,
    S("let*"): _LETSTAR,
    S("letrec"): _LETREC,
    S("letrec*"): _LETREC,
    S("begin"): _BEGIN,
    S("set!"): _SET,
    S("quote"): _QUOTEF,
    S("quasiquote"): _QUASIF,
    S("cond"): _COND,
    S("case"): _CASE,
    S("and"): _AND,
    S("or"): _OR,
    S("when"): _WHEN,
    S("unless"): _UNLESS,
    S("do"): _DO,
    S("delay"): _DELAY,
    S("use-modules"): _USE_MODULES,
    S("define-module"): _DEFINE_MODULE,
    S("define-syntax"): _DEFINE_SYNTAX,
}


class Promise:
    """``(delay expr)``."""

    __slots__ = ("expr", "env", "done", "value")

    def __init__(self, expr: Any, env: Env) -> None:
        self.expr = expr
        self.env = env
        self.done = False
        self.value: Any = None


def _syntax(msg: str, form: Any) -> SchemeError:
    return SchemeError("syntax-error", f"{msg}: {shorten(to_text(form), 160)}")


class Scheme:
    """One Scheme interpreter: a global environment and an evaluator over it (empty:
    :func:`robocog.atomspace.schemelib.install` gives it the standard procedures,
    :func:`robocog.atomspace.cogscm.make_scheme` those and OpenCog's).

    ``known_modules`` are the module names ``use-modules`` accepts (others are an
    error, as Guile reports a missing module).
    """

    def __init__(self) -> None:
        self.globals = Env({}, None)
        self.source = "<string>"
        self.out = sys.stdout
        #: evaluation steps left (None: no limit); a program that runs past it ends with
        #: a ``step-limit`` error (for untrusted text: a loop cannot run forever)
        self.budget: int | None = None
        #: whether the program may read and write files (``load``, ``export-all-atoms``):
        #: yes for a user's own program, no for text from elsewhere (``run_text``)
        self.files = True
        #: module name -> the bindings ``use-modules`` brings into the globals
        self.known_modules: dict[str, dict] = {}

    # -- public entry points
    def define(self, name: str, value: Any) -> None:
        """Bind ``name`` in the global environment (a Python callable becomes a
        primitive procedure)."""
        if callable(value) and not isinstance(value, Procedure | Primitive):
            value = Primitive(value, name)
        self.globals.vars[sym(name)] = value

    def lookup(self, name: str) -> Any:
        """The global value of ``name``; SchemeError if unbound."""
        return self.globals.find(sym(name))[sym(name)]

    def eval_text(
        self, text: str, source: str = "<string>", each: Callable[[Any, Any], None] | None = None
    ) -> Any:
        """Read and evaluate every top-level form of ``text``; returns the last value.

        ``each(form, value)`` is called after each top-level form. Any failure is a
        :class:`SchemeError` with the place of the innermost form that failed.
        """
        self.source = source
        value: Any = UNSPECIFIED
        for form in read(text, source):
            value = self.eval_top(form)
            if each is not None:
                each(form, value)
        return value

    def eval_top(self, form: Any) -> Any:
        """Evaluate one top-level datum, turning every failure into a SchemeError."""
        old_limit = sys.getrecursionlimit()
        if old_limit < MAX_DEPTH:
            sys.setrecursionlimit(MAX_DEPTH)
        try:
            return self.evaluate(form, self.globals)
        except SchemeError as exc:
            if not exc.line and isinstance(form, Form):
                raise exc.located(form.line, form.col, self.source) from None
            raise
        except Throw as t:
            raise self._error_at(
                form,
                "uncaught-throw",
                f"uncaught throw to {shorten(to_text(t.key))}: {shorten(to_text(t.args))}",
            ) from None
        except ControlFlow as exc:  # an escaping continuation used after its extent
            raise self._error_at(
                form, "misc-error", f"continuation called outside its extent ({type(exc).__name__})"
            ) from None
        except RecursionError:
            raise self._error_at(
                form,
                "stack-overflow",
                f"recursion deeper than the limit ({MAX_DEPTH} Python frames)",
            ) from None
        except Exception as exc:  # noqa: BLE001 - the documented error type, always
            raise self._error_at(
                form,
                _KEYS.get(type(exc).__name__, "misc-error"),
                shorten(str(exc) or type(exc).__name__, MAX_MESSAGE),
            ) from None
        finally:
            if old_limit < MAX_DEPTH:
                sys.setrecursionlimit(old_limit)

    def _error_at(self, form: Any, key: str, message: str) -> SchemeError:
        """A top-level failure as the SchemeError ``key``, placed at ``form`` (0, 0 for a
        datum that carries no place)."""
        return SchemeError(
            key, message, getattr(form, "line", 0), getattr(form, "col", 0), self.source
        )

    def apply(self, f: Any, args: list) -> Any:
        """Call a Scheme procedure (or primitive) with evaluated arguments."""
        if f.__class__ is Primitive:
            return self._call_primitive(f, args)
        if f.__class__ is Procedure:
            env = self._bind(f, args)
            body = f.body
            for x in body[:-1]:
                self.evaluate(x, env)
            return self.evaluate(body[-1], env)
        if callable(f) and not isinstance(f, type):
            return self._call_primitive(Primitive(f, getattr(f, "__name__", "?")), args)
        raise SchemeError("wrong-type-arg", f"Wrong type to apply: {shorten(to_text(f))}")

    def _call_primitive(self, f: Primitive, args: list) -> Any:
        try:
            return f.fn(*args)
        except (SchemeError, ControlFlow, RecursionError):
            raise
        except TypeError as exc:
            msg = str(exc)
            if "positional argument" in msg or "required" in msg or "takes" in msg:
                raise SchemeError(
                    "wrong-number-of-args", f"Wrong number of arguments to {f.name}"
                ) from None
            raise SchemeError("wrong-type-arg", f"In procedure {f.name}: {msg}") from None
        except (OverflowError, ZeroDivisionError) as exc:
            raise SchemeError("numerical-overflow", f"In procedure {f.name}: {exc}") from None
        except Exception as exc:  # noqa: BLE001 - every failure is a Scheme error
            key = _KEYS.get(type(exc).__name__, "wrong-type-arg")
            raise SchemeError(
                key, f"In procedure {f.name}: {shorten(str(exc) or type(exc).__name__, 300)}"
            ) from None

    def _bind(self, f: Procedure, args: list) -> Env:
        params = f.params
        n = len(params)
        if f.rest is None:
            if len(args) != n:
                raise SchemeError(
                    "wrong-number-of-args",
                    f"Wrong number of arguments to {f.name}: {len(args)} given, {n} expected",
                )
            return Env(dict(zip(params, args, strict=True)), f.env)
        if len(args) < n:
            raise SchemeError(
                "wrong-number-of-args",
                f"Wrong number of arguments to {f.name}: {len(args)} given, at least {n}",
            )
        d = dict(zip(params, args[:n], strict=True))
        d[f.rest] = list(args[n:])
        return Env(d, f.env)

    # -- the evaluator
    def evaluate(self, x: Any, env: Env) -> Any:  # noqa: C901 - one loop for tail calls
        """Evaluate ``x`` in ``env`` (tail positions loop instead of recursing)."""
        while True:
            if self.budget is not None:
                self.budget -= 1
                if self.budget < 0:
                    self.budget = None
                    raise SchemeError("step-limit", "evaluation took more steps than allowed")
            cls = x.__class__
            if cls is Sym:
                e = env
                while e is not None:
                    v = e.vars
                    if x in v:
                        return v[x]
                    e = e.parent
                raise SchemeError("unbound-variable", f"Unbound variable: {shorten(x)}", args=[x])
            if cls is not Form and cls is not DottedForm:
                if isinstance(x, Form):
                    pass
                else:
                    return x
            if not x:
                raise SchemeError("syntax-error", "Illegal empty combination ()")
            try:
                head = x[0]
                code = SPECIAL.get(head) if head.__class__ is Sym else None
                if code is not None and not self._shadowed(head, env):
                    if code == _IF:
                        n = len(x)
                        if n not in (3, 4):
                            raise _syntax("if takes a test and one or two branches", x)
                        if self.evaluate(x[1], env) is not False:
                            x = x[2]
                        elif n == 4:
                            x = x[3]
                        else:
                            return UNSPECIFIED
                        continue
                    if code == _DEFINE:
                        return self._define(x, env)
                    if code == _LAMBDA:
                        return self._lambda(x, env, "#f")
                    if code == _BEGIN:
                        if len(x) == 1:
                            return UNSPECIFIED
                        for y in x[1:-1]:
                            self.evaluate(y, env)
                        x = x[-1]
                        continue
                    if code == _LET:
                        x, env = self._let(x, env)
                        continue
                    if code == _LETSTAR:
                        x, env = self._letstar(x, env)
                        continue
                    if code == _LETREC:
                        x, env = self._letrec(x, env)
                        continue
                    if code == _SET:
                        if len(x) != 3 or x[1].__class__ is not Sym:
                            raise _syntax("set! takes a name and a value", x)
                        where = env.find(x[1])
                        where[x[1]] = self.evaluate(x[2], env)
                        return UNSPECIFIED
                    if code == _QUOTEF:
                        if len(x) != 2:
                            raise _syntax("quote takes one datum", x)
                        return _datum(x[1])
                    if code == _QUASIF:
                        if len(x) != 2:
                            raise _syntax("quasiquote takes one datum", x)
                        return self._quasi(x[1], env, 1)
                    if code == _COND:
                        nxt = self._cond(x, env)
                        if nxt is _DONE:
                            return self._last
                        x, env = nxt
                        continue
                    if code == _CASE:
                        nxt = self._case(x, env)
                        if nxt is _DONE:
                            return self._last
                        x = nxt
                        continue
                    if code == _AND:
                        if len(x) == 1:
                            return True
                        for y in x[1:-1]:
                            if self.evaluate(y, env) is False:
                                return False
                        x = x[-1]
                        continue
                    if code == _OR:
                        if len(x) == 1:
                            return False
                        for y in x[1:-1]:
                            v = self.evaluate(y, env)
                            if v is not False:
                                return v
                        x = x[-1]
                        continue
                    if code == _WHEN or code == _UNLESS:
                        if len(x) < 2:
                            raise _syntax("when/unless take a test", x)
                        t = self.evaluate(x[1], env) is not False
                        if t != (code == _WHEN) or len(x) == 2:
                            return UNSPECIFIED
                        for y in x[2:-1]:
                            self.evaluate(y, env)
                        x = x[-1]
                        continue
                    if code == _DO:
                        return self._do(x, env)
                    if code == _DELAY:
                        return Promise(x[1], env)
                    if code == _USE_MODULES:
                        return self._use_modules(x)
                    if code == _DEFINE_MODULE:
                        return UNSPECIFIED
                    if code == _DEFINE_SYNTAX:
                        raise SchemeError("syntax-error", "define-syntax is not supported")
                f = self.evaluate(head, env)
                args = [self.evaluate(a, env) for a in x[1:]]
                if f.__class__ is Procedure:
                    env = self._bind(f, args)
                    body = f.body
                    for y in body[:-1]:
                        self.evaluate(y, env)
                    x = body[-1]
                    continue
                if f.__class__ is Primitive:
                    return self._call_primitive(f, args)
                return self.apply(f, args)
            except SchemeError as exc:
                if not exc.line and x.__class__ in (Form, DottedForm) and x.line:
                    raise exc.located(x.line, x.col, self.source) from None
                raise

    _last: Any = None

    def _shadowed(self, name: Sym, env: Env) -> bool:
        e = env
        while e is not None:
            if name in e.vars:
                return True
            e = e.parent
        return False

    def _lambda(self, x: list, env: Env, name: str) -> Procedure:
        if len(x) < 3:
            raise _syntax("lambda needs parameters and a body", x)
        params, rest = self._params(x[1], x)
        return Procedure(params, rest, _body(x[2:]), env, name)

    def _params(self, spec: Any, x: Any) -> tuple[list, Sym | None]:
        if spec.__class__ is Sym:
            return [], spec
        if isinstance(spec, DottedForm):
            params = list(spec)
            rest = spec.tail
        elif isinstance(spec, list):
            params = list(spec)
            rest = None
        else:
            raise _syntax("bad parameter list", x)
        clean = []
        optional = False
        for p in params:
            if isinstance(p, Keyword):
                if p in ("optional", "key"):
                    optional = True
                    continue
                if p == "rest":
                    optional = False
                    continue
                raise _syntax("bad parameter list", x)
            if optional and isinstance(p, list) and p and p[0].__class__ is Sym:
                clean.append(p[0])
                continue
            if p.__class__ is not Sym:
                raise _syntax("bad parameter list", x)
            clean.append(p)
        if rest is not None and rest.__class__ is not Sym:
            raise _syntax("bad parameter list", x)
        return clean, rest

    def _define(self, x: list, env: Env) -> Any:
        if len(x) < 2:
            raise _syntax("define needs a name", x)
        target = x[1]
        if target.__class__ is Sym:
            value = self.evaluate(x[2], env) if len(x) > 2 else UNSPECIFIED
            if isinstance(value, Procedure) and value.name == "#f":
                value.name = str.__str__(target)
            env.vars[target] = value
            return UNSPECIFIED
        if isinstance(target, list) and target and len(x) >= 3:
            # (define (name . params) body...), also curried (define ((f a) b) ...)
            name = target[0]
            params = (
                DottedForm(target[1:], target.tail, 0, 0)
                if isinstance(target, DottedForm)
                else Form(target[1:])
            )
            lam = Form([S("lambda"), params, *x[2:]], x.line, x.col)
            if name.__class__ is Sym:
                p, rest = self._params(params, x)
                env.vars[name] = Procedure(p, rest, _body(x[2:]), env, str.__str__(name))
                return UNSPECIFIED
            return self._define(Form([S("define"), name, lam], x.line, x.col), env)
        raise _syntax("bad define", x)

    def _let(self, x: list, env: Env) -> tuple[Any, Env]:
        if len(x) < 3:
            raise _syntax("let needs bindings and a body", x)
        if x[1].__class__ is Sym:  # named let
            name, bindings, body = x[1], x[2], x[3:]
            if not body:
                raise _syntax("named let needs a body", x)
            names, values = self._bindings(bindings, env, x)
            loop_env = Env({}, env)
            proc = Procedure(names, None, _body(body), loop_env, str.__str__(name))
            loop_env.vars[name] = proc
            new = Env(dict(zip(names, values, strict=True)), loop_env)
        else:
            names, values = self._bindings(x[1], env, x)
            body = x[2:]
            new = Env(dict(zip(names, values, strict=True)), env)
        for y in body[:-1]:
            self.evaluate(y, new)
        return body[-1], new

    def _bindings(self, bindings: Any, env: Env, x: Any) -> tuple[list, list]:
        if not isinstance(bindings, list):
            raise _syntax("bad let bindings", x)
        names, values = [], []
        for b in bindings:
            if not isinstance(b, list) or not b or b[0].__class__ is not Sym or len(b) > 2:
                raise _syntax("bad let binding", x)
            names.append(b[0])
            values.append(self.evaluate(b[1], env) if len(b) == 2 else UNSPECIFIED)
        return names, values

    def _letstar(self, x: list, env: Env) -> tuple[Any, Env]:
        if len(x) < 3 or not isinstance(x[1], list):
            raise _syntax("let* needs bindings and a body", x)
        for b in x[1]:
            if not isinstance(b, list) or not b or b[0].__class__ is not Sym or len(b) > 2:
                raise _syntax("bad let* binding", x)
            env = Env({b[0]: self.evaluate(b[1], env) if len(b) == 2 else UNSPECIFIED}, env)
        env = Env({}, env)
        for y in x[2:-1]:
            self.evaluate(y, env)
        return x[-1], env

    def _letrec(self, x: list, env: Env) -> tuple[Any, Env]:
        if len(x) < 3 or not isinstance(x[1], list):
            raise _syntax("letrec needs bindings and a body", x)
        new = Env({}, env)
        for b in x[1]:
            if not isinstance(b, list) or len(b) != 2 or b[0].__class__ is not Sym:
                raise _syntax("bad letrec binding", x)
            new.vars[b[0]] = UNSPECIFIED
        for b in x[1]:
            v = self.evaluate(b[1], new)
            if isinstance(v, Procedure) and v.name == "#f":
                v.name = str.__str__(b[0])
            new.vars[b[0]] = v
        for y in x[2:-1]:
            self.evaluate(y, new)
        return x[-1], new

    def _cond(self, x: list, env: Env) -> Any:
        for clause in x[1:]:
            if not isinstance(clause, list) or not clause:
                raise _syntax("bad cond clause", x)
            if clause[0] is _ELSE:
                t: Any = True
            else:
                t = self.evaluate(clause[0], env)
            if t is False:
                continue
            if len(clause) == 1:
                self._last = t
                return _DONE
            if clause[1] is _ARROW and len(clause) == 3:
                f = self.evaluate(clause[2], env)
                self._last = self.apply(f, [t])
                return _DONE
            for y in clause[1:-1]:
                self.evaluate(y, env)
            return clause[-1], env
        self._last = UNSPECIFIED
        return _DONE

    def _case(self, x: list, env: Env) -> Any:
        if len(x) < 2:
            raise _syntax("case needs a key", x)
        key = self.evaluate(x[1], env)
        for clause in x[2:]:
            if not isinstance(clause, list) or len(clause) < 2:
                raise _syntax("bad case clause", x)
            data = clause[0]
            if data is _ELSE or (isinstance(data, list) and any(eqv(key, d) for d in data)):
                for y in clause[1:-1]:
                    self.evaluate(y, env)
                return clause[-1]
        self._last = UNSPECIFIED
        return _DONE

    def _do(self, x: list, env: Env) -> Any:
        if len(x) < 3 or not isinstance(x[1], list) or not isinstance(x[2], list) or not x[2]:
            raise _syntax("bad do", x)
        specs = x[1]
        new = Env({}, env)
        for s in specs:
            if not isinstance(s, list) or len(s) < 2 or s[0].__class__ is not Sym:
                raise _syntax("bad do binding", x)
            new.vars[s[0]] = self.evaluate(s[1], env)
        test = x[2]
        while self.evaluate(test[0], new) is False:
            for y in x[3:]:
                self.evaluate(y, new)
            steps = {s[0]: self.evaluate(s[2], new) for s in specs if len(s) == 3}
            new = Env({**new.vars, **steps}, env)
        value: Any = UNSPECIFIED
        for y in test[1:]:
            value = self.evaluate(y, new)
        return value

    def _quasi(self, x: Any, env: Env, depth: int) -> Any:
        if isinstance(x, Vector):
            return Vector(self._quasi(list(x), env, depth))
        if not isinstance(x, list):
            return _datum(x)
        if x and x[0] is _UNQ and len(x) == 2:
            if depth == 1:
                return self.evaluate(x[1], env)
            return [_UNQ, self._quasi(x[1], env, depth - 1)]
        if x and x[0] is _QUASI and len(x) == 2:
            return [_QUASI, self._quasi(x[1], env, depth + 1)]
        out: list = []
        for y in x:
            if isinstance(y, list) and len(y) == 2 and y[0] is _UNQS and depth == 1:
                v = self.evaluate(y[1], env)
                if not isinstance(v, list):
                    raise SchemeError("wrong-type-arg", "unquote-splicing of a non-list")
                out.extend(v)
            else:
                out.append(self._quasi(y, env, depth))
        if isinstance(x, DottedForm):
            tail = self._quasi(x.tail, env, depth)
            if isinstance(tail, list):
                return out + tail
            value: Any = tail
            for y in reversed(out):
                value = Pair(y, value)
            return value
        return out

    def _use_modules(self, x: list) -> Any:
        found = []
        for spec in x[1:]:
            if isinstance(spec, list) and spec and spec[0].__class__ is not Sym:
                spec = spec[0]  # ((ice-9 readline) #:select ...)
            name = " ".join(to_text(p) for p in spec) if isinstance(spec, list) else to_text(spec)
            if name not in self.known_modules:
                raise SchemeError(
                    "misc-error", f"no code for module ({shorten(name)})", args=[name]
                )
            found.append(self.known_modules[name])
        for bindings in found:  # all or nothing, as Guile's use-modules
            self.globals.vars.update(bindings)
        return UNSPECIFIED


_DONE = object()
_KEYS = {
    "GroundedError": "grounded-error",
    "PatternError": "pattern-error",
    "FlowError": "flow-error",
    "MemoryError": "out-of-memory",
}


def _body(body: list) -> list:
    """A procedure body with inner ``define``s kept in order (they define in the
    procedure's frame when run)."""
    if not body:
        raise SchemeError("syntax-error", "empty body")
    return list(body)


def _datum(x: Any) -> Any:
    """A quoted datum: read dotted lists become pairs, at any depth."""
    if isinstance(x, DottedForm):
        value: Any = _datum(x.tail)
        for y in reversed(x):
            value = Pair(_datum(y), value)
        return value
    if isinstance(x, Form) and any(isinstance(y, Form) for y in x):
        return [_datum(y) for y in x]
    return x


def eqv(a: Any, b: Any) -> bool:
    """Scheme ``eqv?``: identity, or equal numbers/characters of the same exactness."""
    if a is b:
        return True
    if isinstance(a, bool) or isinstance(b, bool):
        return False
    if isinstance(a, int | float | Fraction) and isinstance(b, int | float | Fraction):
        return type(a) is type(b) and a == b
    if isinstance(a, Char) and isinstance(b, Char):
        return str(a) == str(b)
    if isinstance(a, Sym) or isinstance(b, Sym):
        return False
    if isinstance(a, str) and isinstance(b, str):
        return False
    if isinstance(a, list) and isinstance(b, list):
        return not a and not b
    return type(a) is type(b) and _atomish(a) and a == b


def _atomish(x: Any) -> bool:
    """Atoms are unique in an AtomSpace, so equal atoms are one object to ``eq?``."""
    return isinstance(x, tuple)


__all__ = [
    "MAX_DEPTH",
    "MAX_MESSAGE",
    "ControlFlow",
    "DottedForm",
    "Keyword",
    "Vector",
    "shorten",
    "MAX_NESTING",
    "MAX_TEXT",
    "Char",
    "Env",
    "Form",
    "Pair",
    "Primitive",
    "Procedure",
    "Scheme",
    "SchemeError",
    "Sym",
    "Throw",
    "UNSPECIFIED",
    "eqv",
    "is_true",
    "read",
    "sym",
    "to_text",
]
