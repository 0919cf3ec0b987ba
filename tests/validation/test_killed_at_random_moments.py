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


@pytest.mark.slow
def test_train_killed_at_random_moments_resumes_into_the_uninterrupted_model(tmp_path):
    whole = tmp_path / "whole.json"
    moments = _moments(38, _timed_run([*TRAIN, "--out", str(whole)]))
    for number, delay in enumerate(moments):
        part = tmp_path / f"part{number}.json"
        _kill_after([*TRAIN, "--out", str(part)], delay)
        assert main([*TRAIN, "--out", str(part), "--resume"]) == 0, f"killed after {delay:.2f} s"
        assert json.loads(part.read_text()) == json.loads(whole.read_text()), f"killed after {delay:.2f} s"
    assert _temporaries(tmp_path) == []


@pytest.mark.slow
def test_bench_killed_at_random_moments_resumes_into_the_uninterrupted_files(tmp_path):
    whole = tmp_path / "whole"
    moments = _moments(83, _timed_run([*BENCH, "--out", str(whole)]))
    for number, delay in enumerate(moments):
        part = tmp_path / f"part{number}"
        _kill_after([*BENCH, "--out", str(part)], delay)
        assert main([*BENCH, "--out", str(part), "--resume"]) == 0, f"killed after {delay:.2f} s"
        for name in CAMPAIGN_FILES:
            assert (part / name).read_bytes() == (whole / name).read_bytes(), f"{name}, killed after {delay:.2f} s"
    assert _temporaries(tmp_path) == []
