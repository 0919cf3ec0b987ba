"""Numbers of one episode (`fuzzynav run --json`): a flat JSON-safe dict.

Always: ``scenario``, ``controller``, ``task``, ``outcome``, ``reached_goal`` (goal reached, path
completed or target captured), ``collision``, ``timeout``, ``time_s``, ``steps``,
``path_length_m`` (length of the driven polyline), ``min_clearance_m`` (smallest gap between
the robot's footprint disc and any obstacle or the boundary; < 0 means overlap),
``mean_speed_mps`` (mean of the speed V commanded at each step, signed: reversing counts
negative; ``path_length_m / time_s`` is the distance covered per second), ``final_speed_mps`` (speed commanded at the last step: 0 before any step;
≤ 0.2 m/s for a robot that stops at its goal as Table IV.1's does), ``final_distance_m`` (to the
goal / current waypoint / target), ``steering_effort_rad`` (mean |α|), ``steering_variation_rad``
(Σ |Δα|) and ``collision_by`` (``"robot"`` or ``"obstacle"``: who moved into whom,
:mod:`fuzzynav.sim.fault`; None without a collision) and ``invalid_command`` (the outcome
``"invalid_command"``: the controller returned a NaN or infinite command, and this says at which
step and what, e.g. ``"step 3: steering nan, speed 1.0"``; None otherwise). With moving obstacles the clearances are
measured to where they are at each step.
Path tasks add ``completed``, ``waypoints_reached``, ``mean_cross_track_m`` and
``max_cross_track_m`` (distance from each visited position to the path polyline, thesis §V.4).
Target tasks add ``captured``, ``capture_time_s`` (None when not captured) and
``final_error_m`` (robot–target distance at the end).
"""

from __future__ import annotations

import math

import numpy as np

from fuzzynav.sim.arguments import check_ran_on
from fuzzynav.sim.trace import Trace
from fuzzynav.world.polylines import path_length
from fuzzynav.world.scenario import Scenario


def _number(value) -> float | None:
    value = float(value)
    return value if math.isfinite(value) else None


def cross_track(positions, waypoints) -> np.ndarray:
    """Distance ``(T,)`` from each position ``(T, 2)`` to the polyline through ``waypoints``."""
    waypoints = np.asarray(waypoints, dtype=float)
    if len(waypoints) == 1:
        return np.hypot(*(positions - waypoints[0]).T)
    points, a, e = np.asarray(positions, dtype=float)[:, None, :], waypoints[None, :-1], np.diff(waypoints, axis=0)
    u = np.clip(np.einsum("nmk,mk->nm", points - a, e) / np.einsum("ij,ij->i", e, e), 0.0, 1.0)
    gap = points - (a + u[..., None] * e[None])  # to the nearest point of each segment
    return np.hypot(gap[..., 0], gap[..., 1]).min(axis=1)


def metrics(trace: Trace, scenario: Scenario) -> dict:
    """The metrics dict of ``trace`` run on ``scenario`` (keys in the module docstring)."""
    check_ran_on(trace, scenario)
    xy = trace.pose[:, :2]
    world = scenario.world
    clearance = (world.clearance(xy) if trace.obstacle_offsets is None
                 else world.clearance_over_time(xy, trace.obstacle_offsets)) - trace.robot_radius
    final_distance = np.hypot(*(trace.target[-1] - xy[-1]))
    result = {
        "scenario": trace.scenario,
        "controller": trace.controller,
        "task": trace.task,
        "outcome": trace.outcome,
        "reached_goal": trace.reached,
        "collision": trace.collision,
        "collision_by": trace.collision_by,
        "invalid_command": trace.invalid_command,
        "timeout": trace.outcome == "timeout",
        "time_s": round(trace.time, 10),
        "steps": trace.steps,
        "path_length_m": path_length(xy),
        "min_clearance_m": float(clearance.min()),
        "mean_speed_mps": float(trace.speed.mean()) if trace.steps else 0.0,
        "final_speed_mps": float(trace.speed[-1]) if trace.steps else 0.0,
        "final_distance_m": float(final_distance),
        "steering_effort_rad": float(np.abs(trace.steering).mean()) if trace.steps else 0.0,
        "steering_variation_rad": float(np.abs(np.diff(trace.steering)).sum()) if trace.steps > 1 else 0.0,
    }
    if trace.task == "path":
        errors = cross_track(xy, scenario.path.waypoints)
        result.update({
            "completed": trace.reached,
            "waypoints_reached": int(trace.waypoint_index[-1]) + (1 if trace.reached else 0),
            "mean_cross_track_m": float(errors.mean()),
            "max_cross_track_m": float(errors.max()),
        })
    elif trace.task == "target":
        result.update({
            "captured": trace.reached,
            "capture_time_s": round(trace.time, 10) if trace.reached else None,
            "final_error_m": float(final_distance),
        })
    return {key: _number(value) if isinstance(value, float) else value for key, value in result.items()}
