"""``NUMBA_DISABLE_JIT=1`` runs the very same kernels as plain Python (the debugging story): a
short fuzzy-5b-thesis episode and a batch of rays, the learned avoidance navigator's inputs,
grid premise and drive, and a default fuzzy-2b episode that backs out, turns and follows a
boundary (recovery, loop escape, route), give the numbers of the compiled run."""

import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

SCRIPT = """
import json, numpy as np
from fuzzynav.catalog.controllers import make_controller
from fuzzynav.sim import run_episode
from fuzzynav.world.scenario import load_scenario
import fuzzynav.kernels.beams as beams
scenario = load_scenario("fig-IV-22a")
trace = run_episode(scenario, make_controller("fuzzy-5b-thesis"), max_time=4.0)
poses = np.array([[5.0, 5.0, 0.3], [12.0, 9.0, -2.0], [3.0, 16.0, 1.0]])
ranges = scenario.world.ranges(poses, np.linspace(-np.pi, np.pi, 9), 4.0)
print(json.dumps({"jit": hasattr(beams.read, "py_func"), "pose": trace.pose.tolist(),
                  "labels": trace.behaviour.tolist(), "ranges": ranges.tolist()}))
"""


LEARNED = """
import json, numpy as np
from fuzzynav.control import learned
from fuzzynav.learn.envs import GridPremise
from fuzzynav.learn.tasks import fql_avoid
import fuzzynav.kernels.learned as kernels
rng = np.random.default_rng(5)
ranges = np.minimum(rng.random((40, 7)) * 5.0, 4.0)
pose = np.column_stack([rng.random((40, 2)) * 20.0, rng.uniform(-3.0, 3.0, 40)])
goal = learned.goal_inputs(pose, rng.random((40, 2)) * 20.0)
x = learned.avoidance_inputs(ranges, True)
system = fql_avoid.avoid_system([0, 2, 1] * 4 + [0, 2], [0, 1, 2] * 4 + [2, 1])
navigator = learned.LearnedAvoidanceNavigator(system)
w = GridPremise(system).firing_strengths(x, normalise=False)
drive = navigator.drive(*navigator.avoider_shares(x), ranges, goal)
print(json.dumps({"jit": hasattr(kernels.drive, "py_func"), "values": [goal.tolist(), x.tolist(), w.tolist(),
                  [v.tolist() for v in drive]]}))
"""

ROBUST = """
import json
from pathlib import Path
from fuzzynav.catalog.controllers import make_controller
from fuzzynav.sim import run_episode
from fuzzynav.world.scenario import scenario_from_dict
import fuzzynav.kernels.route as route
worlds = json.loads(Path(%r).read_text())["worlds"]
trace = run_episode(scenario_from_dict(worlds["dense-0-007"]), make_controller("fuzzy-2b"), seed=0)
print(json.dumps({"jit": hasattr(route.target, "py_func"), "pose": trace.pose.tolist(),
                  "labels": trace.behaviour.tolist()}))
""" % str(Path(__file__).parents[1] / "control" / "data" / "robust_traces.json")  # noqa: UP031 (braces in the script)


def _run(disable: bool, script: str = SCRIPT) -> dict:
    env = {**os.environ, "NUMBA_DISABLE_JIT": "1" if disable else "0"}
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, env=env, timeout=600)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


@pytest.mark.slow
def test_kernels_run_as_plain_python_with_the_same_numbers():
    plain, compiled = _run(True), _run(False)
    assert not plain["jit"] and compiled["jit"]
    assert plain["labels"] == compiled["labels"] and len(plain["pose"]) == 41
    np.testing.assert_allclose(plain["pose"], compiled["pose"], rtol=0, atol=1e-12)
    np.testing.assert_allclose(plain["ranges"], compiled["ranges"], rtol=0, atol=1e-12)


def test_learned_navigator_kernels_run_as_plain_python_with_the_same_numbers():
    plain, compiled = _run(True, LEARNED), _run(False, LEARNED)
    assert not plain["jit"] and compiled["jit"]
    assert plain["values"] == compiled["values"]


@pytest.mark.slow
def test_layers_of_the_default_navigators_run_as_plain_python_with_the_same_numbers():
    plain, compiled = _run(True, ROBUST), _run(False, ROBUST)
    assert not plain["jit"] and compiled["jit"]
    assert plain["labels"] == compiled["labels"] and {"REC-BACK", "REC-TURN", "BF"} <= set(plain["labels"])
    np.testing.assert_allclose(plain["pose"], compiled["pose"], rtol=0, atol=1e-12)
