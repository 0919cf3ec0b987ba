"""Timing of the goal-seeking controller (Table IV.1, 35 rules) in fuzzynav and its Python peers.

    python benchmarks/fuzzy_bench.py            # table
    python benchmarks/fuzzy_bench.py --json     # one JSON object keyed by implementation

For each implementation: ``single_call_us`` (median latency of one evaluation of (d_rg, θ_rg))
and ``batch_evals_per_s`` (evaluations per second over a batch of 100,000 inputs; peers without
a batch API are timed as a loop of single calls over a smaller sample, and say so).

Peers: pyfuzzylite (the same system exported as FLL; its vectorised engine), simpful (Sugeno,
AND_PRODUCT: the same TS0), scikit-fuzzy (its control API is Mamdani-only: the same table with
narrow triangles at the singletons — same work per call, outputs not identical). A peer that is
not installed is reported as such and skipped. pyfuzzylite pins numpy < 2, so it usually lives in
its own virtual environment: if it is not importable here, the script reruns itself for that
peer with ``--fll-python`` (default ``/work/venv-fll/bin/python`` or ``$FUZZYNAV_FLL_PYTHON``),
e.g. ``python -m venv /work/venv-fll && /work/venv-fll/bin/pip install -e '.[fll]'``.
"""

from __future__ import annotations

import argparse
import contextlib
import importlib
import importlib.metadata
import json
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

from fuzzynav.fuzzy.io import to_fll
from fuzzynav.fuzzy.systems import goal_seeking

N_BATCH = 100_000
DEFAULT_FLL_PYTHON = os.environ.get("FUZZYNAV_FLL_PYTHON", "/work/venv-fll/bin/python")


def _inputs(n: int, seed: int = 0) -> np.ndarray:
    rng = np.random.default_rng(seed)
    return np.column_stack([rng.uniform(0.0, 25.0, n), rng.uniform(-np.pi, np.pi, n)])


def _median_time(fn, repeats: int) -> float:
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def _single_us(call, X: np.ndarray, rounds: int = 7) -> float:
    """Median over ``rounds`` of the mean latency of one call over the rows of X (µs)."""
    rows = X.tolist()  # plain floats: time the call, not NumPy scalar indexing

    def run():
        for a, b in rows:
            call(a, b)
    return _median_time(run, rounds) / len(X) * 1e6


def bench_fuzzynav() -> dict:
    system = goal_seeking()
    X = _inputs(N_BATCH)
    batch = _median_time(lambda: system.evaluate(X), 9)
    return {"batch_evals_per_s": N_BATCH / batch, "single_call_us": _single_us(system.evaluate_one, X[:20_000]),
            "note": "FuzzySystem.evaluate (NumPy batch) / evaluate_one (plain-Python fast path)"}


def bench_pyfuzzylite() -> dict:
    import fuzzylite as fl

    engine = fl.FllImporter().from_string(to_fll(goal_seeking()))
    X = _inputs(N_BATCH)

    def process(batch):
        engine.input_values = batch
        engine.process()
        return engine.output_values

    batch = _median_time(lambda: process(X), 5)
    drg, theta = engine.input_variables

    def one(a, b):
        drg.value, theta.value = a, b
        engine.process()
        return engine.output_values

    return {"batch_evals_per_s": N_BATCH / batch, "single_call_us": _single_us(one, X[:300], 5),
            "note": f"pyfuzzylite {fl.__version__}, vectorised engine (input_values = (N, 2) array)"}


def bench_simpful() -> dict:
    import simpful as sf

    system = goal_seeking()
    fs = sf.FuzzySystem(show_banner=False, operators=["AND_PRODUCT"], verbose=False)
    for var in system.inputs:
        lo, hi = var.universe
        sets = []
        for label, mf in var.terms.items():
            a, b, c = mf.params()
            points = ([[lo, 1.0]] if a == -np.inf else [[a, 0.0]]) + [[b, 1.0]] + ([[hi, 1.0]] if c == np.inf else [[c, 0.0]])
            sets.append(sf.FuzzySet(points=points, term=label))
        fs.add_linguistic_variable(var.name, sf.LinguisticVariable(sets, universe_of_discourse=[lo, hi]))
    for var in system.outputs:
        for label, mf in var.terms.items():
            fs.set_crisp_output_value(f"{var.name}_{label}", mf.value)
    rules = []
    for rule in system.rules:
        premise = " AND ".join(f"({v} IS {t})" for v, t in rule.premises)
        rules += [f"IF {premise} THEN ({v} IS {v}_{t})" for v, t in rule.conclusions]
    fs.add_rules(rules)

    def one(a, b):
        fs.set_variable("drg", a)
        fs.set_variable("theta", b)
        return fs.Sugeno_inference(["alpha", "v"])

    us = _single_us(one, _inputs(300), 5)
    return {"batch_evals_per_s": 1e6 / us, "single_call_us": us,
            "note": f"simpful {importlib.metadata.version('simpful')}: no batch API, batch = loop of single calls"}


def bench_scikit_fuzzy() -> dict:
    import skfuzzy as fuzz
    from skfuzzy import control as ctrl

    system = goal_seeking()
    ants = {}
    for var in system.inputs:
        lo, hi = var.universe
        ant = ctrl.Antecedent(np.linspace(lo, hi, 201), var.name)
        for label, mf in var.terms.items():
            ant[label] = mf(ant.universe)
        ants[var.name] = ant
    cons = {}
    for var in system.outputs:
        lo, hi = var.universe
        con = ctrl.Consequent(np.linspace(lo, hi, 201), var.name)
        step = (hi - lo) / 200
        for label, mf in var.terms.items():
            con[label] = fuzz.trimf(con.universe, [mf.value - step, mf.value, mf.value + step])
        cons[var.name] = con
    rules = []
    for rule in system.rules:
        (v1, t1), (v2, t2) = rule.premises
        premise = ants[v1][t1] & ants[v2][t2]
        rules.append(ctrl.Rule(premise, [cons[v][t] for v, t in rule.conclusions]))
    sim = ctrl.ControlSystemSimulation(ctrl.ControlSystem(rules))

    def one(a, b):
        sim.input["drg"] = a
        sim.input["theta"] = b
        sim.compute()
        return sim.output

    us = _single_us(one, _inputs(30), 3)
    return {"batch_evals_per_s": 1e6 / us, "single_call_us": us,
            "note": "scikit-fuzzy control API (Mamdani-only: same table, narrow triangles at the singletons); "
                    "batch = loop of single calls"}


PEERS = {"fuzzynav": bench_fuzzynav, "pyfuzzylite": bench_pyfuzzylite, "simpful": bench_simpful,
         "scikit-fuzzy": bench_scikit_fuzzy}
MODULES = {"pyfuzzylite": "fuzzylite", "simpful": "simpful", "scikit-fuzzy": "skfuzzy.control"}


def run_peer(name: str, fll_python: str) -> dict:
    module = MODULES.get(name)
    if module:
        try:
            importlib.import_module(module)
        except ImportError as error:
            if name == "pyfuzzylite" and Path(fll_python).exists():
                done = subprocess.run([fll_python, __file__, "--only", name, "--json"], capture_output=True, text=True)
                if done.returncode == 0:
                    result = json.loads(done.stdout)[name]
                    result["note"] += f" (run in {fll_python})"
                    return result
                return {"skipped": f"failed in {fll_python}: {done.stderr.strip()[-300:]}"}
            return {"skipped": f"{module} cannot be imported here ({error})"}
    return PEERS[name]()


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    parser.add_argument("--only", choices=list(PEERS), action="append", help="time only these")
    parser.add_argument("--fll-python", default=DEFAULT_FLL_PYTHON, help="python of a venv with pyfuzzylite")
    args = parser.parse_args(argv)
    with contextlib.redirect_stdout(sys.stderr):  # peers chatter on stdout (simpful, on every call)
        results = {name: run_peer(name, args.fll_python) for name in (args.only or PEERS)}
    if args.json:
        print(json.dumps(results, indent=2))
        return 0
    base = results.get("pyfuzzylite", {}).get("batch_evals_per_s")
    print(f"Goal seeking, Table IV.1 (35 rules); batch of {N_BATCH:,}; numpy {np.__version__}")
    print(f"{'implementation':<14} {'batch evals/s':>14} {'single call':>12}  {'× pyfuzzylite batch':>20}")
    for name, r in results.items():
        if "skipped" in r:
            print(f"{name:<14} skipped: {r['skipped']}")
            continue
        ratio = f"{r['batch_evals_per_s'] / base:.1f}" if base else "-"
        print(f"{name:<14} {r['batch_evals_per_s']:>14,.0f} {r['single_call_us']:>9.1f} µs  {ratio:>20}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
