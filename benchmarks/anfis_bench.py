"""ANFIS quality and speed against its peers, measured in one run (thesis §V.3.5, Fig V.23).

Task: the ANFIS tracker's map α = (π/4)·tanh(1.5·θ_er), 100 training points evenly spaced on
[−π, π], test RMSE on 1,000 fresh points drawn uniformly (seeded), 5 generalized-bell MFs.
Goals: test RMSE ≤ 1e-4 rad, training ≤ 0.1 s, one prediction ≤ 5 µs.

Contenders (training time = median of the fits, prediction = median per-call time of the scalar path):

- ``fuzzynav`` — :class:`fuzzynav.learn.anfis.ANFIS` (bell, 200 epochs, hybrid learning), ``predict_one``;
- ``sklearn-mlp`` — scikit-learn's MLPRegressor (10, 10) tanh, lbfgs, through
  :func:`fuzzynav.learn.neural.fit_inverse_model`; latency of the folded NumPy pass and of
  ``MLPRegressor.predict`` on one sample;
- ``anfis-toolbox`` — ``ANFISRegressor(n_mfs=5, mf_type="bell", epochs=200)``, hybrid optimiser;
- ``xanfis`` — ``AnfisRegressor(num_rules=5, mf_class="GBell")``, its default Adam + least-squares.

The two peers run in their own virtual environment (``--peer-python PATH``, or the environment
variable ``FUZZYNAV_ANFIS_PEER_PYTHON``: xanfis pins numpy ≤ 1.26 and pulls in torch), each in a
subprocess that receives the same data as JSON; a peer that is not installed, or no interpreter
given, is reported, not faked. ``python benchmarks/anfis_bench.py [--json] [--repeats N] [--peer-python PATH]``.
"""

from __future__ import annotations

import json
import math
import os
import statistics
import subprocess
import sys
import time
import warnings

import numpy as np

from fuzzynav.cli import Parser

GOALS = {"test_rmse_rad": 1e-4, "train_s": 0.1, "predict_us": 5.0}
PEER_PYTHON_VARIABLE = "FUZZYNAV_ANFIS_PEER_PYTHON"  # the peers' interpreter, unless --peer-python

PEER_CODE = r'''
import json, statistics, sys, time, warnings
import numpy as np
warnings.filterwarnings("ignore")
data = json.load(sys.stdin)
X, y, Xt, yt = (np.array(data[k]) for k in ("X", "y", "Xt", "yt"))
name, repeats = data["peer"], data["repeats"]
def latency(f, x, n):
    blocks = []
    for _ in range(5):
        t = time.perf_counter()
        for _ in range(n):
            f(x)
        blocks.append((time.perf_counter() - t) / n * 1e6)
    return statistics.median(blocks)
if name == "anfis-toolbox":
    import anfis_toolbox
    from anfis_toolbox import ANFISRegressor
    make = lambda: ANFISRegressor(n_mfs=5, mf_type="bell", epochs=200, optimizer="hybrid", random_state=0,
                                  verbose=False)
    version = anfis_toolbox.__version__ if hasattr(anfis_toolbox, "__version__") else "?"
else:
    import xanfis, torch
    torch.set_num_threads(1)
    from xanfis import AnfisRegressor
    make = lambda: AnfisRegressor(num_rules=5, mf_class="GBell", verbose=False, seed=42)
    version = getattr(xanfis, "__version__", "?")
times, model = [], None
for _ in range(repeats):
    model = make()
    t = time.perf_counter()
    model.fit(X, y)
    times.append(time.perf_counter() - t)
pred = np.asarray(model.predict(Xt), dtype=float).ravel()
one = Xt[:1]
print(json.dumps({"version": version, "train_s": statistics.median(times),
                  "test_rmse_rad": float(np.sqrt(np.mean((pred - yt) ** 2))),
                  "predict_us": latency(model.predict, one, 200), "numpy": np.__version__}))
'''


def target(theta):
    return math.pi / 4 * np.tanh(1.5 * theta)


def latency_us(f, x, n: int) -> float:
    """Median over 5 blocks of the per-call time of ``f(x)``, in µs."""
    blocks = []
    for _ in range(5):
        start = time.perf_counter()
        for _ in range(n):
            f(x)
        blocks.append((time.perf_counter() - start) / n * 1e6)
    return statistics.median(blocks)


def timed_fits(make, X, y, repeats: int):
    times, model = [], None
    for _ in range(repeats):
        start = time.perf_counter()
        model = make(X, y)
        times.append(time.perf_counter() - start)
    return model, statistics.median(times)


def rmse(pred, truth) -> float:
    return float(np.sqrt(np.mean((np.asarray(pred).ravel() - truth) ** 2)))


def bench_fuzzynav(data, repeats: int) -> dict:
    from fuzzynav.learn.anfis import ANFIS

    X, y, Xt, yt = data
    model, train_s = timed_fits(lambda a, b: ANFIS(n_mfs=5, mf="bell", epochs=200).fit(a, b), X, y, repeats)
    return {"name": "fuzzynav ANFIS (bell, 200 epochs)", "train_s": train_s, "test_rmse_rad": rmse(model.predict(Xt), yt),
            "predict_us": latency_us(model.predict_one, 0.3, 20000),
            "train_rmse_rad": model.history_["train_rmse"][model.best_epoch_], "epochs": model.n_epochs_}


def bench_mlp(data, repeats: int) -> dict:
    from sklearn.exceptions import ConvergenceWarning
    from sklearn.neural_network import MLPRegressor

    from fuzzynav.learn.neural import fit_inverse_model

    X, y, Xt, yt = data
    model, train_s = timed_fits(lambda a, b: fit_inverse_model(a, b, (10, 10)), X, y, repeats)
    raw = MLPRegressor(hidden_layer_sizes=(10, 10), activation="tanh", solver="lbfgs", max_iter=5000, random_state=0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ConvergenceWarning)
        raw.fit(X, y)
    return {"name": "scikit-learn MLP (10,10) tanh lbfgs", "train_s": train_s, "test_rmse_rad": rmse(model.predict(Xt), yt),
            "predict_us": latency_us(model.predict_one, 0.3, 20000),
            "sklearn_predict_us": latency_us(raw.predict, Xt[:1], 500)}


def bench_peer(peer: str, python: str, data, repeats: int) -> dict:
    X, y, Xt, yt = data
    payload = json.dumps({"peer": peer, "repeats": repeats, "X": X.tolist(), "y": y.tolist(), "Xt": Xt.tolist(),
                          "yt": yt.tolist()})
    try:
        done = subprocess.run([python, "-c", PEER_CODE], input=payload, capture_output=True, text=True, timeout=1800)
    except (OSError, subprocess.TimeoutExpired) as error:
        return {"name": peer, "error": f"could not run {python}: {error}"}
    if done.returncode != 0:
        return {"name": peer, "error": done.stderr.strip().splitlines()[-1] if done.stderr.strip() else "failed"}
    result = json.loads(done.stdout.strip().splitlines()[-1])
    label = {"anfis-toolbox": "anfis-toolbox (bell, 200 epochs, hybrid)",
             "xanfis": "xanfis AnfisRegressor (GBell, defaults)"}[peer]
    return {"name": f"{label} {result.pop('version')}", **result}


def main(argv=None) -> int:
    parser = Parser(description=__doc__.splitlines()[0])
    parser.add_argument("--json", action="store_true", help="print the results as JSON")
    parser.add_argument("--repeats", type=int, default=5, help="fits per contender (median time); peers use 3 / 1")
    parser.add_argument("--peer-python", default=os.environ.get(PEER_PYTHON_VARIABLE),
                        help=f"interpreter of the peers' venv (default: ${PEER_PYTHON_VARIABLE}; none: no peers)")
    parser.add_argument("--no-peers", action="store_true", help="skip anfis-toolbox and xanfis")
    args = parser.parse_args(argv)

    X = np.linspace(-math.pi, math.pi, 100)[:, None]
    Xt = np.random.default_rng(2024).uniform(-math.pi, math.pi, (1000, 1))
    data = (X, target(X[:, 0]), Xt, target(Xt[:, 0]))
    results = [bench_fuzzynav(data, args.repeats), bench_mlp(data, args.repeats)]
    if not args.no_peers:
        for peer, repeats in (("anfis-toolbox", max(1, min(3, args.repeats))), ("xanfis", 1)):
            results.append(bench_peer(peer, args.peer_python, data, repeats) if args.peer_python else
                           {"name": peer, "error": f"not run: give --peer-python or ${PEER_PYTHON_VARIABLE}"})
    ours = results[0]
    verdict = {key: ours[key] <= goal for key, goal in GOALS.items()}
    report = {"task": "alpha = (pi/4) tanh(1.5 theta), 100 train points on [-pi, pi], 1000 test points, 5 bell MFs",
              "numpy": np.__version__, "python": sys.version.split()[0], "goals": GOALS, "fuzzynav_meets_goals": verdict,
              "results": results}
    if args.json:
        print(json.dumps(report, indent=2))
        return 0
    print(f"{'contender':52s} {'test RMSE rad':>14s} {'train s':>9s} {'predict µs':>11s}")
    for r in results:
        if "error" in r:
            print(f"{r['name']:52s} not run: {r['error']}")
            continue
        extra = f"  (sklearn predict {r['sklearn_predict_us']:.0f} µs)" if "sklearn_predict_us" in r else ""
        print(f"{r['name']:52s} {r['test_rmse_rad']:14.2e} {r['train_s']:9.3f} {r['predict_us']:11.2f}{extra}")
    print("goals (fuzzynav): " + ", ".join(f"{k} <= {v:g}: {'yes' if verdict[k] else 'NO'}" for k, v in GOALS.items()))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
