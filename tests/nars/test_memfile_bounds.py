"""Every memory robocog saves, it loads: sessions driven to each boundary the reader
checks are saved and loaded back, and the save of a state past them is refused."""

from __future__ import annotations

from pathlib import Path

import pytest

from robocog.nars import memfile
from robocog.nars.config import MAX_TIME, RANGES, Config
from robocog.nars.memfile_io import MemoryFileError
from robocog.nars.nar import NAR
from robocog.nars.narsese import NarseseError


def _nar(*lines: str, **config: object) -> NAR:
    nar = NAR(seed=3, **config)
    nar.output = lambda line: None  # type: ignore[method-assign]
    for line in lines:
        nar.add_input(line)
    return nar


def _round_trip(nar: NAR, tmp_path: Path) -> NAR:
    path = tmp_path / "m.nar"
    nar.save(path)
    back = NAR.load(path)
    assert memfile.encode(back) == memfile.encode(nar)
    return back


def test_a_session_at_the_end_of_its_clock_and_stamps_saves_a_loadable_file(
    tmp_path: Path,
) -> None:
    nar = _nar(
        f"*currenttime={MAX_TIME - 6}",
        f"*stampid={MAX_TIME - 6}",
        "<a --> b>. :|: {1.0 0.99}",
        f"dt={MAX_TIME} <(c &/ ^go) =/> g>. :|:",
        f"dt=-{MAX_TIME} <x --> y>. :|: {{0 0}}",
        "<(a &/ ^go) =/> g>.",
        "g! :|:",
        "10",
    )
    assert nar.time > MAX_TIME  # the cycles ran past it
    back = _round_trip(nar, tmp_path)
    # at its end the clock takes no more input, but the memory is whole
    with pytest.raises(NarseseError):
        back.add_input("<c --> d>.")
    with pytest.raises(NarseseError):
        back.add_input("5")
    assert back.time == nar.time


def test_stamp_ids_at_their_end_are_saved_and_loaded(tmp_path: Path) -> None:
    nar = _nar(f"*stampid={MAX_TIME - 1}", "<a --> b>.")
    assert nar.stamp_base == MAX_TIME
    with pytest.raises(NarseseError):
        nar.add_input("<b --> c>.")
    _round_trip(nar, tmp_path)


@pytest.mark.parametrize("end", [0, 1])
def test_every_parameter_at_each_end_of_its_range_round_trips(end: int, tmp_path: Path) -> None:
    small = {
        "concepts_max",
        "cycling_belief_events_max",
        "cycling_goal_events_max",
        "cycling_goal_events_layers",
        "operations_max",
        "table_size",
        "stamp_size",
        "occurrence_time_index_size",
        "top_k_declarative_implications",
        "belief_concept_match_target",
    }
    values = {
        k: (r[end] if k not in small or end == 0 else min(r[1], 64)) for k, r in RANGES.items()
    }
    nar = _nar(**values)
    for line in ("<a --> b>. :|:", "<(a &/ ^left) =/> g>.", "g! :|:", "3"):
        try:
            nar.add_input(line)
        except NarseseError:
            pass
    back = _round_trip(nar, tmp_path)
    for k in RANGES:
        assert getattr(back.config, k) == getattr(nar.config, k)


def test_a_state_past_the_clock_the_reader_takes_is_not_saved(tmp_path: Path) -> None:
    nar = _nar("<a --> b>.")
    nar.time = memfile.CLOCK_MAX + 1  # (only a program driving the reasoner gets here)
    with pytest.raises(MemoryFileError, match="CLOCK_MAX"):
        nar.save(tmp_path / "m.nar")
    assert not (tmp_path / "m.nar").exists()


def test_names_and_terms_at_their_longest_round_trip(tmp_path: Path) -> None:
    name = "^" + "o" * (memfile.MAX_NAME_CHARS - 1)
    nar = _nar(f"*setopname 1 {name}", f"<{'a' * 4000} --> b>.")
    assert Config().operations_max >= 1
    _round_trip(nar, tmp_path)
