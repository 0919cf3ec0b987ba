"""Moving obstacles, the dynamic environments of the thesis' perspectives (Conclusion générale):
the ``motion`` of an obstacle and the offsets of a world's moving obstacles over time
(docs/dynamic.md).

An obstacle with a ``motion`` is moved rigidly: at time t every point of its shape is translated
by p(t) − p(0). The motions:

- ``line``, ``circle``, ``sinusoid``: the closed forms of the moving target
  (:class:`~fuzzynav.world.motion.TargetMotion`, same parameters), p(0) the centre of the
  obstacle's bounding box; a ``line`` reflects at the world's border: its bounding box folds back
  inside [0, W] × [0, H] (a triangle wave on each axis, so the reflected motion is closed-form too);
- ``waypoints``: along the polyline ``points`` at constant ``speed`` (> 0), p(0) = ``points[0]``;
  with ``loop: true`` it returns to the first point and repeats, otherwise it stops at the last.

Every motion is a closed-form function of t, vectorised over t; the simulator asks for the
offsets of all moving obstacles over a block of steps at once (:func:`offsets`), and the compiled
step places them (:mod:`fuzzynav.kernels.traffic`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from fuzzynav.world.motion import MOTION_PARAMS, TargetMotion, read_motion
from fuzzynav.world.polylines import arc_lengths, at_arc

# scenario-file parameters of each obstacle motion: name -> default (None when required)
OBSTACLE_MOTIONS: dict[str, dict[str, object]] = {
    **{kind: params for kind, params in MOTION_PARAMS.items() if kind != "static"},
    "waypoints": {"points": None, "speed": None, "loop": False},  # [[x, y], ...], m/s (> 0), bool
}


@dataclass(frozen=True)
class ObstacleMotion:
    """The motion of one obstacle (``type`` a key of :data:`OBSTACLE_MOTIONS`): ``course`` the
    closed form of a line, circle or sinusoid from the obstacle's reference point, or the
    ``points``, ``speed`` and ``loop`` of a waypoint patrol."""

    type: str
    course: TargetMotion | None = None
    points: np.ndarray | None = None
    speed: float = 0.0
    loop: bool = False

    def offsets(self, t, lower, upper, width: float, height: float) -> np.ndarray:
        """Translation p(t) − p(0) ``(T, 2)`` at times ``t`` ``(T,)`` of an obstacle whose
        bounding box spans ``lower`` … ``upper`` at t = 0, in a ``width`` × ``height`` world."""
        t = np.asarray(t, dtype=float).reshape(-1)
        if self.type == "waypoints":
            return along(self.points, self.speed, self.loop, t) - self.points[0]
        offset = self.course.position(t) - self.course.start
        if self.type == "line":
            lo, hi = -np.asarray(lower, dtype=float), np.array([width, height]) - np.asarray(upper, dtype=float)
            offset = fold(offset, lo, np.maximum(hi, lo))
        return offset

    def top_speed(self) -> float:
        """The largest speed (m/s) of the obstacle (a line reflected at the border keeps its own)."""
        return abs(self.speed) if self.course is None else self.course.top_speed()

    def to_dict(self) -> dict:
        """The scenario-file form of the motion."""
        doc: dict = {"type": self.type}
        for key in OBSTACLE_MOTIONS[self.type]:
            value = getattr(self.course, key) if self.course is not None else getattr(self, key)
            doc[key] = value.tolist() if isinstance(value, np.ndarray) else value
        return doc


def fold(u, lo, hi):
    """``u`` reflected into [lo, hi] (elementwise): the position of a point moving freely to ``u``
    between two mirrors at ``lo`` and ``hi`` (a triangle wave of period 2 (hi − lo))."""
    span = hi - lo
    period = np.where(span > 0, 2.0 * span, 1.0)
    m = np.mod(u - lo, period)
    return np.where(span > 0, lo + np.where(m <= span, m, period - m), lo)


def along(points, speed: float, loop: bool, t) -> np.ndarray:
    """Position ``(T, 2)`` at times ``t`` on the polyline ``points`` driven at ``speed`` from its
    first point: with ``loop`` round the closed polyline (back to the first point) again and
    again, otherwise stopping at the last point."""
    points = np.asarray(points, dtype=float)
    if loop:
        points = np.vstack([points, points[:1]])
    arc = arc_lengths(points)
    s = speed * np.asarray(t, dtype=float)
    s = np.mod(s, arc[-1]) if loop and arc[-1] > 0 else np.minimum(s, arc[-1])
    return at_arc(points, arc, s)


def parse_motion(check, document, field: str, shape) -> ObstacleMotion:
    """The :class:`ObstacleMotion` of an obstacle's ``motion`` entry at ``field`` (problems name
    ``<field>.<key>``); ``shape`` gives the reference point of the closed-form motions."""
    kind, values = read_motion(check, document, field, OBSTACLE_MOTIONS)
    if kind == "waypoints":
        if not values["speed"] > 0:
            check.fail(f"{field}.speed", f"must be > 0, got {values['speed']:g}")
        if not np.any(np.diff(values["points"], axis=0)):
            check.fail(f"{field}.points", "all points are the same (the obstacle would not move)")
        return ObstacleMotion(kind, points=values["points"], speed=values["speed"], loop=values["loop"])
    lower, upper = shape.bounds()
    reference = 0.5 * (np.asarray(lower) + np.asarray(upper))
    if kind == "circle" and np.allclose(values["center"], reference):
        check.fail(f"{field}.center", "must differ from the obstacle's centre (zero radius)")
    return ObstacleMotion(kind, course=TargetMotion(type=kind, start=reference, **values))


def offsets(world, t) -> np.ndarray:
    """Translations ``(T, M, 2)`` at times ``t`` ``(T,)`` of the M moving obstacles of ``world``
    (in the order of :attr:`~fuzzynav.world.world.World.moving`)."""
    t = np.asarray(t, dtype=float).reshape(-1)
    out = np.zeros((len(t), len(world.moving), 2))
    for m, index in enumerate(world.moving):
        lower, upper = world.obstacles[index].bounds()
        out[:, m] = world.motions[index].offsets(t, lower, upper, world.width, world.height)
    return out
