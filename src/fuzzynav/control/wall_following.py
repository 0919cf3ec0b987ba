"""``wall-follow``: the hand-made fuzzy wall follower of thesis §VI.5.3.1 (Figs VI.25–VI.28,
Table VI.2 as reconstructed in :mod:`fuzzynav.fuzzy.systems_navigation`).

It reads three distances — d_d on the right (C6, −90°), d_f ahead (C1, 0°), d_g on the left
(C7, +90°) — and infers α and V_r; it follows the wall on its left and ignores the goal (an
episode ends at the goal only if the followed wall leads there). With nothing seen between its
three rays, it cuts sharp corners and hits their tips or meets an acute corner too late: the
collisions of Fig VI.28 that the QLF-optimised follower of §VI.5.3.2 removes. Label: ``WF``.

Rule base by role (``systems=``): ``"wall"`` (d_d, d_f, d_g) → (α, V_r) [Table VI.2]. The decision
is compiled (:func:`fuzzynav.kernels.navigators.act_one`).
"""

from __future__ import annotations

from collections.abc import Mapping

from fuzzynav.control.batched import CompiledNavigator, navigator_params
from fuzzynav.fuzzy.systems_navigation import wall_follower
from fuzzynav.kernels.navigators import WALL_FOLLOWER

WALL_SENSORS_DEG = (-90.0, 0.0, 90.0)  # d_d, d_f, d_g


class WallFollower(CompiledNavigator):
    """Table VI.2 on (d_d, d_f, d_g); role ``"wall"``. ``system_options`` go to
    :func:`~fuzzynav.fuzzy.systems_navigation.wall_follower` (the default table)."""

    name = "wall-follow"
    kind, labels, roles, sensors_deg = WALL_FOLLOWER, ("WF",), ("wall",), WALL_SENSORS_DEG

    def __init__(self, systems: Mapping | None = None, **system_options):
        self._build(systems, lambda: {"wall": wall_follower(**system_options)}, navigator_params())


def make(**options) -> WallFollower:
    """Factory of the ``wall-follow`` entry of :data:`fuzzynav.catalog.controllers.CONTROLLERS`."""
    return WallFollower(**options)
