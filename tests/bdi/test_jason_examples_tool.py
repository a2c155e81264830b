"""tools/jason_examples.py: how it classifies projects and compares outputs."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

TOOL = Path(__file__).resolve().parents[2] / "tools" / "jason_examples.py"


def _tool():  # noqa: ANN202 - the module
    spec = importlib.util.spec_from_file_location("jason_examples_tool", TOOL)
    mod = importlib.util.module_from_spec(spec)
    sys.modules["jason_examples_tool"] = mod
    spec.loader.exec_module(mod)
    return mod


def test_counters_are_placeholders_and_agents_are_compared_apart() -> None:
    tool = _tool()
    jason = "[a] x(_71) @p__4\n[b] two\n[RunLocalMAS] noise\n[a] end\n"
    assert tool.compare("demo", jason, "[b] two\n[a] x(_3) @p__1\n[a] end\n", False, False) is None
    diff = tool.compare("demo", jason, "[a] x(_3) @p__1\n[b] three\n[a] end\n", False, False)
    assert diff is not None and diff.startswith("[b] line 1")


def test_a_run_jason_cut_short_must_begin_robocogs() -> None:
    tool = _tool()
    jason = "[a] 1\n[a] 2\n"
    assert tool.compare("demo", jason, "[a] 1\n[a] 2\n[a] 3\n", True, False) is None
    assert tool.compare("demo", jason, "[a] 1\n", True, False) is not None
    assert tool.compare("demo", jason, "[a] 1\n", True, True) is None


def test_java_parts_of_a_project(tmp_path: Path) -> None:
    tool = _tool()
    (tmp_path / "jia").mkdir()
    (tmp_path / "jia" / "dist.java").write_text("class dist {}\n")
    (tmp_path / "a.asl").write_text("+!g <- jia.dist(1, 2, D); .print(D).\n")
    mas = tmp_path / "p.mas2j"
    mas.write_text(
        "MAS p {\n // environment: Old\n environment: RoomEnv(1)\n"
        ' agents: a beliefBaseClass jason.bb.IndexedBB("b(key)") agentArchClass my.Arch;\n}\n'
    )
    assert tool.java_parts(mas) == [
        "agentArchClass my.Arch",
        "environment RoomEnv",
        "internal action jia.dist",
    ]


def test_the_module_contract_net_masks_what_varies_in_jason_only() -> None:
    tool = _tool()
    name = "examples/contract-net-protocol-module"
    jason = (
        "[alice] Sending CFP for fix(tv) to [company_B1,company_A2]\n"
        "[alice] Winner to fix tv is company_A3\n"
        "[company_A1] Proposing 12.45 for task fix(tv) from agent alice\n"
        "[company_A1] I lost CNP in tv for task fix(tv).\n"
    )
    other_run = (
        "[company_A1] My proposal in tv for task fix(tv) won!\n"
        "[alice] Sending CFP for fix(tv) to [company_A2,company_B1]\n"
        "[company_A1] Proposing 10.9 for task fix(tv) from agent alice\n"
        "[alice] Winner to fix tv is company_A1\n"
    )
    assert tool.compare(name, jason, other_run, False, False) is None
    # the task and the namespace are not masked
    wrong = other_run.replace("in tv for task", "in pc for task")
    assert tool.compare(name, jason, wrong, False, False) is not None
