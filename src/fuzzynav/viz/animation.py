"""Animated GIF of an episode: the robot, its trail and its sensor rays over the world.

Uses matplotlib's ``FuncAnimation`` with the Pillow writer (no ffmpeg needed). Long episodes
are subsampled to at most ``max_frames`` frames; every frame shows the time and the active
behaviour.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
from matplotlib import patches
from matplotlib.animation import FuncAnimation, PillowWriter
from matplotlib.collections import LineCollection
from matplotlib.figure import Figure

from fuzzynav.sim.trace import Trace
from fuzzynav.viz.trajectories import draw_world, sensor_segments
from fuzzynav.world.scenario import Scenario


def animate_episode(trace: Trace, scenario: Scenario, path, *, fps: int = 10, max_frames: int = 150,
                    rays: bool = True, dpi: int = 70) -> int:
    """Write the episode as a GIF to ``path``; returns the number of frames."""
    figure = Figure(figsize=(5, 5), layout="tight")
    ax = figure.add_subplot(111)
    draw_world(ax, scenario, trace)
    frames = np.unique(np.linspace(0, len(trace.pose) - 1, min(max_frames, len(trace.pose))).round().astype(int))
    trail, = ax.plot([], [], color="tab:blue", linewidth=1.5)
    body = patches.Circle(trace.pose[0, :2], trace.robot_radius, fill=False, edgecolor="k")
    ax.add_patch(body)
    heading, = ax.plot([], [], color="k", linewidth=1.5)
    beams = LineCollection([], colors="tab:orange", linewidths=0.7, alpha=0.8)
    ax.add_collection(beams)
    target, = ax.plot([], [], "*", color="tab:green", markersize=12)
    title = ax.set_title("", fontsize=9)

    def draw(k):
        pose = trace.pose[k]
        trail.set_data(trace.pose[: k + 1, 0], trace.pose[: k + 1, 1])
        body.center = pose[:2]
        tip = pose[:2] + 2 * trace.robot_radius * np.array([np.cos(pose[2]), np.sin(pose[2])])
        heading.set_data([pose[0], tip[0]], [pose[1], tip[1]])
        if rays:
            beams.set_segments(sensor_segments(pose, trace.sensor_angles, trace.ranges[k]))
        target.set_data([trace.target[k, 0]], [trace.target[k, 1]])
        behaviour = trace.behaviour[min(k, trace.steps - 1)] if trace.steps else ""
        title.set_text(f"{trace.scenario} — {trace.controller}  t = {trace.t[k]:.1f} s  {behaviour}")
        return trail, body, heading, beams, target, title

    animation = FuncAnimation(figure, draw, frames=frames, blit=False)
    Path(path).parent.mkdir(parents=True, exist_ok=True)
    animation.save(str(path), writer=PillowWriter(fps=fps), dpi=dpi)
    return len(frames)
