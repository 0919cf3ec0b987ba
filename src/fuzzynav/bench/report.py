"""The end of a campaign: ``summary.json``, ``summary.md``, plots and an ``index.html`` showing them.

- ``summary.json``: the records of :func:`fuzzynav.bench.stats.summarise` (rates, 95 % Wilson
  intervals, medians, mean BARN score) and the campaign's arguments;
- ``summary.md``: one table per suite;
- ``rates.png``: success, collision and timeout rates per controller and suite, with their intervals;
- ``path_ratio.png``: box plots of the path ratio (successful runs, n under each box) per controller and suite;
- ``failures-<controller>.png``: a gallery of up to ``gallery`` failed runs of each controller,
  re-run with their seed (runs are deterministic) to draw their trajectories;
- ``index.html``: the tables (HTML) and every plot, each with a title and a sentence, on one page.
"""

from __future__ import annotations

import html
import json
import sys
from pathlib import Path

import numpy as np
from matplotlib.figure import Figure

from fuzzynav.bench.campaign import Plan
from fuzzynav.bench.stats import summarise
from fuzzynav.storage import savefig_atomic, write_text_atomic


def _pct(block: dict) -> str:
    low, high = block["ci95"]
    return f"{100 * block['rate']:.1f} [{100 * low:.1f}, {100 * high:.1f}]"


def _num(value, digits: int = 2) -> str:
    return "–" if value is None else f"{value:.{digits}f}"


def markdown(records: list[dict]) -> str:
    """``summary.md``: one table per suite (rates in %, 95 % Wilson intervals in brackets)."""
    lines = ["# Benchmark summary", "",
             "Rates in % with 95 % Wilson intervals; medians over the successful runs (time, path ratio) "
             "or all runs (clearance, steering effort); BARN score: mean over all runs, with the true optimal "
             "path; challenge's: with the path length the challenge's run.py uses (on DynaBARN −31 m).", ""]
    for suite in dict.fromkeys(record["suite"] for record in records):
        lines += [f"## {suite}", "",
                  "| controller | runs | success % | collision % | timeout % | median time (s) | median path ratio "
                  "| median min clearance (m) | median steering effort (rad) | BARN score | BARN score (challenge's) |",
                  "|---|---|---|---|---|---|---|---|---|---|---|"]
        for r in (record for record in records if record["suite"] == suite):
            lines.append(f"| {r['controller']} | {r['runs']} | {_pct(r['reached'])} | {_pct(r['collision'])} | "
                         f"{_pct(r['timeout'])} | {_num(r['median_time_s'], 1)} | {_num(r['median_path_ratio'], 3)} | "
                         f"{_num(r['median_min_clearance_m'])} | {_num(r['median_steering_effort_rad'], 3)} | "
                         f"{_num(r['mean_barn_score'], 3)} | {_num(r.get('mean_barn_score_challenge'), 3)} |")
        lines.append("")
    return "\n".join(lines)


OUTCOME_PANELS = (("reached", "success"), ("collision", "collision"), ("timeout", "timeout"))


def plot_rates(records: list[dict], path: Path) -> None:
    """Success, collision and timeout rates (%) per controller and suite, one panel each, with
    their 95 % Wilson intervals; the legend of suites sits beside the panels, outside the bars."""
    suites = list(dict.fromkeys(r["suite"] for r in records))
    controllers = list(dict.fromkeys(r["controller"] for r in records))
    figure = Figure(figsize=(max(7.5, 1.4 * len(controllers) * max(len(suites), 2) / 2 + 2), 8.5),
                    layout="constrained")
    width = 0.8 / len(suites)
    axes = figure.subplots(len(OUTCOME_PANELS), 1, sharex=True)
    for ax, (outcome, label) in zip(axes, OUTCOME_PANELS):
        for j, suite in enumerate(suites):
            by_name = {r["controller"]: r for r in records if r["suite"] == suite}
            x = np.arange(len(controllers)) + (j - (len(suites) - 1) / 2) * width
            rate = np.array([100 * by_name[c][outcome]["rate"] if c in by_name else np.nan for c in controllers])
            ci = np.array([[100 * v for v in by_name[c][outcome]["ci95"]] if c in by_name else [np.nan] * 2
                           for c in controllers])
            ax.bar(x, rate, width, label=suite, yerr=np.abs(np.vstack([rate - ci[:, 0], ci[:, 1] - rate])), capsize=2)
        ax.set_ylabel(f"{label} (%)")
        ax.set_ylim(0, 105)
        ax.grid(axis="y", alpha=0.3)
    axes[-1].set_xticks(np.arange(len(controllers)), controllers, rotation=20)
    axes[0].legend(title="suite", fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    savefig_atomic(figure, path, dpi=90)


def plot_ratios(rows: list[dict], path: Path) -> None:
    """Box plots of the path ratio (successful runs only) per controller, one panel per suite, with
    the number of runs each box holds (n) under it: a box of one run is a point, not a spread."""
    suites = list(dict.fromkeys(r["suite"] for r in rows))
    controllers = list(dict.fromkeys(r["controller"] for r in rows))
    figure = Figure(figsize=(max(6, 1.2 * len(controllers)), 2.9 * len(suites)), layout="constrained")
    for i, suite in enumerate(suites):
        ax = figure.add_subplot(len(suites), 1, i + 1)
        runs = [[r for r in rows if r["suite"] == suite and r["controller"] == c] for c in controllers]
        data = [[r["path_ratio"] for r in mine if r["path_ratio"] is not None] for mine in runs]
        ax.boxplot([values or [np.nan] for values in data], showfliers=True)
        ax.set_xticks(np.arange(1, len(controllers) + 1),
                      [f"{c}\nn = {len(values)} of {len(mine)}" for c, values, mine in zip(controllers, data, runs)],
                      fontsize=8)
        ax.set_title(f"{suite}: path / shortest path, successful runs", fontsize=9)
        ax.set_ylabel("path ratio")
        ax.grid(axis="y", alpha=0.3)
    savefig_atomic(figure, path, dpi=90)


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
        trace = run_episode(scenario, build_controller(spec), seed=row["seed"], plant=plan.plant)
        draw_world(ax, scenario, trace)
        ax.plot(trace.pose[:, 0], trace.pose[:, 1], lw=1.0, color="tab:red")
        ax.tick_params(labelsize=6)
    figure.tight_layout()
    savefig_atomic(figure, path, dpi=90)
    return True


TABLE_COLUMNS = ("controller", "runs", "success %", "collision %", "timeout %", "median time (s)",
                 "median path ratio", "median min clearance (m)", "median steering effort (rad)", "BARN score",
                 "BARN score (challenge's)")
PLOT_TEXTS = {
    "rates.png": ("Success, collision and timeout rates",
                  "Each bar is the share of a controller's runs on a suite that reached the goal, collided or ran out "
                  "of time; the whiskers are the 95 % Wilson interval of that share."),
    "path_ratio.png": ("Path length against the shortest path",
                       "Boxes of the driven path over the shortest collision-free path, over the successful runs only; "
                       "n under each box says how many runs it holds out of all — compare boxes only where n is large."),
}


def html_tables(records: list[dict]) -> str:
    """The tables of :func:`markdown` as HTML ``<table>`` elements, one per suite."""
    parts = []
    for suite in dict.fromkeys(record["suite"] for record in records):
        head = "".join(f"<th>{html.escape(name)}</th>" for name in TABLE_COLUMNS)
        body = []
        for r in (record for record in records if record["suite"] == suite):
            cells = (r["controller"], r["runs"], _pct(r["reached"]), _pct(r["collision"]), _pct(r["timeout"]),
                     _num(r["median_time_s"], 1), _num(r["median_path_ratio"], 3), _num(r["median_min_clearance_m"]),
                     _num(r["median_steering_effort_rad"], 3), _num(r["mean_barn_score"], 3),
                     _num(r.get("mean_barn_score_challenge"), 3))
            body.append("<tr>" + "".join(f"<td>{html.escape(str(cell))}</td>" for cell in cells) + "</tr>")
        parts.append(f"<h3>{html.escape(suite)}</h3>\n<table>\n<thead><tr>{head}</tr></thead>\n<tbody>\n"
                     + "\n".join(body) + "\n</tbody>\n</table>")
    return "\n".join(parts)


def index_html(records: list[dict], images: list[str]) -> str:
    """A self-contained page: the summary tables and every plot, each with a title and a sentence."""
    style = ("body{font-family:sans-serif;max-width:75em;margin:auto;padding:1em}table{border-collapse:collapse}"
             "th,td{border:1px solid #bbb;padding:.25em .5em;text-align:right}th{background:#eee}"
             "td:first-child{text-align:left}img{max-width:100%}")
    body = ["<h1>fuzzynav bench</h1>",
            "<p>Rates in % with their 95 % Wilson intervals in brackets; medians over the successful runs (time, "
            "path ratio) or over all runs (clearance, steering effort); BARN score: the mean over all runs.</p>",
            "<h2>Results by suite</h2>", html_tables(records)]
    for name in images:
        title, sentence = PLOT_TEXTS.get(name, (f"Failed runs of {name[len('failures-'):-len('.png')]}",
                                                "Trajectories of runs that did not reach the goal (up to --gallery of them), re-run "
                                                "with their seed (each panel: world, seed, outcome, time)."))
        body.append(f"<h2>{html.escape(title)}</h2><p>{html.escape(sentence)}</p>"
                    f'<img src="{html.escape(name)}" alt="{html.escape(title)}">')
    return ("<!DOCTYPE html><html><head><meta charset='utf-8'><title>fuzzynav bench</title>"
            f"<style>{style}</style></head><body>\n" + "\n".join(body) + "\n</body></html>\n")


def write_reports(plan: Plan, rows: list[dict], out: Path, *, gallery: int = 6, arguments: dict | None = None) -> dict:
    """Write every report file of the module docstring into ``out``; returns the summary dict."""
    records = summarise(rows)
    summary = {"arguments": arguments or {}, "results": records}
    write_text_atomic(out / "summary.json", json.dumps(summary, indent=1) + "\n")
    text = markdown(records)
    write_text_atomic(out / "summary.md", text)
    images = []
    if rows:
        print(f"writing plots into {out}/ …", file=sys.stderr, flush=True)
        plot_rates(records, out / "rates.png")
        plot_ratios(rows, out / "path_ratio.png")
        images += ["rates.png", "path_ratio.png"]
        for label, _ in plan.controllers:
            name = f"failures-{label}.png"
            if gallery > 0 and plot_failures(plan, rows, label, out / name, gallery):
                images.append(name)
    write_text_atomic(out / "index.html", index_html(records, images))
    return summary
