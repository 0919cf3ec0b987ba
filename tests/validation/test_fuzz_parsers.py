"""Property-based fuzzing of every parser: a generated document (valid, valid mutated at a random
place, or structurally random) either loads or raises :class:`InputError` — never another
exception. Each test runs 1,000 derandomized examples (``strategies.FUZZ``)."""

from __future__ import annotations

import io
import json
import shutil
import tempfile
from contextlib import redirect_stderr, redirect_stdout
from pathlib import Path

import numpy as np
import yaml
from hypothesis import given, strategies as st

from fuzzynav.catalog.tasks import load_controller
from fuzzynav.cli import main
from fuzzynav.cli.fis import _read_csv
from fuzzynav.errors import InputError
from fuzzynav.fuzzy.io import dumps, from_document, loads, to_document
from fuzzynav.fuzzy.systems import get_system
from fuzzynav.learn.checkpoint import check_same_run, load_checkpoint, restore, save_checkpoint
from fuzzynav.learn.tabular import TabularLearner
from fuzzynav.storage import save_document
from fuzzynav.validation import parse_yaml
from fuzzynav.world.scenario import BUILTIN_DIR, read_yaml, scenario_from_dict

from .strategies import FUZZ, documents, mutated, mutated_text

WORK = Path(tempfile.mkdtemp(prefix="fuzzynav-fuzz-"))  # module-wide: hypothesis runs many examples per test


def teardown_module():
    """Remove the files the examples wrote (pytest calls this once the module's tests are done)."""
    shutil.rmtree(WORK, ignore_errors=True)
GOAL_SEEKING = get_system("goal-seeking")
SCENARIOS = [read_yaml(BUILTIN_DIR / f"{name}.yaml") for name in ("example-goal",)] + [
    {"robot": {"x": 2, "y": 2}, "path": [[3, 3], [9, 3], [9, 9]], "path_tolerance": 0.5, "speed": 1.0,
     "obstacles": [{"wall": {"start": [12, 1], "end": [12, 8], "thickness": 0.2}},
                   {"ellipse": {"center": [15, 15], "radii": [2, 1], "angle": 0.3}},
                   {"polygon": {"points": [[5, 12], [8, 12], [8, 15]]}}]},
    {"robot": {"x": 2, "y": 2}, "target": {"x": 10, "y": 10, "tolerance": 0.3,
                                          "motion": {"type": "sinusoid", "velocity": [0.2, 0], "amplitude": 1,
                                                     "period": 10}}},
]
SCENARIO_KEYS = st.sampled_from(["world", "robot", "goal", "path", "target", "obstacles", "max_time", "x", "y",
                                 "radius", "points", "center", "radii", "width", "motion", "type"]) | st.text(max_size=6)
FIS = to_document(GOAL_SEEKING)
MAMDANI = {**FIS, "method": "mamdani", "defuzzifier": "centroid", "resolution": 50,
           "outputs": [{"name": "alpha", "universe": [-1, 1],
                        "terms": {"N": {"kind": "triangle", "params": [-1, -1, 0]},
                                  "P": {"kind": "triangle", "params": [0, 1, 1]}}}],
           "rules": {"grid": {"rows": "theta", "columns": "drg", "outputs": ["alpha"],
                              "cells": [" ".join("N" if i < 2 else "P" for _ in FIS["inputs"][0]["terms"])
                                        for i in range(len(FIS["inputs"][1]["terms"]))]}}}
FIS_KEYS = st.sampled_from(["method", "resolution", "kind", "params", "universe", "terms", "rules", "grid", "cells",
                            "row_labels", "inputs", "outputs", "name"]) | st.text(max_size=6)
MODEL = {"kind": "fql-goal", **FIS, "constant_speed": 1.0}
NEURAL = {"kind": "neural-tracker", "input_range": [-3.2, 3.2], "speed": 1.0,
          "model": {"format": "fuzzynav-mlp", "version": 1, "activation": "tanh", "output_activation": "identity",
                    "weights": [[[0.5, -0.2]], [[0.3], [0.1]]], "biases": [[0.0, 0.1], [0.0]], "loss_curve": [1.0]}}


def learner():
    return TabularLearner(4, 2)


def _checkpoint_document() -> dict:
    path = WORK / "valid.checkpoint.json"
    save_checkpoint(path, learner(), np.random.default_rng(0), 2,
                    {"mean_reward": [[0.5], [0.25]], "steps": [[3], [4]], "success": [[True], [False]]},
                    {"task": "t", "seed": 0})
    return json.loads(path.read_text())


CHECKPOINT = _checkpoint_document()


def loads_or_refuses(function, *args):
    """Call ``function``; an InputError is a refusal (fine), any other exception fails the test."""
    try:
        return function(*args)
    except InputError as error:
        assert str(error)
        return None


def _write(name: str, content) -> Path:
    path = WORK / name
    if isinstance(content, bytes):
        path.write_bytes(content)
    else:
        path.write_text(content, encoding="utf-8", errors="surrogatepass")
    return path


def test_the_seeds_the_fuzzing_mutates_load_whole():
    """The valid documents every fuzz test starts from load (a parser refusing everything would
    pass the fuzz tests, whose refusals are all fine)."""
    for document in SCENARIOS:
        assert scenario_from_dict(document, "<seed>").name
    for document in (FIS, MAMDANI):
        assert np.isfinite(from_document(document, "<seed>").evaluate(np.array([[1.0, 0.5]]))).all()
    for fmt in ("json", "yaml", "fll", "fis"):
        system = loads(dumps(GOAL_SEEKING, fmt), fmt, "<seed>")
        assert np.allclose(system.evaluate(np.array([[1.0, 0.5]])), GOAL_SEEKING.evaluate(np.array([[1.0, 0.5]])))
    for name, document in (("model.json", MODEL), ("neural.json", NEURAL)):
        assert load_controller(_write(name, json.dumps(document))) is not None
    assert load_controller(_write("model.npz", NPZ)) is not None
    loaded = load_checkpoint(_write("seed.checkpoint.json", json.dumps(CHECKPOINT)))
    check_same_run(loaded, {"task": "t", "seed": 0}, 10, "<seed>")
    restore(learner(), np.random.default_rng(), loaded, "<seed>")
    assert _read_csv(GOAL_SEEKING, str(_write("seed.csv", CSV))) is not None


# -- scenarios --------------------------------------------------------------------------------
@FUZZ
@given(st.one_of(st.sampled_from(SCENARIOS), st.sampled_from(SCENARIOS).flatmap(lambda d: mutated(d, SCENARIO_KEYS)),
                 documents(SCENARIO_KEYS)))
def test_scenario_documents(document):
    loads_or_refuses(scenario_from_dict, document, "<fuzz>")


@FUZZ
@given(st.sampled_from([yaml.safe_dump(d) for d in SCENARIOS]).flatmap(mutated_text) | st.text(max_size=200))
def test_scenario_yaml_text(text):
    def parse(content):
        return scenario_from_dict(parse_yaml(content, "<fuzz>"), "<fuzz>")
    loads_or_refuses(parse, text)


# -- fuzzy systems ------------------------------------------------------------------------------
@FUZZ
@given(st.one_of(st.sampled_from([FIS, MAMDANI]), st.sampled_from([FIS, MAMDANI]).flatmap(lambda d: mutated(d, FIS_KEYS)),
                 documents(FIS_KEYS)))
def test_fuzzy_documents(document):
    system = loads_or_refuses(from_document, document, "<fuzz>")
    if system is not None:  # a system that loads evaluates without an exception
        system.evaluate(np.zeros((2, len(system.inputs))))


@FUZZ
@given(st.sampled_from(["json", "yaml"]).flatmap(
    lambda fmt: st.tuples(st.just(fmt), mutated_text(dumps(GOAL_SEEKING, fmt)) | st.text(max_size=200))))
def test_fuzzy_json_yaml_text(case):
    fmt, text = case
    loads_or_refuses(loads, text, fmt, "<fuzz>")


@FUZZ
@given(mutated_text(dumps(GOAL_SEEKING, "fll")) | st.text(max_size=200))
def test_fuzzy_fll_text(text):
    loads_or_refuses(loads, text, "fll", "<fuzz>")


@FUZZ
@given(mutated_text(dumps(GOAL_SEEKING, "fis")) | st.text(max_size=200))
def test_fuzzy_fis_text(text):
    loads_or_refuses(loads, text, "fis", "<fuzz>")


# -- model files, checkpoints -------------------------------------------------------------------
@FUZZ
@given(st.one_of(st.sampled_from([MODEL, NEURAL]).flatmap(lambda d: mutated(d, FIS_KEYS)), documents(FIS_KEYS)))
def test_json_model_files(document):
    loads_or_refuses(load_controller, _write("model.json", json.dumps(document)))


def _npz_bytes() -> bytes:
    path = WORK / "valid.npz"
    save_document(path, MODEL)
    return path.read_bytes()


NPZ = _npz_bytes()


@FUZZ
@given(st.lists(st.tuples(st.integers(0, len(NPZ) - 1), st.integers(0, 255)), min_size=1, max_size=8))
def test_npz_model_files(flips):
    data = bytearray(NPZ)
    for position, value in flips:
        data[position] = value
    loads_or_refuses(load_controller, _write("model.npz", bytes(data)))


@FUZZ
@given(st.one_of(mutated(CHECKPOINT, st.sampled_from(["rng", "state", "learner", "q", "curve", "extra", "episode"])),
                 documents()))
def test_checkpoints(document):
    path = _write("run.checkpoint.json", json.dumps(document))

    def resume():
        loaded = load_checkpoint(path)
        check_same_run(loaded, {"task": "t", "seed": 0}, 10, str(path))
        restore(learner(), np.random.default_rng(), loaded, str(path))
    loads_or_refuses(resume)


# -- CSV and command-line values ----------------------------------------------------------------
CSV = "drg,theta\n1.0,0.5\n3,-1\n"


@FUZZ
@given(mutated_text(CSV) | mutated_text("\ufeff" + CSV) | st.text(max_size=100))
def test_csv_tables(text):
    loads_or_refuses(_read_csv, GOAL_SEEKING, str(_write("in.csv", text)))


@FUZZ
@given(st.lists(st.text(max_size=12) | st.sampled_from(["drg=1", "theta=0", "drg=nan", "theta=1e999", "drg=10**20"]),
                max_size=3))
def test_command_line_values(values):
    argv = ["fis", "eval", "goal-seeking"] + [item for value in values for item in ("--input", value)]
    with redirect_stdout(io.StringIO()), redirect_stderr(io.StringIO()):
        try:
            status = main(argv)
        except SystemExit as stop:  # argparse's own refusal: usage and exit status 2
            status = stop.code
    assert status in (0, 2)
