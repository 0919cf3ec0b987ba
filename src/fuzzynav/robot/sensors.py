"""Range-sensor ring of the robot, thesis §IV.7 (Figs IV.16–IV.18).

The thesis' robot carries seven ultrasonic sensors C1…C7 measuring distances d1…d7: d1 straight
ahead, d2/d4/d6 on the right side, d3/d5/d7 on the left side. Their angles are not given; this
package uses 0°, −30°, +30°, −60°, +60°, −90°, +90° (CCW positive, relative to the heading) and a
range D_max = 4 m (docs/ARCHITECTURE.md). Rays start at the robot centre (x, y).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from fuzzynav.errors import InputError

THESIS_SENSOR_ANGLES = np.deg2rad([0.0, -30.0, 30.0, -60.0, 60.0, -90.0, 90.0])
THESIS_SENSOR_NAMES = ("C1", "C2", "C3", "C4", "C5", "C6", "C7")


@dataclass(frozen=True)
class SensorRing:
    """A ring of range sensors: directions relative to the heading, range, optional noise.

    ``noise_std`` (m) adds zero-mean Gaussian noise drawn from the generator passed to
    :meth:`read`; readings stay within [0, max_range].
    """

    angles: np.ndarray = field(default_factory=lambda: THESIS_SENSOR_ANGLES.copy())
    max_range: float = 4.0
    noise_std: float = 0.0

    def __post_init__(self):
        angles = np.asarray(self.angles, dtype=float).reshape(-1)
        if angles.size == 0 or not np.all(np.isfinite(angles)):
            raise InputError("needs at least one finite angle", field="sensors.angles")
        if not np.isfinite(self.max_range) or self.max_range <= 0:
            raise InputError(f"must be > 0, got {self.max_range!r}", field="sensors.max_range")
        if not np.isfinite(self.noise_std) or self.noise_std < 0:
            raise InputError(f"must be ≥ 0, got {self.noise_std!r}", field="sensors.noise_std")
        object.__setattr__(self, "angles", angles)

    @property
    def count(self) -> int:
        return int(self.angles.size)

    def read(self, world, poses, rng: np.random.Generator | None = None) -> np.ndarray:
        """Readings ``(N, S)`` for poses ``(N, 3)`` in ``world`` (a :class:`fuzzynav.world.World`);
        a noisy ring needs ``rng``."""
        return world.ranges(poses, self.angles, self.max_range, noise_std=self.noise_std, rng=rng)
