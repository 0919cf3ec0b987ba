"""Motions of a moving target, thesis §V.5 (Figs V.29–V.34), and the reading of a ``motion``
entry of a scenario file (the target's, and a moving obstacle's: :mod:`fuzzynav.world.moving`).

The target starts at its scenario position p0 and moves along a straight line, a circle or a
sinusoid; its position (and velocity) are known at all times. Every motion is a closed-form
function of time, vectorised over ``t``.
"""

from __future__ import annotations

import difflib
from dataclasses import dataclass

import numpy as np

from fuzzynav import validation
from fuzzynav.world import limits

# scenario-file parameters of each motion type: name -> (default or None when required)
MOTION_PARAMS: dict[str, dict[str, object]] = {
    "static": {},
    "line": {"velocity": None},  # [vx, vy] m/s
    "circle": {"center": None, "speed": None},  # centre of the circle, linear speed (m/s, > 0 CCW)
    "sinusoid": {"velocity": None, "amplitude": None, "period": None},  # carrier [vx, vy], m, s
}


@dataclass(frozen=True)
class TargetMotion:
    """Trajectory p(t) of the target from its start p0 (``type`` is a key of MOTION_PARAMS).

    - ``static``: p(t) = p0.
    - ``line``: p(t) = p0 + v t.
    - ``circle``: around ``center`` at linear ``speed`` (> 0 counter-clockwise); the radius is
      |p0 − center|.
    - ``sinusoid``: p(t) = p0 + v t + n A sin(2π t / T), n the unit left normal of v.
    """

    type: str = "static"
    start: np.ndarray = None
    velocity: np.ndarray | None = None
    center: np.ndarray | None = None
    speed: float = 0.0
    amplitude: float = 0.0
    period: float = 1.0

    def __post_init__(self):
        object.__setattr__(self, "start", np.asarray(self.start, dtype=float).reshape(2))

    def _normal(self):
        v = np.asarray(self.velocity, dtype=float)
        norm = np.hypot(*v)
        return np.array([-v[1], v[0]]) / norm if norm > 0 else np.zeros(2)

    def position(self, t):
        """Target position at time(s) ``t``: ``(2,)`` for a scalar, ``(T, 2)`` for an array."""
        t = np.asarray(t, dtype=float)
        tt = t[..., None]
        if self.type == "static":
            return np.broadcast_to(self.start, tt.shape[:-1] + (2,)).copy()
        if self.type == "line":
            return self.start + tt * np.asarray(self.velocity)
        if self.type == "circle":
            rel = self.start - self.center
            radius = np.hypot(*rel)
            phase = np.arctan2(rel[1], rel[0]) + self.speed / radius * t
            return self.center + radius * np.stack([np.cos(phase), np.sin(phase)], axis=-1)
        omega = 2.0 * np.pi / self.period
        return self.start + tt * np.asarray(self.velocity) + self.amplitude * np.sin(omega * tt) * self._normal()

    def velocity_at(self, t):
        """Target velocity dp/dt at time(s) ``t`` (same shapes as :meth:`position`)."""
        t = np.asarray(t, dtype=float)
        tt = t[..., None]
        if self.type == "static":
            return np.zeros(tt.shape[:-1] + (2,))
        if self.type == "line":
            return np.broadcast_to(np.asarray(self.velocity, dtype=float), tt.shape[:-1] + (2,)).copy()
        if self.type == "circle":
            rel = self.start - self.center
            radius = np.hypot(*rel)
            phase = np.arctan2(rel[1], rel[0]) + self.speed / radius * t
            return self.speed * np.stack([-np.sin(phase), np.cos(phase)], axis=-1)
        omega = 2.0 * np.pi / self.period
        return np.asarray(self.velocity) + self.amplitude * omega * np.cos(omega * tt) * self._normal()

    def top_speed(self) -> float:
        """The largest speed (m/s) of the motion: |v| of a line, |speed| of a circle, and of a
        sinusoid √(|v|² + (2πA / T)²) (its wave moves across v, along the normal n)."""
        if self.type == "static":
            return 0.0
        if self.type == "circle":
            return abs(float(self.speed))
        wave = 2.0 * np.pi * abs(self.amplitude) / self.period if self.type == "sinusoid" else 0.0
        return float(np.hypot(np.hypot(*self.velocity), wave))


def read_motion(check, document, field: str, table: dict[str, dict[str, object]]) -> tuple[str, dict]:
    """``(type, values)`` of a scenario file's ``motion`` mapping at ``field``, its ``type`` a key
    of ``table`` (parameter name -> default, ``None`` when required; :data:`MOTION_PARAMS` for the
    target): every value checked by the scenario's :class:`~fuzzynav.world.checks.Checks`
    ``check``, each problem naming ``<field>.<key>``."""
    if not isinstance(document, dict) or "type" not in document:
        check.fail(f"{field}.type", "missing (one of: " + ", ".join(table) + ")")
    kind = document["type"]
    if not isinstance(kind, str) or kind not in table:
        close = difflib.get_close_matches(str(kind), list(table), n=1)
        hint = f" (did you mean {close[0]!r}?)" if close else ""
        check.fail(f"{field}.type", f"unknown motion {kind!r}{hint}; known: {', '.join(table)}")
    params = table[kind]
    check.mapping(document, field, ("type", *params), required=[k for k, v in params.items() if v is None])
    values = {}
    for key, default in params.items():
        value, where = document.get(key, default), f"{field}.{key}"
        if key == "center":
            values[key] = check.point(value, where)
        elif key == "points":
            values[key] = check.points(value, where, 2, limits.MAX_WAYPOINTS)
        elif key == "loop":
            if not isinstance(value, bool):
                check.fail(where, f"must be true or false, got {validation.shown(value)}")
            values[key] = value
        elif key == "velocity":
            values[key] = np.array(validation.numbers(value, check.source, where, length=2,
                                                      lo=-limits.MAX_TARGET_SPEED, hi=limits.MAX_TARGET_SPEED))
        elif key == "speed":
            values[key] = validation.number(value, check.source, where, lo=-limits.MAX_TARGET_SPEED,
                                            hi=limits.MAX_TARGET_SPEED)
        elif key == "period":
            values[key] = validation.number(value, check.source, where, lo=0.0, lo_open=True, hi=limits.MAX_TIME)
        else:
            values[key] = check.number(value, where, positive=key != "amplitude")
    if kind == "sinusoid" and not np.any(values["velocity"]):
        check.fail(f"{field}.velocity", "must not be zero: it sets the direction the sinusoid moves along and "
                                        "across (with [0, 0] nothing moves)")
    return kind, values
