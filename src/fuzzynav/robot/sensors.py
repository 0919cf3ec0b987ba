"""Range-sensor ring of the robot, thesis §IV.7 (Figs IV.16–IV.18).

The thesis' robot carries seven ultrasonic sensors C1…C7 measuring distances d1…d7: d1 straight
ahead, d2/d4/d6 on the right side, d3/d5/d7 on the left side. Their angles are not given; this
package uses 0°, −30°, +30°, −60°, +60°, −90°, +90° (CCW positive, relative to the heading) and a
range D_max = 4 m (docs/ARCHITECTURE.md). Rays start at the robot centre (x, y).

Three rings by name (:func:`named_ring`, the ``--sensors`` option and the scenario's ``sensors``
key):

- ``thesis``: the seven directions as single rays (a reading is the first hit along the ray),
  the setting of every reproduced figure;
- ``beam``: the same seven sensors with a 30° beam (``beam_width``): each reads the nearest echo
  inside its cone, the usual model of an ultrasonic sensor (Borenstein & Koren, *Obstacle
  avoidance with ultrasonic sensors*, IEEE J. Robotics Automation 1988); 30° is the beam of the
  common Polaroid-type sonar and the spacing of the ring, so the cones tile ±105°;
- ``lidar``: 271 rays, 1° apart over 270° (a planar laser scanner such as the Hokuyo UTM-30LX).
  A navigator that reads the thesis' seven sensors takes from it the nearest reading of each
  sensor's 30° sector; one that needs the whole scan (gap finding) uses every ray.

A 15 cm post 4 m away spans 2.1°: between two of the thesis' rays (30° apart) it is seen only
once it is within 0.3 m of one of them, while the beam and the lidar see it at full range.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from fuzzynav import validation
from fuzzynav.errors import InputError

THESIS_SENSOR_ANGLES = np.deg2rad([0.0, -30.0, 30.0, -60.0, 60.0, -90.0, 90.0])
THESIS_SENSOR_NAMES = ("C1", "C2", "C3", "C4", "C5", "C6", "C7")


@dataclass(frozen=True)
class SensorRing:
    """A ring of range sensors: directions relative to the heading, range, optional noise.

    ``noise_std`` (m) is Gaussian noise of the real sensor's model
    (:mod:`fuzzynav.robot.imperfections`, ``range_sigma``: an echo gets the noise, kept within
    [0, max_range]; no echo stays at the reach), drawn from the generator passed to :meth:`read`;
    the simulator adds it to the scenario's ``range_sigma``.
    """

    angles: np.ndarray = field(default_factory=lambda: THESIS_SENSOR_ANGLES.copy())
    max_range: float = 4.0
    noise_std: float = 0.0
    beam_width: float = 0.0  # rad; 0: single rays

    def __post_init__(self):
        angles = np.asarray(self.angles, dtype=float).reshape(-1)
        if angles.size == 0 or not np.all(np.isfinite(angles)):
            raise InputError("needs at least one finite angle", field="sensors.angles")
        validation.positive(self.max_range, field="sensors.max_range")
        validation.number(self.noise_std, field="sensors.noise_std", lo=0.0)
        validation.number(self.beam_width, field="sensors.beam_width", lo=0.0, hi=np.pi, hi_open=True)
        object.__setattr__(self, "angles", angles)

    @property
    def count(self) -> int:
        return int(self.angles.size)

    def read(self, world, poses, rng: np.random.Generator | None = None) -> np.ndarray:
        """Readings ``(N, S)`` for poses ``(N, 3)`` in ``world`` (a :class:`fuzzynav.world.World`);
        a noisy ring needs ``rng``."""
        readings = world.ranges(poses, self.angles, self.max_range, beam_width=self.beam_width)
        if self.noise_std > 0.0:
            from fuzzynav.kernels import imperfect
            from fuzzynav.robot.imperfections import Imperfections

            if not isinstance(rng, np.random.Generator):
                raise ValueError("noisy ranges need an explicit numpy.random.Generator (rng)")
            real = imperfect.record(Imperfections(range_sigma=self.noise_std), 1.0, len(readings),
                                    np.random.SeedSequence(int(rng.integers(2**63))))
            imperfect.plant_sense(real, readings, np.ones(len(readings), dtype=bool), self.max_range)
        return readings


LIDAR_ANGLES = np.deg2rad(np.arange(-135.0, 135.5, 1.0))
RINGS = {"thesis": {}, "beam": {"beam_width": np.deg2rad(30.0)}, "lidar": {"angles": LIDAR_ANGLES}}


def named_ring(name: str, max_range: float = 4.0, noise_std: float = 0.0) -> SensorRing:
    """The ring called ``name`` (``thesis``, ``beam`` or ``lidar``, module docstring)."""
    if name not in RINGS:
        raise InputError(f"unknown sensor ring {name!r} (choose {', '.join(RINGS)})", field="sensors")
    return SensorRing(**{"angles": THESIS_SENSOR_ANGLES.copy(), **RINGS[name]}, max_range=max_range,
                      noise_std=noise_std)
