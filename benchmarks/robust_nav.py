"""Navigators that never freeze: success, collisions, timeouts and stand-stills of a chapter IV
navigator on generated world families, seed by seed.

Families:

- ``mixed`` and ``circles``: :func:`fuzzynav.world.generate.generate_worlds`, the worlds of
  ``fuzzynav evaluate`` (same worlds, same episode seed: the same outcomes);
- ``dense`` and ``utrap``: taken from :mod:`fuzzynav.world.generate` when it provides them;
  otherwise drawn here (:func:`dense_world`, :func:`utrap_world`):
  ``dense`` — 12 to 20 obstacles of the mixed shapes, start and goal ≥ 10 m apart, solvable
  for a disc of 0.6 m radius (every passage of the connecting route ≥ 1.2 m wide);
  ``utrap`` — a U-shaped wall (inside 3–5 m wide, 3–5 m deep, any orientation) between start
  and goal: the goal 3–5 m behind its closed end, the start inside the U or 2–4 m in front of
  its opening, plus 0–4 mixed obstacles; solvable like ``mixed`` (room to turn).

For every episode the script records the outcome and, for episodes that end away from the goal,
how long the robot stood still at the end (``|V| < 1e-6``). Per family and seed it prints the
rates and ``stood_still_10s``: episodes ending more than 10 s at a stand-still away from the goal.

    python benchmarks/robust_nav.py --controller fuzzy-5b-rays --family mixed dense utrap --seeds 0 1 2 3 4 [--n 100] [--json]
"""

from __future__ import annotations

import argparse
import json
import math

import numpy as np

from fuzzynav.catalog.controllers import make_controller
from fuzzynav.errors import InputError
from fuzzynav.sim import run_episode
from fuzzynav.world import generate
from fuzzynav.world.scenario import scenario_from_dict
from fuzzynav.world.world import World

DENSE_COUNTS = (12, 20)
DENSE_PASSAGE = 1.2  # m: the narrowest passage the connecting route may have


def _mixed_shape(rng) -> dict:
    makers = generate._MAKERS["mixed"]  # the mixed family's shape drawers
    return makers[int(rng.integers(len(makers)))](rng)


def _clear_of(shape: dict, points, clearance: float) -> bool:
    (kind, params), = shape.items()
    alone = World(generate.WIDTH, generate.HEIGHT, (generate._CLASSES[kind](**params),))
    return bool((alone.nearest_obstacle(np.asarray(points, dtype=float))[0] >= clearance).all())


def _scenario(name, start, theta, goal, obstacles, max_time=120.0):
    return scenario_from_dict({"name": name, "robot": {"x": round(float(start[0]), 2), "y": round(float(start[1]), 2),
                                                       "theta": round(float(theta), 3)},
                               "goal": {"x": round(float(goal[0]), 2), "y": round(float(goal[1]), 2)},
                               "obstacles": obstacles, "max_time": max_time}, source=name)


def dense_world(rng, name: str):
    """One ``dense`` world (module docstring)."""
    while True:
        start, goal = rng.uniform(generate.BORDER, generate.WIDTH - generate.BORDER, (2, 2))
        if np.hypot(*(goal - start)) < generate.MIN_START_GOAL:
            continue
        obstacles = [shape for shape in (_mixed_shape(rng) for _ in range(int(rng.integers(DENSE_COUNTS[0], DENSE_COUNTS[1] + 1))))
                     if _clear_of(shape, [start, goal], generate.POINT_CLEARANCE)]
        if len(obstacles) < DENSE_COUNTS[0]:
            continue
        scenario = _scenario(name, start, rng.uniform(-math.pi, math.pi), goal, obstacles)
        if generate.connected(scenario.world, start, goal, DENSE_PASSAGE / 2):
            return scenario


def utrap_world(rng, name: str):
    """One ``utrap`` world (module docstring)."""
    while True:
        width, depth = rng.uniform(3.0, 5.0, 2)
        phi = rng.uniform(-math.pi, math.pi)
        axis, across = np.array([math.cos(phi), math.sin(phi)]), np.array([-math.sin(phi), math.cos(phi)])
        centre = rng.uniform(6.0, 14.0, 2)
        base = centre + axis * depth / 2
        corners = [base + across * width / 2, base - across * width / 2]
        ends = [c - axis * depth for c in corners]
        walls = [{"wall": {"start": corners[0].round(2).tolist(), "end": corners[1].round(2).tolist(), "thickness": 0.3}}]
        walls += [{"wall": {"start": c.round(2).tolist(), "end": e.round(2).tolist(), "thickness": 0.3}}
                  for c, e in zip(corners, ends)]
        goal = base + axis * rng.uniform(3.0, 5.0)
        inside = rng.random() < 0.5
        start = centre - axis * (0.0 if inside else depth / 2 + rng.uniform(2.0, 4.0))
        points = np.array([start, goal])
        if not ((points > 1.5).all() and (points < generate.WIDTH - 1.5).all()):
            continue
        extra = [shape for shape in (_mixed_shape(rng) for _ in range(int(rng.integers(0, 5))))
                 if _clear_of(shape, [start, goal, centre, base], 2.0)]
        try:
            scenario = _scenario(name, start, phi + rng.uniform(-0.5, 0.5), goal, walls + extra)
        except InputError:  # a drawn obstacle overlaps the start footprint: draw again
            continue
        if generate.connected(scenario.world, start, goal, 0.3 + generate.TURNING_MARGIN):
            return scenario


DRAWN = {"dense": dense_world, "utrap": utrap_world}


def worlds(family: str, n: int, seed: int):
    """``n`` worlds of ``family`` for ``seed`` (world i depends only on family, seed, i)."""
    if family in generate.KINDS:
        return generate.generate_worlds(family, n, seed), "world.generate"
    children = np.random.SeedSequence([int(seed), 100 + sorted(DRAWN).index(family)]).spawn(n)
    return [DRAWN[family](np.random.default_rng(c), f"{family}-{seed}-{i:03d}") for i, c in enumerate(children)], \
        "benchmarks/robust_nav.py"


def stand_still(trace) -> float:
    """Seconds the robot stood still (|V| < 1e-6) at the end of the episode."""
    moving = np.flatnonzero(np.abs(trace.speed) >= 1e-6)
    last = moving[-1] + 1 if len(moving) else 0
    return float((len(trace.speed) - last) * trace.dt)


def run(controller: str, family: str, n: int, seed: int) -> dict:
    scenarios, source = worlds(family, n, seed)
    episodes = []
    for scenario in scenarios:
        trace = run_episode(scenario, make_controller(controller), seed=seed)
        away = float(np.hypot(*(trace.pose[-1, :2] - scenario.goal.position)))
        episodes.append({"scenario": scenario.name, "outcome": trace.outcome, "time_s": float(trace.time),
                         "still_s": stand_still(trace) if trace.outcome != "reached" else 0.0, "goal_distance_m": away})
    rate = lambda o: sum(e["outcome"] == o for e in episodes) / n
    return {"controller": controller, "family": family, "worlds_from": source, "seed": seed, "n": n,
            "success_rate": rate("reached"), "collision_rate": rate("collision"), "timeout_rate": rate("timeout"),
            "stood_still_10s": sum(int(e["still_s"] > 10.0) for e in episodes),
            "failures": [e for e in episodes if e["outcome"] != "reached"]}


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--controller", default="fuzzy-5b-rays")
    parser.add_argument("--family", nargs="+", default=["mixed", "dense", "utrap"])
    parser.add_argument("--seeds", nargs="+", type=int, default=[0, 1, 2, 3, 4])
    parser.add_argument("--n", type=int, default=100)
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args(argv)
    results = []
    for family in args.family:
        for seed in args.seeds:
            results.append(run(args.controller, family, args.n, seed))
            r = results[-1]
            if not args.json:
                print(f"{r['controller']:16s} {family:7s} seed {seed}: success {100 * r['success_rate']:5.1f} %  "
                      f"collisions {100 * r['collision_rate']:4.1f} %  timeouts {100 * r['timeout_rate']:4.1f} %  "
                      f"stood still >10 s: {r['stood_still_10s']}  ({r['worlds_from']})", flush=True)
                for e in r["failures"]:
                    print(f"    {e['scenario']}: {e['outcome']} at {e['time_s']:.1f} s, {e['goal_distance_m']:.1f} m from "
                          f"the goal, still for the last {e['still_s']:.1f} s", flush=True)
    if args.json:
        print(json.dumps(results))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
