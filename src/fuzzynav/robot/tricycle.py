"""Tricycle (car-like) robot kinematics, thesis §IV.4, eq IV.1–IV.2.

Two rear driving wheels on one motor, one steered front wheel. Controls: steering α (rad,
α > 0 turns left) and linear speed V (m/s). State: pose (x, y, θ), θ CCW from +x.

The thesis gives neither Δt, the wheelbase l nor the width D; :class:`TricycleParams` holds the
defaults fixed in docs/ARCHITECTURE.md (Δt = 0.1 s, l = 0.5 m, D = 0.5 m, footprint disc of
radius 0.3 m, |α| ≤ π/4, 0 ≤ V ≤ 4 m/s), under which the figures of chapter IV are plausible
(episodes of ~25 s over 20 m at up to ~4 m/s). The thesis' robot has no reverse gear (§IV.4);
this package's robot may reverse at up to ``max_reverse_speed`` (default 0.5 m/s, V < 0 in the
same equations), which the thesis' navigators never ask for. A scenario sets these under
``robot:`` (:mod:`fuzzynav.world.scenario`).

Everything is vectorised over a batch of robots: poses ``(N, 3)``, commands ``(N,)``; a single
pose ``(3,)`` with scalar commands works too.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np

from fuzzynav import validation
from fuzzynav.errors import InputError

INTEGRATORS = ("euler", "arc")


@dataclass(frozen=True)
class TricycleParams:
    """Physical parameters and limits of the robot (defaults: docs/ARCHITECTURE.md).

    ``integrator`` is ``"euler"`` (eq IV.2, the thesis' discrete model) or ``"arc"`` (exact
    integration of eq IV.1 for α, V constant over the step: the robot moves on a circular arc).
    """

    dt: float = 0.1  # integration step Δt (s)
    wheelbase: float = 0.5  # l: distance rear axle – front wheel (m)
    width: float = 0.5  # D: robot width (m), used for drawing
    radius: float = 0.3  # collision footprint: disc of this radius centred on (x, y) (m)
    max_steering: float = np.pi / 4  # |α| ≤ max_steering (rad), Fig V.6 range of the trackers
    min_speed: float = 0.0  # V ≥ min_speed (m/s) when the robot cannot reverse (max_reverse_speed = 0)
    max_speed: float = 4.0  # V ≤ max_speed (m/s), the TG singleton of Table IV.1
    integrator: str = "euler"
    max_reverse_speed: float = 0.5  # V ≥ −max_reverse_speed (m/s) when > 0: reverse driving

    def __post_init__(self):
        for name in ("dt", "wheelbase", "width", "radius", "max_steering", "max_speed"):
            validation.positive(getattr(self, name), field=name)
        if self.max_steering >= np.pi / 2:
            raise InputError(f"must be below π/2 (90°), got {self.max_steering!r}", field="max_steering")
        if not np.isfinite(self.min_speed) or self.min_speed > self.max_speed:
            raise InputError("must be finite and ≤ max_speed", field="min_speed")
        if not np.isfinite(self.max_reverse_speed) or self.max_reverse_speed < 0:
            raise InputError(f"must be a finite number ≥ 0, got {self.max_reverse_speed!r}", field="max_reverse_speed")
        if self.integrator not in INTEGRATORS:
            raise InputError(f"must be one of {', '.join(INTEGRATORS)}", field="integrator")

    @property
    def lowest_speed(self) -> float:
        """The lowest speed a command may ask for: −max_reverse_speed, or min_speed without reverse."""
        return -self.max_reverse_speed if self.max_reverse_speed > 0 else self.min_speed

    def clip(self, steering, speed):
        """Clip commands to the limits: |α| ≤ max_steering, :attr:`lowest_speed` ≤ V ≤ max_speed
        (NaN stays NaN). Returns new arrays."""
        low = self.lowest_speed
        steering = np.minimum(np.maximum(steering, -self.max_steering), self.max_steering)
        speed = np.minimum(np.maximum(speed, low), self.max_speed)
        return steering, speed

    def array(self, integrator: str | None = None) -> np.ndarray:
        """The parameters as the kernels read them (:data:`fuzzynav.kernels.motion.ROBOT_FIELDS`; a
        shared read-only array)."""
        method = integrator or self.integrator
        if method not in INTEGRATORS:
            raise InputError(f"must be one of {', '.join(INTEGRATORS)}", field="integrator")
        return _robot_array(self, method)


@functools.lru_cache(maxsize=16)
def _robot_array(params: TricycleParams, method: str) -> np.ndarray:
    values = np.array([params.dt, params.wheelbase, params.radius, params.max_steering, params.lowest_speed,
                       params.max_speed, float(method == "arc")])
    values.flags.writeable = False
    return values


DEFAULT_PARAMS = TricycleParams()


def step(pose, steering, speed, params: TricycleParams = DEFAULT_PARAMS, integrator: str | None = None):
    """Advance poses by one step Δt under (α, V); commands are used as given (clip first).

    ``pose`` is ``(3,)`` or ``(N, 3)``; ``steering`` and ``speed`` are scalars or ``(N,)``.
    ``"euler"`` is eq IV.2: x += Δt V cos θ, y += Δt V sin θ, θ += Δt V tan(α) / l.
    ``"arc"`` integrates eq IV.1 exactly: with ω = V tan(α) / l and θ' = θ + ω Δt,
    x += V (sin θ' − sin θ) / ω, y −= V (cos θ' − cos θ) / ω (the straight line when ω → 0).
    Returns the new poses (same shape), θ wrapped to (−π, π] (:func:`fuzzynav.kernels.motion.advance`).
    """
    from fuzzynav.kernels import motion  # numba, imported when first needed

    robot = params.array(integrator)
    pose = np.asarray(pose, dtype=float)
    shape = np.broadcast_shapes(pose.shape[:-1], np.shape(steering), np.shape(speed))
    poses = np.ascontiguousarray(pose if pose.shape[:-1] == shape else np.broadcast_to(pose, shape + (3,))).reshape(-1, 3)
    steering, speed = (np.ascontiguousarray(v if np.shape(v) == shape else np.broadcast_to(v, shape), dtype=float)
                       .reshape(-1) for v in (steering, speed))
    out = np.empty_like(poses)
    motion.advance_all(poses, steering, speed, robot, out)
    return out.reshape(shape + (3,))
