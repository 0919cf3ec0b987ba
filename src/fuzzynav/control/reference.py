"""Corner-smoothed reference of a waypoint path, followed by the chapter V trackers (an addition to the thesis).

The thesis' trackers aim at the current waypoint and switch inside a tolerance zone (§V.2): at a
sharp corner the robot, whose tightest turn has radius R_min = l / tan(α_max) (eq IV.1; 0.5 m for
l = 0.5 m, α_max = π/4), overshoots; switching earlier cuts the corner instead. A turn of angle φ
on the arc of radius R tangent to both segments (tangent length R·tan(|φ|/2) from the corner)
cuts inside the corner by R·(1 − cos(|φ|/2)): 0.31 m at 135° for R = R_min.

:func:`smoothed_path` builds a drivable reference that halves that error: before each corner it
shifts the path *outwards* by

    e(φ, R) = R·(1 − cos(|φ|/2)) / 2,

through a straight transition of length ``transition``, drives the arc of radius R tangent to the
two outward-shifted lines (their corner lies e / cos(|φ|/2) out along the bisector, the arc
starts R·tan(|φ|/2) before it) and shifts back after the corner. With the arc centre s =
(R − e) / cos(|φ|/2) from the corner, the arc's deepest point inside the corner is
(R − e) − R·cos(|φ|/2) from both segments, equal to the outward shift e for the value above: the
smallest max cross-track error of a turn at radius R that is tangent to lines parallel to the
segments (0.084 m at 97°, 0.050 m at 74° for R = 0.5 m). The arc passes (R − e)/cos(|φ|/2) − R
from the corner; for sharp corners (from 134.8° on with R = 0.5 m) e is enlarged to
R − (R + d)·cos(|φ|/2) so that this closest approach stays within d = ``APPROACH`` = 0.4 m
(e = 0.156 m instead of 0.154 m at 135°) and the
robot still enters the simulator's waypoint tolerance zone (0.5 m by default, §V.2). Corners with
too little room on their segments for that construction get the plain tangent arc, its radius
reduced so that it fits and passes within d of the corner (down to a sharp corner, where the
robot drives to the waypoint and turns as the thesis' tracker does).

The reference is sampled every ``step`` metres; :func:`advance` moves each robot's index to its
nearest sample in a window ahead (progress is monotonic) and the trackers aim at the sample
``lookahead`` metres further along (:class:`~fuzzynav.control.tracking.AngleErrorTracker`).
"""

from __future__ import annotations

import numpy as np

from fuzzynav import validation
from fuzzynav.world.geometry import wrap_angle
from fuzzynav.world.polylines import arc_lengths, at_arc

STEP = 0.02  # m between reference samples
WINDOW = 2.0  # m of reference searched ahead of the current index
APPROACH = 0.4  # m, the largest distance of the smoothed corner from the waypoint


def swing_offset(turn, radius: float, approach: float = APPROACH):
    """Outward shift before a corner of heading change φ: max(R·(1 − cos(|φ|/2)) / 2,
    R − (R + d)·cos(|φ|/2)) with d = ``approach`` (module docstring)."""
    c = np.cos(np.abs(turn) / 2.0)
    return np.maximum(radius * (1.0 - c) / 2.0, radius - (radius + approach) * c)


def _fillet(vertices: np.ndarray, radii: np.ndarray, step: float) -> np.ndarray:
    """Polyline ``vertices`` with every interior vertex k replaced by the arc of radius ``radii[k]``
    tangent to its two segments (tangent points R·tan(|φ_k|/2) from the vertex), sampled every ``step``."""
    d = np.diff(vertices, axis=0)
    u = d / np.hypot(d[:, 0], d[:, 1])[:, None]
    turn = wrap_angle(np.diff(np.arctan2(u[:, 1], u[:, 0])))
    pieces = [vertices[:1]]
    for k in range(1, len(vertices) - 1):
        phi, radius = turn[k - 1], radii[k]
        if abs(phi) < 1e-9 or radius == 0:
            pieces.append(vertices[k:k + 1])
            continue
        start = vertices[k] - radius * np.tan(abs(phi) / 2.0) * u[k - 1]
        normal = np.sign(phi) * np.array([-u[k - 1, 1], u[k - 1, 0]])  # towards the centre
        centre = start + radius * normal
        a0 = np.arctan2(start[1] - centre[1], start[0] - centre[0])
        angles = a0 + phi * np.linspace(0.0, 1.0, max(int(np.ceil(abs(phi) * radius / step)), 2))
        pieces.append(centre + radius * np.column_stack([np.cos(angles), np.sin(angles)]))
    pieces.append(vertices[-1:])
    points = np.concatenate(pieces)
    s = arc_lengths(points)
    keep = np.concatenate([[True], np.diff(s) > 1e-12])
    points, s = points[keep], s[keep]
    return at_arc(points, s, np.append(np.arange(0.0, s[-1], step), s[-1]))


def smoothed_path(waypoints, radius: float, transition: float = 2.0, approach: float = APPROACH,
                  step: float = STEP) -> np.ndarray:
    """Reference samples ``(M, 2)``, ``step`` apart, of the path ``waypoints`` with smoothed corners.

    Each corner k of heading change φ_k gets the outward swing of the module docstring when its
    two segments leave room (half of a segment shared by two corners) for the arc's tangent
    length R·tan(|φ_k|/2), a margin R/2 before the arc, a transition of at least R and a slack
    R/2 for the transition's own small arcs; the transition is ``transition`` metres or what the
    room allows. Otherwise the corner gets the plain tangent arc of radius
    min(R, room / tan(|φ_k|/2), d / (1/cos(|φ_k|/2) − 1)), d = ``approach``.
    """
    path = np.asarray(waypoints, dtype=float)
    validation.positive(radius, field="corner_radius")
    lengths = np.hypot(*np.diff(path, axis=0).T)
    u = np.diff(path, axis=0) / lengths[:, None]
    turn = wrap_angle(np.diff(np.arctan2(u[:, 1], u[:, 0])))
    vertices, radii = [path[0]], [0.0]
    last = len(path) - 2
    for k in range(1, len(path) - 1):
        phi, u_in, u_out = turn[k - 1], u[k - 1], u[k]
        room = min(lengths[k - 1] / (1 if k == 1 else 2), lengths[k] / (1 if k == last + 1 else 2))
        half = abs(phi) / 2.0
        tangent = radius * np.tan(half) if half < np.pi / 2 - 1e-6 else np.inf
        free = room - tangent - radius  # R/2 margin before the arc, R/2 for the transition's own small arcs
        if abs(phi) < 1e-9 or free < radius:
            vertices.append(path[k])
            radii.append(0.0 if abs(phi) < 1e-9 else
                         min(radius, room / np.tan(half), approach / (1.0 / np.cos(half) - 1.0)))
            continue
        run = min(transition, free)
        bisector = (u_in - u_out) / np.hypot(*(u_in - u_out))  # outwards
        corner = path[k] + swing_offset(phi, radius, approach) / np.cos(half) * bisector
        near = tangent + radius / 2.0
        vertices += [path[k] - (near + run) * u_in, corner - near * u_in, corner,
                     corner + near * u_out, path[k] + (near + run) * u_out]
        radii += [radius] * 5
    vertices.append(path[-1])
    radii.append(0.0)
    return _fillet(np.asarray(vertices), np.asarray(radii), step)


def advance(reference: np.ndarray, xy: np.ndarray, index: np.ndarray, window: int) -> np.ndarray:
    """Index ``(N,)`` of the reference sample nearest to each position ``(N, 2)`` among the
    ``window`` samples from ``index`` on (monotonic progress along the reference)."""
    candidates = np.minimum(index[:, None] + np.arange(window)[None, :], len(reference) - 1)
    d = reference[candidates] - xy[:, None, :]
    nearest = np.argmin(d[..., 0] ** 2 + d[..., 1] ** 2, axis=1)
    return candidates[np.arange(len(xy)), nearest]
