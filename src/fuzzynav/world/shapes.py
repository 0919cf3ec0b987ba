"""Obstacle shapes of a world: circle, polygon, wall (thick segment), ellipse (obstacles of any shape, thesis §IV.7).

Frozen records that check their values when built (an :class:`~fuzzynav.errors.InputError`
naming the field: NaN sizes, a negative radius, a 2-point polygon, a zero-length wall are
refused; ranges in :mod:`fuzzynav.world.limits`). The vectorised geometry on many shapes at once
lives in :mod:`fuzzynav.kernels.scene` and :class:`fuzzynav.world.world.World`. A :class:`Wall` is the
rectangle of its given thickness around the segment start–end (its ends are square, so two walls
meeting at a corner leave a notch of thickness/2 unless they overlap). ``to_dict`` gives the
scenario-file form (docs/ARCHITECTURE.md), so generated worlds can be written back as YAML.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from fuzzynav.errors import InputError
from fuzzynav.world import limits


def _array(values, field: str, shape: tuple) -> np.ndarray:
    """``values`` as a float array of ``shape`` (-1: any length), every entry a bounded coordinate."""
    try:
        array = np.asarray(values, dtype=float)
    except (TypeError, ValueError, OverflowError):
        raise InputError(f"must be numbers, got {values!r}", field=field) from None
    if array.ndim != len(shape) or any(n not in (-1, m) for n, m in zip(shape, array.shape)):
        raise InputError(f"must have shape {shape}, got {array.shape}".replace("-1", "n"), field=field)
    for value in array.ravel().tolist():
        limits.coordinate(value, field=field)
    return array


def _point(values, field: str = "center") -> np.ndarray:
    return _array(values, field, (2,))


@dataclass(frozen=True)
class Circle:
    """Disc of ``radius`` (m) around ``center``; the obstacle of Table IV.2 / Fig IV.15."""

    center: np.ndarray
    radius: float
    kind = "circle"

    def __post_init__(self):
        object.__setattr__(self, "center", _point(self.center))
        object.__setattr__(self, "radius", limits.length(self.radius, field="radius"))

    def bounds(self) -> tuple[np.ndarray, np.ndarray]:
        """Lower-left and upper-right corners of the bounding box."""
        return self.center - self.radius, self.center + self.radius

    def to_dict(self) -> dict:
        return {"circle": {"center": self.center.tolist(), "radius": self.radius}}


@dataclass(frozen=True)
class Polygon:
    """Simple polygon given by its vertices ``(n, 2)`` (3 ≤ n ≤ MAX_POLYGON_VERTICES, either
    orientation); scenario files are also checked by :func:`polygon_self_intersects`."""

    points: np.ndarray
    kind = "polygon"

    def __post_init__(self):
        points = _array(self.points, "points", (-1, 2))
        if not 3 <= len(points) <= limits.MAX_POLYGON_VERTICES:
            raise InputError(f"needs 3 to {limits.MAX_POLYGON_VERTICES} points, got {len(points)}", field="points")
        object.__setattr__(self, "points", points)

    def bounds(self) -> tuple[np.ndarray, np.ndarray]:
        """Lower-left and upper-right corners of the bounding box."""
        return self.points.min(axis=0), self.points.max(axis=0)

    @property
    def vertices(self) -> np.ndarray:
        return self.points

    def to_dict(self) -> dict:
        return {"polygon": {"points": self.points.tolist()}}


@dataclass(frozen=True)
class Wall:
    """Thick segment: the rectangle of width ``thickness`` (m) centred on ``start``–``end``."""

    start: np.ndarray
    end: np.ndarray
    thickness: float = 0.2
    kind = "wall"

    def __post_init__(self):
        object.__setattr__(self, "start", _point(self.start, "start"))
        object.__setattr__(self, "end", _point(self.end, "end"))
        object.__setattr__(self, "thickness", limits.length(self.thickness, field="thickness"))
        if np.hypot(*(self.end - self.start)) < limits.MIN_LENGTH:
            raise InputError(f"must differ from start by at least {limits.MIN_LENGTH:g} m (zero-length wall)", field="end")

    def bounds(self) -> tuple[np.ndarray, np.ndarray]:
        """Lower-left and upper-right corners of the bounding box."""
        corners = self.vertices
        return corners.min(axis=0), corners.max(axis=0)

    @property
    def vertices(self) -> np.ndarray:
        """The four corners of the rectangle, counter-clockwise."""
        direction = self.end - self.start
        length = np.hypot(*direction)
        normal = np.array([-direction[1], direction[0]]) / length * (0.5 * self.thickness)
        return np.array([self.start - normal, self.end - normal, self.end + normal, self.start + normal])

    def to_dict(self) -> dict:
        return {"wall": {"start": self.start.tolist(), "end": self.end.tolist(), "thickness": self.thickness}}


@dataclass(frozen=True)
class Ellipse:
    """Ellipse with semi-axes ``radii`` = (a, b) (m) around ``center``, rotated by ``angle`` (rad)."""

    center: np.ndarray
    radii: np.ndarray
    angle: float = 0.0
    kind = "ellipse"

    def __post_init__(self):
        object.__setattr__(self, "center", _point(self.center))
        radii = _point(self.radii, "radii")
        object.__setattr__(self, "radii", np.array([limits.length(r, field=f"radii[{i}]") for i, r in enumerate(radii)]))
        object.__setattr__(self, "angle", limits.angle(self.angle, field="angle"))

    def bounds(self) -> tuple[np.ndarray, np.ndarray]:
        """Lower-left and upper-right corners of a bounding box (the disc of the major semi-axis)."""
        reach = float(self.radii.max())
        return self.center - reach, self.center + reach

    def to_dict(self) -> dict:
        return {"ellipse": {"center": self.center.tolist(), "radii": self.radii.tolist(), "angle": self.angle}}


Shape = Circle | Polygon | Wall | Ellipse


def _overlapping_pairs(a: np.ndarray, b: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Index pairs (i < j) of the edges a→b whose x-extents overlap: edges sorted by their left
    end, each paired with the run of edges starting before its right end (a sweep over x).
    O(n log n + k) for k overlapping pairs; k ≤ n²/2 and n ≤ MAX_POLYGON_VERTICES bound it."""
    left, right = np.minimum(a[:, 0], b[:, 0]), np.maximum(a[:, 0], b[:, 0])
    order = np.argsort(left, kind="stable")
    stop = np.searchsorted(left[order], right[order], side="right")  # edges order[k+1:stop[k]] overlap
    counts = np.maximum(stop - np.arange(len(order)) - 1, 0)
    first = np.repeat(np.arange(len(order)), counts)
    offset = np.arange(counts.sum()) - np.repeat(np.cumsum(counts) - counts, counts)
    i, j = order[first], order[first + 1 + offset]
    return np.minimum(i, j), np.maximum(i, j)


def polygon_self_intersects(points) -> bool:
    """True when two edges of the closed polygon ``points`` cross or touch (other than neighbours
    at their shared vertex), or when it has a repeated vertex or zero area. Only edges whose
    x-extents overlap are compared (:func:`_overlapping_pairs`)."""
    pts = np.asarray(points, dtype=float)
    n = len(pts)
    a, b = pts, np.roll(pts, -1, axis=0)
    if np.any(np.hypot(*(b - a).T) == 0.0):
        return True
    area = 0.5 * np.sum(a[:, 0] * b[:, 1] - b[:, 0] * a[:, 1])
    if area == 0.0:
        return True

    def orient(p, q, r):
        return np.sign((q[..., 0] - p[..., 0]) * (r[..., 1] - p[..., 1]) - (q[..., 1] - p[..., 1]) * (r[..., 0] - p[..., 0]))

    i, j = _overlapping_pairs(a, b)
    keep = (j - i != 1) & ~((i == 0) & (j == n - 1))  # skip neighbouring edges
    i, j = i[keep], j[keep]
    p1, p2, q1, q2 = a[i], b[i], a[j], b[j]
    o1, o2 = orient(p1, p2, q1), orient(p1, p2, q2)
    o3, o4 = orient(q1, q2, p1), orient(q1, q2, p2)
    proper = (o1 * o2 < 0) & (o3 * o4 < 0)

    def on_segment(p, q, r):  # r collinear with p–q and within its box
        return (
            (orient(p, q, r) == 0)
            & (np.minimum(p[:, 0], q[:, 0]) <= r[:, 0]) & (r[:, 0] <= np.maximum(p[:, 0], q[:, 0]))
            & (np.minimum(p[:, 1], q[:, 1]) <= r[:, 1]) & (r[:, 1] <= np.maximum(p[:, 1], q[:, 1]))
        )

    touching = on_segment(p1, p2, q1) | on_segment(p1, p2, q2) | on_segment(q1, q2, p1) | on_segment(q1, q2, p2)
    # neighbours share a vertex; they only "touch" badly when they fold back onto each other
    k = np.arange(n)
    prev_, cur, next_ = a[k], b[k], b[(k + 1) % n]
    folds = (orient(prev_, cur, next_) == 0) & (
        np.einsum("ij,ij->i", cur - prev_, next_ - cur) < 0
    )
    return bool(np.any(proper | touching) or np.any(folds))
