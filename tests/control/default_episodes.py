"""Episodes of the default ``fuzzy-5b`` recorded before its kernels were made cheaper
(tests/control/test_default_same.py checks today's drive them alike; today's run without the
pace, without reusing the car route, without planning the next arc as one ends and driving the
car route's arcs only in tight places, and steering straight at a target the line to which is free, as
then: ``paced=False``, ``guide_car_reuse`` 0, ``guide_car_chain`` 0, ``guide_car_tight`` 0.5, ``guide_off_heading``
0 — what came later changes the decisions). Record again, from a
checkout whose decisions are the reference: ``PYTHONPATH=<checkout>/src python -m tests.control.default_episodes``."""

import hashlib
import json
from pathlib import Path

FILE = Path(__file__).with_name("default_episodes.json")
WORLDS = [("mixed", i) for i in range(4)] + [("dense", i) for i in range(2)]  # generated, seed 0


def run_all() -> dict:
    """{world: [outcome, steps, hash of the behaviour labels, final pose]} of ``fuzzy-5b`` without the pace,
    the car route's reuse and the chained arcs."""
    from fuzzynav.catalog.controllers import make_controller
    from fuzzynav.sim import run_episode
    from fuzzynav.world.generate import generate_world

    out = {}
    for kind, i in WORLDS:
        controller = make_controller("fuzzy-5b", paced=False, guidance={"guide_car_reuse": 0.0, "guide_car_chain": 0.0,
                                                                         "guide_car_tight": 0.5, "guide_off_heading": 0.0})
        trace = run_episode(generate_world(kind, 0, i), controller, seed=0)
        labels = "|".join(trace.behaviour.tolist()).encode()
        out[f"{kind}-{i}"] = [trace.outcome, int(trace.steps), hashlib.sha256(labels).hexdigest()[:16],
                              [float(v) for v in trace.pose[-1]]]
    return out


if __name__ == "__main__":
    FILE.write_text(json.dumps(run_all(), indent=1) + "\n")
    print(f"{len(WORLDS)} episodes -> {FILE}")
