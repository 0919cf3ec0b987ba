"""Animated GIF of an episode: the robot, its trail and its sensor beams over the world.

The world (obstacles, start, goal or path, axes and ticks) and a legend of the behaviours the
episode used are rendered once with Agg and kept as a background; every frame restores it and
draws only the moving artists (trail coloured by behaviour as in the static plots, the robot's
footprint and heading, the beams it senses, target, title) — blitting, far cheaper than
redrawing and re-laying out the whole figure per frame — and the frames, mapped to one 64-colour
palette, are written with Pillow (no ffmpeg needed). Long episodes are subsampled to at most
``max_frames`` evenly spaced frames (the last one is the end of the episode); every frame shows
the time and the active behaviour, and the last one, held for :data:`HOLD_S`, the outcome.
"""

from __future__ import annotations

import textwrap
from pathlib import Path

import numpy as np
from matplotlib import patches
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.collections import LineCollection
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from PIL import Image

from fuzzynav import validation
from fuzzynav.settings import flag
from fuzzynav.sim.arguments import check_ran_on
from fuzzynav.sim.trace import Trace
from fuzzynav.storage import atomic_write
from fuzzynav.viz.moving import MovingArtists
from fuzzynav.viz.palette import GOAL_COLOUR, RAY_COLOUR, behaviour_style, legend_order
from fuzzynav.viz.trajectories import draw_world, output_file, sensor_segments
from fuzzynav.world.scenario import Scenario

HOLD_S = 2.5  # seconds the last frame, with the outcome, stays on screen before the GIF loops
MIN_SIZE, MAX_SIZE = 64, 4000  # pixels of the GIF's width and height (``run --size``)
MIN_FPS, MAX_FPS = 0.1, 100.0  # frames per second (``run --fps``; GIF frame times are whole 10 ms)
MAX_PIXELS = 100 * MAX_SIZE**2  # pixels of all the frames together: 100 frames of the largest size, 1.6 GB
MAX_BEAMS = 60  # beams drawn per frame at most (a lidar's 271 are thinned evenly)
BODY_COLOUR = "#ffd54f"
LEGEND_WIDTH = 42  # characters of a legend line (two columns fit the figure's 5 inches at 6.5 pt)


def short_meaning(label: str) -> str:
    """The legend text of a behaviour up to its first detail: ``GSB: goal seeking``."""
    return behaviour_style(label)[1].split(" (")[0].split(",")[0]


def behaviour_legend(figure, trace: Trace) -> None:
    """A legend, below the axes and within the figure's width, of the behaviours the episode used,
    the robot and its beams: two columns, a long text wrapped (the figure's constrained layout
    leaves room for it)."""
    labels = sorted(dict.fromkeys(str(b) for b in trace.behaviour), key=legend_order)
    handles = [Line2D([], [], color=behaviour_style(label)[0], linewidth=2.5) for label in labels]
    handles += [patches.Patch(facecolor=BODY_COLOUR, edgecolor="k"), Line2D([], [], color=RAY_COLOUR, linewidth=1)]
    texts = [short_meaning(label) for label in labels] + ["robot footprint, heading", "sensed beams"]
    figure.legend(handles, [textwrap.fill(text, LEGEND_WIDTH) for text in texts], loc="outside lower center",
                  ncols=2, fontsize=6.5, frameon=False)


def gif_file(path, field: str = "path") -> Path:
    """``path`` as the animation to write: a file name, not a folder, ending in ``.gif`` (Pillow's
    writer); otherwise an InputError on ``field`` naming the path."""
    path = output_file(path, field, "animation")
    if not str(path).lower().endswith(".gif"):
        validation.fail(f"{str(path)!r}: the animation is written as GIF, give a name ending in .gif", field=field)
    return path


def check_options(trace: Trace, path, fps, max_frames, size) -> tuple[Path, float, int, int]:
    """The GIF file ``path`` (its name ending in ``.gif``, as ``run --animate`` wants:
    :func:`fuzzynav.cli.arguments.gif_path`), ``fps`` in [:data:`MIN_FPS`, :data:`MAX_FPS`],
    ``size`` an integer in [:data:`MIN_SIZE`, :data:`MAX_SIZE`] (``run --fps``, ``--size``) and
    ``max_frames`` an integer >= 1 whose frames of ``trace`` hold at most :data:`MAX_PIXELS`, returned
    as ``(path, fps, max_frames, size)``; otherwise an InputError naming the argument."""
    path = gif_file(path)
    fps = validation.number(fps, field="fps", lo=MIN_FPS, hi=MAX_FPS)
    size = validation.integer(size, field="size", lo=MIN_SIZE, hi=MAX_SIZE)
    max_frames = validation.integer(max_frames, field="max_frames", lo=1)
    frames = min(max_frames, len(trace.pose))
    if frames * size**2 > MAX_PIXELS:
        validation.fail(f"{frames} frames of {size} x {size} pixels are more than the {MAX_PIXELS:,} pixels of "
                        f"one animation: ask for at most {MAX_PIXELS // size**2} frames or a smaller size",
                        field="max_frames")
    return path, fps, max_frames, size


def animate_episode(trace: Trace, scenario: Scenario, path, *, fps: float = 10, max_frames: int = 100,
                    rays: bool = True, size: int = 400) -> int:
    """Write the episode as a GIF of ``size`` × ``size`` pixels at ``fps`` frames per second to
    ``path``, at most ``max_frames`` frames; returns the number of frames. Bad values are refused
    before anything is drawn (:func:`check_options`)."""
    check_ran_on(trace, scenario)
    rays = flag(rays, "rays")
    path, fps, max_frames, size = check_options(trace, path, fps, max_frames, size)
    dpi = size / 5
    figure = Figure(figsize=(5, 5), dpi=dpi, layout="constrained")
    canvas = FigureCanvasAgg(figure)
    ax = figure.add_subplot(111)
    draw_world(ax, scenario, trace, moving_obstacles=False)
    obstacles = MovingArtists(ax, scenario, trace)  # moving obstacles and their tracks, frame by frame
    behaviour_legend(figure, trace)
    every = max(1, -(-len(trace.sensor_angles) // MAX_BEAMS))
    frames = np.unique(np.linspace(0, len(trace.pose) - 1, min(max_frames, len(trace.pose))).round().astype(int))
    trail = LineCollection([], linewidths=1.8, antialiaseds=False)  # coloured by behaviour, as in the static plots
    ax.add_collection(trail)
    xy = trace.pose[:, :2]
    segments = np.stack([xy[:-1], xy[1:]], axis=1)
    colours = [behaviour_style(str(b))[0] for b in trace.behaviour]
    body = patches.Circle(trace.pose[0, :2], trace.robot_radius, facecolor=BODY_COLOUR, edgecolor="k", linewidth=1.2)
    ax.add_patch(body)
    heading, = ax.plot([], [], color="k", linewidth=2.0)
    beams = LineCollection([], colors=RAY_COLOUR, linewidths=0.7, alpha=0.8)
    ax.add_collection(beams)
    target, = ax.plot([], [], "*", color=GOAL_COLOUR, markersize=12)
    title = ax.set_title(f"{trace.scenario} — {trace.controller}  t = {trace.t[-1]:.1f} s", fontsize=9)
    moving = (*obstacles.artists, trail, beams, body, heading, target, title)
    for artist in moving:
        artist.set_animated(True)
    canvas.draw()  # the one full draw: layout, world, axes
    figure.set_layout_engine("none")
    background = canvas.copy_from_bbox(figure.bbox)

    def image(k: int) -> Image.Image:
        """Frame ``k`` drawn over the background (every artist set from ``k`` alone)."""
        pose = trace.pose[k]
        obstacles.show(k)
        trail.set_segments(segments[:k])
        trail.set_color(colours[:k])
        body.center = pose[:2]
        tip = pose[:2] + 2 * trace.robot_radius * np.array([np.cos(pose[2]), np.sin(pose[2])])
        heading.set_data([pose[0], tip[0]], [pose[1], tip[1]])
        if rays:
            beams.set_segments(sensor_segments(pose, trace.sensor_angles[::every], trace.ranges[k][::every]))
        target.set_data([trace.target[k, 0]], [trace.target[k, 1]])
        behaviour = trace.behaviour[min(k, trace.steps - 1)] if trace.steps else ""
        status = trace.outcome.upper() if k == frames[-1] else behaviour
        title.set_text(f"{trace.scenario} — {trace.controller}  t = {trace.t[k]:.1f} s  {status}")
        canvas.restore_region(background)
        for artist in moving:
            figure.draw_artist(artist)
        return Image.fromarray(np.asarray(canvas.buffer_rgba())[..., :3].copy())

    # one palette, from the busiest frame (the whole trail), drawn first: each frame is mapped to it
    # as soon as it is drawn, so the frames are held at one byte a pixel, not three
    palette = image(frames[-1]).quantize(colors=64)
    images = [image(k).quantize(palette=palette, dither=Image.Dither.NONE) for k in frames]
    step_ms = 10 * max(1, round(100 / fps))  # a GIF's frame time is whole 10 ms: the nearest (15 fps: 70 ms, not 60)
    durations = [step_ms] * (len(images) - 1) + [max(step_ms, int(1000 * HOLD_S))]
    atomic_write(path, lambda handle: images[0].save(handle, format="GIF", save_all=True, append_images=images[1:],
                                                     duration=durations, loop=0))
    return len(frames)
