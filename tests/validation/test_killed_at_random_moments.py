"""``kill -9`` at pseudo-random moments of ``train --checkpoint-every`` and ``bench``, then
``--resume``: the results equal an uninterrupted run's and no temporary file is left, wherever the
kill lands (while importing, between checkpoints, in the middle of a save, after the end).

The moments are drawn from a seeded generator across the duration of an uninterrupted run of the
same command, measured in the test; the assertions hold for every moment, so the test is
deterministic whatever the machine's speed."""

import json
import os
import random
import signal
import subprocess
import sys
import time

import pytest

from fuzzynav.cli import main

KILLS = 3  # moments per command
TRAIN = ["train", "fql-goal-traces", "--episodes", "1000", "--seed", "5", "--checkpoint-every", "100", "--quiet",
         "--parallel", "50"]
BENCH = ["bench", "circles:3:5", "--controllers", "goal-seeking,vfh", "--seeds", "2", "--workers", "1", "--quiet",
         "--gallery", "1"]
CAMPAIGN_FILES = ("runs.csv", "runs.jsonl", "summary.json", "summary.md")


def _command(argv):
    return [sys.executable, "-m", "fuzzynav", *argv]


def _timed_run(argv) -> float:
    started = time.monotonic()
    subprocess.run(_command(argv), check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=300)
    return time.monotonic() - started


def _kill_after(argv, delay: float) -> None:
    process = subprocess.Popen(_command(argv), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        process.wait(timeout=delay)  # a kill after the end is one of the moments too
    except subprocess.TimeoutExpired:
        os.kill(process.pid, signal.SIGKILL)
        process.wait(timeout=60)


def _moments(seed: int, duration: float) -> list[float]:
    rng = random.Random(seed)
    return sorted(rng.uniform(0.05, 0.95) * duration for _ in range(KILLS))


def _temporaries(folder):
    return sorted(str(p.relative_to(folder)) for p in folder.rglob("*") if p.name.endswith(".tmp"))


def _model(path):
    return json.loads(path.read_text())


def _campaign(folder):
    return {name: (folder / name).read_bytes() for name in CAMPAIGN_FILES}


@pytest.mark.slow
@pytest.mark.parametrize(("argv", "seed", "out", "result"), [(TRAIN, 38, "m.json", _model), (BENCH, 83, "campaign", _campaign)],
                         ids=["train", "bench"])
def test_killed_at_random_moments_then_resumed_equals_an_uninterrupted_run(tmp_path, argv, seed, out, result):
    whole = tmp_path / "whole" / out
    moments = _moments(seed, _timed_run([*argv, "--out", str(whole)]))
    for number, delay in enumerate(moments):
        part = tmp_path / f"killed{number}" / out
        _kill_after([*argv, "--out", str(part)], delay)
        assert main([*argv, "--out", str(part), "--resume"]) == 0, f"killed after {delay:.2f} s"
        assert result(part) == result(whole), f"killed after {delay:.2f} s"
    assert _temporaries(tmp_path) == []
