"""Trajectory and command plots of an episode, like Figs IV.12–IV.15 and IV.22–IV.23.

- :func:`draw_world`: boundary, obstacles, start pose, goal (with its tolerance), path
  waypoints or the moving target's course.
- :func:`plot_trajectory`: the driven path coloured by active behaviour (one colour per behaviour
  in every figure, :mod:`fuzzynav.viz.palette`, with a legend saying what each code means), with
  the points where the behaviour changes lettered A, B, C… as in Fig IV.15 (changes closer than
  0.5 m and 1 s to the previous marker share it: :func:`merged_changes`), the robot footprint at
  the end, and optionally the sensor rays every few steps, in a colour of their own.
- :func:`plot_commands`: steering α and speed V_r against time (Fig IV.14).
- :func:`plot_episode`: both side by side, saved to a PNG (:func:`save_figure`).

Figures are built with :class:`matplotlib.figure.Figure` (no pyplot state, no GUI backend).
"""

from __future__ import annotations

import string
from pathlib import Path

import numpy as np
from matplotlib import patches
from matplotlib.collections import LineCollection
from matplotlib.figure import Figure

from fuzzynav import validation
from fuzzynav.settings import flag
from fuzzynav.sim.arguments import check_ran_on, check_trace
from fuzzynav.sim.trace import Trace
from fuzzynav.storage import savefig_atomic
from fuzzynav.viz.moving import draw_moving
from fuzzynav.viz.palette import CHANGE_LEGEND, GOAL_COLOUR, RAY_COLOUR, behaviour_style, legend_order
from fuzzynav.world.scenario import Scenario

OBSTACLE_STYLE = {"facecolor": "0.55", "edgecolor": "0.2", "linewidth": 0.8}


def output_file(path, field: str = "path", what: str = "figure") -> Path:
    """``path`` as a file to write: a file name (:func:`fuzzynav.validation.file_path`) the file
    system takes, not a folder; otherwise an InputError on ``field`` naming the path."""
    path = validation.file_path(path, field=field)
    try:
        folder = path.is_dir()
    except OSError as error:  # a name too long for the file system, ...
        validation.fail(f"{validation.shown(str(path))}: not a usable file name ({error.strerror or error})",
                        field=field)
    if folder:
        validation.fail(f"{str(path)!r} is a folder; give the {what}'s file name", field=field)
    return path


def figure_file(path, field: str = "path") -> Path:
    """``path`` as a figure file to write, checked as ``--plot`` and ``--curve`` are
    (:func:`fuzzynav.cli.arguments.figure_path`, which the command line checks with before any
    work): a file name, not a folder (:func:`output_file`), its suffix one matplotlib writes
    (none: PNG); otherwise an InputError on ``field`` naming the path."""
    from matplotlib.backend_bases import FigureCanvasBase

    path = output_file(path, field)
    suffix = path.suffix.lower().lstrip(".")
    supported = FigureCanvasBase.get_supported_filetypes()
    if suffix and suffix not in supported:
        validation.fail(f"{str(path)!r}: matplotlib cannot write '.{suffix}' files (use one of "
                        f"{', '.join(sorted(supported))})", field=field)
    return path


def change_labels(n: int) -> list[str]:
    """Marker names A, B, …, Z, AA, AB, … for ``n`` behaviour changes (Fig IV.15)."""
    letters = string.ascii_uppercase
    return [letters[i] if i < 26 else letters[i // 26 - 1] + letters[i % 26] for i in range(n)]


def merged_changes(trace: Trace, distance: float = 0.5, time: float = 1.0) -> list[int]:
    """Indices of the behaviour-change markers: a change of :meth:`Trace.behaviour_changes`
    closer than ``distance`` (m) or ``time`` (s) to the last marker joins that marker, any other
    starts a new one — a burst of switches is one lettered point, as the thesis letters each
    manoeuvre once (Fig IV.15, A…H)."""
    xy, t = trace.pose[:, :2], trace.t
    markers: list[int] = []
    for k in trace.behaviour_changes():
        if not markers or (np.hypot(*(xy[k] - xy[markers[-1]])) >= distance and t[k] - t[markers[-1]] >= time):
            markers.append(k)
    return markers


def draw_world(ax, scenario: Scenario, trace: Trace | None = None, *, moving_obstacles: bool = True) -> None:
    """Draw the world of ``scenario`` on ``ax`` (equal axes, metres); its moving obstacles with
    their tracks (:func:`fuzzynav.viz.moving.draw_moving`) unless ``moving_obstacles`` is False
    (an animation draws them frame by frame)."""
    world = scenario.world
    ax.add_patch(patches.Rectangle((0, 0), world.width, world.height, fill=False, edgecolor="k", linewidth=1.5))
    for i, shape in enumerate(world.obstacles):
        if i not in world.moving:
            ax.add_patch(shape.patch(**OBSTACLE_STYLE))  # each obstacle type draws itself (fuzzynav.world.shapes)
    if moving_obstacles and world.moving:
        draw_moving(ax, scenario, trace)
    x, y, theta = scenario.start
    ax.plot(x, y, "ks", markersize=6, label="start")
    ax.annotate("", xy=(x + 0.8 * np.cos(theta), y + 0.8 * np.sin(theta)), xytext=(x, y),
                arrowprops={"arrowstyle": "->", "color": "k"})
    if scenario.goal is not None:
        gx, gy = scenario.goal.position
        ax.add_patch(patches.Circle((gx, gy), scenario.goal.tolerance, fill=False, edgecolor=GOAL_COLOUR))
        ax.plot(gx, gy, "*", color=GOAL_COLOUR, markersize=12, label="goal")
    if scenario.path is not None:
        w = scenario.path.waypoints
        ax.plot(w[:, 0], w[:, 1], "--", color="0.3", linewidth=1.0, label="path")
        ax.plot(w[:, 0], w[:, 1], "o", color="0.3", markersize=3)
    if scenario.target is not None:
        course = trace.target if trace is not None else scenario.target.motion.position(np.array([0.0]))
        ax.plot(course[:, 0], course[:, 1], ":", color=GOAL_COLOUR, linewidth=1.2, label="target's course")
        ax.plot(course[-1, 0], course[-1, 1], "*", color=GOAL_COLOUR, markersize=12)
    ax.set_xlim(-0.5, world.width + 0.5)
    ax.set_ylim(-0.5, world.height + 0.5)
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")


def sensor_segments(pose, angles, ranges) -> np.ndarray:
    """Ray segments ``(S, 2, 2)`` from the robot centre to each reading."""
    heading = pose[2] + np.asarray(angles)
    ends = pose[:2] + np.asarray(ranges)[:, None] * np.stack([np.cos(heading), np.sin(heading)], axis=1)
    return np.stack([np.broadcast_to(pose[:2], ends.shape), ends], axis=1)


def plot_trajectory(trace: Trace, scenario: Scenario, ax=None, *, rays: bool = False, ray_every: int = 20,
                    markers: bool = True):
    """Trajectory of ``trace`` on the world; returns the axes. The legend, below the axes, names
    each behaviour's code and meaning and what the letters mark. With ``rays``, the sensor rays
    of every ``ray_every``-th step (an integer >= 1)."""
    check_ran_on(trace, scenario)
    rays, markers = flag(rays, "rays"), flag(markers, "markers")
    ray_every = validation.integer(ray_every, field="ray_every", lo=1)
    if ax is None:
        ax = Figure(figsize=(6, 7), layout="constrained").add_subplot(111)
    draw_world(ax, scenario, trace)
    xy = trace.pose[:, :2]
    labels = sorted(dict.fromkeys(trace.behaviour), key=legend_order)  # the legend lists them in one order
    if len(labels) > 1 or (labels and labels[0]):
        style = {b: behaviour_style(str(b)) for b in labels}
        segments = np.stack([xy[:-1], xy[1:]], axis=1)
        ax.add_collection(LineCollection(segments, colors=[style[b][0] for b in trace.behaviour], linewidths=1.8))
        for b in labels:
            ax.plot([], [], color=style[b][0], linewidth=1.8, label=style[b][1])
    else:
        ax.plot(xy[:, 0], xy[:, 1], color=behaviour_style("")[0], linewidth=1.8, label="robot")
    if rays:
        for k in range(0, len(trace.pose), ray_every):
            segs = sensor_segments(trace.pose[k], trace.sensor_angles, trace.ranges[k])
            ax.add_collection(LineCollection(segs, colors=RAY_COLOUR, linewidths=0.6, alpha=0.7))
        ax.plot([], [], color=RAY_COLOUR, linewidth=0.6, label=f"range sensors, every {ray_every} steps")
    if markers:
        changes = merged_changes(trace)
        for name, k in zip(change_labels(len(changes)), changes):
            ax.plot(*xy[k], "k.", markersize=5)
            ax.annotate(name, xy[k], xytext=(4, 4), textcoords="offset points", fontsize=9, weight="bold")
        if changes:
            ax.plot([], [], "k.", markersize=5, label=CHANGE_LEGEND)
    end = trace.pose[-1]
    colour = "tab:red" if trace.collision else "k"
    ax.add_patch(patches.Circle(end[:2], trace.robot_radius, fill=False, edgecolor=colour))
    ax.set_title(f"{trace.scenario} — {trace.controller}: {trace.outcome} at t = {trace.time:.1f} s", fontsize=9)
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.1), ncol=1, fontsize=7.5, frameon=False)
    return ax


def plot_commands(trace: Trace, axes=None):
    """Steering α (degrees) and speed V_r (m/s) against time, as in Fig IV.14; returns the axes."""
    check_trace(trace)
    if axes is None:
        figure = Figure(figsize=(6, 5))
        axes = figure.subplots(2, 1, sharex=True)
    t = trace.t[:-1]
    axes[0].step(t, np.degrees(trace.steering), where="post", color="tab:blue")
    axes[0].set_ylabel("steering α (°)")
    axes[0].axhline(0.0, color="0.7", linewidth=0.6)
    axes[1].step(t, trace.speed, where="post", color="tab:red")
    axes[1].set_ylabel("speed V (m/s)")
    axes[1].set_xlabel("time (s)")
    for ax in axes:
        ax.grid(alpha=0.3)
    return axes


def plot_episode(trace: Trace, scenario: Scenario, path=None, *, rays: bool = False) -> Figure:
    """Trajectory (left) and commands (right) in one figure; saved to ``path`` if given (PNG, or
    the format its suffix names: one matplotlib writes, :func:`figure_file`, checked first)."""
    check_ran_on(trace, scenario)
    rays = flag(rays, "rays")
    if path is not None:
        path = figure_file(path)
    figure = Figure(figsize=(12, 7.5), layout="constrained")
    left, right = figure.subfigures(1, 2, width_ratios=[1.1, 1.0])
    plot_trajectory(trace, scenario, left.add_subplot(111), rays=rays)
    plot_commands(trace, right.subplots(2, 1, sharex=True))
    if path is not None:
        save_figure(figure, path)
    return figure


def save_figure(figure: Figure, path, dpi: int = 110) -> str:
    """Save ``figure`` to ``path`` (its folder created), cropped to everything drawn — the
    legends below the axes included; returns the path as a string. A folder or a suffix
    matplotlib does not write is an InputError (:func:`figure_file`)."""
    figure_file(path)
    savefig_atomic(figure, path, dpi=dpi, bbox_inches="tight")
    return str(path)


def save_in(figure: Figure, folder, name: str) -> str:
    """:func:`save_figure` as ``name`` in ``folder`` (the figures of ``fuzzynav reproduce``)."""
    return save_figure(figure, Path(folder) / name)
