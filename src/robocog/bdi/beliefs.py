"""The belief base: facts and rules indexed by predicate, in Jason's order.

Jason adds a new belief at the *front* of its predicate's list, so queries see the
newest belief first; initial beliefs are inserted back to front, so they are seen in
program order. A belief that is added again only gains the new annotations; removing a
belief removes the given annotations and drops the belief once no ``source`` is left.
Iteration order is fully determined by the order of operations.
"""

from __future__ import annotations

import itertools
from collections.abc import Iterator
from typing import Any

from robocog.bdi.logic import solve
from robocog.bdi.parser import Rule
from robocog.bdi.terms import Literal, Term, Var, is_ground, sort_annots
from robocog.bdi.unifier import annots_subset, annots_ways, rename, resolve, undo, unify

_ids = itertools.count()


class StoredRule:
    """A rule in the belief base; its variables are renamed at each use."""

    __slots__ = ("head", "body")

    def __init__(self, head: Literal, body: Term) -> None:
        self.head = head
        self.body = body

    def __repr__(self) -> str:
        return f"{self.head!r} :- {self.body!r}"


def is_ground_annots(annots: tuple) -> bool:
    """True when no annotation holds a variable."""
    return all(is_ground(a) for a in annots)


class BeliefBase:
    """Facts and rules, indexed by ``(functor, arity, negated)``.

    Ground facts are also indexed by their first argument, so a query such as
    ``item(I, V)`` with ``I`` bound looks at the facts about ``I`` only (when the
    predicate has no rule and no fact with variables, which could match anything).
    """

    def __init__(self) -> None:
        self._index: dict[tuple, dict] = {}
        self._first: dict[tuple, dict] = {}
        self._mixed: dict[tuple, int] = {}
        self._size = 0
        #: Jason's ``IndexedBB``: for (functor, arity), the argument positions that are a
        #: key; a new fact replaces the one with the same key
        self.unique_keys: dict[tuple[str, int], tuple[int, ...]] | None = None

    # ---- the two primitive changes (keep both indexes in step)
    def _put(self, key: tuple, k: object, value: Literal | StoredRule, at_end: bool) -> None:
        bucket = self._index.get(key)
        if bucket is None:
            bucket = self._index[key] = {}
        new = k not in bucket
        if at_end and new and bucket:
            items = list(bucket.items())
            bucket.clear()
            bucket[k] = value
            bucket.update(items)
        else:
            bucket[k] = value
        if new:
            self._size += 1
        if value.__class__ is Literal and value.ground and value.args:
            first = self._first.get(key)
            if first is None:
                first = self._first[key] = {}
            a0 = value.args[0]
            sub = first.get(a0)
            if sub is None:
                sub = first[a0] = {}
            if at_end and new and sub:
                items = list(sub.items())
                sub.clear()
                sub[k] = value
                sub.update(items)
            else:
                sub[k] = value
        elif new and not (value.__class__ is Literal and value.ground):
            self._mixed[key] = self._mixed.get(key, 0) + 1

    def _del(self, key: tuple, k: object) -> None:
        value = self._index[key].pop(k)
        self._size -= 1
        if value.__class__ is Literal and value.ground and value.args:
            first = self._first[key]
            a0 = value.args[0]
            sub = first[a0]
            del sub[k]
            if not sub:
                del first[a0]
        elif not (value.__class__ is Literal and value.ground):
            self._mixed[key] -= 1

    # ---- changes
    def add(self, lit: Literal, at_end: bool = False) -> Literal | None:
        """Add ``lit``; returns what was added (annotations new to the base) or ``None``."""
        key = (lit.functor, len(lit.args), lit.neg)
        if self.unique_keys is not None and lit.ground:
            self._replace_key(key, lit)
        if lit.ground:
            k = lit.args
            bucket = self._index.get(key)
            old = bucket.get(k) if bucket else None
            if old is None and not at_end and bucket is not None and k:
                # the common case: a new ground fact with arguments, at the front
                bucket[k] = lit
                self._size += 1
                first = self._first.get(key)
                if first is None:
                    first = self._first[key] = {}
                sub = first.get(k[0])
                if sub is None:
                    first[k[0]] = {k: lit}
                else:
                    sub[k] = lit
                return lit
            if old is not None:
                merged = sort_annots(old.annots + lit.annots)
                if merged == old.annots:
                    return None
                self._put(key, k, Literal(old.functor, old.args, merged, old.neg), False)
                return lit
        else:
            k = ("_var", next(_ids))
        self._put(key, k, lit, at_end)
        return lit

    def _replace_key(self, key: tuple, lit: Literal) -> None:
        positions = self.unique_keys.get((lit.functor, len(lit.args)))
        bucket = self._index.get(key)
        if not positions or not bucket:
            return
        want = [lit.args[p] for p in positions]
        for k, old in list(bucket.items()):
            if (
                old.__class__ is Literal
                and old.ground
                and old.args != lit.args
                and [old.args[p] for p in positions] == want
            ):
                self._del(key, k)

    def add_rule(self, rule: Rule | StoredRule, at_end: bool = False) -> None:
        """Add a rule (rules live with the facts of their head's predicate)."""
        stored = StoredRule(rule.head, rule.body)
        self._put(stored.head.key, stored, stored, at_end)

    def find(self, lit: Literal) -> Literal | None:
        """The stored belief equal to ``lit`` apart from annotations (ground only)."""
        bucket = self._index.get(lit.key)
        if not bucket or not lit.ground:
            return None
        got = bucket.get(lit.args)
        return got if got.__class__ is Literal else None

    def _take_annots(self, key: tuple, k: object, old: Literal, annots: tuple) -> Literal | None:
        """Remove ``annots`` from a stored fact; drop it when no source is left."""
        if not annots or old.annots == annots:
            self._del(key, k)
            return old
        keep = tuple(a for a in old.annots if a not in annots)
        gone = tuple(a for a in old.annots if a in annots)
        if not gone:
            return None
        if any(a.__class__ is Literal and a.functor == "source" for a in keep):
            self._put(key, k, Literal(old.functor, old.args, keep, old.neg), False)
        else:
            self._del(key, k)
        return Literal(old.functor, old.args, gone, old.neg)

    def remove(self, lit: Literal) -> Literal | None:
        """Remove ``lit``'s annotations from its belief; returns what was removed."""
        bucket = self._index.get(lit.key)
        if not bucket or not lit.ground:
            return None
        old = bucket.get(lit.args)
        if old is None or old.__class__ is not Literal:
            return None
        return self._take_annots(lit.key, lit.args, old, lit.annots)

    def remove_first(self, key: tuple, annots: tuple) -> Literal | None:
        """``-+``'s removal: the newest fact of ``key`` that has all of ``annots``
        loses them (and goes if no source is left); returns what was removed."""
        bucket = self._index.get(key)
        if not bucket:
            return None
        for k in reversed(bucket):
            old = bucket[k]
            if old.__class__ is not Literal:
                continue
            oa = old.annots
            for a in annots:
                if a not in oa:
                    break
            else:
                return self._take_annots(key, k, old, annots)
        return None

    def remove_entry(self, stored: Literal) -> bool:
        """Remove exactly this stored belief, whatever its annotations."""
        bucket = self._index.get(stored.key)
        if not bucket:
            return False
        for k, v in bucket.items():
            if v is stored:
                self._del(stored.key, k)
                return True
        return False

    def abolish(self, pattern: Literal) -> list[Literal]:
        """Remove every fact unifying with ``pattern``; returns them."""
        bucket = self._index.get(pattern.key)
        if not bucket:
            return []
        gone = []
        for k, v in list(bucket.items()):
            if v.__class__ is Literal and unify(pattern, v, {}, []):
                self._del(pattern.key, k)
                gone.append(v)
        return gone

    def clear(self) -> None:
        """Forget everything."""
        self._index.clear()
        self._first.clear()
        self._mixed.clear()
        self._size = 0

    # ---- reading
    def _narrowed(self, key: tuple, bucket: dict, args: tuple, s: dict) -> dict | None:
        """The facts of predicate ``key`` (``bucket``, all of them) that a pattern with
        arguments ``args`` can match, as far as its first argument tells: when that is
        ground once its bindings in ``s`` are followed, only the facts filed under it
        (``None`` if there are none), so that ``at(r1, X)`` does not scan every ``at``
        fact; else the whole bucket."""
        if args:
            a0 = args[0]
            while a0.__class__ is Var:
                v = s.get(a0)
                if v is None:
                    break
                a0 = v
            if a0.__class__ is not Var and is_ground(a0):
                return self._first[key].get(a0) or None
        return bucket

    def candidates(self, key: tuple) -> tuple:
        """Facts and rules of one predicate, newest first (a snapshot)."""
        bucket = self._index.get(key)
        if not bucket:
            return ()
        vals = tuple(bucket.values())
        return vals[::-1]

    def query(
        self,
        pattern: Literal,
        s: dict,
        trail: list,
        agent: Any,
    ) -> Iterator[None]:
        """Yield once per fact or rule solution unifying with ``pattern`` (bindings in ``s``)."""
        key = (pattern.functor, len(pattern.args), pattern.neg)
        bucket = self._index.get(key)
        if not bucket:
            return
        if pattern.args and not self._mixed.get(key):
            sub = self._narrowed(key, bucket, pattern.args, s)
            if sub is None:
                return
            if pattern.ground and not pattern.annots:  # (narrowed by its first argument)
                if sub.get(pattern.args) is not None:
                    yield None
                return
            cands = tuple(sub.values())[::-1]
        else:
            cands = tuple(bucket.values())[::-1]
        mark = len(trail)
        if not pattern.annots and pattern.args and not self._mixed.get(key):
            # every argument a distinct unbound variable (``val(_, V)`` in a .findall):
            # each fact binds them as they stand, with no unification to run
            vs = pattern.args
            for v in vs:
                if v.__class__ is not Var or v in s:
                    break
            else:
                if len({id(v) for v in vs}) == len(vs):
                    for b in cands:
                        for v, a in zip(vs, b.args):  # noqa: B905 - same arity (the key)
                            s[v] = a
                            trail.append(v)
                        yield None
                        undo(s, trail, mark)
                    return
        # annotations with variables can match a belief's annotations in several ways
        # (fact(1)[source(S)] against [source(a),source(b)]): each is a solution
        several = bool(pattern.annots) and not is_ground_annots(pattern.annots)
        bare = pattern.without_annots() if several else pattern
        for b in cands:
            if b.__class__ is Literal:
                if not b.ground:
                    b = rename(b, {})
                if unify(bare, b, s, trail):
                    if several:
                        yield from annots_ways(pattern.annots, b.annots, s, trail)
                    else:
                        yield None
                undo(s, trail, mark)
            else:
                m: dict = {}
                head = rename(b.head, m)
                body = rename(b.body, m)
                if unify(pattern, head, s, trail):
                    yield from solve(agent, body, s, trail)
                undo(s, trail, mark)

    def collect(self, pattern: Literal, template: Term, s: dict) -> list | None:
        """``.findall``'s common case without a generator per solution: ``template``
        under each way ``pattern`` unifies with a fact, in :meth:`query`'s order, or
        ``None`` when the predicate has rules or facts with variables, or the pattern
        annotations (use :meth:`query` then). ``s`` is left as it was."""
        key = (pattern.functor, len(pattern.args), pattern.neg)
        bucket = self._index.get(key)
        if not bucket:
            return []
        if self._mixed.get(key) or pattern.annots:
            return None
        args = pattern.args
        vals = self._narrowed(key, bucket, args, s)
        if vals is None:
            return []
        cands = tuple(vals.values())[::-1]
        while template.__class__ is Var:
            v = s.get(template)
            if v is None:
                break
            template = v
        # every argument a distinct unbound variable (``val(_, V)``): each fact binds
        # them as they stand; a template that is one of them is that argument of each
        place = {}
        for k, v in enumerate(args):
            if v.__class__ is not Var or v in s or v in place:
                break
            place[v] = k
        else:
            if template.__class__ is Var:
                k = place.get(template)
                if k is not None:
                    return [b.args[k] for b in cands]
            elif is_ground(template):
                return [template] * len(cands)
        trail: list = []
        out = []
        for b in cands:
            if unify(pattern, b, s, trail):
                out.append(resolve(template, s, {}))
            undo(s, trail, 0)
        return out

    def first(
        self, pattern: Literal, s: dict, trail: list, key: tuple | None = None
    ) -> bool | None:
        """The first fact unifying with ``pattern`` (bindings kept in ``s``): True or
        False, or ``None`` when the predicate has rules or non-ground facts (use
        :meth:`query` then). ``key`` is the pattern's predicate, when known."""
        if key is None:
            key = (pattern.functor, len(pattern.args), pattern.neg)
        bucket = self._index.get(key)
        if not bucket:
            return False
        if self._mixed.get(key):
            return None
        if pattern.ground and not pattern.annots:
            sub = self._first.get(key)
            if pattern.args:
                sub = sub.get(pattern.args[0]) if sub else None
                return bool(sub) and pattern.args in sub
            return pattern.args in bucket
        sub = self._narrowed(key, bucket, pattern.args, s)
        if sub is None:
            return False
        vals = sub.values()
        mark = len(trail)
        annots = pattern.annots
        for b in reversed(vals):
            # unify(pattern, b) for a ground fact of the same predicate, with the
            # common case (an unbound variable against an argument) done in place
            for x, y in zip(pattern.args, b.args):  # noqa: B905 - same arity
                if x.__class__ is Var and x not in s:
                    s[x] = y
                    trail.append(x)
                elif not unify(x, y, s, trail):
                    break
            else:
                if not annots or annots_subset(annots, b.annots, s, trail):
                    return True
            undo(s, trail, mark)
        return False

    def first_det(
        self, pattern: Literal, s: dict, trail: list, key: tuple | None = None
    ) -> bool | None:
        """Like :meth:`first`, but only decides when the answer is unique: True (the one
        fact that can match did, bindings kept in ``s``), False (nothing matches) or
        ``None`` (rules, non-ground facts or several candidates: use :meth:`query`)."""
        if key is None:
            key = (pattern.functor, len(pattern.args), pattern.neg)
        bucket = self._index.get(key)
        if not bucket:
            return False
        if self._mixed.get(key):
            return None
        args = pattern.args
        if pattern.ground and not pattern.annots:
            if args:
                sub = self._first[key].get(args[0])
                return bool(sub) and args in sub
            return args in bucket
        vals = self._narrowed(key, bucket, args, s)
        if vals is None:
            return False
        if len(vals) != 1:
            return None
        for b in vals.values():
            mark = len(trail)
            if unify(pattern, b, s, trail):
                return True
            undo(s, trail, mark)
        return False

    def __iter__(self) -> Iterator[Literal]:
        """All facts (not rules), predicate by predicate, newest first."""
        for bucket in self._index.values():
            for v in reversed(tuple(bucket.values())):
                if v.__class__ is Literal:
                    yield v

    def has_rule(self, functor: str, arity: int) -> bool:
        """True when some rule has the head ``functor/arity``."""
        bucket = self._index.get((functor, arity, False))
        return bool(bucket) and any(v.__class__ is StoredRule for v in bucket.values())

    def rules(self) -> Iterator[StoredRule]:
        """All rules."""
        for bucket in self._index.values():
            for v in reversed(tuple(bucket.values())):
                if v.__class__ is StoredRule:
                    yield v

    def __len__(self) -> int:
        return self._size
