"""What a figure of the thesis shows of a run, as numbers a claim can bound: the route, where the
behaviour changes, which side each obstacle is passed on, and how far two routes lie apart.

The claims of chapters IV and V (:mod:`fuzzynav.experiments.claims_iv`, ``claims_v``) compare
these with the runs of the published tables (:func:`route_check`, :func:`change_check`,
:func:`switch_check`), stored by ``benchmarks/mutations.py --write-references`` in
``experiments/data/published_routes.json``: an edited rule table that moves a route by more than
0.5 m, or changes a tracking error or a pursuit time by more than 20 %, fails those checks.
"""

from __future__ import annotations

import json
import math
from functools import cache
from importlib import resources

import numpy as np

from fuzzynav.experiments.claims import Check
from fuzzynav.world.polylines import arc_lengths, at_arc

SPACING = 0.2  # m between the points of a stored route
REFERENCES = "published_routes.json"


def route(trace, spacing: float = SPACING) -> list[list[float]]:
    """The robot's path resampled every ``spacing`` metres along it (first and last point kept)."""
    xy = np.asarray(trace.pose[:, :2], dtype=float)
    along = arc_lengths(xy)
    if along[-1] == 0.0:
        return [[round(float(v), 3) for v in xy[0]]]
    points = at_arc(xy, along, np.append(np.arange(0.0, along[-1], spacing), along[-1]))
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


KEPT = ("route", "switch_points", "obstacle_sides", "max_cross_track_m", "mean_cross_track_m", "capture_time_s")
LEARNED = ("neural-tracker", "anfis-tracker")  # their runs depend on training, not on a rule table


def published_entries(experiment: str, numbers, skip=(*LEARNED, "anticipation")) -> dict:
    """The reference entries of one experiment's numbers: every run that reports a route, keyed
    ``experiment/name/...`` (list items numbered after their panel: ``fig-IV-12/a1``), with the
    fields of :data:`KEPT` — leaving out the runs named in ``skip`` (by default the learned
    trackers' and the corner-anticipation runs)."""
    entries = {}

    def walk(key: str, value) -> None:
        if isinstance(value, dict):
            if "route" in value:
                entries[key] = {field: value[field] for field in KEPT if field in value}
            for name, inner in value.items():
                if name not in skip:
                    walk(f"{key}/{name}", inner)
        elif isinstance(value, list) and value and isinstance(value[0], dict):
            for i, inner in enumerate(value, 1):
                walk(f"{key}{i}", inner)

    walk(experiment, numbers)
    return entries


@cache
def references() -> dict:
    """The stored routes of the published tables: ``{"<experiment>/<run>": [[x, y], …]}``."""
    text = resources.files("fuzzynav.experiments").joinpath("data", REFERENCES).read_text()
    return json.loads(text)


# --- checks of a run against the published tables' run of the same figure -------------------------

ROUTE_TOLERANCE_M = 0.5  # a route farther than this from the published tables' route has changed
ERROR_TOLERANCE = 0.2  # a tracking error or pursuit time changed by more than this share has changed
ERROR_FLOOR_M = 0.02  # errors below this are "none" (a line straight ahead is tracked exactly)


def reference(key: str) -> dict:
    """The published tables' numbers of run ``key`` (``"fig-IV-15/fig-IV-15a"``…)."""
    return references()[key]


def route_check(label: str, run: dict, key: str) -> Check:
    """The run's route lies within :data:`ROUTE_TOLERANCE_M` of the published tables' route."""
    gap = round(deviation(run["route"], reference(key)["route"]), 3)
    return Check(f"{label}: farthest distance from the route of the published tables (m)", gap,
                 f"≤ {ROUTE_TOLERANCE_M}", gap <= ROUTE_TOLERANCE_M, "package")


def change_check(label: str, value, key: str, field: str, unit: str) -> Check:
    """``value`` within :data:`ERROR_TOLERANCE` of the published tables' ``field`` of run ``key``.

    A tracking error the published table keeps under :data:`ERROR_FLOOR_M` (the thesis' "minimum
    d'erreurs", §V.3.1: a line straight ahead) must stay under the floor; above it, 20 % is the
    whole tolerance (an added floor let a 3 cm mean error move by 80 % and pass)."""
    expected = reference(key)[field]
    if value is None or expected is None:
        return Check(f"{label} ({unit})", value, f"= the published tables' {expected}", value == expected, "package")
    if unit == "m" and expected <= ERROR_FLOOR_M:
        return Check(f"{label} ({unit})", round(value, 3), f"≤ {ERROR_FLOOR_M} (the published tables' {expected:.3f})",
                     value <= ERROR_FLOOR_M, "package")
    ok = abs(value - expected) <= ERROR_TOLERANCE * expected
    return Check(f"{label} ({unit})", round(value, 3),
                 f"within {ERROR_TOLERANCE:.0%} of the published tables' {expected:.3f}", ok, "package")


def switch_check(label: str, run: dict, key: str) -> Check:
    """The behaviour changes where it changes in the published tables' run (within the route tolerance)."""
    ours, theirs = run["switch_points"], reference(key)["switch_points"]
    gap = 0.0 if not ours and not theirs else (math.inf if not ours or not theirs else deviation(ours, theirs))
    return Check(f"{label}: farthest distance of a switch point from those of the published tables (m)",
                 None if math.isinf(gap) else round(gap, 3), f"≤ {ROUTE_TOLERANCE_M}", gap <= ROUTE_TOLERANCE_M,
                 "package")
