"""The garbage experiment's report: a markdown page and PNG plots beside it.

The page reproduces Table II with the measured rates, breaks the misses down by cause
as Section V.D does, explains the gap between the minds from those counts, shows the
trajectory of one run as Fig. 6 does, and gives NARS's answer about where trash
accumulates. Plots need matplotlib (the ``viz`` extra), imported only here; without it
the page is written alone.
"""

from __future__ import annotations

import argparse
import dataclasses
import json
from collections.abc import Callable
from pathlib import Path
from typing import Any

from robocog import __version__
from robocog.argtypes import NEW_DIR_STR, NEW_FILE_STR, SEED, int_range
from robocog.atomic import write_text
from robocog.experiments.garbage import CAUSES, PAPER, ExperimentResult, MindResult
from robocog.worlds.garbage import GarbageField

#: the last section of the page, the only one that depends on the machine
TIMINGS_HEADING = "## Timings (these depend on the machine, not on the seeds)"

CAUSE_TEXT = {
    "detection": "at its checkpoint, but never detected by the camera",
    "grasp": "grasp failed (missed, or lying over after a miss)",
    "decision": "seen and graspable but never picked, not dropped, or its checkpoint skipped",
    "time": "not reached: the battery ran out before its checkpoint",
}


def add_run_arguments(
    parser: argparse.ArgumentParser,
    runs: int,
    runs_help: str,
    report_dir: str,
    least_runs: int = 1,
) -> None:
    """The arguments every seeded case study shares: runs, seed, JSON file, report folder
    (``least_runs`` 0 where the study has a part that runs without them)."""
    parser.add_argument("--runs", type=int_range(least_runs, 100_000), default=runs, help=runs_help)
    parser.add_argument("--seed", type=SEED, default=0, help="seed of the first run")
    parser.add_argument(
        "--json", type=NEW_FILE_STR, metavar="FILE", help="write the figures as JSON"
    )
    parser.add_argument(
        "--out",
        "--report",
        dest="report",
        type=NEW_DIR_STR,
        metavar="DIR",
        default=report_dir,
        help="folder of the markdown report and plots",
    )


def provenance(args: argparse.Namespace, config: object | None = None) -> dict[str, Any]:
    """What a result was made with: the robocog version, the command's arguments and the
    world's whole configuration, so that a report can be run again from itself."""
    plain = (str, int, float, bool, type(None))
    arguments = {
        k: str(v) if isinstance(v, Path) else v
        for k, v in sorted(vars(args).items())
        if isinstance(v, (*plain, Path))
    }
    doc: dict[str, Any] = {"robocog_version": __version__, "arguments": arguments}
    if config is not None and dataclasses.is_dataclass(config) and not isinstance(config, type):
        doc["config"] = dataclasses.asdict(config)
    return doc


def provenance_lines(doc: dict[str, Any]) -> list[str]:
    """The markdown section of :func:`provenance`."""
    lines = ["## Configuration", "", f"robocog {doc['robocog_version']}.", ""]
    lines += ["| argument | value |", "|---|---|"]
    lines += [f"| {k} | {v} |" for k, v in doc["arguments"].items()]
    if "config" in doc:
        lines += ["", "| world setting | value |", "|---|---|"]
        lines += [f"| {k} | {v} |" for k, v in doc["config"].items()]
    return lines


def write_json(path: Path, result: ExperimentResult) -> None:
    """The ``--json`` document, written atomically."""
    write_text(path, json.dumps(result.to_json(), indent=2) + "\n")


def _pct(x: float | None) -> str:
    return "—" if x is None else f"{100 * x:.0f}%"


def comparison_rows(result: ExperimentResult) -> list[tuple[str, str, str, str]]:
    """(mind, measured rate, runs, paper rate) per mind, for tables on screen and page."""
    rows = []
    for name, m in result.minds.items():
        measured = _pct(m.success_rate) if m.ok or m.runs else "not run"
        rows.append((name, measured, str(len(m.runs)), _pct(PAPER.get(name))))
    return rows


def explain(result: ExperimentResult) -> list[str]:
    """Sentences that account for the difference between the minds, from the counts."""
    out: list[str] = []
    ran = {n: m for n, m in result.minds.items() if m.runs}
    for name, m in ran.items():
        c = m.causes()
        placed = sum(r.objects for r in m.runs)
        futile = sum(r.futile_picks for r in m.runs)
        futile_s = sum(r.futile_seconds for r in m.runs)
        parts = ", ".join(f"{c[k]} {k}" for k in CAUSES if c.get(k))
        out.append(
            f"{name} collected {sum(r.collected for r in m.runs)} of {placed} objects "
            f"({_pct(m.success_rate)}); missed: {parts or 'none'}. It made {futile} pick "
            f"attempts at objects already lying over, spending {futile_s:.0f} s of "
            f"simulated time on them."
        )
    for name, m in ran.items():
        ev = m.pick_evidence()
        rule = ev.get("background_rule")
        if rule:
            text = (
                f"At the end of a run {name}'s evidence for "
                "`<(<trash --> [see]> &/ ^pick) =/> <gripper --> [hold]>>` was frequency "
                f"{rule['mean_frequency']:.2f}, confidence {rule['mean_confidence']:.2f} on "
                "average (given as 1.00, 0.90)."
            )
            tipped = ev.get("tipped_instances")
            if tipped and tipped["with_hypothesis"]:
                text += (
                    f" For {tipped['with_hypothesis']} of the {tipped['tipped']} objects "
                    "left lying over it had formed "
                    "`<(<{instance} --> [see]> &/ ^pick) =/> <gripper --> [hold]>>`, with "
                    f"frequency {tipped['mean_frequency']:.2f} on average."
                )
            out.append(text)
    for nars in ("NARS", "ONA"):
        if nars not in ran or "BDI" not in ran:
            continue
        n, b = ran[nars], ran["BDI"]
        nf = sum(r.futile_picks for r in n.runs) / max(1, len(n.runs))
        bf = sum(r.futile_picks for r in b.runs) / max(1, len(b.runs))
        gap = (n.success_rate or 0) - (b.success_rate or 0)
        out.append(
            f"The gap is {100 * gap:+.0f} points for {nars}. Per run, BDI picked at objects "
            f"lying over {bf:.1f} times and {nars} {nf:.1f} times. The BDI plan's context "
            "`see(X) & trash(X)` still holds for a tipped bottle, so the agent tries again "
            "until the camera happens to miss it. The reasoner instead weighs another pick "
            "against moving on: each failed grasp is followed by `<gripper --> [hold]>` "
            "denied instead of confirmed, which is evidence against the pick hypothesis "
            "that was just used, and after frames without a successful operation the "
            "route goal is there to be weighed against it. The time BDI loses is missing "
            f"at the end of the route: {b.causes()['time']} objects (BDI) against "
            f"{n.causes()['time']} ({nars}) were never reached."
        )
    return out


def markdown(result: ExperimentResult, images: dict[str, str]) -> str:
    """The report page."""
    cfg = result.config
    physical = getattr(result, "world", "2d") == "mujoco"
    how = (
        "on the physical field in MuJoCo (detections from rendered frames through the "
        "learned detector, grasps by the arm)"
        if physical
        else f"(detection rate {_pct(cfg.detection_rate)}, grasp success "
        f"{_pct(cfg.pick_success)} on a well-detected object)"
    )
    lines = [
        "# Garbage collection (Hammer et al., Section V)",
        "",
        f"{result.runs} runs per mind, seed {result.seed}, {cfg.light} light "
        f"{how}, {cfg.objects} objects on a "
        f"{cfg.size:g} x {cfg.size:g} m field with {cfg.checkpoints} checkpoints, "
        f"{cfg.mission_time:.0f} s of battery per mission; robocog {__version__}. The full "
        "configuration is at the end of the page.",
        "",
        "## Success rate (Table II)",
        "",
        "| mind | success rate | runs | paper |",
        "|---|---|---|---|",
    ]
    lines += [f"| {a} | {b} | {c} | {d} |" for a, b, c, d in comparison_rows(result)]
    detection = getattr(result, "extra", {}).get("detection")
    if detection:
        lines += [
            "",
            "## Detection by light (Table I), measured from rendered frames",
            "",
            "| light | detected | objects in view | frames | paper |",
            "|---|---|---|---|---|",
        ]
        for light, row in detection.items():
            paper = row.get("paper")
            lines.append(
                f"| {light} | {_pct(row['rate'])} | {row['in_view']} | {row['frames']} | "
                f"{_pct(paper) if paper is not None else '-'} |"
            )
    for name, m in result.minds.items():
        if m.unavailable:
            lines += ["", f"**{name} did not run:** {m.unavailable}"]
        if m.error:
            lines += ["", f"**{name} stopped with an error:** {m.error}"]
    if "success" in images:
        lines += ["", f"![success rates]({images['success']})"]
    lines += ["", "## Failures by cause", ""]
    ran = {n: m for n, m in result.minds.items() if m.runs}
    if ran:
        lines += ["| cause | " + " | ".join(ran) + " |", "|---|" + "---|" * len(ran)]
        for cause in CAUSES:
            cells = " | ".join(str(m.causes()[cause]) for m in ran.values())
            lines.append(f"| {cause}: {CAUSE_TEXT[cause]} | {cells} |")
        lines += ["", *explain(result)]
        if "failures" in images:
            lines += ["", f"![failures by cause]({images['failures']})"]
    lines += ["", "## Trajectories (Fig. 6)", ""]
    for name in ran:
        key = f"trajectory_{name}"
        if key in images:
            lines += [
                f"{name}, first run: checkpoints (orange), path (blue), collected (green), "
                "missed (red; a triangle is an object left lying over).",
                "",
                f"![{name} trajectory]({images[key]})",
                "",
            ]
    acc = result.accumulation
    lines += ["## Where trash accumulates", ""]
    if acc is None:
        lines.append("Not asked in this run (use `--rounds N`).")
    elif acc.unavailable:
        lines.append(f"{acc.mind} could not be asked: {acc.unavailable}")
    else:
        lines += [
            f"After {acc.rounds} rounds, asked "
            f"`<<({{SELF}} * {{?1}}) --> at> =/> <trash --> [see]>>?`, {acc.mind} answered:",
            "",
            "    "
            + (
                "None."
                if acc.answer is None
                else f"{acc.answer[0]}. Truth: frequency={acc.answer[1]:.6f}, "
                f"confidence={acc.answer[2]:.6f}"
            ),
            "",
            f"The field's hotspots are {', '.join(acc.hotspots) or 'none'}; {acc.mind}'s "
            "evidence per checkpoint, best expectation first, beside what the field "
            "counted: arrivals, and the share of them with trash in view (a checkpoint "
            "without a hypothesis comes last: the reasoner formed none or forgot it).",
            "",
            "| place | frequency | confidence | expectation | arrivals | with trash in view "
            "| objects seen there |",
            "|---|---|---|---|---|---|---|",
        ]
        ranked = {r[0] for r in acc.ranking}
        rows = [(p, f"{f:.3f}", f"{c:.3f}", f"{e:.3f}") for p, f, c, e in acc.ranking]
        rows += [(p, "-", "-", "-") for p in acc.arrivals if p not in ranked]
        for place, f, c, e in rows:
            share = acc.trash_share(place)
            mark = f"{place} (hotspot)" if place in acc.hotspots else place
            lines.append(
                f"| {mark} | {f} | {c} | {e} | {acc.arrivals.get(place, 0)} | "
                f"{'-' if share is None else f'{share:.2f}'} | "
                f"{acc.seen_per_place.get(place, 0)} |"
            )
        verdict = acc.hotspots_first
        lines += [
            "",
            "Hotspots ranked first: "
            + ("yes" if verdict else "no" if verdict is False else "not decided"),
        ]
    notes = [(name, note) for name, m in result.minds.items() for note in m.notes()]
    if notes:
        lines += ["", "## How the paper's knowledge was read", ""]
        for name, note in notes:
            lines += [f"**{name}.** {note}", ""]
        lines.pop()
    lines += ["", "## Configuration", "", "| setting | value |", "|---|---|"]
    settings = result.to_json()["config"]
    lines += [f"| {k} | {v} |" for k, v in settings.items()]
    # Timings come last, under their own heading: they are the only part of the page that
    # depends on the machine rather than on the seeds and the settings.
    lines += [
        "",
        TIMINGS_HEADING,
        "",
        f"Wall time {result.wall_seconds:.1f} s.",
        "",
        "| mind | reason p50 (ms) | reason p99 (ms) |",
        "|---|---|---|",
    ]
    for name, m in ran.items():
        s = m.summary()
        lines.append(f"| {name} | {s['reason_p50_ms']:.3f} | {s['reason_p99_ms']:.3f} |")
    return "\n".join(lines) + "\n"


def plots(
    result: ExperimentResult, out: Path, say: Callable[[str], None] | None = None
) -> dict[str, str]:
    """PNG plots into ``out``; empty when matplotlib is not installed.

    ``say`` gets a line as each plot is written: importing matplotlib and drawing take
    a few seconds on a busy machine, which would otherwise be the longest silence of a
    piped demo.
    """
    tell = say or (lambda _line: None)
    try:
        tell(f"writing the report and its plots into {out}")
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return {}
    images: dict[str, str] = {}
    ran = {n: m for n, m in result.minds.items() if m.runs}
    if not ran:
        return images
    fig, ax = plt.subplots(figsize=(4.5, 3.2))
    names = list(ran)
    ax.bar(
        names, [100 * (ran[n].success_rate or 0) for n in names], color="#4477aa", label="measured"
    )
    paper = [100 * PAPER[n] for n in names if n in PAPER]
    if len(paper) == len(names):
        ax.scatter(names, paper, color="#cc3311", zorder=3, label="paper (Table II)")
    ax.set_ylabel("objects collected (%)")
    ax.set_ylim(0, 100)
    ax.legend(loc="lower right", fontsize=8)
    fig.tight_layout()
    fig.savefig(out / "success.png", dpi=110)
    plt.close(fig)
    images["success"] = "success.png"
    tell(f"plot: {out / 'success.png'}")

    fig, ax = plt.subplots(figsize=(5.5, 3.2))
    bottom = [0.0] * len(names)
    colours = {"detection": "#bbbbbb", "grasp": "#ee7733", "decision": "#aa3377", "time": "#0077bb"}
    for cause in CAUSES:
        vals = [ran[n].causes()[cause] / max(1, len(ran[n].runs)) for n in names]
        ax.bar(names, vals, bottom=bottom, label=cause, color=colours[cause])
        bottom = [b + v for b, v in zip(bottom, vals, strict=True)]
    ax.set_ylabel("objects missed per run")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out / "failures.png", dpi=110)
    plt.close(fig)
    images["failures"] = "failures.png"
    tell(f"plot: {out / 'failures.png'}")

    layout = GarbageField(result.config, seed=0).describe()
    for name, m in ran.items():
        run = m.runs[0]
        fig, ax = plt.subplots(figsize=(5, 5))
        size = float(layout["size"])
        ax.plot([0, size, size, 0, 0], [0, 0, size, size, 0], color="black", lw=1)
        cps: dict[str, tuple[float, float]] = layout["checkpoints"]  # type: ignore[assignment]
        ax.scatter(
            [p[0] for p in cps.values()],
            [p[1] for p in cps.values()],
            s=90,
            color="orange",
            zorder=2,
        )
        for cp, (x, y) in cps.items():
            ax.annotate(cp, (x, y), textcoords="offset points", xytext=(6, 6), fontsize=8)
        if run.trajectory:
            ax.plot(
                [p[0] for p in run.trajectory],
                [p[1] for p in run.trajectory],
                color="#1f77b4",
                lw=1,
            )
        for item in run.items:
            colour = "green" if item["collected"] else "red"
            marker = "o" if item["collected"] or item["upright"] else "^"
            ax.scatter(item["x"], item["y"], color=colour, marker=marker, s=30, zorder=3)
        ax.set_xlim(-0.5, size + 0.5)
        ax.set_ylim(-0.5, size + 0.5)
        ax.set_aspect("equal")
        ax.set_title(
            f"{name}: {run.collected}/{run.objects} collected (seed {run.seed})", fontsize=10
        )
        fig.tight_layout()
        fname = f"trajectory_{name.lower()}.png"
        fig.savefig(out / fname, dpi=110)
        plt.close(fig)
        images[f"trajectory_{name}"] = fname
        tell(f"plot: {out / fname}")
    return images


def write_report(
    result: ExperimentResult, out: Path, say: Callable[[str], None] | None = None
) -> Path:
    """Write ``report.md`` (and the plots) into ``out``; returns the page's path."""
    out.mkdir(parents=True, exist_ok=True)
    images = plots(result, out, say)
    page = out / "report.md"
    write_text(page, markdown(result, images))
    return page


def summary_table(result: ExperimentResult) -> Any:
    """A rich Table of the comparison, for the terminal."""
    from rich.markup import escape
    from rich.table import Table

    table = Table(title=f"Garbage collection, {result.config.light} light ({result.runs} runs)")
    for col in ("mind", "success rate", "runs", "paper", "missed: detection/grasp/decision/time"):
        table.add_column(col)
    for (name, measured, runs, paper), m in zip(
        comparison_rows(result), result.minds.values(), strict=True
    ):
        if m.runs:
            missed = "/".join(str(m.causes()[c]) for c in CAUSES)
        else:
            missed = "cannot run yet (see below)" if m.unavailable else "error (see below)"
        table.add_row(escape(name), measured, runs, paper, missed)
    return table


def mind_status(m: MindResult) -> str:
    """One line on whether a mind ran."""
    if m.unavailable:
        return f"{m.name}: not run — {m.unavailable}"
    if m.error:
        return f"{m.name}: stopped — {m.error}"
    return f"{m.name}: {len(m.runs)} runs, success rate {_pct(m.success_rate)}"
