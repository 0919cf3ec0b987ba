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
