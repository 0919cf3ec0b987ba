"""The moving obstacles of a simulated run (:mod:`fuzzynav.world.moving`, docs/dynamic.md).

:class:`MovingObstacles` keeps what the simulator's compiled step needs of them — the static
scene's rows they own, a scene array of the run's own that the step writes them into, their
offsets per step (computed for blocks of steps at once) — and, for a collision, which kernel
column is which moving obstacle (:mod:`fuzzynav.sim.fault`).
"""

from __future__ import annotations

import numpy as np

from fuzzynav.kernels import traffic
from fuzzynav.kernels.records import Traffic
from fuzzynav.world import moving

OFFSET_BLOCK = 1024  # steps of moving-obstacle offsets computed at once
_STILL = np.zeros((0, 2))  # the offsets of a static world's (no) moving obstacles


class MovingObstacles:
    """The moving obstacles of ``world`` stepped every ``dt`` (none: a static world, whose scene
    is never written)."""

    def __init__(self, world, dt: float):
        self.world, self.dt = world, dt
        self.base, self.movers = world.scene, world.movers
        self.scene = world.scene.copy() if len(self.movers) else world.scene
        self.count = int(self.movers.shape[0])
        self.mover_of_column = np.full(len(world.order), -1)
        index = {obstacle: m for m, obstacle in enumerate(world.moving)}
        for column, obstacle in enumerate(world.order[:-1]):
            self.mover_of_column[column] = index.get(int(obstacle), -1)
        self._block = (0, np.zeros((0, self.count, 2)))  # (first step, offsets of the steps from it)

    def offsets(self, k: int) -> np.ndarray:
        """Offsets ``(M, 2)`` of the moving obstacles at step ``k`` (``(0, 2)`` in a static world)."""
        start, block = self._block
        if not 0 <= k - start < len(block):
            if not self.count:
                return _STILL
            start = k - k % OFFSET_BLOCK
            block = moving.offsets(self.world, np.arange(start, start + OFFSET_BLOCK) * self.dt)
            self._block = (start, block)
        return block[k - start]

    def reset(self) -> None:
        """The scene with the moving obstacles where they are at step 0."""
        if self.count:
            self.scene[:] = self.base
            traffic.place(self.base, self.movers, self.offsets(0), self.scene)

    def at(self, k: int) -> Traffic:
        """The compiled step's world record at step ``k``."""
        return Traffic(self.base, self.movers, self.offsets(k), self.scene)
