"""Moving obstacles in the plots and animations (:mod:`fuzzynav.world.moving`): each one's track
(the path of its centre, dotted), where it started (faded) and where it is at the shown time.

- :func:`draw_moving`: on a static plot, the tracks over the episode (or, without a trace, over
  the scenario's ``max_time``) and the obstacles where they were at the end.
- :func:`draw_placed`: the obstacles where they are at one time (a Gymnasium frame);
- :class:`MovingArtists`: in an animation, the obstacles and their tracks so far, moved frame by
  frame (a translation of each patch, no redrawing of the world).
"""

from __future__ import annotations

import numpy as np
from matplotlib.collections import LineCollection
from matplotlib.transforms import Affine2D

from fuzzynav.world import moving

MOVING_STYLE = {"facecolor": "tab:orange", "edgecolor": "0.2", "linewidth": 0.8}
TRACK_STYLE = {"colors": "tab:orange", "linewidths": 1.0, "linestyles": ":"}


def episode_offsets(scenario, trace=None) -> np.ndarray:
    """Offsets ``(K+1, M, 2)`` of the moving obstacles: the trace's, or over the scenario's
    ``max_time`` at the robot's Δt when there is no trace."""
    if trace is not None and trace.obstacle_offsets is not None:
        return trace.obstacle_offsets
    dt = trace.dt if trace is not None else scenario.robot.dt
    return moving.offsets(scenario.world, np.arange(0.0, scenario.max_time + dt / 2, dt))


def tracks(world, offsets) -> np.ndarray:
    """Paths ``(M, K+1, 2)`` of the moving obstacles' bounding-box centres."""
    centres = np.array([np.add(*world.obstacles[i].bounds()) / 2 for i in world.moving]).reshape(-1, 2)
    return centres[:, None, :] + np.swapaxes(offsets, 0, 1)


def _placed(ax, shape, offset, **style):
    patch = shape.patch(**style)
    patch.set_transform(Affine2D().translate(*offset) + ax.transData)
    return patch


def draw_moving(ax, scenario, trace=None) -> None:
    """The moving obstacles of ``scenario`` on ``ax``: faded where they started, their tracks, and
    solid where they were at the end of ``trace`` (at ``max_time`` without one)."""
    world = scenario.world
    offsets = episode_offsets(scenario, trace)
    paths = tracks(world, offsets)
    ax.add_collection(LineCollection(list(paths), **TRACK_STYLE))
    for m, index in enumerate(world.moving):
        shape = world.obstacles[index]
        ax.add_patch(shape.patch(**MOVING_STYLE, alpha=0.3))
        ax.add_patch(_placed(ax, shape, offsets[-1, m], **MOVING_STYLE))
    if world.moving:
        ax.plot([], [], ":", color="tab:orange", label="moving obstacles' tracks")


def draw_placed(ax, world, offsets) -> None:
    """The moving obstacles of ``world`` on ``ax`` where they are at one time (``offsets``
    ``(M, 2)``): a frame of the Gymnasium environments' ``render``."""
    for m, index in enumerate(world.moving):
        ax.add_patch(_placed(ax, world.obstacles[index], offsets[m], **MOVING_STYLE))


class MovingArtists:
    """The animated artists of the moving obstacles: one patch per obstacle and their tracks up
    to the frame (:meth:`show` moves them to step ``k``)."""

    def __init__(self, ax, scenario, trace):
        world = scenario.world
        self.ax, self.offsets = ax, episode_offsets(scenario, trace)
        self.paths = tracks(world, self.offsets)
        self.trails = LineCollection([], **TRACK_STYLE)
        ax.add_collection(self.trails)
        self.patches = [ax.add_patch(world.obstacles[i].patch(**MOVING_STYLE)) for i in world.moving]
        self.artists = (self.trails, *self.patches)

    def show(self, k: int) -> None:
        """Place the obstacles where they are at step ``k`` and their tracks up to it."""
        k = min(k, len(self.offsets) - 1)
        self.trails.set_segments([path[:k + 1] for path in self.paths])
        for patch, offset in zip(self.patches, self.offsets[k]):
            patch.set_transform(Affine2D().translate(*offset) + self.ax.transData)
