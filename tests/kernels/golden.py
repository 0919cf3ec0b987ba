"""The episodes of tests/kernels/test_same_traces.py and how they are stored (also run against an
older checkout to record ``base_traces.npz``: ``PYTHONPATH=<old>/src python -m tests.kernels.golden``)."""

import json
from pathlib import Path

import numpy as np

FILE = Path(__file__).with_name("base_traces.npz")
EPISODES = [(name, controller) for name in ("fig-IV-15a", "fig-IV-22a", "fig-IV-23", "fig-VI-27")
            for controller in ("goal-seeking", "fuzzy-2b", "fuzzy-5b", "wall-follow")]
EPISODES += [("example-path", "fuzzy-tracker"), ("example-target", "pure-pursuit"), ("path-v", "stanley")]
MIXED = [(i, controller) for i in (0, 3, 9) for controller in ("fuzzy-2b", "fuzzy-5b")]
EVERY = 10  # poses kept: every 10th step and the last
# the keys keep the names recorded at the base; goal-seeking, fuzzy-2b / fuzzy-5b there are today's
# thesis navigators with this package's layers (anti-orbit guard, turning room, safety stop, hysteresis)
THESIS = {"goal-seeking": "goal-seeking-guarded", "fuzzy-2b": "fuzzy-2b-layered", "fuzzy-5b": "fuzzy-5b-layered"}


def run_all() -> dict:
    """{key: (outcome, steps, behaviour labels, kept poses)} of every episode."""
    from fuzzynav.catalog.controllers import make_controller
    from fuzzynav.sim import run_episode
    from fuzzynav.world.generate import generate_worlds
    from fuzzynav.world.scenario import load_scenario

    worlds = generate_worlds("mixed", max(i for i, _ in MIXED) + 1, 0)
    runs = [(f"{name}/{c}", load_scenario(name), c) for name, c in EPISODES]
    runs += [(f"mixed-{i}/{c}", worlds[i], c) for i, c in MIXED]
    out = {}
    for key, scenario, controller in runs:
        trace = run_episode(scenario, make_controller(THESIS.get(controller, controller)), seed=0)
        kept = np.vstack([trace.pose[::EVERY], trace.pose[-1:]])
        out[key] = (trace.outcome, trace.steps, "|".join(trace.behaviour.tolist()), kept)
    return out


if __name__ == "__main__":
    runs = run_all()
    meta = {key: run[:3] for key, run in runs.items()}
    np.savez_compressed(FILE, meta=np.array(json.dumps(meta)), **{key: run[3] for key, run in runs.items()})
    print(f"{len(runs)} episodes -> {FILE}")
