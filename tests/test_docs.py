"""Every code example of README.md and docs/*.md runs as written.

The ```python, ```bash and ```console blocks are taken from the Markdown and run, each as
a test of its own named after its file and line (``docs/nars.md:88``):

- a ``bash`` block runs whole under ``bash -e``;
- a ``console`` block runs the lines that start with ``$ `` (a line ending in ``\\`` goes
  on on the next one); the other lines are what the command prints;
- the ``python`` blocks of one file run in order in one interpreter, as a reader types
  them into one session: each block's test runs its file's blocks up to it.

They run in a scratch folder that shows the repository's files (a link to each entry of
its root), so a path such as ``docs/examples/robot.asl`` reads as from the repository's
root, and what an example writes stays out of the repository. A block that cannot run in
CI as written (it needs a robot or a peer, or takes minutes) has the line
``<!-- norun: the reason -->`` directly above its opening fence (docs/design.md,
"Conventions"); it is reported as skipped, with the reason.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
LANGUAGES = ("python", "bash", "console")
FENCE = re.compile(r"^```(\w+)\s*$")
NORUN = re.compile(r"^<!--\s*norun:\s*(.+?)\s*-->\s*$")
#: seconds one block may take (the slow ones are marked norun)
TIMEOUT = 60


@dataclass(frozen=True)
class Block:
    """One code block of a Markdown file."""

    file: str  # relative to the repository
    line: int  # of the opening fence
    language: str
    text: str
    norun: str | None  # the reason, when marked

    @property
    def name(self) -> str:
        return f"{self.file}:{self.line}"


def blocks_of(path: Path, root: Path = ROOT) -> list[Block]:
    """The runnable-language blocks of one Markdown file, in order."""
    lines = path.read_text(encoding="utf-8").splitlines()
    found: list[Block] = []
    i = 0
    while i < len(lines):
        match = FENCE.match(lines[i])
        if match is None:
            if lines[i].startswith("```"):  # another fence: skip to its end
                i += 1
                while i < len(lines) and not lines[i].startswith("```"):
                    i += 1
            i += 1
            continue
        start = i
        i += 1
        body = []
        while i < len(lines) and not lines[i].startswith("```"):
            body.append(lines[i])
            i += 1
        i += 1
        if match.group(1) not in LANGUAGES:
            continue
        above = NORUN.match(lines[start - 1]) if start else None
        found.append(
            Block(
                str(path.relative_to(root)),
                start + 1,
                match.group(1),
                "\n".join(body) + "\n",
                above.group(1) if above else None,
            )
        )
    return found


def all_blocks() -> list[Block]:
    files = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
    return [b for f in files for b in blocks_of(f)]


BLOCKS = all_blocks()


def console_commands(text: str) -> list[str]:
    """The commands of a console block: ``$ `` lines, with their ``\\`` continuations."""
    commands: list[str] = []
    lines = text.splitlines()
    i = 0
    while i < len(lines):
        if lines[i].startswith("$ "):
            command = lines[i][2:]
            while command.endswith("\\") and i + 1 < len(lines):
                i += 1
                command = command[:-1] + " " + lines[i].strip()
            commands.append(command)
        i += 1
    return commands


def _tracked_entries() -> set[str] | None:
    """The names at the repository's root that git tracks (None outside a checkout): an
    untracked folder there (``reports/``, a build) is output, which examples must not
    write into."""
    try:
        listed = subprocess.run(
            ["git", "ls-files"], cwd=ROOT, capture_output=True, text=True, timeout=30
        )
    except (OSError, subprocess.TimeoutExpired):
        return None
    if listed.returncode != 0 or not listed.stdout:
        return None
    return {line.split("/")[0] for line in listed.stdout.splitlines()}


@pytest.fixture
def scratch(tmp_path: Path) -> Path:
    """A folder showing the repository's root entries, where examples write freely."""
    tracked = _tracked_entries()
    for entry in ROOT.iterdir():
        if entry.name != ".git" and (tracked is None or entry.name in tracked):
            (tmp_path / entry.name).symlink_to(entry)
    return tmp_path


def _env() -> dict[str, str]:
    env = dict(os.environ)
    src = str(ROOT / "src")
    env["PYTHONPATH"] = (
        src + os.pathsep + env.get("PYTHONPATH", "") if env.get("PYTHONPATH") else src
    )
    env.setdefault("MPLBACKEND", "Agg")
    env["COLUMNS"] = "100"
    return env


def _run(argv: list[str], cwd: Path, stdin: str = "") -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        argv,
        cwd=cwd,
        env=_env(),
        input=stdin,
        capture_output=True,
        text=True,
        timeout=TIMEOUT,
    )


def _report(block: Block, result: subprocess.CompletedProcess[str], what: str) -> str:
    return (
        f"{block.name} ({block.language}): {what} exited {result.returncode}\n"
        f"--- stdout\n{result.stdout[-3000:]}\n--- stderr\n{result.stderr[-3000:]}"
    )


def test_the_blocks_are_found_with_their_marks(tmp_path: Path) -> None:
    names = {b.name for b in BLOCKS}
    assert any(n.startswith("README.md:") for n in names)
    assert any(b.norun for b in BLOCKS) and any(not b.norun for b in BLOCKS)
    text = (
        "x\n<!-- norun: needs a robot -->\n```bash\nrobocog bridge ros2\n```\n```text\n$ no\n```\n"
    )
    path = tmp_path / "probe.md"
    path.write_text(text, encoding="utf-8")
    [block] = blocks_of(path, tmp_path)
    assert (block.line, block.language, block.norun) == (3, "bash", "needs a robot")
    assert console_commands("$ a \\\n    b\nout\n$ c\n") == ["a  b", "c"]


@pytest.mark.parametrize("block", BLOCKS, ids=lambda b: b.name)
def test_the_example_runs_as_written(block: Block, scratch: Path) -> None:
    if block.norun:
        pytest.skip(f"norun: {block.norun}")
    if block.language == "bash":
        result = _run(["bash", "-e", "-o", "pipefail", "-c", block.text], scratch)
        assert result.returncode == 0, _report(block, result, "the block")
    elif block.language == "console":
        commands = console_commands(block.text)
        assert commands, f"{block.name}: a console block with no '$ ' line"
        for command in commands:
            result = _run(["bash", "-e", "-o", "pipefail", "-c", command], scratch)
            assert result.returncode == 0, _report(block, result, repr(command))
            assert "Traceback" not in result.stderr, _report(block, result, repr(command))
    else:
        session = [b for b in BLOCKS if b.file == block.file and b.language == "python"]
        upto = session[: session.index(block) + 1]
        # blocks marked norun before this one are left out: the ones after them may not
        # need what they define (a block that does is marked too)
        script = "".join(f"# --- {b.name}\n{b.text}" for b in upto if not b.norun)
        (scratch / "_example.py").write_text(script, encoding="utf-8")
        result = _run([sys.executable, "_example.py"], scratch)
        assert result.returncode == 0, _report(block, result, "the session up to it")
