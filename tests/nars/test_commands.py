"""Shell commands and input fields: out-of-range, NaN, infinite and absurd values are
refused with one error line, and a refused line leaves the reasoner exactly as it was."""

from __future__ import annotations

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import robocog.nars as nars
from robocog.nars import NAR, NarseseError, memfile
from robocog.nars.commands import COMMANDS

#: a fixed valid script touching declarative, temporal and procedural reasoning
SCRIPT = [
    "<a --> b>.",
    "<b --> c>.",
    "<(x &/ ^left) =/> g>.",
    "x. :|:",
    "g! :|:",
    "5",
    "<a --> c>?",
    "<(x &/ ^left) =/> g>?",
]


def _fresh() -> tuple[NAR, list[str]]:
    nar = NAR()
    out: list[str] = []
    nar.output = out.append
    nar.config.print_derivations = True
    nar.add_input("<s --> t>.")
    nar.add_input("*setopname 1 ^left")
    return nar, out


PROBES = [
    ("*currenttime=99999999999999999999", "currenttime"),
    ("*currenttime=0", "currenttime"),
    ("*currenttime=-5", "currenttime"),
    ("*currenttime=1e3", "whole number"),
    ("*motorbabbling=nan", "motorbabbling"),
    ("*motorbabbling=inf", "motorbabbling"),
    ("*motorbabbling=-inf", "motorbabbling"),
    ("*motorbabbling=1.5", "out of range"),
    ("*motorbabbling=1e400", "out of range"),
    ("*decisionthreshold=nan", "decisionthreshold"),
    ("*decisionthreshold=", "needs a value"),
    ("*anticipationconfidence=2", "out of range"),
    ("*questionpriming=-0.1", "out of range"),
    ("*similaritydistance=inf", "similaritydistance"),
    ("*volume=101", "out of range"),
    ("*volume=abc", "number"),
    ("*babblingops=0", "out of range"),
    ("*babblingops=100000", "out of range"),
    ("*stampid=0", "out of range"),
    ("*setopname 10000000 ^x", "out of range"),
    ("*setopname 0 ^x", "out of range"),
    ("*setopname 1 left", "operation name"),
    ("*setopname 1 ^a;b", "operation name"),
    ("*setopname 1", "takes an operation number and a name"),
    ("*reset now", "no argument"),
    ("*frobnicate=1", "unknown command"),
    ("*", "command name"),
    ("*save x.nar", "memory directory"),
    ("*load x.nar", "memory directory"),
    ("dt=99999999999999999999 <a =/> b>.", "dt"),
    ("dt=nan <a =/> b>.", "unexpected"),
    ("<a --> b>. {1.5 0.9}", "truth out of range"),
    ("<a --> b>. {0.5 1.0}", "truth out of range"),
    ("¹", "digits"),
    ("١٢", "digits"),
    ("99999999999999999999", "cycles"),
    ("<a --> " + "b" * 5000 + ">.", "longer than"),
    ("(" * 3000 + "a" + ")" * 3000 + ".", ""),
]


@pytest.mark.parametrize(("line", "why"), PROBES)
def test_a_bad_line_is_refused_with_one_line_and_changes_nothing(line: str, why: str) -> None:
    nar, out = _fresh()
    before = memfile.encode(nar)
    printed = len(out)
    with pytest.raises(NarseseError) as info:
        nar.add_input(line)
    assert why in info.value.message and "\n" not in info.value.message
    assert memfile.encode(nar) == before
    assert len(out) == printed
    # and the reasoner goes on as a fresh one does
    other, other_out = _fresh()
    for s in SCRIPT:
        nar.add_input(s)
        other.add_input(s)
    assert out == other_out


def test_add_input_of_a_superscript_digit_raises_the_documented_error() -> None:
    with pytest.raises(NarseseError):
        NAR().add_input("¹")


def test_valid_commands_still_work() -> None:
    nar, out = _fresh()
    for line in [
        "*volume=50",
        "*motorbabbling=false",
        "*motorbabbling=0.05",
        "*babblingops=3",
        "*decisionthreshold=0.6",
        "*currenttime=100",
        "*stampid=50",
        "*setopname 3 ^pick",
        "*setopname=4 ^drop",
        "*space 10",
        "*stats",
    ]:
        nar.add_input(line)
    c = nar.config
    assert c.volume_threshold == pytest.approx(0.5) and c.motor_babbling_chance == 0.05
    assert (c.babbling_ops, c.decision_threshold) == (3, 0.6)
    assert nar.time == 100 and nar.stamp_base == 50
    assert nar.op_names[2:4] == ["^pick", "^drop"]
    assert "Statistics" in out


def test_every_command_has_a_parser_a_handler_and_help() -> None:
    for name, cmd in COMMANDS.items():
        assert cmd.name == name and cmd.help and callable(cmd.parse) and callable(cmd.run)


def test_config_updates_are_checked_before_any_is_set() -> None:
    nar = NAR()
    with pytest.raises(ValueError, match="concepts_max"):
        nar.config.update(decision_threshold=0.7, concepts_max=0)
    assert nar.config.decision_threshold == 0.501
    with pytest.raises(ValueError, match="finite"):
        NAR(motor_babbling_chance=float("nan"))
    with pytest.raises(KeyError):
        NAR(no_such_parameter=1)


# ------------------------------------------------------------------- the property
_names = st.sampled_from(sorted(COMMANDS) + ["", "x", "reset ", "save", "load"])
_values = st.one_of(
    st.sampled_from(
        [
            "nan",
            "inf",
            "-inf",
            "1e400",
            "-1",
            "0",
            "99999999999999999999",
            "1e-400",
            "0x10",
            "1_000",
            "¹",
            "",
            "..",
            "/etc/passwd",
            "true",
            "10000000 ^x",
            "1 ^",
            " = ",
        ]
    ),
    st.integers(-(10**25), 10**25).map(str),
    st.floats(allow_nan=True, allow_infinity=True).map(repr),
    st.text(max_size=12),
)
_command_lines = st.builds(
    lambda n, sep, v: f"*{n}{sep}{v}", _names, st.sampled_from(["=", " ", "= ", ""]), _values
)
_narsese_junk = st.one_of(
    st.builds(lambda d: f"dt={d} <a =/> b>.", st.sampled_from(["1e30", "99999999999999999999"])),
    st.builds(lambda f, c: f"<a --> b>. {{{f} {c}}}", _values, _values),
    st.text(max_size=30),
    st.sampled_from(["¹", "²³", "<a -->", "<<<", "(&&)", "a.!", "?", "dt= <a =/> b>."]),
)
_junk = st.lists(st.one_of(_command_lines, _narsese_junk), min_size=1, max_size=8)


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(_junk)
def test_random_lines_never_break_the_next_valid_inputs(junk: list[str]) -> None:
    """Run on the engine in use (``robocog.nars.ENGINE``: the compiled one where it is
    built, the pure one elsewhere). Junk the reasoner accepts is given to the reference
    as well; junk it refuses must leave no trace."""
    nar, out = _fresh()
    ref, ref_out = _fresh()
    for line in junk:
        if "\n" in line or "\r" in line:
            continue  # one input line is one line
        before = memfile.encode(nar)
        printed = len(out)
        try:
            nar.add_input(line)
        except NarseseError as exc:
            assert "\n" not in exc.message
            assert memfile.encode(nar) == before, line
            assert len(out) == printed, line
        else:
            ref.add_input(line)
    del out[:], ref_out[:]
    for s in SCRIPT:
        nar.add_input(s)
        ref.add_input(s)
    assert out == ref_out


def test_the_engine_in_use_is_named() -> None:
    assert nars.ENGINE == "compiled" or nars.ENGINE.startswith("python")


def test_sizes_read_as_binary_units() -> None:
    from robocog.nars.config import concepts_for_memory, parse_size

    assert parse_size("500MB") == 500 << 20 and parse_size("1.5g") == 3 << 29
    assert parse_size("2048") == 2048 and parse_size("64 kb") == 64 << 10
    for bad in ["", "MB", "5XB", "-1MB", "0", "nan", "inf", "1" * 30]:
        with pytest.raises(ValueError):
            parse_size(bad)
    assert concepts_for_memory(parse_size("1TB")) == 100_000_000  # the config's bound


def _shell_run(lines: list[str], pure: bool) -> list[str]:
    import os
    import subprocess
    import sys
    from pathlib import Path

    env = dict(os.environ, PYTHONPATH=str(Path(__file__).resolve().parents[2] / "src"))
    env.pop("ROBOCOG_PURE_PYTHON", None)
    if pure:
        env["ROBOCOG_PURE_PYTHON"] = "1"
    r = subprocess.run(
        [sys.executable, "-m", "robocog", "nar", "--quiet"],
        input="\n".join(lines) + "\n",
        capture_output=True,
        text=True,
        timeout=120,
        env=env,
    )
    assert r.returncode == 0, r.stderr
    return r.stdout.splitlines()


_ENGINES = ["pure"] + (["compiled"] if nars.ENGINE == "compiled" else [])


# two shell processes an example: the property itself has 60 examples in process above,
# so a few here show that the shell, on each engine, keeps it too
@pytest.mark.slow
@pytest.mark.parametrize("engine", _ENGINES)
@settings(max_examples=5, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(junk=_junk)
def test_random_lines_never_break_the_shell_on_each_engine(engine: str, junk: list[str]) -> None:
    """The same property through ``robocog nar``, once per engine this install has:
    the script after the junk prints what it prints after the junk's accepted lines
    alone (the refused ones leave only their error lines)."""
    junk = [
        j for j in junk if j.strip() and "\n" not in j and "\r" not in j and j.rstrip() != "quit"
    ]
    pure = engine == "pure"
    marker = "//the script"
    out = _shell_run([*junk, marker, *SCRIPT], pure)
    refused = {int(x.split()[2].rstrip(",")) for x in out if x.startswith("Error: line ")}
    kept = [j for i, j in enumerate(junk, start=1) if i not in refused]
    ref = _shell_run([*kept, marker, *SCRIPT], pure)
    start = "Comment: the script"
    assert out[out.index(start) :] == ref[ref.index(start) :]
