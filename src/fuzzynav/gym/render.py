"""Frames of an environment with matplotlib: the world, the robot's footprint and heading, its
rays, its target and the moving obstacles where they are (the drawing of :func:`fuzzynav.viz.trajectories.draw_world`).

``rgb_array`` renders off-screen (Agg) and returns an (H, W, 3) ``uint8`` array; ``human``
draws into a pyplot window and pauses 1 / fps (with a non-interactive backend it only draws,
so it runs without a display).
"""

from __future__ import annotations

import numpy as np

from fuzzynav.viz.moving import draw_placed
from fuzzynav.viz.trajectories import draw_world, sensor_segments


class Renderer:
    """One figure reused for every frame."""

    def __init__(self, mode: str, fps: int, size: float = 5.0):
        self.mode, self.fps = mode, fps
        if mode == "human":
            import matplotlib.pyplot as plt

            self.figure = plt.figure(figsize=(size, size))
        else:
            from matplotlib.backends.backend_agg import FigureCanvasAgg
            from matplotlib.figure import Figure

            self.figure = Figure(figsize=(size, size), dpi=80)
            FigureCanvasAgg(self.figure)

    def draw(self, scenario, pose, target, sensors, ranges, obstacle_offsets=None):
        """One frame; ``obstacle_offsets`` ``(M, 2)``: where the moving obstacles are now."""
        from matplotlib import patches

        self.figure.clf()
        ax = self.figure.add_subplot()
        draw_world(ax, scenario, moving_obstacles=False)
        if scenario.world.moving:
            draw_placed(ax, scenario.world, obstacle_offsets)
        if target is not None:
            ax.plot(*target, "x", color="tab:red", markersize=8)
        if ranges is not None:
            for (a, b) in sensor_segments(pose, sensors.angles, ranges):
                ax.plot([a[0], b[0]], [a[1], b[1]], color="tab:orange", linewidth=0.8)
        x, y, theta = pose
        ax.add_patch(patches.Circle((x, y), 0.3, color="tab:blue", alpha=0.6))
        ax.plot([x, x + 0.6 * np.cos(theta)], [y, y + 0.6 * np.sin(theta)], color="k", linewidth=1.5)
        canvas = self.figure.canvas
        canvas.draw()
        if self.mode == "human":
            import matplotlib
            import matplotlib.pyplot as plt

            if matplotlib.get_backend().lower() != "agg":
                plt.pause(1.0 / self.fps)
            return None
        return np.asarray(canvas.buffer_rgba())[..., :3].copy()

    def close(self) -> None:
        if self.mode == "human":
            import matplotlib.pyplot as plt

            plt.close(self.figure)
