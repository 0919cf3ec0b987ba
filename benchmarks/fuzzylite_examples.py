"""Import every fuzzylite example engine and compare fuzzynav with pyfuzzylite 8 on it.

    python benchmarks/fuzzylite_examples.py --examples DIR [--examples DIR2 ...] [--json]
    FUZZYNAV_FLL_EXAMPLES=DIR1:DIR2 python benchmarks/fuzzylite_examples.py

DIR is a folder holding fuzzylite's example engines (``examples/`` of the fuzzylite and
pyfuzzylite repositories; GPL, so they are never copied into this repository): every ``*.fll``
below it is read. Run it with a Python that has both fuzzynav and pyfuzzylite (its own venv:
``pip install -e '.[fll]'``). For each engine: does fuzzynav import it; then the largest
difference from pyfuzzylite, relative to the output's range, on the rows of its ``.fld``
dataset (when there is one) and on 1,000 random inputs of which 20 % lie outside the input
ranges (up to 50 % of the range beyond either end; lock-range as written); and whether
exporting it to FLL and importing that again computes the same bit for bit. Agreement means
both, and every difference ≤ 1e-9 × range (NaN on both sides counts as equal). pyfuzzylite evaluates
activation methods other than General one row at a time, so those engines are compared row by
row there.

``--fis`` surveys the ``.fis`` files instead: each is read (MATLAB's semantics) and compared
with its ``.fll`` twin (the same engine converted by fuzzylite) on the same random inputs, the
outputs' defuzzification settings a ``.fis`` leaves to its reader taken from the twin; then
written back as ``.fis`` and read again (bit-for-bit the same outputs).
"""

from __future__ import annotations

import json
import math
import os
import sys
from dataclasses import replace
from pathlib import Path

import numpy as np

from fuzzynav.cli import Parser
from fuzzynav.errors import InputError
from fuzzynav.fuzzy.engine import Engine
from fuzzynav.fuzzy.io import from_fll, to_fll
from fuzzynav.fuzzy.io.fis import from_fis, to_fis
from fuzzynav.fuzzy.io.fll import from_fll_engine

TOLERANCE = 1e-9


def _theirs(text: str, X: np.ndarray) -> np.ndarray:
    import fuzzylite as fl

    engine = fl.FllImporter().from_string(text)
    rowwise = any(type(b.activation).__name__ != "General" for b in engine.rule_blocks)
    if not rowwise:
        engine.input_values = X
        engine.process()
        return np.atleast_2d(engine.output_values).reshape(len(X), -1)
    out = []
    for row in X:  # scalar values: pyfuzzylite's Proportional activation fails on a one-row array
        for variable, value in zip(engine.input_variables, row):
            variable.value = float(value)
        engine.process()
        out.append([float(np.asarray(v.value).ravel()[-1]) for v in engine.output_variables])
    return np.array(out)


def _scale(system) -> np.ndarray:
    widths = []
    for v in system.outputs:
        lo, hi = v.universe
        widths.append(hi - lo if math.isfinite(hi - lo) and hi > lo else 1.0)
    return np.array(widths)


def _difference(ours: np.ndarray, theirs: np.ndarray, scale: np.ndarray) -> float:
    both_nan = np.isnan(ours) & np.isnan(theirs)
    same_inf = np.isinf(ours) & (ours == theirs)
    diff = np.where(both_nan | same_inf, 0.0, np.abs(ours - theirs)) / scale
    return float(np.nan_to_num(diff, nan=np.inf).max(initial=0.0))


def _random_inputs(system, n: int, seed: int) -> np.ndarray:
    rng = np.random.default_rng(seed)
    cols = []
    for v in system.inputs:
        lo, hi = v.universe
        if not (math.isfinite(lo) and math.isfinite(hi)) or hi <= lo:
            lo, hi = -1.0, 1.0
        width = hi - lo
        x = rng.uniform(lo, hi, n)
        outside = rng.random(n) < 0.2
        side = rng.random(n) < 0.5
        beyond = rng.uniform(0.0, 0.5 * width, n)
        cols.append(np.where(outside, np.where(side, lo - beyond, hi + beyond), x))
    return np.column_stack(cols)


def _fld_rows(path: Path, system) -> np.ndarray | None:
    if not path.exists():
        return None
    lines = path.read_text().splitlines()
    header = lines[0].split()
    index = [header.index(name) for name in system.input_names]
    rows = [[float(v) for v in line.split()] for line in lines[1:] if line.strip()]
    return np.array(rows)[:, index]


def check(path: Path) -> dict:
    text = path.read_text()
    try:
        system = from_fll(text, source=str(path))
    except InputError as error:
        return {"imported": False, "error": str(error)}
    result = {"imported": True, "kind": type(system).__name__}
    scale = _scale(system)
    for name, X in (("fld", _fld_rows(path.with_suffix(".fld"), system)),
                    ("random", _random_inputs(system, 1000, 0))):
        if X is None:
            continue
        result[f"{name}_rows"] = len(X)
        result[f"{name}_max_rel_diff"] = _difference(system.evaluate(X), _theirs(text, X), scale)
        if name == "random":  # FLL export and re-import computes the same, bit for bit
            again = from_fll(to_fll(system), source="re-exported")
            result["round_trip"] = bool(np.array_equal(again.evaluate(X), system.evaluate(X), equal_nan=True))
    result["agrees"] = result["round_trip"] and all(v <= TOLERANCE for k, v in result.items() if k.endswith("max_rel_diff"))
    return result


def _with_settings_of(engine, twin):
    """``engine`` with each output's defuzzifier, aggregation and default taken from ``twin``: the
    settings a ``.fis`` file leaves to the program reading it (resolution, sampling, what an
    output is when no rule fires, a Sugeno aggregation MATLAB ignores)."""
    outputs = [replace(v, defuzzifier=t.defuzzifier, aggregation=t.aggregation, default=t.default)
               for v, t in zip(engine.outputs, twin.outputs)]
    return Engine(engine.inputs, outputs, engine.blocks, name=engine.name)


def check_fis(path: Path) -> dict:
    """A ``.fis`` file read the MATLAB way: against its ``.fll`` twin (with the twin's output
    settings, see :func:`_with_settings_of`), and written back as ``.fis`` and read again (the
    same results bit for bit)."""
    twin = path.with_suffix(".fll")
    try:
        matlab = from_fis(path.read_text(), source=str(path))
    except InputError as error:
        return {"imported": False, "error": str(error)}
    result = {"imported": True}
    X = _random_inputs(matlab, 1000, 0)
    again = from_fis(to_fis(matlab), source="re-exported")
    result["round_trip"] = bool(np.array_equal(again.evaluate(X), matlab.evaluate(X), equal_nan=True))
    if twin.exists():
        reference = from_fll(twin.read_text(), source=str(twin))
        if reference.output_names == matlab.output_names and reference.input_names == matlab.input_names:
            reference = from_fll_engine(twin.read_text(), source=str(twin))
            ours = _with_settings_of(matlab, reference)
            result["fll_max_rel_diff"] = _difference(ours.evaluate(X), reference.evaluate(X), _scale(reference))
        else:
            result["fll_twin"] = "different variables"
    result["agrees"] = result["round_trip"] and result.get("fll_max_rel_diff", 0.0) <= TOLERANCE
    return result


def main(argv=None) -> int:
    parser = Parser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--examples", action="append", metavar="DIR",
                        help="folder of fuzzylite example engines (repeat; default $FUZZYNAV_FLL_EXAMPLES, ':'-separated)")
    parser.add_argument("--fis", action="store_true", help="survey the .fis files instead (against their .fll twins)")
    parser.add_argument("--json", action="store_true", help="one JSON object per engine, then the counts")
    args = parser.parse_args(argv)
    folders = args.examples or [d for d in os.environ.get("FUZZYNAV_FLL_EXAMPLES", "").split(os.pathsep) if d]
    if not folders:
        parser.error("give --examples DIR (or set FUZZYNAV_FLL_EXAMPLES)")
    files = sorted(p for d in folders for p in Path(d).rglob("*.fll"))
    if args.fis:
        files = sorted(p for d in folders for p in Path(d).rglob("*.fis"))
    results = {}
    for path in files:
        try:
            results[str(path)] = check_fis(path) if args.fis else check(path)
        except Exception as error:  # a crash is a finding to report, not a reason to stop the survey
            results[str(path)] = {"imported": True, "agrees": False, "error": f"{type(error).__name__}: {error}"}
        r = results[str(path)]
        if args.json:
            print(json.dumps({"file": str(path), **r}))
        elif not r.get("agrees"):
            print(f"{path}: {r.get('error') or r}", file=sys.stderr)
    counts = {"files": len(files), "imported": sum(r["imported"] for r in results.values()),
              "agree": sum(bool(r.get("agrees")) for r in results.values())}
    print(json.dumps(counts))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
