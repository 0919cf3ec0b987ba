"""``gymnasium.make("fuzzynav.gym:fuzzynav/GoalSeeking-v0")`` imports and registers the environments
on its own (Gymnasium 1.x has no plug-in entry points: its ``module:id`` form is the way)."""

import subprocess
import sys


def test_make_by_module_path_needs_no_import_of_fuzzynav():
    code = ("import gymnasium as g; env = g.make('fuzzynav.gym:fuzzynav/GoalSeeking-v0'); "
            "obs, info = env.reset(seed=0); print(type(env.unwrapped).__name__, len(obs))")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr[-2000:]
    assert done.stdout.split()[0] == "FuzzynavEnv"
