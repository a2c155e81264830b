"""A sweep's report: success curves per mind with 95% intervals, the paired difference
between two minds with its interval, where that lead changes sign, and what the misses
were, as a markdown page with PNG plots (matplotlib, the ``viz`` extra) beside it.

The intervals are over missions: each mission is one observation (its share of objects
collected, or 1/0 where a mission succeeds or not), so a point's interval is the mean's
Student-t interval over its missions, or the Wilson score interval where every mission
either succeeded or failed. The difference of two minds is paired: both minds
meet the same seeded fields, so it is the mean of the per-mission differences, whose
interval is much narrower than the two separate ones would suggest.
"""

from __future__ import annotations

import math
import statistics
from collections import defaultdict
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from robocog import __version__
from robocog.atomic import write_text
from robocog.experiments.sweep import SweepSpec, check

#: two-sided 95% quantiles of Student's t for 1..30 degrees of freedom; beyond, the normal
_T95 = (
    12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228,
    2.201, 2.179, 2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086,
    2.080, 2.074, 2.069, 2.064, 2.060, 2.056, 2.052, 2.048, 2.045, 2.042,
)  # fmt: skip


def t95(df: int) -> float:
    """The two-sided 95% quantile of Student's t with ``df`` degrees of freedom."""
    return _T95[df - 1] if 1 <= df <= len(_T95) else 1.96


@dataclass(frozen=True)
class Estimate:
    """A mean with its 95% interval over ``n`` observations."""

    mean: float
    low: float
    high: float
    n: int

    @classmethod
    def of(cls, values: Sequence[float], bounds: tuple[float, float] = (0.0, 1.0)) -> Estimate:
        """The mean of ``values`` and its Student-t interval (a point for one value),
        clipped to ``bounds``, the range the measure can take."""
        n = len(values)
        mean = statistics.fmean(values)
        if bounds == (0.0, 1.0) and all(v in (0.0, 1.0) for v in values):
            return cls.wilson(mean, n)
        if n < 2:
            return cls(mean, mean, mean, n)
        half = t95(n - 1) * statistics.stdev(values) / math.sqrt(n)
        return cls(mean, max(bounds[0], mean - half), min(bounds[1], mean + half), n)

    @classmethod
    def wilson(cls, share: float, n: int) -> Estimate:
        """A share of successes among ``n`` missions that each succeed or fail, with its
        Wilson score interval (which, unlike the t interval, stays sensible at 0/n and
        n/n)."""
        z = 1.96
        centre = (share + z * z / (2 * n)) / (1 + z * z / n)
        half = z * math.sqrt(share * (1 - share) / n + z * z / (4 * n * n)) / (1 + z * z / n)
        return cls(share, max(0.0, centre - half), min(1.0, centre + half), n)

    @property
    def excludes_zero(self) -> bool:
        """The interval lies wholly on one side of zero."""
        return self.low > 0 or self.high < 0

    def text(self, percent: bool = True) -> str:
        """``68% [61, 75]``-style text."""
        if percent:
            return f"{100 * self.mean:.1f}% [{100 * self.low:.1f}, {100 * self.high:.1f}]"
        return f"{self.mean:.3f} [{self.low:.3f}, {self.high:.3f}]"


Point = tuple[tuple[str, float], ...]


@dataclass
class Summary:
    """What a report is written from."""

    spec: SweepSpec
    success: str
    #: (mind, point) -> estimate of the success measure
    curves: dict[tuple[str, Point], Estimate]
    #: point -> estimate of the paired difference first mind - second mind
    difference: dict[Point, Estimate]
    #: (mind, point) -> mean of every other numeric column (misses by cause, picks, ...)
    means: dict[tuple[str, Point], dict[str, float]]
    compared: tuple[str, str] | None
    missing: int
    #: every setting of the world where no axis varies it
    base: dict[str, Any]

    def crossings(self) -> list[dict[str, Any]]:
        """Where the difference changes sign along each axis, the others held fixed:
        the two neighbouring values and the value where the straight line between
        their means crosses zero."""
        out: list[dict[str, Any]] = []
        if not self.difference:
            return out
        for i, axis in enumerate(self.spec.axes):
            others = [a for j, a in enumerate(self.spec.axes) if j != i]
            for held in _product(others):
                line = []
                for v in axis.values:
                    point = _point(self.spec, {**held, axis.name: v})
                    if point in self.difference:
                        line.append((v, self.difference[point].mean))
                # a mean of exactly zero is no side: the sign changes across it
                signed = [(v, d) for v, d in line if d != 0]
                for (v0, d0), (v1, d1) in zip(signed, signed[1:], strict=False):
                    if d0 * d1 < 0:
                        at = v0 + (v1 - v0) * d0 / (d0 - d1)
                        out.append(
                            {"axis": axis.name, "held": held, "between": (v0, v1), "at": at,
                             "from": d0, "to": d1}
                        )  # fmt: skip
        return out


def _product(axes: Sequence[Any]) -> list[dict[str, float]]:
    combos: list[dict[str, float]] = [{}]
    for axis in axes:
        combos = [{**c, axis.name: v} for c in combos for v in axis.values]
    return combos


def _point(spec: SweepSpec, values: dict[str, float]) -> Point:
    return tuple((a.name, values[a.name]) for a in spec.axes)


def summarise(
    spec: SweepSpec, rows: Sequence[dict[str, Any]], compare: tuple[str, str] | None = None
) -> Summary:
    """Estimates per mind and point, and the paired difference of two minds (by default
    the first two of the sweep), from the table's rows."""
    study = check(spec)
    names = [a.name for a in spec.axes]
    by_cell: dict[tuple[str, Point], list[dict[str, Any]]] = defaultdict(list)
    for row in rows:
        point = tuple((n, float(row[n])) for n in names)
        by_cell[(row["mind"], point)].append(row)
    curves = {
        cell: Estimate.of([float(r[study.success]) for r in cell_rows])
        for cell, cell_rows in by_cell.items()
    }
    means: dict[tuple[str, Point], dict[str, float]] = {}
    skip = {"key", "mind", "seed", "run", "mission_seed", *names}
    for cell, cell_rows in by_cell.items():
        numeric = [
            k for k, v in cell_rows[0].items()
            if k not in skip and isinstance(v, (int, float)) and not isinstance(v, bool)
        ]  # fmt: skip
        means[cell] = {k: statistics.fmean(float(r[k]) for r in cell_rows) for k in numeric}
    if compare is None and len(spec.minds) >= 2:
        compare = (spec.minds[0], spec.minds[1])
    difference: dict[Point, Estimate] = {}
    if compare is not None:
        first, second = compare
        paired: dict[Point, dict[tuple[int, int], list[float]]] = defaultdict(dict)
        for row in rows:
            if row["mind"] not in compare:
                continue
            point = tuple((n, float(row[n])) for n in names)
            slot = paired[point].setdefault((row["seed"], row["run"]), [math.nan, math.nan])
            slot[0 if row["mind"] == first else 1] = float(row[study.success])
        for point, pairs in paired.items():
            diffs = [a - b for a, b in pairs.values() if not (math.isnan(a) or math.isnan(b))]
            if diffs:
                difference[point] = Estimate.of(diffs, (-1.0, 1.0))
    missing = spec.missions - len(rows)
    base = study.base(dict(spec.fixed))
    return Summary(spec, study.success, curves, difference, means, compare, missing, base)


# -- the page -----------------------------------------------------------------------


def _fmt(v: float) -> str:
    return f"{v:g}"


def markdown(summary: Summary, images: dict[str, str]) -> str:
    """The report page."""
    spec = summary.spec
    axes = ", ".join(f"{a.name} {_fmt(a.values[0])}..{_fmt(a.values[-1])}" for a in spec.axes)
    measure = "share of objects collected" if summary.success == "rate" else summary.success
    lines = [
        f"# Sweep: {spec.experiment}",
        "",
        f"Minds {', '.join(spec.minds)}; {axes or 'no varied setting'}; "
        f"{spec.runs} runs x {spec.seeds} seeds per mind and point "
        f"({spec.missions} missions). Success is the {measure} per mission; "
        "intervals are 95% intervals over the missions (Student-t; Wilson where each "
        "mission either succeeds or fails).",
    ]
    if spec.fixed:
        lines += ["", "Fixed: " + ", ".join(f"{k}={v}" for k, v in spec.fixed) + "."]
    if summary.missing:
        lines += [
            "",
            f"**{summary.missing} missions are not in the table yet** (resume the sweep).",
        ]
    for key, title in (("success", "Success per mind"), ("difference", "Paired difference")):
        if key in images:
            lines += ["", f"![{title}]({images[key]})"]
    names = [a.name for a in spec.axes]
    points = spec.points
    lines += ["", "## Success rate per mind", ""]
    head = [*names, *spec.minds]
    if summary.compared:
        head.append(f"{summary.compared[0]} - {summary.compared[1]}")
    lines += ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for point in points:
        cells = [_fmt(v) for _n, v in point]
        for mind in spec.minds:
            est = summary.curves.get((mind, point))
            cells.append(est.text() if est else "—")
        if summary.compared:
            d = summary.difference.get(point)
            cells.append((d.text() + (" *" if d.excludes_zero else "")) if d else "—")
        lines.append("| " + " | ".join(cells) + " |")
    if summary.compared:
        a, b = summary.compared
        lines += [
            "",
            f"`*`: the interval of {a} - {b} excludes zero at that point.",
            "",
            "## Where the lead changes sign",
            "",
        ]
        crossings = summary.crossings()
        if not crossings:
            signs = {d.mean > 0 for d in summary.difference.values()}
            lead = a if signs == {True} else b if signs == {False} else "neither"
            lines.append(
                f"Nowhere along the swept axes: {lead} leads at every point."
                if lead != "neither"
                else "The difference is zero at some points; no strict sign change."
            )
        for c in crossings:
            held = ", ".join(f"{k}={_fmt(v)}" for k, v in c["held"].items())
            lines.append(
                f"- along {c['axis']}{' with ' + held if held else ''}: from "
                f"{100 * c['from']:+.1f} points at {_fmt(c['between'][0])} to "
                f"{100 * c['to']:+.1f} at {_fmt(c['between'][1])}, crossing zero near "
                f"{c['at']:.3f}"
            )
    if "causes" in images:
        lines += ["", "## What was missed", "", f"![misses by cause]({images['causes']})"]
    lines += ["", "## Mean per mission", ""]
    columns = sorted({k for m in summary.means.values() for k in m})
    if columns:
        lines += [
            "| mind | " + " | ".join([*names, *columns]) + " |",
            "|" + "---|" * (1 + len(names) + len(columns)),
        ]
        for point in points:
            for mind in spec.minds:
                m = summary.means.get((mind, point))
                if m is None:
                    continue
                cells = [mind, *(_fmt(v) for _n, v in point)]
                cells += [f"{m.get(c, math.nan):.2f}" for c in columns]
                lines.append("| " + " | ".join(cells) + " |")
    lines += ["", "## Configuration", "", f"robocog {__version__}; the swept axes above, and:"]
    lines += ["", "| setting | value |", "|---|---|"]
    varied = {a.name for a in spec.axes}
    lines += [f"| {k} | {v} |" for k, v in summary.base.items() if k not in varied]
    return "\n".join(lines) + "\n"


def plots(summary: Summary, out: Path) -> dict[str, str]:
    """PNG plots along the first axis (one line per mind, the other axes averaged over
    their values); empty without matplotlib or without an axis."""
    spec = summary.spec
    if not spec.axes:
        return {}
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return {}
    axis = spec.axes[0]
    others = spec.axes[1:]
    images: dict[str, str] = {}

    def marginal(
        values_at: dict[Point, Estimate], extra: dict[str, float]
    ) -> list[Estimate | None]:
        """Along the first axis, the estimate at each value, the other axes held."""
        out = []
        for v in axis.values:
            out.append(values_at.get(_point(spec, {**extra, axis.name: v})))
        return out

    held_sets = _product(others) if others else [{}]
    held_sets = held_sets[:: max(1, len(held_sets) // 4)][:4]  # a few lines, not a thicket
    fig, ax = plt.subplots(figsize=(7, 4.2))
    for mind in spec.minds:
        for held in held_sets:
            est = marginal({p: e for (m, p), e in summary.curves.items() if m == mind}, held)
            xs = [x for x, e in zip(axis.values, est, strict=True) if e]
            es = [e for e in est if e]
            if not es:
                continue
            label = mind + (
                ""
                if not held
                else " (" + ", ".join(f"{k}={_fmt(v)}" for k, v in held.items()) + ")"
            )
            line = ax.plot(xs, [e.mean for e in es], marker="o", label=label)[0]
            ax.fill_between(
                xs, [e.low for e in es], [e.high for e in es], alpha=0.15, color=line.get_color()
            )
    ax.set_xlabel(axis.name)
    ax.set_ylabel("success" if summary.success != "rate" else "share collected")
    ax.set_ylim(0, 1)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title(f"{spec.experiment}: success per mind, 95% intervals")
    fig.tight_layout()
    fig.savefig(out / "success.png", dpi=110)
    plt.close(fig)
    images["success"] = "success.png"
    if summary.compared and summary.difference:
        fig, ax = plt.subplots(figsize=(7, 3.6))
        for held in held_sets:
            est = marginal(summary.difference, held)
            xs = [x for x, e in zip(axis.values, est, strict=True) if e]
            es = [e for e in est if e]
            label = ", ".join(f"{k}={_fmt(v)}" for k, v in held.items()) or None
            line = ax.plot(xs, [100 * e.mean for e in es], marker="o", label=label)[0]
            ax.fill_between(
                xs,
                [100 * e.low for e in es],
                [100 * e.high for e in es],
                alpha=0.15,
                color=line.get_color(),
            )
        ax.axhline(0, color="black", lw=0.8)
        ax.set_xlabel(axis.name)
        a, b = summary.compared
        ax.set_ylabel(f"{a} - {b} (points)")
        ax.grid(alpha=0.3)
        if any(held_sets[0]):
            ax.legend(fontsize=8)
        ax.set_title(f"paired difference {a} - {b}, 95% intervals")
        fig.tight_layout()
        fig.savefig(out / "difference.png", dpi=110)
        plt.close(fig)
        images["difference"] = "difference.png"
    causes = sorted({k for m in summary.means.values() for k in m if k.startswith("missed_")})
    if causes:
        fig, axes = plt.subplots(
            1, len(spec.minds), figsize=(4 * len(spec.minds), 3.4), sharey=True, squeeze=False
        )
        for ax, mind in zip(axes[0], spec.minds, strict=True):
            for cause in [*causes, "futile_picks"]:
                ys = []
                for v in axis.values:
                    cells = [
                        summary.means[(mind, p)].get(cause, 0.0)
                        for p in (
                            _point(spec, {**h, axis.name: v}) for h in (_product(others) or [{}])
                        )
                        if (mind, p) in summary.means
                    ]
                    ys.append(statistics.fmean(cells) if cells else math.nan)
                ax.plot(axis.values, ys, marker=".", label=cause.replace("missed_", "missed: "))
            ax.set_title(mind)
            ax.set_xlabel(axis.name)
            ax.grid(alpha=0.3)
        axes[0][0].set_ylabel("per mission")
        axes[0][-1].legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(out / "causes.png", dpi=110)
        plt.close(fig)
        images["causes"] = "causes.png"
    return images


def write_report(summary: Summary, out: Path) -> Path:
    """The page and its plots into ``out``; the page's path."""
    out.mkdir(parents=True, exist_ok=True)
    page = out / "report.md"
    write_text(page, markdown(summary, plots(summary, out)))
    return page
