"""The rule table's matchers: one straight-line function per row of ``rules.RULES``.

GENERATED from the rule table by ``rulegen.matcher_source()``: do not edit. After a
change to the table, ``python tools/nars_rule_matchers.py`` writes this file again;
tests/nars/test_rule_matchers.py fails while it does not match the table.

Each function matches the premises ``t1`` and ``t2`` against its rule's patterns, with
no recursion and no dictionary of bindings (a pattern variable is a local), and hands
the conclusion, its truth and whether variables are to be introduced to ``emit``. As a
module rather than code made at import, it is compiled with the rest of the engine.
"""

from __future__ import annotations

from . import truth as tf
from .rules import Emit, make
from .terms import Term, compound
from .truth import Truth


def r0(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<S --> M>, <M --> P> |- <S --> P> (deduction, NAL-1)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    S: Term = a1[0]
    M: Term = a1[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a2 = t2.args
    if a2[0] is not M:
        return
    P: Term = a2[1]
    k3 = compound("-->", (S, P))
    emit(k3, tf.deduction(v1, v2), False)


def r1(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<A --> B>, <A --> C> |- <C --> B> (induction, NAL-1)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    A: Term = a1[0]
    B: Term = a1[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a2 = t2.args
    if a2[0] is not A:
        return
    C: Term = a2[1]
    k3 = compound("-->", (C, B))
    emit(k3, tf.induction(v1, v2), False)


def r2(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<A --> C>, <B --> C> |- <B --> A> (abduction, NAL-1)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    A: Term = a1[0]
    C: Term = a1[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a2 = t2.args
    B: Term = a2[0]
    if a2[1] is not C:
        return
    k3 = compound("-->", (B, A))
    emit(k3, tf.abduction(v1, v2), False)


def r3(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<A --> B>, <B --> C> |- <C --> A> (exemplification, NAL-1)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    A: Term = a1[0]
    B: Term = a1[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a2 = t2.args
    if a2[0] is not B:
        return
    C: Term = a2[1]
    k3 = compound("-->", (C, A))
    emit(k3, tf.exemplification(v1, v2), False)


def r4(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<S <-> P> |- <P <-> S> (structural_intersection, NAL-2)"""
    if t1.op != "<->" or len(t1.args) != 2:
        return
    a1 = t1.args
    S: Term = a1[0]
    P: Term = a1[1]
    k2 = compound("<->", (P, S))
    emit(k2, tf.structural_intersection(v1, v2), False)


def r5(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<M <-> P>, <S <-> M> |- <S <-> P> (resemblance, NAL-2)"""
    if t1.op != "<->" or len(t1.args) != 2:
        return
    a1 = t1.args
    M: Term = a1[0]
    P: Term = a1[1]
    if t2.op != "<->" or len(t2.args) != 2:
        return
    a2 = t2.args
    S: Term = a2[0]
    if a2[1] is not M:
        return
    k3 = compound("<->", (S, P))
    emit(k3, tf.resemblance(v1, v2), False)


def r6(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<P --> M>, <S --> M> |- <S <-> P> (comparison, NAL-2)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    P: Term = a1[0]
    M: Term = a1[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a2 = t2.args
    S: Term = a2[0]
    if a2[1] is not M:
        return
    k3 = compound("<->", (S, P))
    emit(k3, tf.comparison(v1, v2), False)


def r7(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<M --> P>, <M --> S> |- <S <-> P> (comparison, NAL-2)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    M: Term = a1[0]
    P: Term = a1[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a2 = t2.args
    if a2[0] is not M:
        return
    S: Term = a2[1]
    k3 = compound("<->", (S, P))
    emit(k3, tf.comparison(v1, v2), False)


def r8(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<M --> P>, <S <-> M> |- <S --> P> (analogy, NAL-2)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    M: Term = a1[0]
    P: Term = a1[1]
    if t2.op != "<->" or len(t2.args) != 2:
        return
    a2 = t2.args
    S: Term = a2[0]
    if a2[1] is not M:
        return
    k3 = compound("-->", (S, P))
    emit(k3, tf.analogy(v1, v2), False)


def r9(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<P --> M>, <S <-> M> |- <P --> S> (analogy, NAL-2)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    P: Term = a1[0]
    M: Term = a1[1]
    if t2.op != "<->" or len(t2.args) != 2:
        return
    a2 = t2.args
    S: Term = a2[0]
    if a2[1] is not M:
        return
    k3 = compound("-->", (P, S))
    emit(k3, tf.analogy(v1, v2), False)


def r10(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """S, <S <-> P> |- P (analogy, NAL-2)"""
    S: Term = t1
    if t2.op != "<->" or len(t2.args) != 2:
        return
    a1 = t2.args
    if a1[0] is not S:
        return
    P: Term = a1[1]
    emit(P, tf.analogy(v1, v2), False)


def r11(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """S, <P <-> S> |- P (analogy, NAL-2)"""
    S: Term = t1
    if t2.op != "<->" or len(t2.args) != 2:
        return
    a1 = t2.args
    P: Term = a1[0]
    if a1[1] is not S:
        return
    emit(P, tf.analogy(v1, v2), False)


def r12(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<S --> {P}> |- <S <-> {P}> (structural_intersection, NAL-2)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    S: Term = a1[0]
    x2: Term = a1[1]
    if x2.op != "{}" or len(x2.args) != 1:
        return
    a3 = x2.args
    P: Term = a3[0]
    k4 = make("{}", (P,))
    k5 = compound("<->", (S, k4))
    emit(k5, tf.structural_intersection(v1, v2), False)


def r13(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<[S] --> P> |- <[S] <-> P> (structural_intersection, NAL-2)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "[]" or len(x2.args) != 1:
        return
    a3 = x2.args
    S: Term = a3[0]
    P: Term = a1[1]
    k4 = make("[]", (S,))
    k5 = compound("<->", (k4, P))
    emit(k5, tf.structural_intersection(v1, v2), False)


def r14(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<{M} --> P>, <S <-> M> |- <{S} --> P> (analogy, NAL-2)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "{}" or len(x2.args) != 1:
        return
    a3 = x2.args
    M: Term = a3[0]
    P: Term = a1[1]
    if t2.op != "<->" or len(t2.args) != 2:
        return
    a4 = t2.args
    S: Term = a4[0]
    if a4[1] is not M:
        return
    k5 = make("{}", (S,))
    k6 = compound("-->", (k5, P))
    emit(k6, tf.analogy(v1, v2), False)


def r15(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<P --> [M]>, <S <-> M> |- <P --> [S]> (analogy, NAL-2)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    P: Term = a1[0]
    x2: Term = a1[1]
    if x2.op != "[]" or len(x2.args) != 1:
        return
    a3 = x2.args
    M: Term = a3[0]
    if t2.op != "<->" or len(t2.args) != 2:
        return
    a4 = t2.args
    S: Term = a4[0]
    if a4[1] is not M:
        return
    k5 = make("[]", (S,))
    k6 = compound("-->", (P, k5))
    emit(k6, tf.analogy(v1, v2), False)


def r16(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<{A} <-> {B}> |- <A <-> B> (structural_intersection, NAL-2)"""
    if t1.op != "<->" or len(t1.args) != 2:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "{}" or len(x2.args) != 1:
        return
    a3 = x2.args
    A: Term = a3[0]
    x4: Term = a1[1]
    if x4.op != "{}" or len(x4.args) != 1:
        return
    a5 = x4.args
    B: Term = a5[0]
    k6 = compound("<->", (A, B))
    emit(k6, tf.structural_intersection(v1, v2), False)


def r17(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<[A] <-> [B]> |- <A <-> B> (structural_intersection, NAL-2)"""
    if t1.op != "<->" or len(t1.args) != 2:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "[]" or len(x2.args) != 1:
        return
    a3 = x2.args
    A: Term = a3[0]
    x4: Term = a1[1]
    if x4.op != "[]" or len(x4.args) != 1:
        return
    a5 = x4.args
    B: Term = a5[0]
    k6 = compound("<->", (A, B))
    emit(k6, tf.structural_intersection(v1, v2), False)


def r18(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<{A B} --> M> |- <{A} --> M> (structural_deduction, NAL-3)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "{}" or len(x2.args) != 2:
        return
    a3 = x2.args
    A: Term = a3[0]
    M: Term = a1[1]
    k4 = make("{}", (A,))
    k5 = compound("-->", (k4, M))
    emit(k5, tf.structural_deduction(v1, v2), False)


def r19(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<{A B} --> M> |- <{B} --> M> (structural_deduction, NAL-3)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "{}" or len(x2.args) != 2:
        return
    a3 = x2.args
    B: Term = a3[1]
    M: Term = a1[1]
    k4 = make("{}", (B,))
    k5 = compound("-->", (k4, M))
    emit(k5, tf.structural_deduction(v1, v2), False)


def r20(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<M --> [A B]> |- <M --> [A]> (structural_deduction, NAL-3)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    M: Term = a1[0]
    x2: Term = a1[1]
    if x2.op != "[]" or len(x2.args) != 2:
        return
    a3 = x2.args
    A: Term = a3[0]
    k4 = make("[]", (A,))
    k5 = compound("-->", (M, k4))
    emit(k5, tf.structural_deduction(v1, v2), False)


def r21(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<M --> [A B]> |- <M --> [B]> (structural_deduction, NAL-3)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    M: Term = a1[0]
    x2: Term = a1[1]
    if x2.op != "[]" or len(x2.args) != 2:
        return
    a3 = x2.args
    B: Term = a3[1]
    k4 = make("[]", (B,))
    k5 = compound("-->", (M, k4))
    emit(k5, tf.structural_deduction(v1, v2), False)


def r22(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<(S | P) --> M> |- <S --> M> (structural_deduction, NAL-3)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "|" or len(x2.args) != 2:
        return
    a3 = x2.args
    S: Term = a3[0]
    M: Term = a1[1]
    k4 = compound("-->", (S, M))
    emit(k4, tf.structural_deduction(v1, v2), False)


def r23(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<M --> (S & P)> |- <M --> S> (structural_deduction, NAL-3)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    M: Term = a1[0]
    x2: Term = a1[1]
    if x2.op != "&" or len(x2.args) != 2:
        return
    a3 = x2.args
    S: Term = a3[0]
    k4 = compound("-->", (M, S))
    emit(k4, tf.structural_deduction(v1, v2), False)


def r24(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<(S | P) --> M> |- <P --> M> (structural_deduction, NAL-3)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "|" or len(x2.args) != 2:
        return
    a3 = x2.args
    P: Term = a3[1]
    M: Term = a1[1]
    k4 = compound("-->", (P, M))
    emit(k4, tf.structural_deduction(v1, v2), False)


def r25(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<M --> (S & P)> |- <M --> P> (structural_deduction, NAL-3)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    M: Term = a1[0]
    x2: Term = a1[1]
    if x2.op != "&" or len(x2.args) != 2:
        return
    a3 = x2.args
    P: Term = a3[1]
    k4 = compound("-->", (M, P))
    emit(k4, tf.structural_deduction(v1, v2), False)


def r26(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<(A ~ S) --> M> |- <A --> M> (structural_deduction, NAL-3)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "~" or len(x2.args) != 2:
        return
    a3 = x2.args
    A: Term = a3[0]
    M: Term = a1[1]
    k4 = compound("-->", (A, M))
    emit(k4, tf.structural_deduction(v1, v2), False)


def r27(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<M --> (B - S)> |- <M --> B> (structural_deduction, NAL-3)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    M: Term = a1[0]
    x2: Term = a1[1]
    if x2.op != "-" or len(x2.args) != 2:
        return
    a3 = x2.args
    B: Term = a3[0]
    k4 = compound("-->", (M, B))
    emit(k4, tf.structural_deduction(v1, v2), False)


def r28(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<(A ~ S) --> M> |- <S --> M> (structural_deduction_negated, NAL-3)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "~" or len(x2.args) != 2:
        return
    a3 = x2.args
    S: Term = a3[1]
    M: Term = a1[1]
    k4 = compound("-->", (S, M))
    emit(k4, tf.structural_deduction_negated(v1, v2), False)


def r29(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<M --> (B - S)> |- <M --> S> (structural_deduction_negated, NAL-3)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    M: Term = a1[0]
    x2: Term = a1[1]
    if x2.op != "-" or len(x2.args) != 2:
        return
    a3 = x2.args
    S: Term = a3[1]
    k4 = compound("-->", (M, S))
    emit(k4, tf.structural_deduction_negated(v1, v2), False)


def r30(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<P --> M>, <S --> M> |- <(P | S) --> M> (intersection, NAL-3)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    P: Term = a1[0]
    M: Term = a1[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a2 = t2.args
    S: Term = a2[0]
    if a2[1] is not M:
        return
    k3 = make("|", (P, S))
    k4 = compound("-->", (k3, M))
    emit(k4, tf.intersection(v1, v2), False)


def r31(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<P --> M>, <S --> M> |- <(P & S) --> M> (union, NAL-3)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    P: Term = a1[0]
    M: Term = a1[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a2 = t2.args
    S: Term = a2[0]
    if a2[1] is not M:
        return
    k3 = make("&", (P, S))
    k4 = compound("-->", (k3, M))
    emit(k4, tf.union(v1, v2), False)


def r32(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<P --> M>, <S --> M> |- <(P ~ S) --> M> (difference, NAL-3)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    P: Term = a1[0]
    M: Term = a1[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a2 = t2.args
    S: Term = a2[0]
    if a2[1] is not M:
        return
    k3 = compound("~", (P, S))
    k4 = compound("-->", (k3, M))
    emit(k4, tf.difference(v1, v2), False)


def r33(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<M --> P>, <M --> S> |- <M --> (P & S)> (intersection, NAL-3)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    M: Term = a1[0]
    P: Term = a1[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a2 = t2.args
    if a2[0] is not M:
        return
    S: Term = a2[1]
    k3 = make("&", (P, S))
    k4 = compound("-->", (M, k3))
    emit(k4, tf.intersection(v1, v2), False)


def r34(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<M --> P>, <M --> S> |- <M --> (P | S)> (union, NAL-3)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    M: Term = a1[0]
    P: Term = a1[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a2 = t2.args
    if a2[0] is not M:
        return
    S: Term = a2[1]
    k3 = make("|", (P, S))
    k4 = compound("-->", (M, k3))
    emit(k4, tf.union(v1, v2), False)


def r35(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<M --> P>, <M --> S> |- <M --> (P - S)> (difference, NAL-3)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    M: Term = a1[0]
    P: Term = a1[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a2 = t2.args
    if a2[0] is not M:
        return
    S: Term = a2[1]
    k3 = compound("-", (P, S))
    k4 = compound("-->", (M, k3))
    emit(k4, tf.difference(v1, v2), False)


def r36(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<S --> M>, <(S | P) --> M> |- <P --> M> (decompose_pnn, NAL-3)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    S: Term = a1[0]
    M: Term = a1[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a2 = t2.args
    x3: Term = a2[0]
    if x3.op != "|" or len(x3.args) != 2:
        return
    a4 = x3.args
    if a4[0] is not S:
        return
    P: Term = a4[1]
    if a2[1] is not M:
        return
    k5 = compound("-->", (P, M))
    emit(k5, tf.decompose_pnn(v1, v2), False)


def r37(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<P --> M>, <(S | P) --> M> |- <S --> M> (decompose_pnn, NAL-3)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    P: Term = a1[0]
    M: Term = a1[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a2 = t2.args
    x3: Term = a2[0]
    if x3.op != "|" or len(x3.args) != 2:
        return
    a4 = x3.args
    S: Term = a4[0]
    if a4[1] is not P:
        return
    if a2[1] is not M:
        return
    k5 = compound("-->", (S, M))
    emit(k5, tf.decompose_pnn(v1, v2), False)


def r38(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<S --> M>, <(S & P) --> M> |- <P --> M> (decompose_npp, NAL-3)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    S: Term = a1[0]
    M: Term = a1[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a2 = t2.args
    x3: Term = a2[0]
    if x3.op != "&" or len(x3.args) != 2:
        return
    a4 = x3.args
    if a4[0] is not S:
        return
    P: Term = a4[1]
    if a2[1] is not M:
        return
    k5 = compound("-->", (P, M))
    emit(k5, tf.decompose_npp(v1, v2), False)


def r39(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<P --> M>, <(S & P) --> M> |- <S --> M> (decompose_npp, NAL-3)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    P: Term = a1[0]
    M: Term = a1[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a2 = t2.args
    x3: Term = a2[0]
    if x3.op != "&" or len(x3.args) != 2:
        return
    a4 = x3.args
    S: Term = a4[0]
    if a4[1] is not P:
        return
    if a2[1] is not M:
        return
    k5 = compound("-->", (S, M))
    emit(k5, tf.decompose_npp(v1, v2), False)


def r40(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<S --> M>, <(S ~ P) --> M> |- <P --> M> (decompose_pnp, NAL-3)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    S: Term = a1[0]
    M: Term = a1[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a2 = t2.args
    x3: Term = a2[0]
    if x3.op != "~" or len(x3.args) != 2:
        return
    a4 = x3.args
    if a4[0] is not S:
        return
    P: Term = a4[1]
    if a2[1] is not M:
        return
    k5 = compound("-->", (P, M))
    emit(k5, tf.decompose_pnp(v1, v2), False)


def r41(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<S --> M>, <(P ~ S) --> M> |- <P --> M> (decompose_nnn, NAL-3)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    S: Term = a1[0]
    M: Term = a1[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a2 = t2.args
    x3: Term = a2[0]
    if x3.op != "~" or len(x3.args) != 2:
        return
    a4 = x3.args
    P: Term = a4[0]
    if a4[1] is not S:
        return
    if a2[1] is not M:
        return
    k5 = compound("-->", (P, M))
    emit(k5, tf.decompose_nnn(v1, v2), False)


def r42(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<M --> S>, <M --> (S & P)> |- <M --> P> (decompose_pnn, NAL-3)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    M: Term = a1[0]
    S: Term = a1[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a2 = t2.args
    if a2[0] is not M:
        return
    x3: Term = a2[1]
    if x3.op != "&" or len(x3.args) != 2:
        return
    a4 = x3.args
    if a4[0] is not S:
        return
    P: Term = a4[1]
    k5 = compound("-->", (M, P))
    emit(k5, tf.decompose_pnn(v1, v2), False)


def r43(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<M --> P>, <M --> (S & P)> |- <M --> S> (decompose_pnn, NAL-3)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    M: Term = a1[0]
    P: Term = a1[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a2 = t2.args
    if a2[0] is not M:
        return
    x3: Term = a2[1]
    if x3.op != "&" or len(x3.args) != 2:
        return
    a4 = x3.args
    S: Term = a4[0]
    if a4[1] is not P:
        return
    k5 = compound("-->", (M, S))
    emit(k5, tf.decompose_pnn(v1, v2), False)


def r44(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<M --> S>, <M --> (S | P)> |- <M --> P> (decompose_npp, NAL-3)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    M: Term = a1[0]
    S: Term = a1[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a2 = t2.args
    if a2[0] is not M:
        return
    x3: Term = a2[1]
    if x3.op != "|" or len(x3.args) != 2:
        return
    a4 = x3.args
    if a4[0] is not S:
        return
    P: Term = a4[1]
    k5 = compound("-->", (M, P))
    emit(k5, tf.decompose_npp(v1, v2), False)


def r45(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<M --> P>, <M --> (S | P)> |- <M --> S> (decompose_npp, NAL-3)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    M: Term = a1[0]
    P: Term = a1[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a2 = t2.args
    if a2[0] is not M:
        return
    x3: Term = a2[1]
    if x3.op != "|" or len(x3.args) != 2:
        return
    a4 = x3.args
    S: Term = a4[0]
    if a4[1] is not P:
        return
    k5 = compound("-->", (M, S))
    emit(k5, tf.decompose_npp(v1, v2), False)


def r46(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<M --> S>, <M --> (S - P)> |- <M --> P> (decompose_pnp, NAL-3)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    M: Term = a1[0]
    S: Term = a1[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a2 = t2.args
    if a2[0] is not M:
        return
    x3: Term = a2[1]
    if x3.op != "-" or len(x3.args) != 2:
        return
    a4 = x3.args
    if a4[0] is not S:
        return
    P: Term = a4[1]
    k5 = compound("-->", (M, P))
    emit(k5, tf.decompose_pnp(v1, v2), False)


def r47(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<M --> S>, <M --> (P - S)> |- <M --> P> (decompose_nnn, NAL-3)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    M: Term = a1[0]
    S: Term = a1[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a2 = t2.args
    if a2[0] is not M:
        return
    x3: Term = a2[1]
    if x3.op != "-" or len(x3.args) != 2:
        return
    a4 = x3.args
    P: Term = a4[0]
    if a4[1] is not S:
        return
    k5 = compound("-->", (M, P))
    emit(k5, tf.decompose_nnn(v1, v2), False)


def r48(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<(A * B) --> (S * M)> |- <A --> S> (structural_deduction, NAL-4)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "*" or len(x2.args) != 2:
        return
    a3 = x2.args
    A: Term = a3[0]
    x4: Term = a1[1]
    if x4.op != "*" or len(x4.args) != 2:
        return
    a5 = x4.args
    S: Term = a5[0]
    k6 = compound("-->", (A, S))
    emit(k6, tf.structural_deduction(v1, v2), False)


def r49(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<(A * B) --> (S * M)> |- <B --> M> (structural_deduction, NAL-4)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "*" or len(x2.args) != 2:
        return
    a3 = x2.args
    B: Term = a3[1]
    x4: Term = a1[1]
    if x4.op != "*" or len(x4.args) != 2:
        return
    a5 = x4.args
    M: Term = a5[1]
    k6 = compound("-->", (B, M))
    emit(k6, tf.structural_deduction(v1, v2), False)


def r50(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<(A * B) --> R> |- <A --> (R /1 B)> (structural_intersection, NAL-4)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "*" or len(x2.args) != 2:
        return
    a3 = x2.args
    A: Term = a3[0]
    B: Term = a3[1]
    R: Term = a1[1]
    k4 = compound("/1", (R, B))
    k5 = compound("-->", (A, k4))
    emit(k5, tf.structural_intersection(v1, v2), False)


def r51(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<A --> (R /1 B)> |- <(A * B) --> R> (structural_intersection, NAL-4)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    A: Term = a1[0]
    x2: Term = a1[1]
    if x2.op != "/1" or len(x2.args) != 2:
        return
    a3 = x2.args
    R: Term = a3[0]
    B: Term = a3[1]
    k4 = compound("*", (A, B))
    k5 = compound("-->", (k4, R))
    emit(k5, tf.structural_intersection(v1, v2), False)


def r52(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<(A * B) --> R> |- <B --> (R /2 A)> (structural_intersection, NAL-4)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "*" or len(x2.args) != 2:
        return
    a3 = x2.args
    A: Term = a3[0]
    B: Term = a3[1]
    R: Term = a1[1]
    k4 = compound("/2", (R, A))
    k5 = compound("-->", (B, k4))
    emit(k5, tf.structural_intersection(v1, v2), False)


def r53(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<B --> (R /2 A)> |- <(A * B) --> R> (structural_intersection, NAL-4)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    B: Term = a1[0]
    x2: Term = a1[1]
    if x2.op != "/2" or len(x2.args) != 2:
        return
    a3 = x2.args
    R: Term = a3[0]
    A: Term = a3[1]
    k4 = compound("*", (A, B))
    k5 = compound("-->", (k4, R))
    emit(k5, tf.structural_intersection(v1, v2), False)


def r54(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<R --> (A * B)> |- <(R \\1 B) --> A> (structural_intersection, NAL-4)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    R: Term = a1[0]
    x2: Term = a1[1]
    if x2.op != "*" or len(x2.args) != 2:
        return
    a3 = x2.args
    A: Term = a3[0]
    B: Term = a3[1]
    k4 = compound("\\1", (R, B))
    k5 = compound("-->", (k4, A))
    emit(k5, tf.structural_intersection(v1, v2), False)


def r55(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<(R \\1 B) --> A> |- <R --> (A * B)> (structural_intersection, NAL-4)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "\\1" or len(x2.args) != 2:
        return
    a3 = x2.args
    R: Term = a3[0]
    B: Term = a3[1]
    A: Term = a1[1]
    k4 = compound("*", (A, B))
    k5 = compound("-->", (R, k4))
    emit(k5, tf.structural_intersection(v1, v2), False)


def r56(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<R --> (A * B)> |- <(R \\2 A) --> B> (structural_intersection, NAL-4)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    R: Term = a1[0]
    x2: Term = a1[1]
    if x2.op != "*" or len(x2.args) != 2:
        return
    a3 = x2.args
    A: Term = a3[0]
    B: Term = a3[1]
    k4 = compound("\\2", (R, A))
    k5 = compound("-->", (k4, B))
    emit(k5, tf.structural_intersection(v1, v2), False)


def r57(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<(R \\2 A) --> B> |- <R --> (A * B)> (structural_intersection, NAL-4)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "\\2" or len(x2.args) != 2:
        return
    a3 = x2.args
    R: Term = a3[0]
    A: Term = a3[1]
    B: Term = a1[1]
    k4 = compound("*", (A, B))
    k5 = compound("-->", (R, k4))
    emit(k5, tf.structural_intersection(v1, v2), False)


def r58(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<{R} |-> [P]>, <{S} |-> [P]> |- <({R} * {S}) --> (+ P)> (frequency_greater, NAL-4)"""
    if t1.op != "|->" or len(t1.args) != 2:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "{}" or len(x2.args) != 1:
        return
    a3 = x2.args
    R: Term = a3[0]
    x4: Term = a1[1]
    if x4.op != "[]" or len(x4.args) != 1:
        return
    a5 = x4.args
    P: Term = a5[0]
    if t2.op != "|->" or len(t2.args) != 2:
        return
    a6 = t2.args
    x7: Term = a6[0]
    if x7.op != "{}" or len(x7.args) != 1:
        return
    a8 = x7.args
    S: Term = a8[0]
    x9: Term = a6[1]
    if x9.op != "[]" or len(x9.args) != 1:
        return
    a10 = x9.args
    if a10[0] is not P:
        return
    k11 = make("{}", (R,))
    k12 = make("{}", (S,))
    k13 = compound("*", (k11, k12))
    k14 = compound("+", (P,))
    k15 = compound("-->", (k13, k14))
    emit(k15, tf.frequency_greater(v1, v2), False)


def r59(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<(A * B) --> (+ P)>, <(B * C) --> (+ P)> |- <(A * C) --> (+ P)> (deduction, NAL-4)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "*" or len(x2.args) != 2:
        return
    a3 = x2.args
    A: Term = a3[0]
    B: Term = a3[1]
    x4: Term = a1[1]
    if x4.op != "+" or len(x4.args) != 1:
        return
    a5 = x4.args
    P: Term = a5[0]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a6 = t2.args
    x7: Term = a6[0]
    if x7.op != "*" or len(x7.args) != 2:
        return
    a8 = x7.args
    if a8[0] is not B:
        return
    C: Term = a8[1]
    x9: Term = a6[1]
    if x9.op != "+" or len(x9.args) != 1:
        return
    a10 = x9.args
    if a10[0] is not P:
        return
    k11 = compound("*", (A, C))
    k12 = compound("+", (P,))
    k13 = compound("-->", (k11, k12))
    emit(k13, tf.deduction(v1, v2), False)


def r60(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<{R} |-> [P]>, <{S} |-> [P]> |- <({R} * {S}) --> (= P)> (frequency_equal, NAL-4)"""
    if t1.op != "|->" or len(t1.args) != 2:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "{}" or len(x2.args) != 1:
        return
    a3 = x2.args
    R: Term = a3[0]
    x4: Term = a1[1]
    if x4.op != "[]" or len(x4.args) != 1:
        return
    a5 = x4.args
    P: Term = a5[0]
    if t2.op != "|->" or len(t2.args) != 2:
        return
    a6 = t2.args
    x7: Term = a6[0]
    if x7.op != "{}" or len(x7.args) != 1:
        return
    a8 = x7.args
    S: Term = a8[0]
    x9: Term = a6[1]
    if x9.op != "[]" or len(x9.args) != 1:
        return
    a10 = x9.args
    if a10[0] is not P:
        return
    k11 = make("{}", (R,))
    k12 = make("{}", (S,))
    k13 = compound("*", (k11, k12))
    k14 = compound("=", (P,))
    k15 = compound("-->", (k13, k14))
    emit(k15, tf.frequency_equal(v1, v2), False)


def r61(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<(A * B) --> (= P)>, <(B * C) --> (= P)> |- <(A * C) --> (= P)> (deduction, NAL-4)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "*" or len(x2.args) != 2:
        return
    a3 = x2.args
    A: Term = a3[0]
    B: Term = a3[1]
    x4: Term = a1[1]
    if x4.op != "=" or len(x4.args) != 1:
        return
    a5 = x4.args
    P: Term = a5[0]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a6 = t2.args
    x7: Term = a6[0]
    if x7.op != "*" or len(x7.args) != 2:
        return
    a8 = x7.args
    if a8[0] is not B:
        return
    C: Term = a8[1]
    x9: Term = a6[1]
    if x9.op != "=" or len(x9.args) != 1:
        return
    a10 = x9.args
    if a10[0] is not P:
        return
    k11 = compound("*", (A, C))
    k12 = compound("=", (P,))
    k13 = compound("-->", (k11, k12))
    emit(k13, tf.deduction(v1, v2), False)


def r62(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<(A * B) --> (= P)> |- <(B * A) --> (= P)> (structural_intersection, NAL-4)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "*" or len(x2.args) != 2:
        return
    a3 = x2.args
    A: Term = a3[0]
    B: Term = a3[1]
    x4: Term = a1[1]
    if x4.op != "=" or len(x4.args) != 1:
        return
    a5 = x4.args
    P: Term = a5[0]
    k6 = compound("*", (B, A))
    k7 = compound("=", (P,))
    k8 = compound("-->", (k6, k7))
    emit(k8, tf.structural_intersection(v1, v2), False)


def r63(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<(A * B) --> R>, <(C * B) --> R> |- <C --> A> (abduction, NAL-4)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "*" or len(x2.args) != 2:
        return
    a3 = x2.args
    A: Term = a3[0]
    B: Term = a3[1]
    R: Term = a1[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a4 = t2.args
    x5: Term = a4[0]
    if x5.op != "*" or len(x5.args) != 2:
        return
    a6 = x5.args
    C: Term = a6[0]
    if a6[1] is not B:
        return
    if a4[1] is not R:
        return
    k7 = compound("-->", (C, A))
    emit(k7, tf.abduction(v1, v2), False)


def r64(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<(A * B) --> R>, <(A * C) --> R> |- <C --> B> (abduction, NAL-4)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "*" or len(x2.args) != 2:
        return
    a3 = x2.args
    A: Term = a3[0]
    B: Term = a3[1]
    R: Term = a1[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a4 = t2.args
    x5: Term = a4[0]
    if x5.op != "*" or len(x5.args) != 2:
        return
    a6 = x5.args
    if a6[0] is not A:
        return
    C: Term = a6[1]
    if a4[1] is not R:
        return
    k7 = compound("-->", (C, B))
    emit(k7, tf.abduction(v1, v2), False)


def r65(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<R --> (A * B)>, <R --> (C * B)> |- <C --> A> (induction, NAL-4)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    R: Term = a1[0]
    x2: Term = a1[1]
    if x2.op != "*" or len(x2.args) != 2:
        return
    a3 = x2.args
    A: Term = a3[0]
    B: Term = a3[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a4 = t2.args
    if a4[0] is not R:
        return
    x5: Term = a4[1]
    if x5.op != "*" or len(x5.args) != 2:
        return
    a6 = x5.args
    C: Term = a6[0]
    if a6[1] is not B:
        return
    k7 = compound("-->", (C, A))
    emit(k7, tf.induction(v1, v2), False)


def r66(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<R --> (A * B)>, <R --> (A * C)> |- <C --> B> (induction, NAL-4)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    R: Term = a1[0]
    x2: Term = a1[1]
    if x2.op != "*" or len(x2.args) != 2:
        return
    a3 = x2.args
    A: Term = a3[0]
    B: Term = a3[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a4 = t2.args
    if a4[0] is not R:
        return
    x5: Term = a4[1]
    if x5.op != "*" or len(x5.args) != 2:
        return
    a6 = x5.args
    if a6[0] is not A:
        return
    C: Term = a6[1]
    k7 = compound("-->", (C, B))
    emit(k7, tf.induction(v1, v2), False)


def r67(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<(A * B) --> R>, <C --> A> |- <(C * B) --> R> (deduction, NAL-4)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "*" or len(x2.args) != 2:
        return
    a3 = x2.args
    A: Term = a3[0]
    B: Term = a3[1]
    R: Term = a1[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a4 = t2.args
    C: Term = a4[0]
    if a4[1] is not A:
        return
    k5 = compound("*", (C, B))
    k6 = compound("-->", (k5, R))
    emit(k6, tf.deduction(v1, v2), False)


def r68(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<(A * B) --> R>, <A --> C> |- <(C * B) --> R> (induction, NAL-4)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "*" or len(x2.args) != 2:
        return
    a3 = x2.args
    A: Term = a3[0]
    B: Term = a3[1]
    R: Term = a1[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a4 = t2.args
    if a4[0] is not A:
        return
    C: Term = a4[1]
    k5 = compound("*", (C, B))
    k6 = compound("-->", (k5, R))
    emit(k6, tf.induction(v1, v2), False)


def r69(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<(A * B) --> R>, <C <-> A> |- <(C * B) --> R> (analogy, NAL-4)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "*" or len(x2.args) != 2:
        return
    a3 = x2.args
    A: Term = a3[0]
    B: Term = a3[1]
    R: Term = a1[1]
    if t2.op != "<->" or len(t2.args) != 2:
        return
    a4 = t2.args
    C: Term = a4[0]
    if a4[1] is not A:
        return
    k5 = compound("*", (C, B))
    k6 = compound("-->", (k5, R))
    emit(k6, tf.analogy(v1, v2), False)


def r70(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<(A * B) --> R>, <C --> B> |- <(A * C) --> R> (deduction, NAL-4)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "*" or len(x2.args) != 2:
        return
    a3 = x2.args
    A: Term = a3[0]
    B: Term = a3[1]
    R: Term = a1[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a4 = t2.args
    C: Term = a4[0]
    if a4[1] is not B:
        return
    k5 = compound("*", (A, C))
    k6 = compound("-->", (k5, R))
    emit(k6, tf.deduction(v1, v2), False)


def r71(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<(A * B) --> R>, <B --> C> |- <(A * C) --> R> (induction, NAL-4)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "*" or len(x2.args) != 2:
        return
    a3 = x2.args
    A: Term = a3[0]
    B: Term = a3[1]
    R: Term = a1[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a4 = t2.args
    if a4[0] is not B:
        return
    C: Term = a4[1]
    k5 = compound("*", (A, C))
    k6 = compound("-->", (k5, R))
    emit(k6, tf.induction(v1, v2), False)


def r72(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<(A * B) --> R>, <C <-> B> |- <(A * C) --> R> (analogy, NAL-4)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "*" or len(x2.args) != 2:
        return
    a3 = x2.args
    A: Term = a3[0]
    B: Term = a3[1]
    R: Term = a1[1]
    if t2.op != "<->" or len(t2.args) != 2:
        return
    a4 = t2.args
    C: Term = a4[0]
    if a4[1] is not B:
        return
    k5 = compound("*", (A, C))
    k6 = compound("-->", (k5, R))
    emit(k6, tf.analogy(v1, v2), False)


def r73(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<R --> (A * B)>, <A --> C> |- <R --> (C * B)> (deduction, NAL-4)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    R: Term = a1[0]
    x2: Term = a1[1]
    if x2.op != "*" or len(x2.args) != 2:
        return
    a3 = x2.args
    A: Term = a3[0]
    B: Term = a3[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a4 = t2.args
    if a4[0] is not A:
        return
    C: Term = a4[1]
    k5 = compound("*", (C, B))
    k6 = compound("-->", (R, k5))
    emit(k6, tf.deduction(v1, v2), False)


def r74(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<R --> (A * B)>, <C --> A> |- <R --> (C * B)> (abduction, NAL-4)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    R: Term = a1[0]
    x2: Term = a1[1]
    if x2.op != "*" or len(x2.args) != 2:
        return
    a3 = x2.args
    A: Term = a3[0]
    B: Term = a3[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a4 = t2.args
    C: Term = a4[0]
    if a4[1] is not A:
        return
    k5 = compound("*", (C, B))
    k6 = compound("-->", (R, k5))
    emit(k6, tf.abduction(v1, v2), False)


def r75(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<R --> (A * B)>, <C <-> A> |- <R --> (C * B)> (analogy, NAL-4)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    R: Term = a1[0]
    x2: Term = a1[1]
    if x2.op != "*" or len(x2.args) != 2:
        return
    a3 = x2.args
    A: Term = a3[0]
    B: Term = a3[1]
    if t2.op != "<->" or len(t2.args) != 2:
        return
    a4 = t2.args
    C: Term = a4[0]
    if a4[1] is not A:
        return
    k5 = compound("*", (C, B))
    k6 = compound("-->", (R, k5))
    emit(k6, tf.analogy(v1, v2), False)


def r76(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<R --> (A * B)>, <B --> C> |- <R --> (A * C)> (deduction, NAL-4)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    R: Term = a1[0]
    x2: Term = a1[1]
    if x2.op != "*" or len(x2.args) != 2:
        return
    a3 = x2.args
    A: Term = a3[0]
    B: Term = a3[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a4 = t2.args
    if a4[0] is not B:
        return
    C: Term = a4[1]
    k5 = compound("*", (A, C))
    k6 = compound("-->", (R, k5))
    emit(k6, tf.deduction(v1, v2), False)


def r77(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<R --> (A * B)>, <C --> B> |- <R --> (A * C)> (abduction, NAL-4)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    R: Term = a1[0]
    x2: Term = a1[1]
    if x2.op != "*" or len(x2.args) != 2:
        return
    a3 = x2.args
    A: Term = a3[0]
    B: Term = a3[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a4 = t2.args
    C: Term = a4[0]
    if a4[1] is not B:
        return
    k5 = compound("*", (A, C))
    k6 = compound("-->", (R, k5))
    emit(k6, tf.abduction(v1, v2), False)


def r78(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<R --> (A * B)>, <C <-> B> |- <R --> (A * C)> (analogy, NAL-4)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    R: Term = a1[0]
    x2: Term = a1[1]
    if x2.op != "*" or len(x2.args) != 2:
        return
    a3 = x2.args
    A: Term = a3[0]
    B: Term = a3[1]
    if t2.op != "<->" or len(t2.args) != 2:
        return
    a4 = t2.args
    C: Term = a4[0]
    if a4[1] is not B:
        return
    k5 = compound("*", (A, C))
    k6 = compound("-->", (R, k5))
    emit(k6, tf.analogy(v1, v2), False)


def r79(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<(A * B) --> R>, <(C * B) --> R> |- <A <-> C> (comparison, NAL-4)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "*" or len(x2.args) != 2:
        return
    a3 = x2.args
    A: Term = a3[0]
    B: Term = a3[1]
    R: Term = a1[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a4 = t2.args
    x5: Term = a4[0]
    if x5.op != "*" or len(x5.args) != 2:
        return
    a6 = x5.args
    C: Term = a6[0]
    if a6[1] is not B:
        return
    if a4[1] is not R:
        return
    k7 = compound("<->", (A, C))
    emit(k7, tf.comparison(v1, v2), False)


def r80(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<(A * B) --> R>, <(A * C) --> R> |- <B <-> C> (comparison, NAL-4)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "*" or len(x2.args) != 2:
        return
    a3 = x2.args
    A: Term = a3[0]
    B: Term = a3[1]
    R: Term = a1[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a4 = t2.args
    x5: Term = a4[0]
    if x5.op != "*" or len(x5.args) != 2:
        return
    a6 = x5.args
    if a6[0] is not A:
        return
    C: Term = a6[1]
    if a4[1] is not R:
        return
    k7 = compound("<->", (B, C))
    emit(k7, tf.comparison(v1, v2), False)


def r81(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<R --> (A * B)>, <R --> (C * B)> |- <A <-> C> (comparison, NAL-4)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    R: Term = a1[0]
    x2: Term = a1[1]
    if x2.op != "*" or len(x2.args) != 2:
        return
    a3 = x2.args
    A: Term = a3[0]
    B: Term = a3[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a4 = t2.args
    if a4[0] is not R:
        return
    x5: Term = a4[1]
    if x5.op != "*" or len(x5.args) != 2:
        return
    a6 = x5.args
    C: Term = a6[0]
    if a6[1] is not B:
        return
    k7 = compound("<->", (A, C))
    emit(k7, tf.comparison(v1, v2), False)


def r82(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<R --> (A * B)>, <R --> (A * C)> |- <B <-> C> (comparison, NAL-4)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    R: Term = a1[0]
    x2: Term = a1[1]
    if x2.op != "*" or len(x2.args) != 2:
        return
    a3 = x2.args
    A: Term = a3[0]
    B: Term = a3[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a4 = t2.args
    if a4[0] is not R:
        return
    x5: Term = a4[1]
    if x5.op != "*" or len(x5.args) != 2:
        return
    a6 = x5.args
    if a6[0] is not A:
        return
    C: Term = a6[1]
    k7 = compound("<->", (B, C))
    emit(k7, tf.comparison(v1, v2), False)


def r83(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """(! A) |- A (negation, NAL-5)"""
    if t1.op != "!" or len(t1.args) != 1:
        return
    a1 = t1.args
    A: Term = a1[0]
    emit(A, tf.negation(v1, v2), False)


def r84(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """(A && B) |- A (structural_deduction, NAL-5)"""
    if t1.op != "&&" or len(t1.args) != 2:
        return
    a1 = t1.args
    A: Term = a1[0]
    emit(A, tf.structural_deduction(v1, v2), False)


def r85(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """(A && B) |- B (structural_deduction, NAL-5)"""
    if t1.op != "&&" or len(t1.args) != 2:
        return
    a1 = t1.args
    B: Term = a1[1]
    emit(B, tf.structural_deduction(v1, v2), False)


def r86(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """(A && B) |- (B && A) (structural_intersection, NAL-5)"""
    if t1.op != "&&" or len(t1.args) != 2:
        return
    a1 = t1.args
    A: Term = a1[0]
    B: Term = a1[1]
    k2 = make("&&", (B, A))
    emit(k2, tf.structural_intersection(v1, v2), False)


def r87(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """S, (S && A) |- A (decompose_pnn, NAL-5)"""
    S: Term = t1
    if t2.op != "&&" or len(t2.args) != 2:
        return
    a1 = t2.args
    if a1[0] is not S:
        return
    A: Term = a1[1]
    emit(A, tf.decompose_pnn(v1, v2), False)


def r88(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """S, (S || A) |- A (decompose_npp, NAL-5)"""
    S: Term = t1
    if t2.op != "||" or len(t2.args) != 2:
        return
    a1 = t2.args
    if a1[0] is not S:
        return
    A: Term = a1[1]
    emit(A, tf.decompose_npp(v1, v2), False)


def r89(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """S, ((! S) && A) |- A (decompose_nnn, NAL-5)"""
    S: Term = t1
    if t2.op != "&&" or len(t2.args) != 2:
        return
    a1 = t2.args
    x2: Term = a1[0]
    if x2.op != "!" or len(x2.args) != 1:
        return
    a3 = x2.args
    if a3[0] is not S:
        return
    A: Term = a1[1]
    emit(A, tf.decompose_nnn(v1, v2), False)


def r90(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """S, ((! S) || A) |- A (decompose_ppp, NAL-5)"""
    S: Term = t1
    if t2.op != "||" or len(t2.args) != 2:
        return
    a1 = t2.args
    x2: Term = a1[0]
    if x2.op != "!" or len(x2.args) != 1:
        return
    a3 = x2.args
    if a3[0] is not S:
        return
    A: Term = a1[1]
    emit(A, tf.decompose_ppp(v1, v2), False)


def r91(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<S ==> M>, <M ==> P> |- <S ==> P> (deduction, NAL-5)"""
    if t1.op != "==>" or len(t1.args) != 2:
        return
    a1 = t1.args
    S: Term = a1[0]
    M: Term = a1[1]
    if t2.op != "==>" or len(t2.args) != 2:
        return
    a2 = t2.args
    if a2[0] is not M:
        return
    P: Term = a2[1]
    k3 = compound("==>", (S, P))
    emit(k3, tf.deduction(v1, v2), False)


def r92(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<A ==> B>, <A ==> C> |- <C ==> B> (induction, NAL-5)"""
    if t1.op != "==>" or len(t1.args) != 2:
        return
    a1 = t1.args
    A: Term = a1[0]
    B: Term = a1[1]
    if t2.op != "==>" or len(t2.args) != 2:
        return
    a2 = t2.args
    if a2[0] is not A:
        return
    C: Term = a2[1]
    k3 = compound("==>", (C, B))
    emit(k3, tf.induction(v1, v2), False)


def r93(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<A ==> C>, <B ==> C> |- <B ==> A> (abduction, NAL-5)"""
    if t1.op != "==>" or len(t1.args) != 2:
        return
    a1 = t1.args
    A: Term = a1[0]
    C: Term = a1[1]
    if t2.op != "==>" or len(t2.args) != 2:
        return
    a2 = t2.args
    B: Term = a2[0]
    if a2[1] is not C:
        return
    k3 = compound("==>", (B, A))
    emit(k3, tf.abduction(v1, v2), False)


def r94(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<A ==> B>, <B ==> C> |- <C ==> A> (exemplification, NAL-5)"""
    if t1.op != "==>" or len(t1.args) != 2:
        return
    a1 = t1.args
    A: Term = a1[0]
    B: Term = a1[1]
    if t2.op != "==>" or len(t2.args) != 2:
        return
    a2 = t2.args
    if a2[0] is not B:
        return
    C: Term = a2[1]
    k3 = compound("==>", (C, A))
    emit(k3, tf.exemplification(v1, v2), False)


def r95(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<A ==> C>, <B ==> C> |- <(A && B) ==> C> (union, NAL-5)"""
    if t1.op != "==>" or len(t1.args) != 2:
        return
    a1 = t1.args
    A: Term = a1[0]
    C: Term = a1[1]
    if t2.op != "==>" or len(t2.args) != 2:
        return
    a2 = t2.args
    B: Term = a2[0]
    if a2[1] is not C:
        return
    k3 = make("&&", (A, B))
    k4 = compound("==>", (k3, C))
    emit(k4, tf.union(v1, v2), False)


def r96(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<A ==> C>, <B ==> C> |- <(A || B) ==> C> (intersection, NAL-5)"""
    if t1.op != "==>" or len(t1.args) != 2:
        return
    a1 = t1.args
    A: Term = a1[0]
    C: Term = a1[1]
    if t2.op != "==>" or len(t2.args) != 2:
        return
    a2 = t2.args
    B: Term = a2[0]
    if a2[1] is not C:
        return
    k3 = make("||", (A, B))
    k4 = compound("==>", (k3, C))
    emit(k4, tf.intersection(v1, v2), False)


def r97(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<C ==> A>, <C ==> B> |- <C ==> (A && B)> (intersection, NAL-5)"""
    if t1.op != "==>" or len(t1.args) != 2:
        return
    a1 = t1.args
    C: Term = a1[0]
    A: Term = a1[1]
    if t2.op != "==>" or len(t2.args) != 2:
        return
    a2 = t2.args
    if a2[0] is not C:
        return
    B: Term = a2[1]
    k3 = make("&&", (A, B))
    k4 = compound("==>", (C, k3))
    emit(k4, tf.intersection(v1, v2), False)


def r98(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<C ==> A>, <C ==> B> |- <C ==> (A || B)> (union, NAL-5)"""
    if t1.op != "==>" or len(t1.args) != 2:
        return
    a1 = t1.args
    C: Term = a1[0]
    A: Term = a1[1]
    if t2.op != "==>" or len(t2.args) != 2:
        return
    a2 = t2.args
    if a2[0] is not C:
        return
    B: Term = a2[1]
    k3 = make("||", (A, B))
    k4 = compound("==>", (C, k3))
    emit(k4, tf.union(v1, v2), False)


def r99(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<(S && P) ==> M>, <S ==> M> |- P (abduction, NAL-5)"""
    if t1.op != "==>" or len(t1.args) != 2:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "&&" or len(x2.args) != 2:
        return
    a3 = x2.args
    S: Term = a3[0]
    P: Term = a3[1]
    M: Term = a1[1]
    if t2.op != "==>" or len(t2.args) != 2:
        return
    a4 = t2.args
    if a4[0] is not S:
        return
    if a4[1] is not M:
        return
    emit(P, tf.abduction(v1, v2), False)


def r100(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<(C && M) ==> P>, <S ==> M> |- <(C && S) ==> P> (deduction, NAL-5)"""
    if t1.op != "==>" or len(t1.args) != 2:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "&&" or len(x2.args) != 2:
        return
    a3 = x2.args
    C: Term = a3[0]
    M: Term = a3[1]
    P: Term = a1[1]
    if t2.op != "==>" or len(t2.args) != 2:
        return
    a4 = t2.args
    S: Term = a4[0]
    if a4[1] is not M:
        return
    k5 = make("&&", (C, S))
    k6 = compound("==>", (k5, P))
    emit(k6, tf.deduction(v1, v2), False)


def r101(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<(C && P) ==> M>, <(C && S) ==> M> |- <S ==> P> (abduction, NAL-5)"""
    if t1.op != "==>" or len(t1.args) != 2:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "&&" or len(x2.args) != 2:
        return
    a3 = x2.args
    C: Term = a3[0]
    P: Term = a3[1]
    M: Term = a1[1]
    if t2.op != "==>" or len(t2.args) != 2:
        return
    a4 = t2.args
    x5: Term = a4[0]
    if x5.op != "&&" or len(x5.args) != 2:
        return
    a6 = x5.args
    if a6[0] is not C:
        return
    S: Term = a6[1]
    if a4[1] is not M:
        return
    k7 = compound("==>", (S, P))
    emit(k7, tf.abduction(v1, v2), False)


def r102(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<(C && M) ==> P>, <M ==> S> |- <(C && S) ==> P> (induction, NAL-5)"""
    if t1.op != "==>" or len(t1.args) != 2:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "&&" or len(x2.args) != 2:
        return
    a3 = x2.args
    C: Term = a3[0]
    M: Term = a3[1]
    P: Term = a1[1]
    if t2.op != "==>" or len(t2.args) != 2:
        return
    a4 = t2.args
    if a4[0] is not M:
        return
    S: Term = a4[1]
    k5 = make("&&", (C, S))
    k6 = compound("==>", (k5, P))
    emit(k6, tf.induction(v1, v2), False)


def r103(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<S <=> P> |- <P <=> S> (structural_intersection, NAL-5)"""
    if t1.op != "<=>" or len(t1.args) != 2:
        return
    a1 = t1.args
    S: Term = a1[0]
    P: Term = a1[1]
    k2 = compound("<=>", (P, S))
    emit(k2, tf.structural_intersection(v1, v2), False)


def r104(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<S ==> P>, <P ==> S> |- <S <=> P> (intersection, NAL-5)"""
    if t1.op != "==>" or len(t1.args) != 2:
        return
    a1 = t1.args
    S: Term = a1[0]
    P: Term = a1[1]
    if t2.op != "==>" or len(t2.args) != 2:
        return
    a2 = t2.args
    if a2[0] is not P:
        return
    if a2[1] is not S:
        return
    k3 = compound("<=>", (S, P))
    emit(k3, tf.intersection(v1, v2), False)


def r105(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<P ==> M>, <S ==> M> |- <S <=> P> (comparison, NAL-5)"""
    if t1.op != "==>" or len(t1.args) != 2:
        return
    a1 = t1.args
    P: Term = a1[0]
    M: Term = a1[1]
    if t2.op != "==>" or len(t2.args) != 2:
        return
    a2 = t2.args
    S: Term = a2[0]
    if a2[1] is not M:
        return
    k3 = compound("<=>", (S, P))
    emit(k3, tf.comparison(v1, v2), False)


def r106(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<M ==> P>, <M ==> S> |- <S <=> P> (comparison, NAL-5)"""
    if t1.op != "==>" or len(t1.args) != 2:
        return
    a1 = t1.args
    M: Term = a1[0]
    P: Term = a1[1]
    if t2.op != "==>" or len(t2.args) != 2:
        return
    a2 = t2.args
    if a2[0] is not M:
        return
    S: Term = a2[1]
    k3 = compound("<=>", (S, P))
    emit(k3, tf.comparison(v1, v2), False)


def r107(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<M ==> P>, <S <=> M> |- <S ==> P> (analogy, NAL-5)"""
    if t1.op != "==>" or len(t1.args) != 2:
        return
    a1 = t1.args
    M: Term = a1[0]
    P: Term = a1[1]
    if t2.op != "<=>" or len(t2.args) != 2:
        return
    a2 = t2.args
    S: Term = a2[0]
    if a2[1] is not M:
        return
    k3 = compound("==>", (S, P))
    emit(k3, tf.analogy(v1, v2), False)


def r108(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<P ==> M>, <S <=> M> |- <P ==> S> (analogy, NAL-5)"""
    if t1.op != "==>" or len(t1.args) != 2:
        return
    a1 = t1.args
    P: Term = a1[0]
    M: Term = a1[1]
    if t2.op != "<=>" or len(t2.args) != 2:
        return
    a2 = t2.args
    S: Term = a2[0]
    if a2[1] is not M:
        return
    k3 = compound("==>", (P, S))
    emit(k3, tf.analogy(v1, v2), False)


def r109(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<M <=> P>, <S <=> M> |- <S <=> P> (resemblance, NAL-5)"""
    if t1.op != "<=>" or len(t1.args) != 2:
        return
    a1 = t1.args
    M: Term = a1[0]
    P: Term = a1[1]
    if t2.op != "<=>" or len(t2.args) != 2:
        return
    a2 = t2.args
    S: Term = a2[0]
    if a2[1] is not M:
        return
    k3 = compound("<=>", (S, P))
    emit(k3, tf.resemblance(v1, v2), False)


def r110(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<M <=> P> |- <M ==> P> (structural_deduction, NAL-5)"""
    if t1.op != "<=>" or len(t1.args) != 2:
        return
    a1 = t1.args
    M: Term = a1[0]
    P: Term = a1[1]
    k2 = compound("==>", (M, P))
    emit(k2, tf.structural_deduction(v1, v2), False)


def r111(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<M <=> P> |- <P ==> M> (structural_deduction, NAL-5)"""
    if t1.op != "<=>" or len(t1.args) != 2:
        return
    a1 = t1.args
    M: Term = a1[0]
    P: Term = a1[1]
    k2 = compound("==>", (P, M))
    emit(k2, tf.structural_deduction(v1, v2), False)


def r112(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<C --> A>, <C --> B> |- <<C --> B> ==> <C --> A>> (induction, NAL-6)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    C: Term = a1[0]
    A: Term = a1[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a2 = t2.args
    if a2[0] is not C:
        return
    B: Term = a2[1]
    k3 = compound("-->", (C, B))
    k4 = compound("-->", (C, A))
    k5 = compound("==>", (k3, k4))
    emit(k5, tf.induction(v1, v2), True)


def r113(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<A --> C>, <B --> C> |- <<B --> C> ==> <A --> C>> (induction, NAL-6)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    A: Term = a1[0]
    C: Term = a1[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a2 = t2.args
    B: Term = a2[0]
    if a2[1] is not C:
        return
    k3 = compound("-->", (B, C))
    k4 = compound("-->", (A, C))
    k5 = compound("==>", (k3, k4))
    emit(k5, tf.induction(v1, v2), True)


def r114(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<C --> A>, <C --> B> |- <<C --> B> <=> <C --> A>> (comparison, NAL-6)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    C: Term = a1[0]
    A: Term = a1[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a2 = t2.args
    if a2[0] is not C:
        return
    B: Term = a2[1]
    k3 = compound("-->", (C, B))
    k4 = compound("-->", (C, A))
    k5 = compound("<=>", (k3, k4))
    emit(k5, tf.comparison(v1, v2), True)


def r115(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<A --> C>, <B --> C> |- <<B --> C> <=> <A --> C>> (comparison, NAL-6)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    A: Term = a1[0]
    C: Term = a1[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a2 = t2.args
    B: Term = a2[0]
    if a2[1] is not C:
        return
    k3 = compound("-->", (B, C))
    k4 = compound("-->", (A, C))
    k5 = compound("<=>", (k3, k4))
    emit(k5, tf.comparison(v1, v2), True)


def r116(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """(! <C --> A>), <C --> B> |- <<C --> B> ==> (! <C --> A>)> (induction, NAL-6)"""
    if t1.op != "!" or len(t1.args) != 1:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "-->" or len(x2.args) != 2:
        return
    a3 = x2.args
    C: Term = a3[0]
    A: Term = a3[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a4 = t2.args
    if a4[0] is not C:
        return
    B: Term = a4[1]
    k5 = compound("-->", (C, B))
    k6 = compound("-->", (C, A))
    k7 = compound("!", (k6,))
    k8 = compound("==>", (k5, k7))
    emit(k8, tf.induction(v1, v2), True)


def r117(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """(! <A --> C>), <B --> C> |- <<B --> C> ==> (! <A --> C>)> (induction, NAL-6)"""
    if t1.op != "!" or len(t1.args) != 1:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "-->" or len(x2.args) != 2:
        return
    a3 = x2.args
    A: Term = a3[0]
    C: Term = a3[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a4 = t2.args
    B: Term = a4[0]
    if a4[1] is not C:
        return
    k5 = compound("-->", (B, C))
    k6 = compound("-->", (A, C))
    k7 = compound("!", (k6,))
    k8 = compound("==>", (k5, k7))
    emit(k8, tf.induction(v1, v2), True)


def r118(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """(! <C --> A>), <C --> B> |- <<C --> B> <=> (! <C --> A>)> (comparison, NAL-6)"""
    if t1.op != "!" or len(t1.args) != 1:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "-->" or len(x2.args) != 2:
        return
    a3 = x2.args
    C: Term = a3[0]
    A: Term = a3[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a4 = t2.args
    if a4[0] is not C:
        return
    B: Term = a4[1]
    k5 = compound("-->", (C, B))
    k6 = compound("-->", (C, A))
    k7 = compound("!", (k6,))
    k8 = compound("<=>", (k5, k7))
    emit(k8, tf.comparison(v1, v2), True)


def r119(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """(! <A --> C>), <B --> C> |- <<B --> C> <=> (! <A --> C>)> (comparison, NAL-6)"""
    if t1.op != "!" or len(t1.args) != 1:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "-->" or len(x2.args) != 2:
        return
    a3 = x2.args
    A: Term = a3[0]
    C: Term = a3[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a4 = t2.args
    B: Term = a4[0]
    if a4[1] is not C:
        return
    k5 = compound("-->", (B, C))
    k6 = compound("-->", (A, C))
    k7 = compound("!", (k6,))
    k8 = compound("<=>", (k5, k7))
    emit(k8, tf.comparison(v1, v2), True)


def r120(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<C --> A>, (! <C --> B>) |- <(! <C --> B>) ==> <C --> A>> (induction, NAL-6)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    C: Term = a1[0]
    A: Term = a1[1]
    if t2.op != "!" or len(t2.args) != 1:
        return
    a2 = t2.args
    x3: Term = a2[0]
    if x3.op != "-->" or len(x3.args) != 2:
        return
    a4 = x3.args
    if a4[0] is not C:
        return
    B: Term = a4[1]
    k5 = compound("-->", (C, B))
    k6 = compound("!", (k5,))
    k7 = compound("-->", (C, A))
    k8 = compound("==>", (k6, k7))
    emit(k8, tf.induction(v1, v2), True)


def r121(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<A --> C>, (! <B --> C>) |- <(! <B --> C>) ==> <A --> C>> (induction, NAL-6)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    A: Term = a1[0]
    C: Term = a1[1]
    if t2.op != "!" or len(t2.args) != 1:
        return
    a2 = t2.args
    x3: Term = a2[0]
    if x3.op != "-->" or len(x3.args) != 2:
        return
    a4 = x3.args
    B: Term = a4[0]
    if a4[1] is not C:
        return
    k5 = compound("-->", (B, C))
    k6 = compound("!", (k5,))
    k7 = compound("-->", (A, C))
    k8 = compound("==>", (k6, k7))
    emit(k8, tf.induction(v1, v2), True)


def r122(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<C --> A>, (! <C --> B>) |- <(! <C --> B>) <=> <C --> A>> (comparison, NAL-6)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    C: Term = a1[0]
    A: Term = a1[1]
    if t2.op != "!" or len(t2.args) != 1:
        return
    a2 = t2.args
    x3: Term = a2[0]
    if x3.op != "-->" or len(x3.args) != 2:
        return
    a4 = x3.args
    if a4[0] is not C:
        return
    B: Term = a4[1]
    k5 = compound("-->", (C, B))
    k6 = compound("!", (k5,))
    k7 = compound("-->", (C, A))
    k8 = compound("<=>", (k6, k7))
    emit(k8, tf.comparison(v1, v2), True)


def r123(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<A --> C>, (! <B --> C>) |- <(! <B --> C>) <=> <A --> C>> (comparison, NAL-6)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    A: Term = a1[0]
    C: Term = a1[1]
    if t2.op != "!" or len(t2.args) != 1:
        return
    a2 = t2.args
    x3: Term = a2[0]
    if x3.op != "-->" or len(x3.args) != 2:
        return
    a4 = x3.args
    B: Term = a4[0]
    if a4[1] is not C:
        return
    k5 = compound("-->", (B, C))
    k6 = compound("!", (k5,))
    k7 = compound("-->", (A, C))
    k8 = compound("<=>", (k6, k7))
    emit(k8, tf.comparison(v1, v2), True)


def r124(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<C --> A>, <C --> B> |- (<C --> B> && <C --> A>) (intersection, NAL-6)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    C: Term = a1[0]
    A: Term = a1[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a2 = t2.args
    if a2[0] is not C:
        return
    B: Term = a2[1]
    k3 = compound("-->", (C, B))
    k4 = compound("-->", (C, A))
    k5 = make("&&", (k3, k4))
    emit(k5, tf.intersection(v1, v2), True)


def r125(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<A --> C>, <B --> C> |- (<B --> C> && <A --> C>) (intersection, NAL-6)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    A: Term = a1[0]
    C: Term = a1[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a2 = t2.args
    B: Term = a2[0]
    if a2[1] is not C:
        return
    k3 = compound("-->", (B, C))
    k4 = compound("-->", (A, C))
    k5 = make("&&", (k3, k4))
    emit(k5, tf.intersection(v1, v2), True)


def r126(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """(! <C --> A>), <C --> B> |- (<C --> B> && (! <C --> A>)) (intersection, NAL-6)"""
    if t1.op != "!" or len(t1.args) != 1:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "-->" or len(x2.args) != 2:
        return
    a3 = x2.args
    C: Term = a3[0]
    A: Term = a3[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a4 = t2.args
    if a4[0] is not C:
        return
    B: Term = a4[1]
    k5 = compound("-->", (C, B))
    k6 = compound("-->", (C, A))
    k7 = compound("!", (k6,))
    k8 = make("&&", (k5, k7))
    emit(k8, tf.intersection(v1, v2), True)


def r127(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """(! <A --> C>), <B --> C> |- (<B --> C> && (! <A --> C>)) (intersection, NAL-6)"""
    if t1.op != "!" or len(t1.args) != 1:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "-->" or len(x2.args) != 2:
        return
    a3 = x2.args
    A: Term = a3[0]
    C: Term = a3[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a4 = t2.args
    B: Term = a4[0]
    if a4[1] is not C:
        return
    k5 = compound("-->", (B, C))
    k6 = compound("-->", (A, C))
    k7 = compound("!", (k6,))
    k8 = make("&&", (k5, k7))
    emit(k8, tf.intersection(v1, v2), True)


def r128(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<C --> A>, (! <C --> B>) |- ((! <C --> B>) && <C --> A>) (intersection, NAL-6)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    C: Term = a1[0]
    A: Term = a1[1]
    if t2.op != "!" or len(t2.args) != 1:
        return
    a2 = t2.args
    x3: Term = a2[0]
    if x3.op != "-->" or len(x3.args) != 2:
        return
    a4 = x3.args
    if a4[0] is not C:
        return
    B: Term = a4[1]
    k5 = compound("-->", (C, B))
    k6 = compound("!", (k5,))
    k7 = compound("-->", (C, A))
    k8 = make("&&", (k6, k7))
    emit(k8, tf.intersection(v1, v2), True)


def r129(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<A --> C>, (! <B --> C>) |- ((! <B --> C>) && <A --> C>) (intersection, NAL-6)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    A: Term = a1[0]
    C: Term = a1[1]
    if t2.op != "!" or len(t2.args) != 1:
        return
    a2 = t2.args
    x3: Term = a2[0]
    if x3.op != "-->" or len(x3.args) != 2:
        return
    a4 = x3.args
    B: Term = a4[0]
    if a4[1] is not C:
        return
    k5 = compound("-->", (B, C))
    k6 = compound("!", (k5,))
    k7 = compound("-->", (A, C))
    k8 = make("&&", (k6, k7))
    emit(k8, tf.intersection(v1, v2), True)


def r130(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<(A * B) --> R>, <(B * A) --> S> |- <<(B * A) --> S> ==> <(A * B) --> R>> (induction, NAL-6)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "*" or len(x2.args) != 2:
        return
    a3 = x2.args
    A: Term = a3[0]
    B: Term = a3[1]
    R: Term = a1[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a4 = t2.args
    x5: Term = a4[0]
    if x5.op != "*" or len(x5.args) != 2:
        return
    a6 = x5.args
    if a6[0] is not B:
        return
    if a6[1] is not A:
        return
    S: Term = a4[1]
    k7 = compound("*", (B, A))
    k8 = compound("-->", (k7, S))
    k9 = compound("*", (A, B))
    k10 = compound("-->", (k9, R))
    k11 = compound("==>", (k8, k10))
    emit(k11, tf.induction(v1, v2), True)


def r131(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """(! <(B * A) --> R>), <(A * B) --> S> |- <<(A * B) --> S> ==> (! <(B * A) --> R>)> (induction, NAL-6)"""
    if t1.op != "!" or len(t1.args) != 1:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "-->" or len(x2.args) != 2:
        return
    a3 = x2.args
    x4: Term = a3[0]
    if x4.op != "*" or len(x4.args) != 2:
        return
    a5 = x4.args
    B: Term = a5[0]
    A: Term = a5[1]
    R: Term = a3[1]
    if t2.op != "-->" or len(t2.args) != 2:
        return
    a6 = t2.args
    x7: Term = a6[0]
    if x7.op != "*" or len(x7.args) != 2:
        return
    a8 = x7.args
    if a8[0] is not A:
        return
    if a8[1] is not B:
        return
    S: Term = a6[1]
    k9 = compound("*", (A, B))
    k10 = compound("-->", (k9, S))
    k11 = compound("*", (B, A))
    k12 = compound("-->", (k11, R))
    k13 = compound("!", (k12,))
    k14 = compound("==>", (k10, k13))
    emit(k14, tf.induction(v1, v2), True)


def r132(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<(B * A) --> R>, (! <(A * B) --> S>) |- <(! <(A * B) --> S>) ==> <(B * A) --> R>> (induction, NAL-6)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "*" or len(x2.args) != 2:
        return
    a3 = x2.args
    B: Term = a3[0]
    A: Term = a3[1]
    R: Term = a1[1]
    if t2.op != "!" or len(t2.args) != 1:
        return
    a4 = t2.args
    x5: Term = a4[0]
    if x5.op != "-->" or len(x5.args) != 2:
        return
    a6 = x5.args
    x7: Term = a6[0]
    if x7.op != "*" or len(x7.args) != 2:
        return
    a8 = x7.args
    if a8[0] is not A:
        return
    if a8[1] is not B:
        return
    S: Term = a6[1]
    k9 = compound("*", (A, B))
    k10 = compound("-->", (k9, S))
    k11 = compound("!", (k10,))
    k12 = compound("*", (B, A))
    k13 = compound("-->", (k12, R))
    k14 = compound("==>", (k11, k13))
    emit(k14, tf.induction(v1, v2), True)


def r133(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """A, B |- (A && B) (intersection, NAL-6)"""
    A: Term = t1
    B: Term = t2
    k1 = make("&&", (A, B))
    emit(k1, tf.intersection(v1, v2), False)


def r134(t1: Term, t2: Term, v1: Truth, v2: Truth, emit: Emit) -> None:
    """<(A * C) --> M>, (<(A * B) --> R> && <(B * C) --> S>) |- <(<(A * B) --> R> && <(B * C) --> S>) ==> <(A * C) --> M>> (induction, NAL-6)"""
    if t1.op != "-->" or len(t1.args) != 2:
        return
    a1 = t1.args
    x2: Term = a1[0]
    if x2.op != "*" or len(x2.args) != 2:
        return
    a3 = x2.args
    A: Term = a3[0]
    C: Term = a3[1]
    M: Term = a1[1]
    if t2.op != "&&" or len(t2.args) != 2:
        return
    a4 = t2.args
    x5: Term = a4[0]
    if x5.op != "-->" or len(x5.args) != 2:
        return
    a6 = x5.args
    x7: Term = a6[0]
    if x7.op != "*" or len(x7.args) != 2:
        return
    a8 = x7.args
    if a8[0] is not A:
        return
    B: Term = a8[1]
    R: Term = a6[1]
    x9: Term = a4[1]
    if x9.op != "-->" or len(x9.args) != 2:
        return
    a10 = x9.args
    x11: Term = a10[0]
    if x11.op != "*" or len(x11.args) != 2:
        return
    a12 = x11.args
    if a12[0] is not B:
        return
    if a12[1] is not C:
        return
    S: Term = a10[1]
    k13 = compound("*", (A, B))
    k14 = compound("-->", (k13, R))
    k15 = compound("*", (B, C))
    k16 = compound("-->", (k15, S))
    k17 = make("&&", (k14, k16))
    k18 = compound("*", (A, C))
    k19 = compound("-->", (k18, M))
    k20 = compound("==>", (k17, k19))
    emit(k20, tf.induction(v1, v2), True)


#: the matcher of each row of the rule table, in the table's order
MATCHERS = (
    r0,
    r1,
    r2,
    r3,
    r4,
    r5,
    r6,
    r7,
    r8,
    r9,
    r10,
    r11,
    r12,
    r13,
    r14,
    r15,
    r16,
    r17,
    r18,
    r19,
    r20,
    r21,
    r22,
    r23,
    r24,
    r25,
    r26,
    r27,
    r28,
    r29,
    r30,
    r31,
    r32,
    r33,
    r34,
    r35,
    r36,
    r37,
    r38,
    r39,
    r40,
    r41,
    r42,
    r43,
    r44,
    r45,
    r46,
    r47,
    r48,
    r49,
    r50,
    r51,
    r52,
    r53,
    r54,
    r55,
    r56,
    r57,
    r58,
    r59,
    r60,
    r61,
    r62,
    r63,
    r64,
    r65,
    r66,
    r67,
    r68,
    r69,
    r70,
    r71,
    r72,
    r73,
    r74,
    r75,
    r76,
    r77,
    r78,
    r79,
    r80,
    r81,
    r82,
    r83,
    r84,
    r85,
    r86,
    r87,
    r88,
    r89,
    r90,
    r91,
    r92,
    r93,
    r94,
    r95,
    r96,
    r97,
    r98,
    r99,
    r100,
    r101,
    r102,
    r103,
    r104,
    r105,
    r106,
    r107,
    r108,
    r109,
    r110,
    r111,
    r112,
    r113,
    r114,
    r115,
    r116,
    r117,
    r118,
    r119,
    r120,
    r121,
    r122,
    r123,
    r124,
    r125,
    r126,
    r127,
    r128,
    r129,
    r130,
    r131,
    r132,
    r133,
    r134,
)
