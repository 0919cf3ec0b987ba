"""``wall-follow``: the hand-made fuzzy wall follower of thesis §VI.5.3.1 (Figs VI.25–VI.28,
Table VI.2 as reconstructed in :mod:`fuzzynav.fuzzy.systems_navigation`).

It reads three distances — d_d on the right (C6, −90°), d_f ahead (C1, 0°), d_g on the left
(C7, +90°) — and infers α and V_r; it follows the wall on its left and ignores the goal (an
episode ends at the goal only if the followed wall leads there). With nothing seen between its
three rays, it cuts sharp corners and hits their tips or meets an acute corner too late: the
collisions of Fig VI.28 that the QLF-optimised follower of §VI.5.3.2 removes. Label: ``WF``.
"""

from __future__ import annotations

import numpy as np

from fuzzynav.control.batched import BatchedController, evaluate, sensor_columns
from fuzzynav.fuzzy.systems_navigation import wall_follower

WALL_SENSORS_DEG = (-90.0, 0.0, 90.0)  # d_d, d_f, d_g


class WallFollower(BatchedController):
    """Table VI.2 on (d_d, d_f, d_g)."""

    name = "wall-follow"

    def __init__(self, **system_options):
        self.system = wall_follower(**system_options)
        self._columns = None

    def act_batch(self, obs):
        if self._columns is None:
            self._columns = sensor_columns(obs.sensor_angles, WALL_SENSORS_DEG)
        out = evaluate(self.system, np.asarray(obs.ranges, dtype=float)[:, self._columns])
        return out[:, 0], out[:, 1], np.full(len(out), "WF")


def make(**options) -> WallFollower:
    """Factory of the ``wall-follow`` entry of :data:`fuzzynav.control.registry.CONTROLLERS`."""
    return WallFollower(**options)
