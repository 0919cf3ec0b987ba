"""Range sensors with a beam width, compiled: each reading is the nearest echo inside the sensor's
cone (the ultrasonic model, Borenstein & Koren 1988; :mod:`fuzzynav.robot.sensors`), single rays
when the half width is 0 (:func:`fuzzynav.kernels.scene.ranges_one`, unchanged).

The nearest point of a shape inside a cone [a − h, a + h] seen from the sensor is either its
nearest point overall (when that lies inside the cone) or on one of the cone's edges:

- a circle: |c| − r when its centre's bearing is inside the cone (the nearest point lies on the
  line to the centre), else the first hit of an edge ray;
- a polygon: its vertices and the feet of the perpendiculars on its edges inside the cone, and
  the edge rays (exact: the distance to a segment along a direction sweep has its minima there);
- an ellipse: its nearest point (the foot of :func:`fuzzynav.kernels.scene.ellipse_foot`) when
  inside the cone, and the edge rays and the axis ray;
- the world's boundary walls: the feet of the perpendiculars inside the cone, and the edge rays.
"""

from __future__ import annotations

import math

import numpy as np

from fuzzynav.jit import jit
from fuzzynav.kernels import scene
from fuzzynav.kernels.layout import AT_EDGES, HEIGHT, N_CIRCLES, N_ELLIPSES, N_POLYGONS, WIDTH
from fuzzynav.kernels.motion import wrap


@jit
def in_cone(px, py, x, y, heading, half):
    """Distance from (x, y) to (px, py) when its bearing lies within ``half`` of ``heading``, else inf."""
    if abs(wrap(math.atan2(py - y, px - x) - heading)) <= half:
        return math.hypot(px - x, py - y)
    return math.inf


@jit
def cone_one(scene_array, x, y, heading, half, max_range, near, edges):
    """The nearest echo inside the cone of half width ``half`` about ``heading``; ``near`` holds
    the columns within reach, ``edges`` (3,) is scratch for the edge and axis rays (cast first:
    their best hit prunes the shapes)."""
    count = near.shape[0]
    edges[0], edges[1], edges[2] = heading - half, heading, heading + half
    rays = np.empty(3)
    scene.cast(scene_array, x, y, 0.0, edges, max_range, rays, near)
    best = min(rays[0], min(rays[1], rays[2]))
    width, height = scene_array[WIDTH], scene_array[HEIGHT]
    for px, py in ((0.0, y), (width, y), (x, 0.0), (x, height)):
        best = min(best, in_cone(px, py, x, y, heading, half))
    for q in range(count):
        kind, at, cx, cy, radius = scene.bounding_disc(scene_array, near[q])
        if math.hypot(cx - x, cy - y) - radius >= best:
            continue
        if kind == 0:
            d = in_cone(cx, cy, x, y, heading, half)
            best = min(best, max(d - scene_array[at + 2], 0.0))
        elif kind == 1:
            for i in range(int(scene_array[at]), int(scene_array[at + 1])):
                e = int(scene_array[AT_EDGES]) + 7 * i
                ax, ay, ex, ey = scene_array[e], scene_array[e + 1], scene_array[e + 4], scene_array[e + 5]
                best = min(best, in_cone(ax, ay, x, y, heading, half))
                u = ((x - ax) * ex + (y - ay) * ey) / scene_array[e + 6]
                if 0.0 < u < 1.0:
                    best = min(best, in_cone(ax + u * ex, ay + u * ey, x, y, heading, half))
        else:
            c, s = scene_array[at + 4], scene_array[at + 5]
            rx, ry = x - cx, y - cy
            fx, fy = scene.ellipse_foot(c * rx + s * ry, -s * rx + c * ry, scene_array[at + 2], scene_array[at + 3])
            best = min(best, in_cone(cx + c * fx - s * fy, cy + s * fx + c * fy, x, y, heading, half))
    return min(best, max_range)


@jit
def read_one(scene_array, x, y, theta, angles, half, max_range, out):
    """Readings of the sensors at headings θ + ``angles`` into ``out``: rays when ``half`` is 0,
    else the nearest echo inside each cone of half width ``half``."""
    near = np.empty(int(scene_array[N_CIRCLES] + scene_array[N_POLYGONS] + scene_array[N_ELLIPSES]), dtype=np.int64)
    if half <= 0.0:
        scene.ranges_one(scene_array, x, y, theta, angles, max_range, out, near)
        return
    within = near[:scene.near_columns(scene_array, x, y, max_range, near)]
    edges = np.empty(3)
    for j in range(angles.shape[0]):
        out[j] = cone_one(scene_array, x, y, theta + angles[j], half, max_range, within, edges)


@jit
def read(scene_array, poses, angles, half, max_range, out):
    """:func:`read_one` of robots at ``poses`` (N, 3) into ``out`` (N, S)."""
    for n in range(poses.shape[0]):
        read_one(scene_array, poses[n, 0], poses[n, 1], poses[n, 2], angles, half, max_range, out[n])


@jit
def read_worlds(scenes, bounds, poses, angles, half, max_range, out):
    """:func:`read_one` of robot n (``poses`` (N, 3)) in its own world, the scene array
    ``scenes[bounds[n, 0]:bounds[n, 1]]`` (:func:`fuzzynav.kernels.scene.nearest_worlds`), into ``out`` (N, S)."""
    for n in range(poses.shape[0]):
        read_one(scenes[bounds[n, 0]:bounds[n, 1]], poses[n, 0], poses[n, 1], poses[n, 2], angles, half, max_range,
                 out[n])
