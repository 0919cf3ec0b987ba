"""Reference paths of chapter V (thesis §V.2): waypoint polylines and their scenarios.

A path is an ``(n, 2)`` array of waypoints joined by straight segments (discontinuous headings).
The generators below build the thesis' test paths:

- :func:`star_lines`: straight lines in six directions from (10, 10), the robot starting there
  with θ = 0 (Figs V.10, V.18, V.26, lines T1…T6); the thesis does not print the directions,
  they are spread every 60° here;
- :func:`segment`: a single straight segment (Figs V.8, V.16, V.24);
- :func:`n_path`, :func:`trapezoid_path`, :func:`v_path`: the N, trapezoid (Figs V.11, V.19,
  V.27) and V paths (Fig V.28) with the corner coordinates fixed here.

:func:`path_scenario` wraps waypoints into a :class:`~fuzzynav.world.scenario.Scenario` with a
waypoint tolerance zone (the simulator switches to the next waypoint once inside) and a
constant speed. :func:`turn_angles` gives the heading change at every corner.
"""

from __future__ import annotations

import math

import numpy as np

from fuzzynav import validation
from fuzzynav.errors import InputError
from fuzzynav.kernels.angles import wrap_angle
from fuzzynav.world.polylines import path_length
from fuzzynav.world.scenario import DEFAULT_PATH_SPEED, DEFAULT_PATH_TOLERANCE, scenario_from_dict

STAR_CENTER = (10.0, 10.0)
STAR_ANGLES = tuple(k * math.pi / 3 for k in range(6))  # T1…T6, every 60°


def _waypoints(points, field: str = "path") -> np.ndarray:
    points = np.asarray(points, dtype=float)
    if points.ndim != 2 or points.shape[1] != 2 or len(points) < 2 or not np.isfinite(points).all():
        raise InputError(f"needs at least two finite [x, y] points, got shape {points.shape}", field=field)
    if (np.hypot(*np.diff(points, axis=0).T) == 0).any():
        raise InputError("two consecutive waypoints coincide (zero-length segment)", field=field)
    return points


def segment(start, end) -> np.ndarray:
    """A single straight segment ``start → end`` (Figs V.8, V.16, V.24), shape ``(2, 2)``."""
    return _waypoints([start, end])


def star_lines(center=STAR_CENTER, length: float = 8.0, angles=STAR_ANGLES) -> list[np.ndarray]:
    """Straight lines T1…T6 from ``center`` in the directions ``angles`` (Figs V.10, V.18, V.26)."""
    validation.positive(length, field="length")
    c = np.asarray(center, dtype=float)
    return [segment(c, c + length * np.array([math.cos(a), math.sin(a)])) for a in angles]


def n_path() -> np.ndarray:
    """N-shaped path (3,3) → (3,17) → (17,3) → (17,17): two 135° corners (Figs V.11, V.19, V.27)."""
    return _waypoints([[3, 3], [3, 17], [17, 3], [17, 17]])


def trapezoid_path() -> np.ndarray:
    """Trapezoid (3,3) → (7,17) → (13,17) → (17,3): two 74° corners (Figs V.11, V.19, V.27)."""
    return _waypoints([[3, 3], [7, 17], [13, 17], [17, 3]])


def v_path() -> np.ndarray:
    """V-shaped path (2,14) → (10,5) → (18,14): one 97° corner, the comparison of Fig V.28."""
    return _waypoints([[2, 14], [10, 5], [18, 14]])


PATHS = {"v": v_path, "n": n_path, "trapezoid": trapezoid_path}


def headings(waypoints) -> np.ndarray:
    """Direction ``(n − 1,)`` of every segment (rad, CCW from +x)."""
    d = np.diff(_waypoints(waypoints), axis=0)
    return np.arctan2(d[:, 1], d[:, 0])


def turn_angles(waypoints) -> np.ndarray:
    """Heading change ``(n − 2,)`` at every interior waypoint, wrapped to (−π, π] (> 0 = left turn)."""
    h = headings(waypoints)
    return wrap_angle(np.diff(h))


def length(waypoints) -> float:
    """Total length of the polyline (m)."""
    return path_length(_waypoints(waypoints))


def path_scenario(waypoints, *, name: str = "path", start=None, theta: float | None = None,
                  tolerance: float = DEFAULT_PATH_TOLERANCE, speed: float = DEFAULT_PATH_SPEED,
                  max_time: float | None = None, description: str = ""):
    """A path-tracking :class:`~fuzzynav.world.scenario.Scenario` on an empty 20 m × 20 m world.

    The robot starts at ``start`` (default: the first waypoint) with heading ``theta`` (default:
    along the first segment — "the robot starts on the path", thesis §V.3.2). ``max_time`` defaults
    to three times the time needed to drive the path at ``speed``, plus 10 s.
    """
    points = _waypoints(waypoints)
    start = points[0] if start is None else np.asarray(start, dtype=float)
    theta = float(headings(points)[0]) if theta is None else float(theta)
    if max_time is None:
        max_time = 3.0 * length(points) / speed + 10.0
    document = {
        "name": name,
        "description": description,
        "robot": {"x": float(start[0]), "y": float(start[1]), "theta": theta},
        "path": points.tolist(),
        "path_tolerance": float(tolerance),
        "speed": float(speed),
        "max_time": float(max_time),
    }
    return scenario_from_dict(document, source=f"<{name}>")
