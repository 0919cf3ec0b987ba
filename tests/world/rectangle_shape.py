"""A new obstacle type written as CONTRIBUTING.md's recipe says, outside the package: one class,
registered (used by tests/world/test_new_shape_recipe.py)."""

from dataclasses import dataclass

import numpy as np

from fuzzynav.world import limits
from fuzzynav.world.shapes import Shape, register


@register
@dataclass(frozen=True)
class Rectangle(Shape):
    """Rectangle of ``size`` = (width, height) (m) centred on ``center``, rotated by ``angle`` (rad)."""

    center: np.ndarray
    size: np.ndarray
    angle: float = 0.0
    kind = "rectangle"
    primitive = "polygon"  # the kernels' simple polygon: its four corners

    def __post_init__(self):
        object.__setattr__(self, "center", np.array([limits.coordinate(v, field="center") for v in self.center]))
        object.__setattr__(self, "size", np.array([limits.length(v, field=f"size[{i}]") for i, v in enumerate(self.size)]))
        object.__setattr__(self, "angle", limits.angle(self.angle, field="angle"))

    @classmethod
    def parse(cls, fields):
        return cls(fields.point("center"), fields.point("size", positive=True), fields.angle("angle"))

    @classmethod
    def random(cls, rng):
        return {"rectangle": {"center": rng.uniform(2.0, 18.0, 2).round(2).tolist(),
                              "size": rng.uniform(0.5, 2.0, 2).round(2).tolist(),
                              "angle": round(float(rng.uniform(-np.pi, np.pi)), 3)}}

    def packed(self):
        half = 0.5 * self.size
        corners = np.array([[-half[0], -half[1]], [half[0], -half[1]], [half[0], half[1]], [-half[0], half[1]]])
        c, s = np.cos(self.angle), np.sin(self.angle)
        return self.center + corners @ np.array([[c, s], [-s, c]])
