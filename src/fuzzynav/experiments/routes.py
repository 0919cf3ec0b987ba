"""What a figure of the thesis shows of a run, as numbers a claim can bound: the route, where the
behaviour changes, which side each obstacle is passed on, and how far two routes lie apart.

The claims of chapters IV and V (:mod:`fuzzynav.experiments.claims_iv`, ``claims_v``) compare
these with the runs of the published tables, stored by ``benchmarks/mutations.py
--write-references`` in ``experiments/data/published_routes.json``.
"""

from __future__ import annotations

import json
from functools import cache
from importlib import resources

import numpy as np

SPACING = 0.2  # m between the points of a stored route
REFERENCES = "published_routes.json"


def route(trace, spacing: float = SPACING) -> list[list[float]]:
    """The robot's path resampled every ``spacing`` metres along it (first and last point kept)."""
    xy = np.asarray(trace.pose[:, :2], dtype=float)
    along = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(xy, axis=0).T))])
    if along[-1] == 0.0:
        return [[round(float(v), 3) for v in xy[0]]]
    at = np.append(np.arange(0.0, along[-1], spacing), along[-1])
    points = np.column_stack([np.interp(at, along, xy[:, 0]), np.interp(at, along, xy[:, 1])])
    return np.round(points, 3).tolist()


def deviation(a, b) -> float:
    """The symmetric Hausdorff distance (m) between two routes given as point lists: the farthest
    any point of one lies from the other (to within half the spacing)."""
    a, b = np.asarray(a, dtype=float).reshape(-1, 2), np.asarray(b, dtype=float).reshape(-1, 2)
    gaps = np.hypot(a[:, None, 0] - b[None, :, 0], a[:, None, 1] - b[None, :, 1])
    return float(max(gaps.min(axis=1).max(), gaps.min(axis=0).max()))


def switch_points(trace) -> list[list[float]]:
    """Positions (x, y) where the active behaviour changes (Fig IV.15's points A, B, …)."""
    return [[round(float(v), 3) for v in trace.pose[k, :2]] for k in trace.behaviour_changes()]


def obstacle_sides(trace, scenario, near: float = 1.0) -> list[str]:
    """For each circular obstacle, the side of the robot it is on where the robot passes nearest
    (``"left"``, ``"right"``), or ``"apart"`` when the body never comes within ``near`` m of it."""
    xy, theta = trace.pose[:, :2], trace.pose[:, 2]
    sides = []
    for shape in scenario.world.obstacles:
        if shape.kind != "circle":
            continue
        centre = np.asarray(shape.center, dtype=float)
        gaps = np.hypot(*(xy - centre).T) - shape.radius - trace.robot_radius
        k = int(np.argmin(gaps))
        if gaps[k] > near:
            sides.append("apart")
            continue
        dx, dy = centre - xy[k]
        sides.append("left" if np.cos(theta[k]) * dy - np.sin(theta[k]) * dx > 0 else "right")
    return sides


@cache
def references() -> dict:
    """The stored routes of the published tables: ``{"<experiment>/<run>": [[x, y], …]}``."""
    text = resources.files("fuzzynav.experiments").joinpath("data", REFERENCES).read_text()
    return json.loads(text)
