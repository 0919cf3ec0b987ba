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
peer with ``--fll-python PYTHON`` (or ``$FUZZYNAV_FLL_PYTHON``), e.g. the ``.venv-fll`` that
``.ci/run`` creates (``python -m venv .venv-fll && .venv-fll/bin/pip install -e '.[fll]'``).

``--examples DIR`` (or ``$FUZZYNAV_FLL_EXAMPLES``; fuzzylite's ``examples/``, GPL, read in place)
times instead fuzzynav against pyfuzzylite on fuzzylite's Mamdani examples (every output
defuzzified by an integral method) and first-order Takagi–Sugeno examples (linear conclusions):
a batch of 10,000 random inputs each, median of 5 runs, the two engines interleaved, in the
Python given by ``--fll-python`` (which must have both packages). ``--clock cpu`` times them by
the CPU time of the process instead of the wall clock: steadier on a machine shared with other
work, where a wall-clock run mostly measures who was descheduled. ``--calls K`` makes each sample
the mean of K calls in a row (the throughput of repeated batches; with one call a sample, each
engine starts right after the other's, its data and code out of cache). Each engine's line says when it
is not evaluated by the fused kernel (``Engine.fallback``: why), and the count is printed.
"""

from __future__ import annotations

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

from fuzzynav.cli import Parser
from fuzzynav.fuzzy.io import to_fll
from fuzzynav.fuzzy.systems import goal_seeking

N_BATCH = 100_000
DEFAULT_FLL_PYTHON = os.environ.get("FUZZYNAV_FLL_PYTHON")
N_EXAMPLE_BATCH = 10_000


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


def run_peer(name: str, fll_python: str | None) -> dict:
    module = MODULES.get(name)
    if module:
        try:
            importlib.import_module(module)
        except ImportError as error:
            if name == "pyfuzzylite" and fll_python and Path(fll_python).exists():
                done = subprocess.run([fll_python, __file__, "--only", name, "--json"], capture_output=True, text=True)
                if done.returncode == 0:
                    result = json.loads(done.stdout)[name]
                    result["note"] += f" (run in {fll_python})"
                    return result
                return {"skipped": f"failed in {fll_python}: {done.stderr.strip()[-300:]}"}
            return {"skipped": f"{module} cannot be imported here ({error})"}
    return PEERS[name]()


def _example_kind(engine) -> str | None:
    """``mamdani`` (every output integral-defuzzified), ``ts1`` (a linear conclusion) or None."""
    from fuzzynav.fuzzy.membership import Linear

    outputs = engine.outputs
    if all(v.defuzzifier is not None and v.defuzzifier.integral for v in outputs):
        return "mamdani"
    if any(isinstance(mf, Linear) for v in outputs for mf in v.terms.values()):
        return "ts1"
    return None


CLOCKS = {"wall": time.perf_counter, "cpu": time.process_time}


def bench_examples(folders: list[str], clock: str = "wall", calls: int = 1) -> dict:
    """fuzzynav / pyfuzzylite batch time on every Mamdani and TS1 example engine under ``folders``,
    by the ``clock`` of :data:`CLOCKS`: each sample the mean of ``calls`` calls in a row."""
    now = CLOCKS[clock]
    import fuzzylite as fl

    from fuzzynav.fuzzy.io.fll import from_fll_engine

    rows = {}
    for path in sorted(p for d in folders for p in Path(d).rglob("*.fll")):
        text = path.read_text()
        ours = from_fll_engine(text, source=str(path))
        kind = _example_kind(ours)
        theirs = fl.FllImporter().from_string(text)
        if kind is None or any(type(b.activation).__name__ != "General" for b in theirs.rule_blocks):
            continue
        rng = np.random.default_rng(0)
        X = np.column_stack([rng.uniform(v.minimum, v.maximum, N_EXAMPLE_BATCH) if np.isfinite(v.maximum - v.minimum)
                             else rng.uniform(-1, 1, N_EXAMPLE_BATCH) for v in ours.inputs])

        def process(batch, engine=theirs):
            engine.input_values = batch
            engine.process()
        times = {"fuzzynav": [], "pyfuzzylite": []}
        for _ in range(5):  # interleaved: both see the same machine load
            for name, run in (("fuzzynav", lambda ours=ours, X=X: ours.evaluate(X)), ("pyfuzzylite", lambda X=X: process(X))):
                t0 = now()
                for _ in range(calls):
                    run()
                times[name].append((now() - t0) / calls)
        ours_s, theirs_s = statistics.median(times["fuzzynav"]), statistics.median(times["pyfuzzylite"])
        rows[str(path)] = {"kind": kind, "fuzzynav_ms": 1e3 * ours_s, "pyfuzzylite_ms": 1e3 * theirs_s,
                           "ratio": theirs_s / ours_s, "path": ours.fallback or "fused"}
    return rows


def _print_examples(rows: dict, clock: str, calls: int) -> None:
    per_sample = "one call a sample" if calls == 1 else f"each sample the mean of {calls} calls in a row"
    print(f"fuzzylite examples, batch of {N_EXAMPLE_BATCH:,} random inputs, median of 5 (interleaved; {per_sample}), "
          f"{clock} clock")
    print(f"{'kind':<8} {'fuzzynav ms':>12} {'pyfuzzylite ms':>15} {'ratio':>7}  engine")
    for path, r in sorted(rows.items(), key=lambda item: (item[1]["kind"], item[0])):
        print(f"{r['kind']:<8} {r['fuzzynav_ms']:>12.2f} {r['pyfuzzylite_ms']:>15.2f} {r['ratio']:>7.1f}  {path}"
              + ("" if r["path"] == "fused" else f"  [NumPy path: {r['path']}]"))
    fallbacks = sum(r["path"] != "fused" for r in rows.values())
    print(f"{len(rows) - fallbacks} engines evaluated by the fused kernel, {fallbacks} by the NumPy path")
    for kind in ("mamdani", "ts1"):
        ratios = [r["ratio"] for r in rows.values() if r["kind"] == kind]
        if ratios:
            print(f"{kind}: {len(ratios)} engines, ratio median {statistics.median(ratios):.1f}, min {min(ratios):.1f}, "
                  f"max {max(ratios):.1f}, geometric mean {float(np.exp(np.mean(np.log(ratios)))):.1f}")


def main(argv=None) -> int:
    parser = Parser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    parser.add_argument("--only", choices=list(PEERS), action="append", help="time only these")
    parser.add_argument("--fll-python", default=DEFAULT_FLL_PYTHON,
                        help="python of a venv with pyfuzzylite (default $FUZZYNAV_FLL_PYTHON)")
    parser.add_argument("--examples", action="append", metavar="DIR",
                        help="time fuzzylite's Mamdani and TS1 example engines under DIR instead "
                             "(default $FUZZYNAV_FLL_EXAMPLES, ':'-separated)")
    parser.add_argument("--clock", choices=list(CLOCKS), default="wall",
                        help="time the examples by the wall clock (default) or the process's CPU time")
    parser.add_argument("--calls", type=int, default=1, metavar="K",
                        help="examples: time K calls in a row per sample (default 1: each sample one call, right "
                             "after the other engine's; K > 1 measures the throughput of repeated batches)")
    args = parser.parse_args(argv)
    folders = args.examples or [d for d in os.environ.get("FUZZYNAV_FLL_EXAMPLES", "").split(os.pathsep) if d]
    if folders:
        try:
            importlib.import_module("fuzzylite")
        except ImportError:
            if not args.fll_python:
                parser.error("pyfuzzylite is not importable here: give --fll-python (a venv with fuzzynav and "
                             "pyfuzzylite)")
            command = [args.fll_python, __file__, "--clock", args.clock, "--calls", str(args.calls),
                       *sum((["--examples", d] for d in folders), [])]
            return subprocess.run(command + (["--json"] if args.json else [])).returncode
        if args.calls < 1:
            parser.error("--calls must be at least 1")
        rows = bench_examples(folders, args.clock, args.calls)
        print(json.dumps(rows, indent=2)) if args.json else _print_examples(rows, args.clock, args.calls)
        return 0
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
