"""ONA 0.9.3's behaviour (``NAR(ona="0.9.3")``): one test per new inference, each a
small input and the lines ONA 0.9.3's own shell prints for it (built from its v0.9.3
tag), beside what 0.9.2 prints where the two differ."""

from __future__ import annotations

import gzip
import json
from pathlib import Path

import pytest

from robocog.nars import NAR, memfile
from robocog.nars.config import NEWER_PARAMETERS, ONA_VERSIONS, Config
from robocog.nars.goalreasoning import inheritance_subgoal
from robocog.nars.narsese import parse_term
from robocog.nars.terms import F_IMAGE
from tests.nars.test_nar import run_lines


def run(lines: list[str], ona: str = "0.9.3", **config: object) -> list[str]:
    """The shell's output lines for ``lines`` (derivations shown, as the shell does)."""
    return run_lines(NAR(ona=ona, **config), lines)


def answers(out: list[str]) -> list[str]:
    return [line for line in out if line.startswith("Answer:")]


def test_the_presets_differ_only_where_ona_changed() -> None:
    old, new = Config.for_ona("0.9.2"), Config.for_ona("0.9.3")
    assert old == Config()
    changed = {k for k, v in new.as_dict().items() if old.as_dict()[k] != v}
    assert changed == set(ONA_VERSIONS["0.9.3"])
    assert (new.max_sequence_len, new.table_size) == (3, 120)
    assert Config.for_ona("0.9.3", table_size=7).table_size == 7
    with pytest.raises(ValueError, match="0.9.4"):
        Config.for_ona("0.9.4")
    with pytest.raises(ValueError):
        NAR(ona="0.9")


def test_anticipation_counts_failures_of_a_precondition_seen_long_ago() -> None:
    # 30 cycles after ``a`` the 0.9.2 prediction (a projected to now) is too weak to
    # count a failure when ``c`` arrives; 0.9.3 predicts from ``a`` as it was
    lines = ["*motorbabbling=false", "a. :|:", "b. :|:", "30", "c. :|:", "<a =/> b>?"]
    assert answers(run(lines, "0.9.2")) == [
        "Answer: <a =/> b>. creationTime=2 Stamp=[1,2] "
        "Truth: frequency=0.982144, confidence=0.285894"
    ]
    assert answers(run(lines)) == [
        "Answer: <a =/> b>. creationTime=2 Stamp=[1,2] "
        "Truth: frequency=0.964915, confidence=0.289521"
    ]


def test_a_predicted_negation_predicts_the_negated_term() -> None:
    lines = [
        "*motorbabbling=false",
        "<a =/> (! b)>.",
        "b. :|:",
        "a. :|:",
        "b? :/:",
        "(! b)? :/:",
    ]
    out = run(lines)
    assert answers(out) == [
        "Answer: b. :|: occurrenceTime=3 creationTime=3 Stamp=[3,1] "
        "Truth: frequency=0.000000, confidence=0.810000",
        "Answer: (! b). :|: occurrenceTime=3 creationTime=3 Stamp=[3,1] "
        "Truth: frequency=1.000000, confidence=0.810000",
    ]
    # 0.9.3 does not print predictions as derivations
    assert not any(line.startswith("Derived: (! b)") for line in out)
    assert answers(run(lines, "0.9.2"))[0] == "Answer: None."


def test_inheritance_subgoaling() -> None:
    out = run(
        [
            "*motorbabbling=false",
            "<cat --> animal>.",
            "<tom --> cat>.",
            "<[happy] --> [content]>.",
            "<cat --> [happy]>! :|:",
        ]
    )
    goals = [line for line in out if line.startswith("Derived:") and "! :|:" in line]
    assert goals == [
        "Derived: <animal --> [happy]>! :|: occurrenceTime=4 Priority=0.350102 "
        "Stamp=[1,4] Truth: frequency=1.000000, confidence=0.810000",
        "Derived: <tom --> [happy]>! :|: occurrenceTime=4 Priority=0.275887 "
        "Stamp=[2,4] Truth: frequency=1.000000, confidence=0.426316",
        "Derived: <cat --> [content]>! :|: occurrenceTime=4 Priority=0.350102 "
        "Stamp=[3,4] Truth: frequency=1.000000, confidence=0.810000",
        "Derived: <cat --> [content]>! :|: occurrenceTime=4 Priority=0.334434 "
        "Stamp=[3,4] Truth: frequency=1.000000, confidence=0.729000",
    ]


def test_product_goals_take_subgoals_for_each_argument_and_the_relation() -> None:
    out = run(
        ["*motorbabbling=false", "<cat --> animal>.", "<(cat * fish) --> eat>! :|:"]
        + ["<eat --> like>.", "3"]
    )
    goals = [line for line in out if line.startswith(("Derived:", "Selected:")) and "!" in line]
    assert goals == [
        "Selected: <(cat * fish) --> eat>! :|: occurrenceTime=2 Priority=1.000000 "
        "Stamp=[2] Truth: frequency=1.000000, confidence=0.900000",
        "Derived: <(animal * fish) --> eat>! :|: occurrenceTime=2 Priority=0.350102 "
        "Stamp=[1,2] Truth: frequency=1.000000, confidence=0.810000",
        "Selected: <(animal * fish) --> eat>! :|: occurrenceTime=2 Priority=0.350067 "
        "Stamp=[1,2] Truth: frequency=1.000000, confidence=0.810000",
        "Derived: <(animal * fish) --> like>! :|: occurrenceTime=2 Priority=0.088496 "
        "Stamp=[3,1,2] Truth: frequency=1.000000, confidence=0.383684",
        "Selected: <(animal * fish) --> like>! :|: occurrenceTime=2 Priority=0.088487 "
        "Stamp=[3,1,2] Truth: frequency=1.000000, confidence=0.383684",
    ]


@pytest.mark.parametrize(
    ("goal", "belief", "subgoal", "converted"),
    [
        ("<x --> y>", "<z --> x>", "<z --> y>", True),
        ("<x --> y>", "<x --> z>", "<z --> y>", False),
        ("<x --> y>", "<y --> z>", "<x --> z>", False),
        ("<x --> y>", "<z --> y>", "<x --> z>", True),
        ("<(a * b) --> w>", "<z --> a>", "<(z * b) --> w>", True),
        ("<(a * b) --> w>", "<b --> z>", "<(a * z) --> w>", True),
        ("<(a * b) --> w>", "<z --> w>", "<(a * b) --> z>", False),
        ("<x --> y>", "<p --> q>", None, False),
    ],
)
def test_the_inheritance_cases(
    goal: str, belief: str, subgoal: str | None, converted: bool
) -> None:
    found = inheritance_subgoal(parse_term(goal), parse_term(belief))
    if subgoal is None:
        assert found is None
    else:
        assert found == (parse_term(subgoal), converted)


def test_implication_subgoaling_deduces_from_the_earlier_goal() -> None:
    lines = ["<<$1 --> rain> ==> <$1 --> wet>>.", "<street --> wet>! :|:", "<street --> wet>! :|:"]
    lines.append("5")
    out = run(lines)
    assert (
        "Derived: <street --> rain>! :|: occurrenceTime=3 Priority=0.452500 Stamp=[2,1] "
        "Truth: frequency=1.000000, confidence=0.810000"
    ) in out
    assert not any("<street --> rain>!" in line for line in run(lines, "0.9.2"))


def test_implication_subgoaling_predicts_when_the_condition_just_happened() -> None:
    lines = ["*motorbabbling=false", "<<$1 --> rain> ==> <$1 --> wet>>."]
    lines += ["<street --> rain>. :|:", "<street --> wet>! :|:", "<street --> wet>! :|:"]
    lines.append("<street --> wet>? :/:")
    (answer,) = answers(run(lines))
    # ONA 0.9.3 gives this event (its creationTime is 2 there: made by another path)
    assert answer.startswith("Answer: <street --> wet>. :|: occurrenceTime=2 creationTime=")
    assert answer.endswith("Stamp=[2,1] Truth: frequency=1.000000, confidence=0.810000")
    assert not any("<street --> rain>!" in line for line in run(lines))
    assert answers(run(lines, "0.9.2")) == ["Answer: None."]


def test_sequences_of_three_events() -> None:
    lines = ["*motorbabbling=false", "a. :|:", "b. :|:", "c. :|:", "d. :|:"]
    lines += ["<((a &/ b) &/ c) =/> d>?", "<(b &/ c) =/> d>?"]
    two = (
        "Answer: <(b &/ c) =/> d>. creationTime=4 Stamp=[2,4,3] "
        "Truth: frequency=0.984048, confidence=0.244307"
    )
    assert answers(run(lines)) == [
        "Answer: <((a &/ b) &/ c) =/> d>. creationTime=4 Stamp=[1,4,3,2] "
        "Truth: frequency=0.985427, confidence=0.203297",
        two,
    ]
    assert answers(run(lines, "0.9.2")) == ["Answer: None.", two]


def test_restricted_concept_creation() -> None:
    lines = ["<a --> b>.", "<b --> c>.", "5", "<a --> c>?"]
    assert answers(run(["*restrictedconceptcreation=true", *lines])) == ["Answer: None."]
    assert answers(run(lines))[0].startswith("Answer: <a --> c>.")


def test_concurrent_implications_can_be_switched_off() -> None:
    lines = ["*motorbabbling=false", "a. :|:", "*concurrent", "b. :|:", "<a =/> b>?"]
    assert answers(run(lines))[0].startswith("Answer: <a =/> b>.")
    assert answers(run(lines, allow_concurrent_implications=False)) == ["Answer: None."]


def test_a_memory_saved_before_the_switches_existed_loads(tmp_path: Path) -> None:
    nar = NAR()
    nar.add_input("<a --> b>.")
    path = tmp_path / "old.nar"
    nar.save(path)
    doc = json.loads(gzip.decompress(path.read_bytes()))
    for k in NEWER_PARAMETERS:
        del doc["config"][k]
    again = memfile.decode(json.dumps(doc).encode())
    assert again.config == Config().as_dict()
    doc["config"]["allow_var_intro"] = 1
    with pytest.raises(memfile.MemoryFileError, match="allow_var_intro"):
        memfile.decode(json.dumps(doc).encode())


def test_fresh_eternal_beliefs_travel_through_implications_each_cycle() -> None:
    lines = ["<<$1 --> [smokes]> ==> <$1 --> [cancerous]>>. %0.6%", "<{Edward} --> [smokes]>."]
    lines += ["5", "<{Edward} --> [cancerous]>?"]
    out = run(lines)
    assert (
        "Derived: <{Edward} --> [cancerous]>. Priority=1.000000 Stamp=[2,1] "
        "Truth: frequency=0.600000, confidence=0.486000"
    ) in out
    assert answers(out) == [
        "Answer: <{Edward} --> [cancerous]>. creationTime=2 Stamp=[2,1] "
        "Truth: frequency=0.600000, confidence=0.486000"
    ]
    # 0.9.2 reaches the same belief later, by semantic inference on the selected event
    assert not any(line.startswith("Selected: <{Edward} --> [cancerous]>") for line in out)
    assert any(
        line.startswith("Selected: <{Edward} --> [cancerous]>") for line in run(lines, "0.9.2")
    )


def test_a_conditional_deduction_feeds_the_declarative_pass() -> None:
    # a ground ``==>`` from a conditional deduction is kept, and Anna's fresh belief
    # travels through it (0.9.2 drops it, and answers nothing within these cycles)
    lines = [
        "<(<#1 --> [smokes]> && <(#1 * $1) --> friend>) ==> <$1 --> [smokes]>>.",
        "<({Anna} * {Bob}) --> friend>.",
        "<{Anna} --> [smokes]>.",
        "5",
        "<{Bob} --> [smokes]>?",
    ]
    assert answers(run(lines)) == [
        "Answer: <{Bob} --> [smokes]>. creationTime=3 Stamp=[3,2,1] "
        "Truth: frequency=1.000000, confidence=0.729000"
    ]
    assert answers(run(lines, "0.9.2")) == ["Answer: None."]


def test_two_beliefs_meet_a_conjunctive_condition_through_their_conjunction() -> None:
    # 0.9.3's rule table concludes ``(A && B)`` from any two premises: the conjunction
    # of two relations is kept as a belief (not cycled as an event) and, fresh, meets
    # the transitive rule's condition in the declarative pass. ONA 0.9.3 answers
    # ``Answer: <(C1 * B1) --> same>. creationTime=4 Stamp=[4,2,3,1,1] Truth:
    # frequency=1.000000, confidence=0.590490`` (its pass meets the pairs in another
    # order, so its stamp and time differ)
    lines = [
        "<<($1 * $2) --> same> ==> <($2 * $1) --> same>>.",
        "<(<($1 * #1) --> same> && <(#1 * $2) --> same>) ==> <($1 * $2) --> same>>.",
        "<(A1 * B1) --> same>.",
        "<(A1 * C1) --> same>.",
        "10",
        "<(C1 * B1) --> same>?",
    ]
    nar = NAR(ona="0.9.3")
    out = run_lines(nar, lines)
    (answer,) = answers(out)
    assert answer.startswith("Answer: <(C1 * B1) --> same>.")
    assert answer.endswith("Truth: frequency=1.000000, confidence=0.590490")
    # (B1 * A1) at 0.81 (by symmetry) with (A1 * C1) at 0.9: the condition with #1 = A1
    kept = nar.memory.find(parse_term("(<(B1 * A1) --> same> && <(A1 * C1) --> same>)"))
    assert kept is not None and kept.belief is not None
    assert round(kept.belief.truth.c, 6) == 0.729
    assert not any(line.startswith(("Derived: (", "Selected: (")) for line in out)
    # without the row, nothing in 0.9.3 brings the two relations to the rule in time
    assert answers(run(lines, plain_conjunctions=False)) == ["Answer: None."]


def test_a_conjunction_with_an_image_needs_its_concept() -> None:
    # ONA 0.9.3's memory lists ``(<c --> r> && <(a * b) --> r>)`` for these lines but
    # no conjunction with the image ``(r /1 b)`` in it: a derived conjunction or ``==>``
    # with an image enters only a concept that exists
    lines = ["<a --> (r /1 b)>.", "<c --> r>.", "5"]
    with_image = parse_term("(<c --> r> && <a --> (r /1 b)>)")
    plain = parse_term("(<c --> r> && <(a * b) --> r>)")
    nar = NAR(ona="0.9.3")
    run_lines(nar, lines)
    assert nar.memory.find(plain) is not None
    assert nar.memory.find(with_image) is None
    assert not any(c.term.op == "==>" and c.term.flags & F_IMAGE for c in nar.memory)
    nar = NAR(ona="0.9.3", image_compounds_need_concept=False)
    run_lines(nar, lines)
    assert nar.memory.find(with_image) is not None


def test_a_derived_implication_is_no_premise_of_semantic_inference() -> None:
    # ONA 0.9.3 makes no concept for a derived ``==>`` (it lives in its consequence's
    # links), so Edward's smoking reaches Anna by analogy (Anna and Edward share the
    # friend Frank) before the friendship rule's ground ``==>`` could detach it. ONA
    # 0.9.3 answers these two exactly so (creationTime=8 for the first)
    lines = [
        "<<$1 --> [smokes]> ==> <$1 --> [cancerous]>>. %0.6%",
        "<(<#1 --> [smokes]> && <($1 * #1) --> friend>) ==> <$1 --> [smokes]>>.",
        "<(<#1 --> [smokes]> && <(#1 * $1) --> friend>) ==> <$1 --> [smokes]>>.",
        "<({Anna} * {Edward}) --> friend>.",
        "<({Anna} * {Frank}) --> friend>.",
        "<({Edward} * {Frank}) --> friend>.",
        "<{Anna} --> [smokes]>.",
        "<{Edward} --> [smokes]>.",
        "20",
        "<{Anna} --> [cancerous]>?",
        "<{Anna} --> [smokes]>?",
    ]
    out = answers(run(lines))
    got = [a.split(" creationTime")[0] for a in out]
    stamps = [a.split("Stamp=")[1] for a in out]
    assert got == ["Answer: <{Anna} --> [cancerous]>.", "Answer: <{Anna} --> [smokes]>."]
    assert stamps == [
        "[7,1,8,6,5] Truth: frequency=0.600000, confidence=0.489412",
        "[7,8,6,5] Truth: frequency=1.000000, confidence=0.906318",
    ]
    # as a premise, the ``==>`` detaches first and Anna's smoking is revised with it
    old = [a.split("Stamp=")[1] for a in answers(run(lines, derived_links_are_premises=True))]
    assert old[1] == "[7,8,4,2] Truth: frequency=1.000000, confidence=0.921198"


def test_the_pass_deduces_from_shared_evidence_unless_told_not_to() -> None:
    """ONA 0.9.3's declarative pass deduces through a link made from the belief it meets
    (``<b --> a>`` with a stamp counting inputs 2 and 3 twice); with
    ``declarative_pass_disjoint_evidence`` it refuses those pairs, as the other
    inferences do, and only those."""
    lines = ["*volume=100", "<a --> b>.", "<b --> c>.", "<c --> d>.", "<d --> e>.", "20"]

    def stamps(out: list[str]) -> list[list[str]]:
        found = []
        for line in out:
            if line.startswith("Derived:") and "Stamp=[" in line:
                found.append(line.split("Stamp=[")[1].split("]")[0].split(","))
        return found

    faithful = stamps(run(lines))
    disjoint = stamps(run(lines, declarative_pass_disjoint_evidence=True))
    assert any(len(set(s)) < len(s) for s in faithful)
    assert disjoint and all(len(set(s)) == len(s) for s in disjoint)
    # what does not repeat evidence is derived alike
    assert [s for s in faithful if len(set(s)) == len(s)][:5] == disjoint[:5]
