"""World layer: geometry, obstacle shapes, collisions, range casting and scenario files."""

from fuzzynav.world.shapes import Circle, Ellipse, Polygon, Wall
from fuzzynav.world.world import World

__all__ = ["Circle", "Ellipse", "Polygon", "Wall", "World"]
