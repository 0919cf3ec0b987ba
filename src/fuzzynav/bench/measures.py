"""The numbers of one benchmark run: :func:`fuzzynav.sim.metrics.metrics` plus the path ratio
and the BARN score.

- ``shortest_path_m``: length of the shortest collision-free path of the robot's disc from the
  start into the goal's tolerance disc: the shortest path to the goal centre
  (:func:`fuzzynav.world.planning.shortest_path`, radius = the simulated robot's) less the
  tolerance (exact when its last straight piece is longer than the tolerance, as it is in open
  goal regions), among the obstacles that stand still (the moving ones are left out), computed once per world and cached (in memory, and on disk under the
  campaign's ``cache/`` folder); ``path_ratio`` = driven length / that length, for runs that
  reached the goal.
- ``collision_by``: ``"robot"`` or ``"obstacle"`` after a collision (who moved into whom,
  :mod:`fuzzynav.sim.fault`); the summary counts the robot's as ``collision_at_fault``.
- ``barn_score`` (worlds with a BARN reference): the BARN Challenge's metric, success ×
  t_opt / clip(t, 2 t_opt, 8 t_opt) with t_opt = optimal path length / 2 m/s (the challenge's
  ``run.py``), the optimal path length being BARN's own (``benchmark.json``, or the family's,
  :func:`fuzzynav.world.generate.family_reference`);
- ``barn_score_challenge`` (worlds whose reference gives ``barn_challenge_path_m``): the same
  formula with the path length the challenge's ``run.py`` uses, right or wrong — for DynaBARN's
  worlds it is GOAL_POSITION[0] − INIT_POSITION[0] = −31 m, and with t_opt < 0 numpy's clip
  returns its upper bound 8 t_opt, so every success scores t_opt / 8 t_opt = 0.125
  (docs/dynamic.md). Both are reported so that results compare with published ones.
"""

from __future__ import annotations

import hashlib
import json
import math
from pathlib import Path

from fuzzynav import validation
from fuzzynav.bench.stored import json_mapping
from fuzzynav.storage import write_text_atomic
from fuzzynav.world.planning import shortest_path
from fuzzynav.world.polylines import path_length
from fuzzynav.world.scenario import Scenario

BARN_SPEED = 2.0  # m/s: the challenge's t_opt = optimal path length / 2 m/s
_MEMORY: dict[str, float | None] = {}


def world_key(scenario: Scenario, radius: float) -> str:
    """A digest of what the shortest path depends on: obstacles, world size, start, goal, radius."""
    doc = scenario.to_dict()
    relevant = {key: doc.get(key) for key in ("world", "robot", "goal", "obstacles")}
    relevant["radius"] = float(radius)
    return hashlib.sha1(json.dumps(relevant, sort_keys=True).encode()).hexdigest()


def shortest_length(scenario: Scenario, radius: float, cache_dir: str | Path | None = None) -> float | None:
    """Shortest path length (m) of the disc on ``scenario`` (None: no path, or not a goal task)."""
    if scenario.goal is None:
        return None
    key = world_key(scenario, radius)
    file = Path(cache_dir) / "shortest" / f"{key}.json" if cache_dir is not None else None
    if key in _MEMORY:  # computed by an earlier campaign of this process: still written to this one's cache
        length = _MEMORY[key]
    elif file is not None and file.is_file():
        length = _cached_length(file)
    else:
        path = shortest_path(scenario.world.standing(), scenario.start, scenario.goal.position, radius)
        length = None if path is None else round(max(path_length(path) - scenario.goal.tolerance, 1e-6), 6)
    if file is not None and not file.is_file():
        write_text_atomic(file, json.dumps({"scenario": scenario.name, "shortest_path_m": length}))
    _MEMORY[key] = length
    return length


def _cached_length(file: Path) -> float | None:
    """The ``shortest_path_m`` of a cache file, read back as user input (a number > 0 or null)."""
    source = str(file)
    document = json_mapping(file)
    length = document.get("shortest_path_m")
    return None if length is None else validation.number(length, source, "shortest_path_m", lo=0.0, lo_open=True)


def barn_score(reached: bool, time_s: float, optimal_path_m: float) -> float:
    """The BARN Challenge score of one run (module docstring); ``min(max(·))`` is numpy's ``clip``,
    also when ``optimal_path_m`` < 0 (the challenge's value on DynaBARN)."""
    optimal = optimal_path_m / BARN_SPEED
    return float(reached) * optimal / min(max(time_s, 2 * optimal), 8 * optimal)


def run_row(numbers: dict, shortest: float | None, reference: dict) -> dict:
    """The benchmark fields of one run from its :func:`~fuzzynav.sim.metrics.metrics` dict."""
    reached = numbers["outcome"] == "reached"
    ratio = numbers["path_length_m"] / shortest if reached and shortest else None
    optimal = reference.get("barn_optimal_path_m")
    challenge = reference.get("barn_challenge_path_m")
    return {
        "outcome": numbers["outcome"],
        "time_s": numbers["time_s"],
        "path_length_m": numbers["path_length_m"],
        "shortest_path_m": shortest,
        "path_ratio": ratio,
        "min_clearance_m": numbers["min_clearance_m"],
        "steering_effort_rad": numbers["steering_effort_rad"],
        "steering_variation_rad": numbers["steering_variation_rad"],
        "final_distance_m": numbers["final_distance_m"],
        "barn_score": barn_score(reached, numbers["time_s"], optimal) if optimal else None,
        "barn_score_challenge": barn_score(reached, numbers["time_s"], challenge) if challenge else None,
        "collision_by": numbers["collision_by"],
    }


def is_number(value) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)
