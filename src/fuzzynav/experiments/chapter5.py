"""Figures of chapter V (§V.3–V.5): control surface, training curves, tracking comparison, pursuit.

- ``fig-V-7``: control surface α(θ_er, dθ_er) of the fuzzy tracker (Table V.1);
- ``fig-V-15``: the MLP inverse model on 100 unseen generalized-learning pairs (desired vs network
  output, and their error) with its training loss;
- ``fig-V-23``: the same for the ANFIS tracker, with its training / validation RMSE per epoch;
- ``fig-V-10`` / ``fig-V-18`` / ``fig-V-26``: the six straight lines T1…T6 from (10,10), robot
  heading 0 (:func:`fuzzynav.sim.paths.star_lines`), tracked by CF / CN / CNF; each also draws one
  straight segment per panel joined from beside its start (Figs V.8 / V.16 / V.24, :data:`SEGMENTS`)
  and the steering it takes (Figs V.9 / V.17 / V.25);
- ``fig-V-11`` / ``fig-V-19`` / ``fig-V-27``: the N (a) and trapezoid (b) paths (scenarios
  ``path-n``, ``path-trapezoid``) by CF / CN / CNF, as in the thesis (solid) and with this
  package's corner anticipation (dashed, :mod:`fuzzynav.control.reference`);
- ``fig-V-28``: the V path (scenario ``fig-V-28``, robot at (2,14) heading 0) tracked by the
  fuzzy (CF), neural (CN) and ANFIS (CNF) controllers as in the thesis (tolerance-zone
  switching, ``corner_radius=0``), overlaid, with a zoom on the corner (panel d);
- ``fig-V-29`` … ``fig-V-31``: pursuit of a target on a line, a circle and a sinusoid (robot at
  (4,4) heading 0, target from (4,12)) by the three controllers, panels (a–c);
- ``fig-V-32``: pursuit of a target on a line by CF, CN, CNF (a–c) and their trajectories
  compared near the capture (d); ``fig-V-33``: two more straight-line targets (a, b);
  ``fig-V-34``: a circular (a) and a sinusoidal (b) target, the three controllers overlaid
  (§V.5.1; the thesis prints no motion parameters, the scenarios ``fig-V-32``, ``fig-V-33a/b``,
  ``fig-V-34a/b`` choose them).

The fuzzy tracker's Table V.1 is the role ``tracker`` of :mod:`fuzzynav.experiments.rule_bases`
(``reproduce --fis tracker=FILE`` replaces it, in the surface of Fig V.7 too); the learned trackers'
models are replaced by :func:`fuzzynav.experiments.learned_models.replaced`. Every run reports
its route (:func:`fuzzynav.experiments.routes.route`) beside its errors or capture time.
Path figures run the trackers as in the thesis (``corner_radius=0``) unless said otherwise.
Every function has the registry signature ``(out_dir, quick, seed) -> dict`` and writes PNGs;
the episodes are short (a few seconds in all), so ``quick`` changes nothing but the ANFIS epochs.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from matplotlib.figure import Figure

from fuzzynav.experiments import learned_models, routes
from fuzzynav.experiments.rule_bases import controller, system
from fuzzynav.learn.tasks import trackers as tt
from fuzzynav.sim import metrics, paths, run_episode
from fuzzynav.viz import palette
from fuzzynav.viz.training import plot_training
from fuzzynav.viz.trajectories import draw_world, save_in
from fuzzynav.world.scenario import load_scenario

TRACKERS = {"fuzzy-tracker": "CF", "neural-tracker": "CN", "anfis-tracker": "CNF"}
COLOURS = {name: colour for name, (colour, _) in palette.TRACKERS.items()}
PATH_KEYS = ("completed", "mean_cross_track_m", "max_cross_track_m", "time_s", "route")
PURSUIT_KEYS = ("captured", "capture_time_s", "path_length_m", "route")
# line styles of the trackers where their curves overlap (CN and CNF coincide, fig-V-28)
STYLES: dict[str, dict[str, Any]] = {"fuzzy-tracker": {"linestyle": "-"},
          "neural-tracker": {"linestyle": "--", "marker": "o", "markevery": 25, "markersize": 4, "fillstyle": "none"},
          "anfis-tracker": {"linestyle": ":", "marker": "x", "markevery": (12, 25), "markersize": 4}}
# Figs V.8 / V.16 / V.24: one straight segment per panel, (start, end) of the reference and the
# robot's start, heading 0, beside it — read off Fig V.8: the robot turns right to join it (Fig V.9)
SEGMENTS = {"a": (((3.0, 16.0), (16.0, 3.0)), (2.5, 15.5)), "b": (((16.0, 16.0), (3.0, 3.0)), (15.5, 16.5))}
SEGMENT_FIGURES = {"fig-V-10": ("fig-V-8", "fig-V-9"), "fig-V-18": ("fig-V-16", "fig-V-17"),
                   "fig-V-26": ("fig-V-24", "fig-V-25")}


def _figure(doc: str, draw, *arguments):
    """The registry function of a figure that ``draw(*arguments, out_dir, seed)`` makes (its
    episodes are short, so ``quick`` changes nothing), with docstring ``doc``."""

    def figure(out_dir, quick: bool = False, seed: int = 0) -> dict:
        return draw(*arguments, out_dir, seed)

    figure.__doc__ = doc
    return figure


PEAKS = (-np.pi / 2, -np.pi / 6, 0.0, np.pi / 6, np.pi / 2)  # NG, NM, Z, PM, PG of θ_er and dθ_er (Fig V.5)


def fig_v_7(out_dir, quick: bool = False, seed: int = 0) -> dict:
    """Fig V.7: control surface of Table V.1, and its value at the 25 peaks of the partition
    (rows θ_er, columns dθ_er: there the surface is the table's singleton)."""
    from fuzzynav.fuzzy.plot import plot_surface, surface

    tracker = system("tracker")
    _, _, alpha = surface(tracker)
    figure = plot_surface(tracker)
    ax = figure.axes[0]
    ax.set(xlabel="θ_er (rad)", ylabel="dθ_er (rad per step of 0.1 s)", zlabel="steering α (rad)",
           title="Fuzzy tracker, Table V.1: control surface")
    grid = np.array([[e, de] for e in PEAKS for de in PEAKS])
    at_peaks = tracker.evaluate(grid)[:, 0].reshape(5, 5)
    return {"figure": save_in(figure, out_dir, "fig-V-7.png"), "alpha_min_rad": float(alpha.min()),
            "alpha_max_rad": float(alpha.max()), "alpha_at_peaks_rad": np.round(at_peaks, 6).tolist()}


def _training_figure(kind: str, out_dir, quick: bool, seed: int) -> dict:
    data = tt.tracker_data(seed)
    model = learned_models.model(kind, seed, quick)
    name = "fig-V-15.png" if kind == "neural-tracker" else "fig-V-23.png"
    figure = plot_training(kind, model, data, None)
    residual = data.y_val - model.predict(data.x_val)
    return {"figure": save_in(figure, out_dir, name), "validation_rmse_rad": float(np.sqrt(np.mean(residual ** 2))),
            "validation_max_error_rad": float(np.abs(residual).max())}


def fig_v_15(out_dir, quick: bool = False, seed: int = 0) -> dict:
    """Fig V.15: validation of the MLP inverse model (and its training loss)."""
    return _training_figure("neural-tracker", out_dir, quick, seed)


def fig_v_23(out_dir, quick: bool = False, seed: int = 0) -> dict:
    """Fig V.23: validation of the ANFIS tracker (and its training curve)."""
    return _training_figure("anfis-tracker", out_dir, quick, seed)


def _run(scenario, name: str, seed: int, **options):
    """One episode of tracker ``name`` (the learned ones trained with ``seed``, or their
    replacement of :mod:`~fuzzynav.experiments.learned_models`): trace and metrics."""
    robot = controller(name, **options) if name == "fuzzy-tracker" else learned_models.tracker(name, seed, **options)
    trace = run_episode(scenario, robot, seed=seed)
    return trace, {**metrics(trace, scenario), "route": routes.route(trace)}


def _runs(scenario_name: str, seed: int, **options):
    scenario = load_scenario(scenario_name)
    return scenario, {name: _run(scenario, name, seed, **options) for name in TRACKERS}


def _numbers(m: dict, keys) -> dict:
    return {k: m[k] for k in keys}


def _draw(ax, trace, name: str, label: str | None = None) -> None:
    """The route of tracker ``name`` in its colour and line style (:data:`STYLES`)."""
    ax.plot(trace.pose[:, 0], trace.pose[:, 1], color=COLOURS[name], label=label or TRACKERS[name], **STYLES[name])


def _segments(kind: str, figure_id: str, out_dir, seed: int) -> dict:
    """Figs V.8 / V.16 / V.24 (one segment per panel) and V.9 / V.17 / V.25 (the steering α(t))."""
    route_figure, command_figure = (Figure(figsize=(11, 5.4), layout="constrained"),
                                    Figure(figsize=(11, 3.4), layout="constrained"))
    names = SEGMENT_FIGURES[figure_id]
    result = {}
    for ax, commands, (panel, (ends, start)) in zip(route_figure.subplots(1, 2), command_figure.subplots(1, 2),
                                                    SEGMENTS.items()):
        scenario = paths.path_scenario(np.array(ends), name=f"segment {panel}", start=start, theta=0.0)
        trace, m = _run(scenario, kind, seed, corner_radius=0.0)
        draw_world(ax, scenario, None)
        _draw(ax, trace, kind, "robot")
        ax.set_title(f"({panel}) max cross-track {m['max_cross_track_m']:.2f} m")
        ax.legend(loc="upper right", fontsize=7)
        commands.step(trace.t[:-1], trace.steering, where="post", color=COLOURS[kind])
        commands.set(title=f"({panel}) steering α", xlabel="time (s)", ylabel="α (rad)")
        commands.grid(alpha=0.3)
        result[panel] = _numbers(m, PATH_KEYS)
    route_figure.suptitle(f"{TRACKERS[kind]} ({kind}): one straight segment")
    command_figure.suptitle(f"{TRACKERS[kind]} ({kind}): commands generated")
    return {"segments": result, "segment_figures": [save_in(route_figure, out_dir, f"{names[0]}.png"),
                                                    save_in(command_figure, out_dir, f"{names[1]}.png")]}


def _star_lines(kind: str, figure_id: str, out_dir, seed: int) -> dict:
    """Figs V.10 / V.18 / V.26: lines T1…T6 from (10,10), robot heading 0, tracker ``kind``."""
    figure = Figure(figsize=(6, 6), layout="constrained")
    ax = figure.subplots()
    lines = {}
    for i, line in enumerate(paths.star_lines()):
        scenario = paths.path_scenario(line, name=f"T{i + 1}", theta=0.0)
        trace, m = _run(scenario, kind, seed, corner_radius=0.0)
        if i == 0:
            draw_world(ax, scenario, None)
        ax.plot(line[:, 0], line[:, 1], "--", color="0.3", linewidth=1.0)
        _draw(ax, trace, kind)
        ax.annotate(f"T{i + 1}", line[1], textcoords="offset points", xytext=(4, 4))
        lines[f"T{i + 1}"] = _numbers(m, PATH_KEYS)
    ax.set(title=f"{TRACKERS[kind]} ({kind}): straight lines T1…T6 from (10, 10), θ = 0",
           xlabel="x (m)", ylabel="y (m)")
    return {"figure": save_in(figure, out_dir, f"{figure_id}.png"), "lines": lines,
            "all_completed": all(v["completed"] for v in lines.values()),
            "worst_max_cross_track_m": max(v["max_cross_track_m"] for v in lines.values()),
            **_segments(kind, figure_id, out_dir, seed)}


def _polygon_paths(kind: str, figure_id: str, out_dir, seed: int) -> dict:
    """Figs V.11 / V.19 / V.27: N (a) and trapezoid (b) paths by tracker ``kind``, as in the
    thesis (solid) and with corner anticipation (dashed)."""
    figure = Figure(figsize=(11, 5.4), layout="constrained")
    result = {}
    for ax, letter, scenario_name in zip(figure.subplots(1, 2), "ab", ("path-n", "path-trapezoid")):
        scenario = load_scenario(scenario_name)
        thesis, m_thesis = _run(scenario, kind, seed, corner_radius=0.0)
        anticipating, m_anticipating = _run(scenario, kind, seed)
        draw_world(ax, scenario, thesis)
        _draw(ax, thesis, kind, f"{TRACKERS[kind]} (thesis)")
        ax.plot(anticipating.pose[:, 0], anticipating.pose[:, 1], "--", color="k", linewidth=0.9,
                label=f"{TRACKERS[kind]} with corner anticipation")
        ax.set_title(f"({letter}) {scenario_name}: max cross-track {m_thesis['max_cross_track_m']:.2f} m "
                     f"(thesis) / {m_anticipating['max_cross_track_m']:.2f} m")
        ax.legend(loc="lower center", fontsize=7)
        result[scenario_name] = {"thesis": _numbers(m_thesis, PATH_KEYS),
                                 "anticipation": _numbers(m_anticipating, PATH_KEYS)}
    figure.suptitle(f"{TRACKERS[kind]} ({kind}): N and trapezoid paths")
    return {"figure": save_in(figure, out_dir, f"{figure_id}.png"), **result}


def fig_v_28(out_dir, quick: bool = False, seed: int = 0) -> dict:
    """Fig V.28: the V path by CF, CN, CNF (a–c) and the overlay zoomed on the corner (d)."""
    scenario, runs = _runs("fig-V-28", seed, corner_radius=0.0)
    figure = Figure(figsize=(16, 4.4), layout="constrained")
    axes = figure.subplots(1, 4)
    for ax, (name, (trace, _)) in zip(axes, runs.items()):
        draw_world(ax, scenario, trace)
        _draw(ax, trace, name)
        ax.set_title(f"({'abc'[list(TRACKERS).index(name)]}) {TRACKERS[name]}")
    zoom = axes[3]
    corner = scenario.path.waypoints[1]
    w = scenario.path.waypoints
    zoom.plot(w[:, 0], w[:, 1], "--", color="0.3", label="reference")
    for name, (trace, _) in runs.items():
        _draw(zoom, trace, name)
    zoom.set(xlim=(corner[0] - 1.5, corner[0] + 1.5), ylim=(corner[1] - 1.0, corner[1] + 2.0),
             aspect="equal", title="(d) comparison at the corner", xlabel="x (m)", ylabel="y (m)")
    zoom.legend()
    gap = routes.deviation(runs["neural-tracker"][1]["route"], runs["anfis-tracker"][1]["route"])
    figure.suptitle(f"CN and CNF learn the same inverse map α = f(θ_er) from the same pairs, so their curves "
                    f"coincide (at most {gap:.2f} m apart): CN dashed with circles, CNF dotted with crosses")
    return {"figure": save_in(figure, out_dir, "fig-V-28.png"), "cn_cnf_route_gap_m": gap,
            **{name: _numbers(m, PATH_KEYS) for name, (_, m) in runs.items()}}


def _pursuit(scenario_name: str, out_dir, seed: int) -> dict:
    scenario, runs = _runs(scenario_name, seed)
    figure = Figure(figsize=(13, 4.4), layout="constrained")
    for ax, (name, (trace, _)) in zip(figure.subplots(1, 3), runs.items()):
        draw_world(ax, scenario, trace)
        _draw(ax, trace, name, "robot")
        ax.set_title(f"({'abc'[list(TRACKERS).index(name)]}) {TRACKERS[name]}")
        ax.legend(loc="upper right", fontsize=7)
    return {"figure": save_in(figure, out_dir, f"{scenario_name}.png"),
            **{name: _numbers(m, PURSUIT_KEYS) for name, (_, m) in runs.items()}}


def _overlay(ax, scenario, runs: dict, title: str) -> None:
    """The three controllers' trajectories on one axis, with the target's course."""
    draw_world(ax, scenario, next(iter(runs.values()))[0])
    for name, (trace, _) in runs.items():
        _draw(ax, trace, name)
    ax.set_title(title)
    ax.legend(loc="upper right", fontsize=7)


def fig_v_32(out_dir, quick: bool = False, seed: int = 0) -> dict:
    """Fig V.32: a target on a line pursued by CF, CN, CNF (a–c), compared near the capture (d)."""
    scenario, runs = _runs("fig-V-32", seed)
    figure = Figure(figsize=(16, 4.4), layout="constrained")
    axes = figure.subplots(1, 4)
    for ax, (name, (trace, m)) in zip(axes, runs.items()):
        draw_world(ax, scenario, trace)
        _draw(ax, trace, name, "robot")
        ax.set_title(f"({'abc'[list(TRACKERS).index(name)]}) {TRACKERS[name]}: captured at {m['capture_time_s']} s")
        ax.legend(loc="upper right", fontsize=7)
    capture = runs["anfis-tracker"][0].pose[-1, :2]
    zoom = axes[3]
    zoom.plot(*runs["anfis-tracker"][0].target.T, ":", color="k", label="target")
    for name, (trace, _) in runs.items():
        _draw(zoom, trace, name)
    zoom.set(xlim=(capture[0] - 2.0, capture[0] + 2.0), ylim=(capture[1] - 2.0, capture[1] + 2.0), aspect="equal",
             title="(d) comparison near the capture", xlabel="x (m)", ylabel="y (m)")
    zoom.legend(fontsize=7)
    return {"figure": save_in(figure, out_dir, "fig-V-32.png"),
            **{name: _numbers(m, PURSUIT_KEYS) for name, (_, m) in runs.items()}}


def _two_pursuits(figure_id: str, scenario_names, titles, out_dir, seed: int) -> dict:
    figure = Figure(figsize=(11, 5.4), layout="constrained")
    result = {}
    for ax, letter, scenario_name, title in zip(figure.subplots(1, 2), "ab", scenario_names, titles):
        scenario, runs = _runs(scenario_name, seed)
        _overlay(ax, scenario, runs, f"({letter}) {title}")
        result[scenario_name] = {name: _numbers(m, PURSUIT_KEYS) for name, (_, m) in runs.items()}
    return {"figure": save_in(figure, out_dir, f"{figure_id}.png"), **result}


def fig_v_33(out_dir, quick: bool = False, seed: int = 0) -> dict:
    """Fig V.33: targets on two straight lines, CF, CN, CNF overlaid."""
    return _two_pursuits("fig-V-33", ("fig-V-33a", "fig-V-33b"),
                         ("target on a line to the right", "target on a line towards the robot"), out_dir, seed)


def fig_v_34(out_dir, quick: bool = False, seed: int = 0) -> dict:
    """Fig V.34: a circular and a sinusoidal target, CF, CN, CNF overlaid."""
    return _two_pursuits("fig-V-34", ("fig-V-34a", "fig-V-34b"),
                         ("target on a circle", "target on a sinusoid"), out_dir, seed)


# the figures one function above draws, per tracker or per scenario
fig_v_10 = _figure("Fig V.10: lines T1…T6, fuzzy tracker CF.", _star_lines, "fuzzy-tracker", "fig-V-10")
fig_v_18 = _figure("Fig V.18: lines T1…T6, neural tracker CN.", _star_lines, "neural-tracker", "fig-V-18")
fig_v_26 = _figure("Fig V.26: lines T1…T6, ANFIS tracker CNF.", _star_lines, "anfis-tracker", "fig-V-26")
fig_v_11 = _figure("Fig V.11: N and trapezoid paths, fuzzy tracker CF.", _polygon_paths, "fuzzy-tracker", "fig-V-11")
fig_v_19 = _figure("Fig V.19: N and trapezoid paths, neural tracker CN.", _polygon_paths, "neural-tracker", "fig-V-19")
fig_v_27 = _figure("Fig V.27: N and trapezoid paths, ANFIS tracker CNF.", _polygon_paths, "anfis-tracker", "fig-V-27")
fig_v_29 = _figure("Fig V.29: pursuit of a target moving on a straight line.", _pursuit, "fig-V-29")
fig_v_30 = _figure("Fig V.30: pursuit of a target moving on a circle.", _pursuit, "fig-V-30")
fig_v_31 = _figure("Fig V.31: pursuit of a target moving on a sinusoid.", _pursuit, "fig-V-31")
