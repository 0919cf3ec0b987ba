"""Every benchmark script still runs: ``--help`` of each (a new script is picked up by itself), and
a tiny real run of those that compare, score or time something cheaply. The numbers they measure
belong in docs/, with their commands; here only that the scripts work."""

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
SCRIPTS = sorted((ROOT / "benchmarks").glob("*.py"))
BARN = ROOT / "tests" / "data" / "barn"


def _run(script: str, *args: str, check: bool = True) -> subprocess.CompletedProcess:
    done = subprocess.run([sys.executable, str(ROOT / "benchmarks" / script), *args], capture_output=True, text=True,
                          timeout=600, cwd=ROOT)
    if check:
        assert done.returncode == 0, done.stderr[-2000:]
    return done


@pytest.mark.parametrize("script", SCRIPTS, ids=[path.name for path in SCRIPTS])
def test_help(script):
    done = _run(script.name, "--help")
    assert done.stdout.startswith("usage: ") and script.name in done.stdout


def test_no_machine_paths_and_no_imports_from_the_tests():
    for script in SCRIPTS:
        text = script.read_text(encoding="utf-8")
        assert "/work/" not in text and "/home/" not in text, script.name
        assert "from tests" not in text and "import tests" not in text, script.name


def test_barn_eval_runs_and_scores_a_world(tmp_path):
    out = tmp_path / "barn.json"
    _run("barn_eval.py", "--barn", str(BARN), "--worlds", "0", "--controller", "fuzzy-5b-thesis", "--out", str(out))
    result = json.loads(out.read_text())
    run = result["runs"][0]
    assert run["outcome"] in ("reached", "collision", "timeout") and 0.0 <= run["score"] <= 0.5
    assert (run["score"] > 0) == (run["outcome"] == "reached")


def test_same_results_compares_byte_for_byte_without_timings(tmp_path):
    for side, value in (("base", 1.0), ("new", 1.0)):
        (tmp_path / side / "models").mkdir(parents=True)
        (tmp_path / side / "models" / "m.json").write_text(json.dumps({"w": value, "train_seconds": len(side)}))
    args = ("--base", "x", "--new", "y", "--out", str(tmp_path), "--compare-only")
    assert "1 of 1 files identical" in _run("same_results.py", *args).stdout
    (tmp_path / "new" / "models" / "m.json").write_text(json.dumps({"w": 2.0}))
    done = _run("same_results.py", *args, check=False)
    assert done.returncode == 1 and "DIFFERENT  models/m.json" in done.stdout


def test_trace_compare_finds_a_moved_pose(tmp_path):
    pose = np.zeros((3, 3))
    meta = json.dumps({"w/c": {"outcome": "reached", "steps": 2, "behaviour": "GSB"}})
    np.savez(tmp_path / "old.npz", meta=np.array(meta), **{"w/c/pose": pose, "w/c/command": np.zeros((2, 2))})
    np.savez(tmp_path / "new.npz", meta=np.array(meta), **{"w/c/pose": pose + 1e-3, "w/c/command": np.zeros((2, 2))})
    assert _run("trace_compare.py", "--compare", str(tmp_path / "old.npz"), str(tmp_path / "old.npz")).returncode == 0
    done = _run("trace_compare.py", "--compare", str(tmp_path / "old.npz"), str(tmp_path / "new.npz"), check=False)
    assert done.returncode == 1 and "largest pose/command difference 0.001" in done.stdout


def test_learn_core_times_one_batch():
    rows = json.loads(_run("learn_core.py", "--batches", "1").stdout.splitlines()[-1])["rows"]
    assert [row["batch"] for row in rows] == [1] and rows[0]["fql_learner_us"] > 0


def test_anfis_bench_reports_peers_it_cannot_run(monkeypatch):
    monkeypatch.delenv("FUZZYNAV_ANFIS_PEER_PYTHON", raising=False)
    report = json.loads(_run("anfis_bench.py", "--json", "--repeats", "1").stdout)
    errors = {result["name"]: result.get("error", "") for result in report["results"]}
    assert "not run: give --peer-python" in errors["anfis-toolbox"] and "not run" in errors["xanfis"]


# The smallest configuration of each script that measures something in this Python: (script,
# arguments, text its output must hold). The peers a script compares with are found only through
# its flags or environment variables; without them it says what it did not run.
SMALLEST = [
    ("default_cost.py", ("--parts", "--n", "2", "--robots", "1", "--steps", "10"), '"benchmark": "default_cost"'),
    ("astar_backing.py", ("--n", "1", "--json"), '"benchmark": "astar_backing"'),
    ("astar_planners.py", ("mixed:1", "--episodes", "--json"), '"plan_median_s"'),
    ("batch_threads.py", ("--controller", "fuzzy-5b-thesis", "--robots", "70", "--steps", "3", "--chunks", "1",
                          "--json"), '"same_states": true'),
    ("bench_overhead.py", ("--worlds", "1", "--repeats", "1", "--controllers", "goal-seeking", "--json"), '"cpu_ratio"'),
    ("fuzzy_bench.py", ("--only", "fuzzynav", "--json"), '"single_call_us"'),
    ("navigator_profile.py", ("--robots", "1", "--steps", "10", "--json"), '"part_share"'),
    ("navigator_profile.py", ("--singles", "--robots", "2", "--steps", "5"), '"singles_us_per_robot_step"'),
    ("navigator_profile.py", ("--searches", "--steps", "20"), '"share_of_time"'),
    ("navigator_parts.py", ("--steps", "20", "--repeats", "1", "--json"), '"blocked directions"'),
    ("robust_nav.py", ("--family", "mixed", "--seeds", "0", "--n", "1", "--json"), '"stood_still_10s"'),
    ("robust_nav.py", ("--layers", "--controller", "fuzzy-2b-thesis", "--family", "mixed", "--seeds", "0", "--n", "1"),
     "| fuzzy-2b-thesis | all layers |"),
    ("sim_core.py", ("--json",), '"irsim": null'),
    ("physics_plant.py", ("cost", "fig-IV-22a"), "fig-IV-22a mujoco: reached"),
    ("robustness.py", ("mixed:1", "--navigators", "goal-seeking", "--quick", "--out", "{tmp}/sweep"), "| combined |"),
    ("route_bound.py", ("--family", "forest", "--seed", "0", "--n", "2"), "forest seed 0, 2 worlds: exploration factor"),
]
# Scripts whose smallest run is too long for the suite (their --help still runs above: the argument
# parsing and every import) or that need a peer Python: why, and what checks them instead.
NOT_RUN_HERE = {
    "fuzzify_bench.py": "about a minute of timing loops at any size",
    "mutations.py": "two minutes for one role (every claim of chapters IV and V rerun per mutation)",
    "tracking_bench.py": "about a minute: every tracker timed on the three chapter V paths",
    "tuning_compare.py": "a tuner needs at least one generation: 400 episodes",
    "train_time.py": "trains with the task's whole default budget in fresh processes",
    "chapter6_probes.py": "avoid-rules reads a trained fql-avoid model (minutes of training first); wall-bound "
                          "searches the wall follower's interpretations for tens of minutes, wall-corners runs 19,683 of them at "
                          "two corners (45 minutes); table-vi-1 trains four tables "
                          "(20 s for 60 episodes each)",
    "irsim_peer.py": "needs the ir-sim package (its own virtualenv); its world conversion is tested below",
    # smallest runs (the arguments given) of 20-45 s on an idle 2-core machine:
    "gym_vector.py": "--robots 2 --steps 5 --rounds 1: 25 s (every task's environments built twice)",
    "tune_speed.py": "--worlds mixed:1 --population 2: 22 s (the tuner's compiled call is compiled first)",
    "tune_holdout.py": "--suites mixed:1: 20 s (the tuner's compiled call is compiled first)",
    "rl_bench.py": "--tasks q-goal --seeds 1 --episodes 50: 20 s (a training and its evaluation)",
    "rl_compare.py": "--algos fql --tasks goal --seeds 1 --steps 200 --checkpoints 100 200: 43 s",
}


@pytest.mark.slow
@pytest.mark.parametrize(("script", "args", "expect"), SMALLEST, ids=[f"{s}-{i}" for i, (s, _, _) in enumerate(SMALLEST)])
def test_smallest_configuration_runs(script, args, expect, tmp_path):
    done = _run(script, *(arg.format(tmp=tmp_path) for arg in args))
    assert expect in done.stdout, done.stdout[-2000:]


def test_every_script_has_a_smoke_run_or_a_reason():
    covered = {script for script, _, _ in SMALLEST} | set(NOT_RUN_HERE) | {
        "barn_eval.py", "same_results.py", "trace_compare.py", "learn_core.py", "anfis_bench.py",
        "cold_call_bench.py", "fuzzylite_examples.py"}
    assert {path.name for path in SCRIPTS} == covered


@pytest.mark.parametrize(("script", "args", "message"), [
    ("cold_call_bench.py", ("engine.fll",), "pyfuzzylite is not importable here"),
    ("fuzzylite_examples.py", (), "give --examples DIR (or set FUZZYNAV_FLL_EXAMPLES)"),
])
def test_scripts_without_their_peer_say_how_to_give_it(script, args, message, monkeypatch):
    monkeypatch.delenv("FUZZYNAV_FLL_EXAMPLES", raising=False)
    done = _run(script, *args, check=False)
    assert done.returncode == 2 and message in done.stderr and "Traceback" not in done.stderr


def test_irsim_peer_builds_the_same_world():
    """The IR-SIM side's world: the 20 m square, one car-like robot at the start, a 7-beam lidar,
    and every obstacle (an ellipse as a 32-gon)."""
    import importlib.util

    spec = importlib.util.spec_from_file_location("irsim_peer", ROOT / "benchmarks" / "irsim_peer.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    job = {"obstacles": [{"circle": {"center": [5, 5], "radius": 1}},
                         {"ellipse": {"center": [10, 10], "radii": [2, 1], "angle": 0.3}}],
           "start": [1, 1, 0], "command": [1.0, 0.0], "dt": 0.1, "max_range": 5.0, "wheelbase": 0.5}
    world = module.world_yaml(job)
    assert (world["world"]["width"], world["world"]["height"]) == (20.0, 20.0)
    (robot,) = world["robot"]
    assert robot["kinematics"]["name"] == "acker" and robot["state"] == [1, 1, 0, 0.0]
    assert robot["sensors"][0]["number"] == 7 and robot["shape"]["wheelbase"] == 0.5
    circle, ellipse = world["obstacle"]
    assert circle == {"shape": {"name": "circle", "radius": 1.0}, "state": [5.0, 5.0, 0.0]}
    assert ellipse["shape"]["name"] == "polygon" and len(ellipse["shape"]["vertices"]) == 32
