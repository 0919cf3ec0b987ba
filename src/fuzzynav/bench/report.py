"""The end of a campaign: ``summary.json``, ``summary.md``, plots and an ``index.html`` showing them.

- ``summary.json``: the records of :func:`fuzzynav.bench.stats.summarise` (rates, 95 % Wilson
  intervals, medians, mean BARN score) and the campaign's arguments;
- ``summary.md``: one table per suite;
- ``rates.png``: success and collision rates per controller and suite, with their intervals;
- ``path_ratio.png``: box plots of the path ratio (successful runs) per controller and suite;
- ``failures-<controller>.png``: a gallery of up to ``gallery`` failed runs of each controller,
  re-run with their seed (runs are deterministic) to draw their trajectories;
- ``index.html``: the tables and every plot on one page.
"""

from __future__ import annotations

import html
import json
from pathlib import Path

import numpy as np
from matplotlib.figure import Figure

from fuzzynav.bench.campaign import Plan
from fuzzynav.bench.stats import summarise
from fuzzynav.storage import write_text_atomic


def _pct(block: dict) -> str:
    low, high = block["ci95"]
    return f"{100 * block['rate']:.1f} [{100 * low:.1f}, {100 * high:.1f}]"


def _num(value, digits: int = 2) -> str:
    return "–" if value is None else f"{value:.{digits}f}"


def markdown(records: list[dict]) -> str:
    """``summary.md``: one table per suite (rates in %, 95 % Wilson intervals in brackets)."""
    lines = ["# Benchmark summary", "",
             "Rates in % with 95 % Wilson intervals; medians over the successful runs (time, path ratio) "
             "or all runs (clearance, steering effort); BARN score: mean over all runs.", ""]
    for suite in dict.fromkeys(record["suite"] for record in records):
        lines += [f"## {suite}", "",
                  "| controller | runs | success % | collision % | timeout % | median time (s) | median path ratio "
                  "| median min clearance (m) | median steering effort (rad) | BARN score |",
                  "|---|---|---|---|---|---|---|---|---|---|"]
        for r in (record for record in records if record["suite"] == suite):
            lines.append(f"| {r['controller']} | {r['runs']} | {_pct(r['reached'])} | {_pct(r['collision'])} | "
                         f"{_pct(r['timeout'])} | {_num(r['median_time_s'], 1)} | {_num(r['median_path_ratio'], 3)} | "
                         f"{_num(r['median_min_clearance_m'])} | {_num(r['median_steering_effort_rad'], 3)} | "
                         f"{_num(r['mean_barn_score'], 3)} |")
        lines.append("")
    return "\n".join(lines)


def _save(figure: Figure, path: Path) -> None:
    tmp = path.with_name(f".{path.name}.tmp.png")
    figure.savefig(tmp, dpi=90)
    tmp.replace(path)


def plot_rates(records: list[dict], path: Path) -> None:
    suites = list(dict.fromkeys(r["suite"] for r in records))
    controllers = list(dict.fromkeys(r["controller"] for r in records))
    figure = Figure(figsize=(max(6, 1.6 * len(controllers) * len(suites) / 2), 6.5))
    width = 0.8 / len(suites)
    for row, outcome in enumerate(("reached", "collision")):
        ax = figure.add_subplot(2, 1, row + 1)
        for j, suite in enumerate(suites):
            by_name = {r["controller"]: r for r in records if r["suite"] == suite}
            x = np.arange(len(controllers)) + (j - (len(suites) - 1) / 2) * width
            rate = np.array([100 * by_name[c][outcome]["rate"] if c in by_name else np.nan for c in controllers])
            ci = np.array([[100 * v for v in by_name[c][outcome]["ci95"]] if c in by_name else [np.nan] * 2
                           for c in controllers])
            ax.bar(x, rate, width, label=suite,
                   yerr=np.abs(np.vstack([rate - ci[:, 0], ci[:, 1] - rate])), capsize=2)
        ax.set_xticks(np.arange(len(controllers)), controllers, rotation=20)
        ax.set_ylabel(f"{'success' if outcome == 'reached' else 'collision'} (%)")
        ax.set_ylim(0, 105)
        ax.grid(axis="y", alpha=0.3)
    figure.axes[0].legend(fontsize=7, ncols=min(4, len(suites)))
    figure.tight_layout()
    _save(figure, path)


def plot_ratios(rows: list[dict], path: Path) -> None:
    suites = list(dict.fromkeys(r["suite"] for r in rows))
    controllers = list(dict.fromkeys(r["controller"] for r in rows))
    figure = Figure(figsize=(max(6, 1.2 * len(controllers)), 2.8 * len(suites)))
    for i, suite in enumerate(suites):
        ax = figure.add_subplot(len(suites), 1, i + 1)
        data = [[r["path_ratio"] for r in rows if r["suite"] == suite and r["controller"] == c
                 and r["path_ratio"] is not None] or [np.nan] for c in controllers]
        ax.boxplot(data, showfliers=True)
        ax.set_xticks(np.arange(1, len(controllers) + 1), controllers, rotation=20)
        ax.set_title(suite, fontsize=9)
        ax.set_ylabel("path / shortest")
        ax.grid(axis="y", alpha=0.3)
    figure.tight_layout()
    _save(figure, path)


def plot_failures(plan: Plan, rows: list[dict], label: str, path: Path, gallery: int) -> bool:
    """Trajectories of up to ``gallery`` failed runs of ``label`` (False when it never failed)."""
    from fuzzynav.bench.cells import build_controller
    from fuzzynav.sim import run_episode
    from fuzzynav.viz.trajectories import draw_world

    failed = [r for r in rows if r["controller"] == label and r["outcome"] != "reached"][:gallery]
    if not failed:
        return False
    spec = dict(plan.controllers).get(label)
    suites = {suite.name: suite for suite in plan.suites}
    columns = min(3, len(failed))
    figure = Figure(figsize=(3.6 * columns, 3.6 * ((len(failed) + columns - 1) // columns)))
    for i, row in enumerate(failed):
        suite = suites.get(row["suite"])
        ax = figure.add_subplot((len(failed) + columns - 1) // columns, columns, i + 1)
        ax.set_title(f"{row['world']} s{row['seed']}: {row['outcome']} {row['time_s']:.0f} s", fontsize=8)
        ax.set_aspect("equal")
        if suite is None or spec is None:
            continue
        index = next(k for k in range(suite.size) if suite.world_name(k, row["seed"]) == row["world"])
        scenario = suite.scenario(index, row["seed"])
        trace = run_episode(scenario, build_controller(spec), seed=row["seed"])
        draw_world(ax, scenario, trace)
        ax.plot(trace.pose[:, 0], trace.pose[:, 1], lw=1.0, color="tab:red")
        ax.tick_params(labelsize=6)
    figure.tight_layout()
    _save(figure, path)
    return True


def index_html(summary_md: str, images: list[str]) -> str:
    """A self-contained page: the summary tables (as preformatted Markdown) and the plots."""
    body = [f"<pre>{html.escape(summary_md)}</pre>"]
    body += [f'<h2>{html.escape(name)}</h2><img src="{html.escape(name)}" style="max-width:100%">' for name in images]
    return ("<!DOCTYPE html><html><head><meta charset='utf-8'><title>fuzzynav bench</title></head><body>"
            + "\n".join(body) + "</body></html>\n")


def write_reports(plan: Plan, rows: list[dict], out: Path, *, gallery: int = 6, arguments: dict | None = None) -> dict:
    """Write every report file of the module docstring into ``out``; returns the summary dict."""
    records = summarise(rows)
    summary = {"arguments": arguments or {}, "results": records}
    write_text_atomic(out / "summary.json", json.dumps(summary, indent=1) + "\n")
    text = markdown(records)
    write_text_atomic(out / "summary.md", text)
    images = []
    if rows:
        plot_rates(records, out / "rates.png")
        plot_ratios(rows, out / "path_ratio.png")
        images += ["rates.png", "path_ratio.png"]
        for label, _ in plan.controllers:
            name = f"failures-{label}.png"
            if gallery > 0 and plot_failures(plan, rows, label, out / name, gallery):
                images.append(name)
    write_text_atomic(out / "index.html", index_html(text, images))
    return summary
