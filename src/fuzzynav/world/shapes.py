"""The registry of obstacle types: each declares, in its one class, everything the package does with it.

An obstacle type is a frozen dataclass deriving :class:`Shape`, added to :data:`SHAPES` by the
:func:`register` decorator. Its class is the one place that says

- its **scenario schema**: the key (``kind``) and the parameters — the dataclass fields, those
  with a default optional — that scenario files (docs/ARCHITECTURE.md) and :meth:`Shape.to_dict`
  use;
- its **validation**: ``__post_init__`` checks the values (an :class:`~fuzzynav.errors.InputError`
  naming the field; ranges in :mod:`fuzzynav.world.limits`) and ``parse(fields)`` reads a scenario
  entry through :class:`fuzzynav.world.checks.ShapeFields` (the checks of
  :mod:`fuzzynav.validation`, errors naming the file and ``obstacles[i].<kind>.<key>``);
- its **packing** for the compiled kernels: ``primitive``, one of the shape kinds the kernels know
  (:data:`fuzzynav.kernels.layout.PRIMITIVES`: a disc, a polygon, an ellipse), and ``packed()``,
  its row of that kind (:func:`fuzzynav.kernels.layout.pack`) — collisions, nearest points and
  rays (:mod:`fuzzynav.kernels.scene`, :mod:`fuzzynav.kernels.beams`) follow from it, and so do
  its bounding box (:meth:`Shape.bounds`) and its drawing (:meth:`Shape.patch`, for
  :func:`fuzzynav.viz.trajectories.draw_world`): what is drawn is what the robot senses;
- its **generation**: ``random(rng)``, one random instance (scenario-file form) in the 20 m × 20 m
  workspace of the generated families (:mod:`fuzzynav.world.generate` names the types each family
  draws).

The scenario parser, the world, the generator and the plots read :data:`SHAPES` and these
methods; none lists the types. Obstacles of any shape are thesis §IV.7. A type whose geometry is
none of the kernels' primitives (a capsule, say) needs a new primitive in the kernels first
(CONTRIBUTING.md, "An obstacle type").
"""

from __future__ import annotations

import dataclasses
import functools
from abc import ABC, abstractmethod
from dataclasses import dataclass

import numpy as np

from fuzzynav.errors import InputError
from fuzzynav.kernels.layout import PRIMITIVES
from fuzzynav.world import limits
from fuzzynav.world.polygons import polygon_self_intersects

SHAPES: dict[str, type[Shape]] = {}  # scenario key -> obstacle type, in the order registered


def register(cls: type[Shape]) -> type[Shape]:
    """Class decorator: add the obstacle type ``cls`` to :data:`SHAPES` under ``cls.kind``."""
    if not (dataclasses.is_dataclass(cls) and issubclass(cls, Shape)):
        raise TypeError(f"{cls.__name__} must be a dataclass deriving fuzzynav.world.shapes.Shape")
    if cls.primitive not in PRIMITIVES:
        raise TypeError(f"{cls.__name__}.primitive must be one of {PRIMITIVES}, got {cls.primitive!r}")
    if cls.kind in SHAPES:
        raise TypeError(f"the obstacle type {cls.kind!r} is already registered ({SHAPES[cls.kind].__name__})")
    SHAPES[cls.kind] = cls
    return cls


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


class Shape(ABC):
    """An obstacle type (see the module docstring); subclasses are frozen dataclasses that set
    ``kind`` and ``primitive`` and implement :meth:`parse` and :meth:`packed` (and :meth:`random`
    when generated worlds draw them)."""

    kind: str = ""  # the scenario-file key
    primitive: str = ""  # the kernels' shape kind it packs as (fuzzynav.kernels.layout.PRIMITIVES)

    @classmethod
    def schema(cls) -> dict:
        """Scenario parameters: name -> default (``None``: required), the dataclass fields."""
        return {f.name: None if f.default is dataclasses.MISSING else f.default for f in dataclasses.fields(cls)}

    @classmethod
    @abstractmethod
    def parse(cls, fields) -> Shape:
        """The obstacle of a scenario entry, its values read through ``fields``
        (:class:`fuzzynav.world.checks.ShapeFields`)."""

    @classmethod
    def random(cls, rng: np.random.Generator) -> dict:
        """One random instance in the generated families' 20 m × 20 m workspace, scenario-file form
        (optional: only the types a generated family draws need it)."""
        raise TypeError(f"obstacle type {cls.kind!r} has no random instances: a generated family cannot draw it")

    @abstractmethod
    def packed(self):
        """Its row for the kernels: (cx, cy, r) for a disc, the vertices ``(V, 2)`` of a simple
        polygon, (cx, cy, a, b, angle) for an ellipse."""

    def to_dict(self) -> dict:
        """The scenario-file form: ``{kind: {parameter: value}}``."""
        values = {f.name: getattr(self, f.name) for f in dataclasses.fields(self)}
        return {self.kind: {k: v.tolist() if isinstance(v, np.ndarray) else v for k, v in values.items()}}

    def bounds(self) -> tuple[np.ndarray, np.ndarray]:
        """Lower-left and upper-right corners of a bounding box of its packed geometry (an
        ellipse's: the disc of its major semi-axis)."""
        row = self.packed()
        if self.primitive == "polygon":
            return row.min(axis=0), row.max(axis=0)
        reach = row[2] if self.primitive == "circle" else max(row[2], row[3])
        return np.array(row[:2]) - reach, np.array(row[:2]) + reach

    def vertex_count(self) -> int:
        """Polygon vertices it adds to the kernels' scene (:data:`~fuzzynav.world.limits.MAX_TOTAL_VERTICES`)."""
        return len(self.packed()) if self.primitive == "polygon" else 0

    def patch(self, **style):
        """A :mod:`matplotlib.patches` patch of its packed geometry, drawn with ``style``."""
        from matplotlib import patches  # plotting only

        row = self.packed()
        if self.primitive == "circle":
            return patches.Circle(row[:2], row[2], **style)
        if self.primitive == "ellipse":
            return patches.Ellipse(row[:2], 2 * row[2], 2 * row[3], angle=np.degrees(row[4]), **style)
        return patches.Polygon(row, closed=True, **style)


@register
@dataclass(frozen=True)
class Circle(Shape):
    """Disc of ``radius`` (m) around ``center``; the obstacle of Table IV.2 / Fig IV.15."""

    center: np.ndarray
    radius: float
    kind = "circle"
    primitive = "circle"

    def __post_init__(self):
        object.__setattr__(self, "center", _point(self.center))
        object.__setattr__(self, "radius", limits.length(self.radius, field="radius"))

    @classmethod
    def parse(cls, fields) -> Circle:
        return cls(fields.point("center"), fields.length("radius"))

    @classmethod
    def random(cls, rng) -> dict:
        return {"circle": {"center": rng.uniform(1.0, 19.0, 2).round(2).tolist(),
                           "radius": round(float(rng.uniform(0.4, 1.4)), 2)}}

    def packed(self):
        return (*self.center, self.radius)


@register
@dataclass(frozen=True)
class Polygon(Shape):
    """Simple polygon given by its vertices ``(n, 2)`` (3 ≤ n ≤ MAX_POLYGON_VERTICES, either
    orientation); scenario files are also checked by :func:`polygon_self_intersects`."""

    points: np.ndarray
    kind = "polygon"
    primitive = "polygon"

    def __post_init__(self):
        points = _array(self.points, "points", (-1, 2))
        if not 3 <= len(points) <= limits.MAX_POLYGON_VERTICES:
            raise InputError(f"needs 3 to {limits.MAX_POLYGON_VERTICES} points, got {len(points)}", field="points")
        object.__setattr__(self, "points", points)

    @classmethod
    def parse(cls, fields) -> Polygon:
        points = fields.points("points", 3, limits.MAX_POLYGON_VERTICES)
        if len(points) > 3 and np.array_equal(points[0], points[-1]):  # a closed ring, as GeoJSON writes one
            fields.fail(f"points[{len(points) - 1}]", "repeats points[0]: a polygon closes itself, leave the last "
                                                     "point out")
        if polygon_self_intersects(points):
            fields.fail("points", "polygon is self-intersecting (or has repeated points / zero area)")
        return cls(points)

    @classmethod
    def random(cls, rng) -> dict:
        center = rng.uniform(1.5, 18.5, 2)
        n = int(rng.integers(3, 7))
        angles = np.linspace(0, 2 * np.pi, n, endpoint=False) + rng.uniform(0, 2 * np.pi)
        radius = rng.uniform(0.6, 1.6) * rng.uniform(0.8, 1.0, n)  # a jittered regular fan: simple, star-shaped
        points = center + np.column_stack([radius * np.cos(angles), radius * np.sin(angles)])
        return {"polygon": {"points": points.round(2).tolist()}}

    @property
    def vertices(self) -> np.ndarray:
        return self.points

    def packed(self):
        return self.points


@register
@dataclass(frozen=True)
class Wall(Shape):
    """Thick segment: the rectangle of width ``thickness`` (m) centred on ``start``–``end`` (its
    ends are square, so two walls meeting at a corner leave a notch of thickness/2 unless they
    overlap)."""

    start: np.ndarray
    end: np.ndarray
    thickness: float = 0.2
    kind = "wall"
    primitive = "polygon"

    def __post_init__(self):
        for name in ("start", "end"):  # private read-only copies: the corners are computed once from them
            point = _point(getattr(self, name), name).copy()
            point.setflags(write=False)
            object.__setattr__(self, name, point)
        object.__setattr__(self, "thickness", limits.length(self.thickness, field="thickness"))
        if np.hypot(*(self.end - self.start)) < limits.MIN_LENGTH:
            raise InputError(f"must differ from start by at least {limits.MIN_LENGTH:g} m (zero-length wall)", field="end")

    @classmethod
    def parse(cls, fields) -> Wall:
        return cls(fields.point("start"), fields.point("end"), fields.length("thickness"))

    @classmethod
    def random(cls, rng) -> dict:
        start = rng.uniform(1.0, 19.0, 2)
        heading = rng.uniform(0, np.pi)
        end = np.clip(start + rng.uniform(2.0, 6.0) * np.array([np.cos(heading), np.sin(heading)]), 0.5, 19.5)
        return {"wall": {"start": start.round(2).tolist(), "end": end.round(2).tolist(),
                         "thickness": round(float(rng.uniform(0.2, 0.4)), 2)}}

    @classmethod
    def chain(cls, points, thickness: float = 0.2) -> tuple[Wall, ...]:
        """The walls of the open polyline through ``points`` (n ≥ 2, 2), all of ``thickness``: the
        same walls as ``Wall(points[i], points[i + 1], thickness)`` one by one, checked and given
        their corners for all walls at once (the random wall courses of training build one per
        episode)."""
        points = _array(points, "points", (-1, 2)).copy()
        if len(points) < 2:
            raise InputError(f"needs at least 2 points, got {len(points)}", field="points")
        thickness = limits.length(thickness, field="thickness")
        along = points[1:] - points[:-1]
        short = np.flatnonzero(np.hypot(along[:, 0], along[:, 1]) < limits.MIN_LENGTH)
        if len(short):
            raise InputError(f"must differ from the point before by at least {limits.MIN_LENGTH:g} m "
                             "(zero-length wall)", field=f"points[{short[0] + 1}]")
        points.setflags(write=False)
        corners = _rectangles(points[:-1], points[1:], thickness)
        walls = []
        for i in range(len(corners)):
            wall = object.__new__(cls)
            wall.__dict__.update(start=points[i], end=points[i + 1], thickness=thickness, vertices=corners[i])
            walls.append(wall)
        return tuple(walls)

    @functools.cached_property
    def vertices(self) -> np.ndarray:
        """The four corners of the rectangle, counter-clockwise (computed once, read-only)."""
        return _rectangles(self.start[None], self.end[None], self.thickness)[0]

    def packed(self):
        return self.vertices


def _rectangles(starts, ends, thickness: float) -> np.ndarray:
    """Corners (W, 4, 2), counter-clockwise and read-only, of the walls from ``starts`` (W, 2) to
    ``ends`` (W, 2), ``thickness`` wide."""
    direction = ends - starts
    normal = np.empty_like(direction)  # the left normal, scaled to half the thickness
    np.negative(direction[:, 1], out=normal[:, 0])
    normal[:, 1] = direction[:, 0]
    normal /= np.hypot(direction[:, 0], direction[:, 1])[:, None]
    normal *= 0.5 * thickness
    corners = np.empty((len(direction), 4, 2))
    np.subtract(starts, normal, out=corners[:, 0])
    np.subtract(ends, normal, out=corners[:, 1])
    np.add(ends, normal, out=corners[:, 2])
    np.add(starts, normal, out=corners[:, 3])
    corners.setflags(write=False)
    return corners


@register
@dataclass(frozen=True)
class Ellipse(Shape):
    """Ellipse with semi-axes ``radii`` = (a, b) (m) around ``center``, rotated by ``angle`` (rad)."""

    center: np.ndarray
    radii: np.ndarray
    angle: float = 0.0
    kind = "ellipse"
    primitive = "ellipse"

    def __post_init__(self):
        object.__setattr__(self, "center", _point(self.center))
        radii = _point(self.radii, "radii")
        object.__setattr__(self, "radii", np.array([limits.length(r, field=f"radii[{i}]") for i, r in enumerate(radii)]))
        object.__setattr__(self, "angle", limits.angle(self.angle, field="angle"))

    @classmethod
    def parse(cls, fields) -> Ellipse:
        return cls(fields.point("center"), fields.point("radii", positive=True), fields.angle("angle"))

    @classmethod
    def random(cls, rng) -> dict:
        radii = rng.uniform(0.4, 1.6, 2)
        return {"ellipse": {"center": rng.uniform(1.5, 18.5, 2).round(2).tolist(), "radii": radii.round(2).tolist(),
                            "angle": round(float(rng.uniform(-np.pi / 2, np.pi / 2)), 3)}}

    def packed(self):
        return (*self.center, *self.radii, self.angle)
