"""A corpus of hostile inputs for every door the first review left open: the Gymnasium
environments, the Python API, unbounded counts, fuzzy files answering nonsense, tampered campaign
and checkpoint folders, scenarios whose own robot decides reachability, ASCII terminals.

Each :class:`~tests.validation.hostile_cases.Case` writes its files, runs a command line or Python
code (``d`` is its folder; the names of :data:`PRELUDE` are bound) and says what must happen:
exit 2 / an ``InputError`` whose message holds ``expect``, or (``status=0``) success with
``expect`` in the output. Used by ``test_hostile_corpus.py`` and ``tests/validation/hostile_subprocesses.py``.
"""

from __future__ import annotations

import json
from pathlib import Path

from tests.validation.hostile_cases import Case

GYM_IDS = ("fuzzynav/GoalSeeking-v0", "fuzzynav/ObstacleAvoidance-v0", "fuzzynav/WallFollowing-v0",
           "fuzzynav/PathTracking-v0")

PRELUDE = """
import json
from pathlib import Path
import numpy as np
import gymnasium
import fuzzynav
import fuzzynav.gym
from fuzzynav.errors import InputError

def step_env(env_id, action, **options):
    env = gymnasium.make(env_id, **options)
    env.reset(seed=0)
    env.step(action)

def step_vector(env_id, batch, n=3, **options):
    env = gymnasium.make_vec(env_id, num_envs=n, vectorization_mode="vector_entry_point", **options)
    env.reset(seed=0)
    env.step(batch)

def campaign(d, tamper=None, fis=None):
    # a one-run campaign into d/out, then tamper with it and resume it
    from fuzzynav.cli import main
    out = d / "out"
    args = ["bench", "circles:1", "--controllers", "goal-seeking", "--out", str(out), "--quiet", "--gallery", "0"]
    assert main(args) == 0
    if tamper is not None:
        tamper(out)
    if fis is not None:
        (out / "fis.json").write_bytes(fis)
    raise SystemExit(main(args + ["--resume"]))

def edit_row(out, raw=None, **changes):
    # rewrite runs.jsonl as its first row with changes; raw: bytes written in place of the world's name
    line = json.loads((out / "runs.jsonl").read_text().splitlines()[0])
    line.update(changes)
    text = (json.dumps(line) + "\\n").encode()
    if raw is not None:
        text = text.replace(json.dumps(line["world"]).encode(), raw)
    (out / "runs.jsonl").write_bytes(text)

def trained_checkpoint(d, change):
    # a real q-goal checkpoint (20 episodes, one a batch: the thesis' protocol), edited by change(document),
    # then resumed
    from fuzzynav.cli import main
    out = d / "q.json"
    assert main(["train", "q-goal", "--episodes", "20", "--quiet", "--out", str(out)]) == 0
    path = d / "q.json.steering.checkpoint.json"
    document = json.loads(path.read_text())
    change(document)
    path.write_text(json.dumps(document))
    raise SystemExit(main(["train", "q-goal", "--episodes", "40", "--quiet", "--resume", "--out", str(out)]))

def locked_bench(d):
    # a second bench on an --out whose lock is held
    from fuzzynav.bench.lock import campaign_lock
    from fuzzynav.cli import main
    with campaign_lock(d / "out"):
        code = main(["bench", "circles:1", "--controllers", "goal-seeking", "--out", str(d / "out"), "--quiet"])
    raise SystemExit(code)

def barn_world(d, name="world_1"):
    # the BARN world of tests/data/barn (MIT licence) copied as d/NAME.world; its path file is the case's
    import shutil
    target = d / f"{name}.world"
    target.parent.mkdir(parents=True, exist_ok=True)
    shutil.copy(BARN_WORLD, target)
    return target

def import_barn(d, *worlds):
    from fuzzynav.cli import main
    raise SystemExit(main(["import", "barn", *map(str, worlds), "--out", str(d / "o")]))

def tuned_then_resumed(d, tamper):
    # a tiny tuning run, its checkpoint's arrays edited by tamper(dict of arrays), then --resume
    from fuzzynav.cli import main
    args = ["tune", "goal-seeking:gsb", "--worlds", "circles:2", "--budget", "8", "--population", "2",
            "--validation", "none", "--out", str(d / "a.yaml"), "--quiet"]
    assert main(args) == 0
    path = d / "a.yaml.tune.npz"
    with np.load(path) as data:
        arrays = dict(data)
    tamper(arrays)
    np.savez(path, **arrays)
    raise SystemExit(main(args[:5] + ["12"] + args[6:] + ["--resume"]))

def edited_system(d, edit):
    # the goal-seeking system as a JSON document, edited by edit(document), loaded back
    from fuzzynav.fuzzy.io.document import to_document
    document = to_document(fuzzynav.thesis_system("goal-seeking"))
    edit(document)
    (d / "edited.json").write_text(json.dumps(document))
    fuzzynav.load_fuzzy_system(d / "edited.json")

def edited_model(d, train, edit, run):
    # a model trained by `fuzzynav train TRAIN... --out d/m.json`, edited by edit(document) into
    # d/x.json, then `fuzzynav RUN... x.json`
    from fuzzynav.cli import main
    assert main(["train", *train, "--out", str(d / "m.json")]) == 0
    document = json.loads((d / "m.json").read_text())
    edit(document)
    (d / "x.json").write_text(json.dumps(document))
    raise SystemExit(main([*run, str(d / "x.json")]))

def fuzzy_model(d, kind, **keys):
    # a learned fuzzy model of KIND holding the goal-seeking system and KEYS, run on fig-IV-23
    from fuzzynav.cli import main
    from fuzzynav.fuzzy.io.document import to_document
    document = {"kind": kind, **to_document(fuzzynav.thesis_system("goal-seeking")), **keys}
    (d / "m.json").write_text(json.dumps(document))
    raise SystemExit(main(["run", "fig-IV-23", "--model", str(d / "m.json")]))

def ascii_terminal(argv):
    # the command line with stdout and stderr encoded as ASCII; prints what it wrote
    import io, sys
    from fuzzynav.cli import main
    real_out, real_err = sys.stdout, sys.stderr
    sys.stdout = sys.stderr = io.TextIOWrapper(io.BytesIO(), encoding="ascii")
    try:
        code = main(argv)
        sys.stdout.flush()
        text = sys.stdout.buffer.getvalue().decode("ascii")
    finally:
        sys.stdout, sys.stderr = real_out, real_err
    print(text, file=sys.stderr if code else sys.stdout)
    raise SystemExit(code)
"""
# the BARN world the import cases copy (tests/data/barn, MIT licence), by absolute path so that the
# prelude also runs in a subprocess whose folder is the case's (tests/validation/hostile_subprocesses.py)
PRELUDE += f"BARN_WORLD = {str(Path(__file__).resolve().parent.parent / 'data' / 'barn' / 'world_0.world')!r}\n"

_FLL = """Engine: t
InputVariable: x
  enabled: true
  range: 0.000 1.000
  term: lo Triangle 0 0 1
  term: hi Triangle 0 1 1
OutputVariable: v
  enabled: true
  range: 0 1
  aggregation: Maximum
  defuzzifier: Centroid 100
  default: nan
  term: lo Triangle 0 0 1
  term: hi Triangle 0 1 1
RuleBlock: rb
  enabled: true
  conjunction: Minimum
  disjunction: Maximum
  implication: Minimum
  activation: General
  rule: if x is lo then v is lo
  rule: if x is hi then v is hi
"""
_HI = "term: hi Triangle 0 1 1\nRuleBlock"
_TS = (_FLL.replace("  aggregation: Maximum\n  defuzzifier: Centroid 100",
                    "  aggregation: none\n  defuzzifier: WeightedAverage")
       .replace("term: lo Triangle 0 0 1\n  " + _HI, "term: lo Function FORMULA\n  term: hi Constant 1\nRuleBlock")
       .replace("implication: Minimum", "implication: none"))
_FIS = """[System]
Name='t'
Type='mamdani'
NumInputs=1
NumOutputs=1
NumRules=2
AndMethod='min'
OrMethod='max'
ImpMethod='min'
AggMethod='max'
DefuzzMethod='centroid'

[Input1]
Name='x'
Range=[0 1]
NumMFs=2
MF1='lo':'trimf',[0 0 1]
MF2='hi':'trimf',[0 1 1]

[Output1]
Name='v'
Range=OUTRANGE
NumMFs=2
MF1='lo':'trimf',[0 0 1]
MF2='hi':'trimf',[0 1 1]

[Rules]
1, 1 (1) : 1
2, 2 (WEIGHT) : 1
"""


def _fis(out_range: str = "[0 1]", weight: str = "1") -> str:
    return _FIS.replace("OUTRANGE", out_range).replace("WEIGHT", weight)


def _sugeno_fis(out_range: str) -> str:
    """The same system as :func:`_fis` written as a Sugeno one, its output two constants."""
    text = _fis(out_range)
    for old, new in (("'mamdani'", "'sugeno'"), ("AndMethod='min'", "AndMethod='prod'"),
                     ("ImpMethod='min'", "ImpMethod='prod'"), ("AggMethod='max'", "AggMethod='sum'"),
                     ("DefuzzMethod='centroid'", "DefuzzMethod='wtaver'")):
        text = text.replace(old, new)
    head, _, rules = text.rpartition("MF1='lo':'trimf',[0 0 1]\nMF2='hi':'trimf',[0 1 1]")
    return head + "MF1='lo':'constant',[0.2]\nMF2='hi':'constant',[0.8]" + rules


def _fll(old: str, new: str) -> str:
    assert old in _FLL
    return _FLL.replace(old, new)


def _eval(name: str) -> tuple:
    return ("fis", "eval", "{d}/" + name, "--input", "x=0.3")


ROBOT = "robot: {x: 5, y: 5}\n"
RUN = ("run", "{d}/s.yaml", "--controller", "goal-seeking", "--json")


GYM = [
    *[Case(f"gym-nan-action-{env.split('/')[1]}",
           python=f"step_env({env!r}, np.full({1 if 'Path' in env else 2}, np.nan, dtype=np.float32))", expect="action: must be finite")
      for env in GYM_IDS],
    *[Case(f"gym-vector-nan-action-{env.split('/')[1]}",
           python=f"step_vector({env!r}, np.full((3, {1 if 'Path' in env else 2}), np.nan, dtype=np.float32))",
           expect="actions[0]: must be finite") for env in GYM_IDS],
    Case("gym-family-with-count", python="gymnasium.make('fuzzynav/GoalSeeking-v0', worlds='mixed:3')",
         expect="a family's size and seed are the n_worlds and world_seed arguments (worlds='mixed')"),
    Case("gym-inf-action", python="step_env('fuzzynav/GoalSeeking-v0', [np.inf, 0.0])", expect="action: must be finite"),
    Case("gym-discrete-minus-one", python="step_env('fuzzynav/GoalSeeking-v0', -1, actions='discrete')",
         expect="action: must be in [0, 8]"),
    Case("gym-discrete-float", python="step_env('fuzzynav/GoalSeeking-v0', 2.7, actions='discrete')",
         expect="action: must be an integer index"),
    Case("gym-discrete-too-large", python="step_env('fuzzynav/ObstacleAvoidance-v0', 9, actions='discrete')",
         expect="action: must be in [0, 8]"),
    Case("gym-action-shape-3", python="step_env('fuzzynav/GoalSeeking-v0', np.zeros(3))",
         expect="action: must be an array of real numbers of shape (2,)"),
    Case("gym-action-shape-2x2", python="step_env('fuzzynav/GoalSeeking-v0', np.zeros((2, 2)))",
         expect="action: must be an array of real numbers of shape (2,)"),
    Case("gym-action-string", python="step_env('fuzzynav/GoalSeeking-v0', 'left')",
         expect="action: must be an array of real numbers"),
    Case("gym-vector-discrete-out-of-range",
         python="step_vector('fuzzynav/GoalSeeking-v0', np.array([0, 1, 99]), actions='discrete')",
         expect="actions[2]: must be in [0, 8]"),
    Case("gym-n-worlds-1e9", python="gymnasium.make('fuzzynav/ObstacleAvoidance-v0', worlds='circles', n_worlds=10**9)",
         expect="n_worlds: must be an integer in [1, 100000]"),
    Case("gym-decision-steps-1e9", python="gymnasium.make('fuzzynav/GoalSeeking-v0', decision_steps=10**9)",
         expect="decision_steps: must be an integer in [1, 1000]"),
    Case("gym-max-steps-float", python="gymnasium.make('fuzzynav/GoalSeeking-v0', max_steps=2.5)",
         expect="max_steps: must be an integer"),
    Case("gym-world-seed-negative",
         python="gymnasium.make('fuzzynav/ObstacleAvoidance-v0', worlds='circles', world_seed=-1)",
         expect="world_seed: must be an integer in [0,"),
    Case("gym-num-envs-1e9", python="step_vector('fuzzynav/GoalSeeking-v0', None, n=10**9)",
         expect="num_envs: must be an integer in [1, 100000]"),
    Case("gym-params-dict", python="gymnasium.make('fuzzynav/GoalSeeking-v0', params={'radius': 1})",
         expect="params: must be a TricycleParams"),
    Case("gym-reset-seed-negative", python="gymnasium.make('fuzzynav/GoalSeeking-v0').reset(seed=-1)",
         expect="seed: must be an integer in [0,"),
    Case("gym-reset-scenario-number", python="gymnasium.make('fuzzynav/GoalSeeking-v0').reset(options={'scenario': 5})",
         expect="scenario: must be a file name"),
    Case("gym-worlds-list", python="gymnasium.make('fuzzynav/GoalSeeking-v0', worlds=['circles'])",
         expect="worlds: must be a string"),
    Case("gym-unknown-option", python="gymnasium.make('fuzzynav/GoalSeeking-v0', n_world=3)",
         expect="unknown key 'n_world' (did you mean 'n_worlds'?)"),
    Case("gym-vector-seed-list-text",
         python="gymnasium.make_vec('fuzzynav/GoalSeeking-v0', num_envs=2, vectorization_mode='vector_entry_point')"
                ".reset(seed=['a', 'b'])", expect="seed[0]: must be an integer"),
    Case("gym-vector-scenarios-number",
         python="gymnasium.make_vec('fuzzynav/GoalSeeking-v0', num_envs=2, vectorization_mode='vector_entry_point')"
                ".reset(options={'scenarios': 5})", expect="scenarios: must be a list"),
    Case("gym-clipped-action-ok", python="step_env('fuzzynav/GoalSeeking-v0', np.array([5.0, -7.0]))\nprint('clipped')",
         status=0, expect="clipped"),
]

_SCENARIO, _CONTROLLER = "fuzzynav.load_scenario('example-goal')", "fuzzynav.make_controller('goal-seeking')"

API = [
    Case("api-run-episode-none", python=f"fuzzynav.run_episode({_SCENARIO}, None)", expect="controller: must be a controller"),
    Case("api-run-episode-dict", python=f"fuzzynav.run_episode({_SCENARIO}, {{}})", expect="controller: must be a controller"),
    Case("api-run-episode-name", python=f"fuzzynav.run_episode({_SCENARIO}, 'goal-seeking')",
         expect="make_controller(name) makes one"),
    Case("api-run-episode-scenario-name", python=f"fuzzynav.run_episode('example-goal', {_CONTROLLER})",
         expect="scenario: must be a Scenario"),
    Case("api-sensors-unknown", python=f"fuzzynav.run_episode({_SCENARIO}, {_CONTROLLER}, sensors='radar')",
         expect="sensors: unknown sensor ring 'radar'"),
    Case("api-sensors-number", python=f"fuzzynav.run_episode({_SCENARIO}, {_CONTROLLER}, sensors=7)",
         expect="sensors: must be a SensorRing or a ring's name"),
    Case("api-sensors-lidar-ok", python=f"print(fuzzynav.run_episode({_SCENARIO}, {_CONTROLLER}, sensors='lidar').outcome)",
         status=0, expect="collision"),
    Case("api-robot-params-dict", python=f"fuzzynav.run_episode({_SCENARIO}, {_CONTROLLER}, robot_params={{'radius': 1}})",
         expect="robot_params: must be a fuzzynav.robot.tricycle.TricycleParams"),
    # a fifth sweep, of the Python API
    Case("api-robot-radius-of-a-nanometre",
         python=f"import dataclasses as dc; s = {_SCENARIO}; fuzzynav.run_episode(s, {_CONTROLLER}, "
                "robot_params=dc.replace(s.robot, radius=1e-9))", expect="robot_params.radius: must be at least 0.001 m"),  # it hung
    Case("api-time-step-of-a-nanosecond",
         python=f"import dataclasses as dc; s = {_SCENARIO}; fuzzynav.run_episode(s, {_CONTROLLER}, "
                "robot_params=dc.replace(s.robot, dt=1e-9))", expect="robot_params.dt: must be >= 0.001"),
    Case("api-one-robot-two-starts", python=f"fuzzynav.run_episode({_SCENARIO}, {_CONTROLLER}, start=[[1, 1, 0], [2, 2, 0]])",
         expect="start: one robot takes one start pose"),  # ran two, returned one
    Case("api-batch-count-and-starts", python=f"from fuzzynav.sim import BatchSimulator; "
                                             f"BatchSimulator({_SCENARIO}, {_CONTROLLER}, n=5, starts=[[1, 1, 0], [2, 2, 0]])",
         expect="n: 5 robots, but 2 start poses"),
    Case("api-evaluate-failures-into-an-empty-name", python="fuzzynav.evaluate('goal-seeking', 'mixed', 2, save_failures='')",
         expect="save_failures: must be a file name of 1 to 4096 characters"),  # it wrote into the working folder
    Case("api-epsilon-above-one", python="from fuzzynav.learn.exploration import EpsilonGreedy; EpsilonGreedy(2.0)",
         expect="epsilon: must stay within [0, 1], but starts at 2.0"),
    Case("api-epsilon-nan", python="from fuzzynav.learn.exploration import EpsilonGreedy; EpsilonGreedy(float('nan'))",
         expect="epsilon: must be finite"),
    Case("api-decay-floor-above-start",
         python="from fuzzynav.learn.schedules import ExponentialDecay; ExponentialDecay(0.1, 0.9, floor=5)",
         expect="floor: must be <= 0.1"),
    Case("api-learning-rate-negative", python="from fuzzynav.learn.tabular import TabularLearner; TabularLearner(3, 2, alpha=-1)",
         expect="alpha: must be >= 0"),
    Case("api-tabular-nan-reward",
         python="from fuzzynav.learn.tabular import TabularLearner; TabularLearner(3, 2).update([0], [0], [float('nan')], [1], [False])",
         expect="r: rewards must be finite"),  # one NaN spread over the whole table
    Case("api-tabular-negative-state",
         python="from fuzzynav.learn.tabular import TabularLearner; TabularLearner(3, 2).act([-1], np.random.default_rng(0))",
         expect="s: must be indices in [0, 3)"),  # it wrapped round to the last state
    Case("api-worlds-negative-margin", python="from fuzzynav.world.generate import generate_worlds; generate_worlds('mixed', 1, margin=-100)",
         expect="margin: must be >= 0"),  # a world kept solvable for a robot smaller than nothing
    Case("api-worlds-negative-radius", python="from fuzzynav.world.generate import generate_worlds; generate_worlds('mixed', 1, robot_radius=-1)",
         expect="robot_radius: must be > 0"),
    Case("api-fll-name-with-a-line-break",
         python="from fuzzynav.fuzzy.systems import get_system; from fuzzynav.fuzzy.io import dumps; "
                "s = get_system('goal-seeking'); s.name = 'a\\nb'; dumps(s, 'fll')",
         expect="name: holds a line break, which a .fll file cannot hold"),  # it wrote a file it could not read back
    Case("api-controller-without-reset",
         python=f"from fuzzynav.control.base import Command\nclass OnlyAct:\n    def act(self, obs): return Command(0.0, 1.0)\n"
                f"print(fuzzynav.run_episode({_SCENARIO}, OnlyAct(), max_time=1).outcome)",
         status=0, expect="timeout"),  # reset is optional: an AttributeError before
    Case("api-act-batch-returns-none",
         python=f"class Bad:\n    def act_batch(self, obs): return None\nfuzzynav.run_episode({_SCENARIO}, Bad())",
         expect="act_batch must return (steering, speed) or (steering, speed, labels), got NoneType"),
    Case("api-act-batch-too-few-labels",
         python=f"class Short:\n    def act_batch(self, obs): return np.zeros(1), np.ones(1), []\n"
                f"fuzzynav.run_episode({_SCENARIO}, Short())", expect="act_batch gave 0 labels for 1 robots"),
    Case("api-metrics-none", python=f"fuzzynav.metrics(None, {_SCENARIO})", expect="trace: must be a Trace"),
    Case("api-metrics-scenario-none", python=f"fuzzynav.metrics(fuzzynav.run_episode({_SCENARIO}, {_CONTROLLER}), None)",
         expect="scenario: must be a Scenario"),
    Case("api-metrics-other-scenario",
         python=f"fuzzynav.metrics(fuzzynav.run_episode({_SCENARIO}, {_CONTROLLER}), "
                "fuzzynav.load_scenario('fig-IV-23'))",
         expect="the trace was run on the goal scenario 'example-goal', not on the goal scenario 'fig-IV-23'"),
    Case("api-seed-negative", python=f"fuzzynav.run_episode({_SCENARIO}, {_CONTROLLER}, seed=-1)",
         expect="seed: must be an integer in [0,"),
    Case("api-evaluate-seed-negative", python="fuzzynav.evaluate('goal-seeking', worlds='circles', n=1, seed=-1)",
         expect="must be an integer in [0,"),
    Case("api-evaluate-n-1e9", python="fuzzynav.evaluate('goal-seeking', worlds='circles', n=10**9)",
         expect="must be an integer in [1, 100000]"),
    Case("api-generate-worlds-1e12", python="fuzzynav.generate_worlds('circles', 10**12)",
         expect="must be an integer in [1, 100000]"),
    Case("api-make-controller-none", python="fuzzynav.make_controller(None)", expect="name: must be a string"),
    Case("api-batch-two-column-starts",
         python=f"fuzzynav.BatchSimulator({_SCENARIO}, {_CONTROLLER}, starts=[[5, 5], [6, 6], [7, 7]])",
         expect="starts: must be one pose (x, y, theta)"),
    Case("api-batch-n-1e9", python=f"fuzzynav.BatchSimulator({_SCENARIO}, {_CONTROLLER}, n=10**9)",
         expect="n: must be an integer in [1, 100000]"),
    Case("api-load-scenario-none", python="fuzzynav.load_scenario(None)", expect="scenario: must be a file name"),
    Case("api-load-controller-number", python="fuzzynav.load_controller(5)", expect="model: must be a file name"),
    Case("api-load-fuzzy-system-none", python="fuzzynav.load_fuzzy_system(None)", expect="path: must be a file name"),
    Case("api-train-episodes-1e12", python="fuzzynav.train('q-goal', d / 'q.json', episodes=10**12)",
         expect="episodes: must be an integer in [1, 10000000]"),
    Case("api-train-task-none", python="fuzzynav.train(None, d / 'q.json')", expect="task: must be a string"),
    Case("api-plot-episode-none", python=f"fuzzynav.plot_episode(None, {_SCENARIO}, d / 'x.png')",
         expect="trace: must be a Trace"),
    Case("api-save-scenario-none", python="fuzzynav.save_scenario(None, d / 'x.yaml')", expect="scenario: must be a Scenario"),
    Case("api-fuzzy-evaluate-text", python="fuzzynav.thesis_system('goal-seeking').evaluate('abc')",
         expect="inputs: must be numbers"),
    Case("api-batch-controller-count",
         python=f"c = {_CONTROLLER}\nfuzzynav.BatchSimulator({_SCENARIO}, [c, c], n=3)",
         expect="controller: 2 controllers for 3 robots"),
]

COUNTS = [
    Case("bench-count-1e11", argv=("bench", "circles:99999999999", "--controllers", "goal-seeking", "--out", "{d}/o"),
         expect="COUNT must be a whole number from 1 to 100,000"),
    Case("bench-count-0", argv=("bench", "circles:0", "--controllers", "goal-seeking", "--out", "{d}/o"),
         expect="COUNT must be a whole number from 1 to 100,000"),
    Case("bench-seeds-1e12", argv=("bench", "circles:1", "--controllers", "goal-seeking", "--seeds", "1000000000000",
                                   "--out", "{d}/o"), expect="--seeds: must be an integer in [1, 10000]"),
    Case("bench-campaign-too-large", argv=("bench", "circles:100000", "--controllers", "goal-seeking,dwa",
                                           "--seeds", "10", "--out", "{d}/o"), expect="more than the 1,000,000"),
    Case("bench-world-seed-past-the-last", argv=("bench", "circles:1:9223372036854775807", "--controllers",
                                                 "goal-seeking", "--seeds", "2", "--out", "{d}/o"),
         expect="would run worlds of seed up to 9223372036854775808"),
    Case("bench-workers-1e9", argv=("bench", "circles:1", "--controllers", "goal-seeking", "--workers", "1000000000",
                                    "--out", "{d}/o"), expect="--workers: must be an integer in [1, 1024]"),
    Case("worlds-generate-1e12", argv=("worlds", "generate", "circles", "--n", "1000000000000", "--out", "{d}/w"),
         expect="--n: must be an integer in [1, 100000]"),
    Case("worlds-generate-5000-digits", argv=("worlds", "generate", "circles", "--n", "9" * 5000, "--out", "{d}/w"),
         expect="--n: must be an integer in [1, 100000]"),
    Case("tune-out-in-a-missing-folder", argv=("tune", "fuzzy-2b:oab", "--worlds", "mixed:2", "--budget", "4",
                                               "--out", "{d}/missing/oab.yaml"),
         expect="oab.yaml: --out: no folder"),
    Case("run-max-time-1e308", argv=("run", "fig-IV-23", "--max-time", "1e308"),
         expect="--max-time: must be <= 3600"),
    Case("train-parallel-not-a-divisor", argv=("train", "q-goal", "--episodes", "5", "--parallel", "3", "--out",
                                               "{d}/q.json"),
         expect="--parallel: for q-goal, N must divide the convergence window of 50 episodes"),
    Case("train-curve-bad-suffix", argv=("train", "q-goal", "--curve", "{d}/x.xyz", "--out", "{d}/q.json"),
         expect="matplotlib cannot write '.xyz'"),
]

FUZZY = [
    Case("fis-output-range-4-4", {"t.fis": _fis("[4 4]")}, _eval("t.fis"), expect="v.range: range [4.0, 4.0] has no width"),
    Case("fis-output-range-nan", {"t.fis": _fis("[0 nan]")}, _eval("t.fis"), expect="Range must be [lo hi]"),
    Case("fis-weight-minus-2", {"t.fis": _fis(weight="-2")}, _eval("t.fis"), expect="rule weight must be a number in [0, 1]"),
    Case("fis-weight-1.5", {"t.fis": _fis(weight="1.5")}, _eval("t.fis"), expect="rule weight must be a number in [0, 1]"),
    Case("fis-ok", {"t.fis": _fis()}, _eval("t.fis"), status=0, expect='{"v": 0.40'),
    # rules name variables and terms by number: a file out of order would read the wrong ones
    Case("fis-mfs-out-of-order", {"t.fis": _fis().replace("MF1='lo':'trimf',[0 0 1]\nMF2='hi'", "MF2='hi'", 1)
                                  .replace("[0 1 1]\n\n[Output1]", "[0 1 1]\nMF1='lo':'trimf',[0 0 1]\n\n[Output1]", 1)},
         _eval("t.fis"), expect="t.fis: line 18 (MF1): MF1 comes after MF2: rules refer to MF by place in the file"),
    Case("fis-export-c-fixed-huge-breakpoint", python="""
from fuzzynav.cli import main
assert main(["fis", "convert", "goal-seeking:gsb", "--to", "fis", "-o", str(d / "g.fis")]) == 0
text = (d / "g.fis").read_text()
assert "[0.1 3.5 8.0]" in text
(d / "g.fis").write_text(text.replace("[0.1 3.5 8.0]", "[0.1 3.5 1e308]", 1))
raise SystemExit(main(["fis", "export-c", str(d / "g.fis"), "-o", str(d / "g.c"), "--fixed", "Q16.16"]))
""", expect="1e+308 does not fit Q16.16"),
    Case("fll-plot-range-too-wide", {"t.fll": _fll("range: 0.000 1.000", "range: -1.7e308 0")},
         ("fis", "plot", "{d}/t.fll", "-o", "{d}/p.png"), expect="x.range: range [-1.7e+308, 0.0] must be finite, at most 1e+300 wide"),
    Case("fll-role-with-a-range-of-no-width", python="""
from fuzzynav.cli import main
assert main(["fis", "convert", "goal-seeking:gsb", "--to", "fll", "-o", str(d / "g.fll")]) == 0
text = (d / "g.fll").read_text()
start = text.index("range:")
(d / "g.fll").write_text(text[:start] + "range: 5 5" + text[text.index("\\n", start):])
raise SystemExit(main(["run", "circles-0-000", "--controller", "goal-seeking", "--fis", f"gsb={d / 'g.fll'}"]))
""", expect="g.fll: drg.universe: is a fuzzylite engine, not a fuzzy system: universe must be finite with lo < hi"),
    Case("fis-inputs-out-of-order", {"t.fis": _fis().replace("[Input1]", "[Input2]").replace("NumInputs=1", "NumInputs=2")
                                     .replace("[Output1]", "[Input1]\nName='y'\nRange=[0 1]\nNumMFs=1\nMF1='a':'trimf',[0 0 1]\n\n[Output1]")},
         _eval("t.fis"), expect="Input1 comes after Input2"),
    Case("fis-repeated-mf-number-read-by-place", {"t.fis": _fis().replace("MF2='hi':'trimf',[0 1 1]\n\n[Output1]",
                                                                          "MF1='hi':'trimf',[0 1 1]\n\n[Output1]", 1)},
         _eval("t.fis"), status=0, expect='{"v": 0.40'),  # MATLAB's slcp1.fis repeats one; it and fuzzylite read by place
    Case("fis-zero-width-output-range-of-a-sugeno", {"t.fis": _sugeno_fis("[0 0]")}, _eval("t.fis"), status=0,
         expect='{"v": '),  # MATLAB's juggler.fis: Range=[0 0] on a Sugeno output
    Case("fll-role-with-an-infinite-singleton", python="""
from fuzzynav.cli import main
assert main(["fis", "convert", "goal-seeking:gsb", "--to", "fll", "-o", str(d / "g.fll")]) == 0
text = (d / "g.fll").read_text()
assert "term: NG Constant -0.6283185307179586" in text
(d / "g.fll").write_text(text.replace("term: NG Constant -0.6283185307179586", "term: NG Constant -inf", 1))
raise SystemExit(main(["run", "circles-0-000", "--controller", "goal-seeking", "--fis", f"gsb={d / 'g.fll'}"]))
""", expect="g.fll: is a fuzzylite engine, not a fuzzy system: singleton value must be finite"),
    Case("fis-input-underscore", {"t.fis": _fis()}, ("fis", "eval", "{d}/t.fis", "--input", "x=1_000"),
         expect="--input x=1_000: '1_000' is not a number"),
    Case("fis-input-overflows", {"t.fis": _fis()}, ("fis", "eval", "{d}/t.fis", "--input", "x=1e400"),
         expect="1e400 is too large for a float"),
    Case("fis-gauss2mf-sigma-0", {"t.fis": _fis().replace("'trimf',[0 0 1]", "'gauss2mf',[0 0.3 0 0.7]", 1)},
         _eval("t.fis"), expect="gaussianproduct needs a finite sd_a > 0, got 0.0"),
    Case("fll-range-1e300", {"t.fll": _fll("  range: 0 1\n", "  range: 0 1e300\n")}, _eval("t.fll"),
         expect="no finite answer for x=0.3"),
    Case("fll-range-inf", {"t.fll": _fll("  range: 0 1\n", "  range: 0 inf\n")}, _eval("t.fll"), expect="range"),
    Case("fll-highest-minus-3", {"t.fll": _fll("activation: General", "activation: Highest -3")}, _eval("t.fll"),
         expect="Highest takes a number of rules >= 1"),
    Case("fll-threshold-nan", {"t.fll": _fll("activation: General", "activation: Threshold >= nan")}, _eval("t.fll"),
         expect="Threshold threshold must be a number in [0, 1]"),
    Case("fll-negative-height", {"t.fll": _fll(_HI, "term: hi Triangle 0 1 1 -2\nRuleBlock")}, _eval("t.fll"),
         expect="v.hi: height must be a number in [0, 1]"),
    Case("fll-discrete-unordered", {"t.fll": _fll(_HI, "term: hi Discrete 1 1 0 0\nRuleBlock")}, _eval("t.fll"),
         expect="v.hi: discrete points must be given by increasing x"),
    Case("fll-rule-weight-minus-2", {"t.fll": _fll("then v is hi\n", "then v is hi with -2\n")}, _eval("t.fll"),
         expect="weight"),
    Case("fll-function-divide-by-zero", {"t.fll": _TS.replace("FORMULA", "1/(x-x)")}, _eval("t.fll"),
         expect="t.fll: formula '1/(x-x)': gives inf at x="),
    Case("fll-function-log-minus-one", {"t.fll": _TS.replace("FORMULA", "log(x-1)")}, _eval("t.fll"),
         expect="no finite answer for x=0.3: v = nan"),
    Case("fll-plot-function-of-another-variable",
         {"t.fll": _fll("term: lo Triangle 0 0 1\n  term: hi Triangle 0 1 1\nOutputVariable",
                        "term: lo Function 1 - v\n  term: hi Triangle 0 1 1\nOutputVariable")},
         ("fis", "plot", "{d}/t.fll", "-o", "{d}/p.png"), status=0, expect="p.png"),
    Case("fll-function-overflow", {"t.fll": _TS.replace("FORMULA", "exp(1000)*exp(1000)")}, _eval("t.fll"),
         expect="t.fll: v.lo: Function 'exp(1000)*exp(1000)' gives inf at every input"),  # when read
    Case("fis-function-pole-at-the-input", {"t.fis": _fis().replace("MF1='lo':'trimf',[0 0 1]\nMF2='hi':'trimf',[0 1 1]\n\n[Output1]",
                                                                    "MF1='lo':'function',[1/(x-0.3)]\nMF2='hi':'trimf',[0 1 1]\n\n[Output1]")},
         _eval("t.fis"), expect="t.fis: formula '1/(x-0.3)': gives inf at x=0.3"),
    Case("fll-function-reads-own-output", {"t.fll": _TS.replace("FORMULA", "v+1")}, _eval("t.fll"),
         expect="v.lo: a Function term of v reads v itself"),
    Case("fll-csv-non-finite-answer", {"t.fll": _TS.replace("FORMULA", "log(x-1)"), "in.csv": "x\n0.3\n"},
         ("fis", "eval", "{d}/t.fll", "--csv", "{d}/in.csv"), expect="no finite answer"),
    Case("fll-csv-infinite-term", {"t.fll": _TS.replace("FORMULA", "1/(x-x)"), "in.csv": "x\n0.3\n"},
         ("fis", "eval", "{d}/t.fll", "--csv", "{d}/in.csv"), expect="gives inf"),
    Case("fll-export-c-an-engine", {"t.fll": _FLL}, ("fis", "export-c", "{d}/t.fll", "-o", "{d}/t.c"),
         expect="inputs clipped to their range (lock-range)"),
    Case("fis-show-a-checkpoint", {"ck.json": '{"kind": "fuzzynav-checkpoint", "episode": 20}'},
         ("fis", "show", "{d}/ck.json"), expect="ck.json: kind: a training checkpoint, not a fuzzy system"),
    Case("run-model-a-checkpoint", {"ck.json": '{"kind": "fuzzynav-checkpoint", "episode": 20}'},
         ("run", "fig-IV-23", "--model", "{d}/ck.json"), expect="ck.json: kind: a training checkpoint, not a model"),
    Case("json-duplicate-terms", {"g.json": '{"name": "g", "inputs": [{"name": "x", "universe": [0, 1], "terms": '
                                            '{"Z": {"kind": "triangle", "params": [0, 0, 1]}, '
                                            '"Z": {"kind": "triangle", "params": [0, 1, 1]}}}]}'},
         ("fis", "show", "{d}/g.json"), expect="the key 'Z' appears twice"),
]


def _row_case(name: str, expect: str, **changes) -> Case:
    args = ", ".join(f"{key}={value!r}" for key, value in changes.items())
    return Case(f"campaign-{name}", python=f"campaign(d, lambda out: edit_row(out, {args}))", expect=expect)


CAMPAIGN = [
    Case("tune-folder-with-a-path-task", {"c.yaml": "robot: {x: 1, y: 1}\npath: [[2, 2], [8, 8]]\n"},
         ("tune", "fuzzy-2b:oab", "--worlds", "{d}", "--budget", "400", "--out", "{d}/o.yaml"),
         expect="c.yaml: task: fuzzy-2b cannot do a path task"),
    _row_case("seed-abc", "line 1.seed: must be an integer", seed="abc"),
    _row_case("seed-null", "line 1.seed: must be an integer", seed=None),
    _row_case("time-fast", "line 1.time_s: must be a number", time_s="fast"),
    _row_case("time-minus-1e9", "line 1.time_s: must be >= 0", time_s=-1e9),
    _row_case("outcome-banana", "line 1.outcome: must be one of reached, collision, timeout", outcome="banana"),
    _row_case("controller-outside-plan", "is not one of this campaign's", controller="dwa"),
    _row_case("world-outside-plan", "is not one of this campaign's", world="circles-0-777"),
    _row_case("non-utf8", "not UTF-8", raw=b'"\xff\xfe"'),
    Case("campaign-missing-column",
         python="campaign(d, lambda out: (out / 'runs.jsonl').write_text(json.dumps({'suite': 'circles:1:0'}) + '\\n'))",
         expect="line 1.world: missing"),
    Case("campaign-middle-line-garbage",
         python="campaign(d, lambda out: (out / 'runs.jsonl').write_text('{{{\\n{}\\n'))",
         expect="line 1: not a JSON object"),
    Case("campaign-fis-json-not-json", python="campaign(d, fis=b'not json')", expect="fis.json: line 1, column 1: invalid JSON"),
    Case("campaign-fis-json-list", python="campaign(d, fis=b'[1, 2]')", expect="fis.json: must be a mapping"),
    Case("campaign-cut-last-line-ok",
         python="campaign(d, lambda out: (out / 'runs.jsonl').write_text((out / 'runs.jsonl').read_text() + '{\"su'))",
         status=0, expect=""),
    Case("campaign-second-writer", python="locked_bench(d)", expect="another `fuzzynav bench` is writing"),
    Case("campaign-benchmark-json-string-entry",
         files={"w.yaml": "robot: {x: 2, y: 2}\ngoal: {x: 15, y: 15}\n",
                "benchmark.json": json.dumps({"scenarios": {"w": "fast"}})},
         argv=("bench", "{d}", "--controllers", "goal-seeking", "--out", "{d}/o"),
         expect="benchmark.json: scenarios.w: must be a mapping"),
]

CHECKPOINT = [
    Case("checkpoint-episode-counter-edited",
         python="trained_checkpoint(d, lambda doc: doc.update(episode=doc['episode'] + 1))",
         expect="holds 20 batches, but the checkpoint says 21 were done"),
    Case("checkpoint-curve-value-edited",
         python="trained_checkpoint(d, lambda doc: doc['curve']['mean_reward'][0].__setitem__(0, 99.0))",
         expect="digest: does not match the checkpoint's content"),
    Case("checkpoint-curve-batch-dropped",
         python="trained_checkpoint(d, lambda doc: [doc['curve'][k].pop() for k in doc['curve']])",
         expect="holds 19 batches, but the checkpoint says 20"),
    Case("checkpoint-qualities-edited",
         python="trained_checkpoint(d, lambda doc: doc['learner']['q'][0][0].__setitem__(0, 5.0))",
         expect="digest: does not match"),
    Case("checkpoint-batch-row-not-a-list-no-digest",  # a TypeError traceback at the resume
         python="trained_checkpoint(d, lambda doc: (doc.pop('digest'), doc['curve']['success'].__setitem__(1, True)))",
         expect="curve.success[1]: must be a list of the batch's episodes, got True"),
]

SCENARIOS = [
    Case("scenario-3m-robot-goal-unreachable", {"s.yaml": "robot: {x: 5, y: 5, radius: 3}\ngoal: {x: 19, y: 19}\n"},
         RUN, expect="the robot (radius 3 m) cannot come closer"),
    Case("scenario-start-within-the-goal-tolerance", {"s.yaml": ROBOT + "goal: {x: 5.1, y: 5.1, tolerance: 0.3}\n"},
         RUN, expect="s.yaml: goal: the start (5, 5) is 0.141421 m from the goal, within its tolerance 0.3 m"),
    Case("scenario-goal-tolerance-larger-than-the-world", {"s.yaml": ROBOT + "goal: {x: 15, y: 15, tolerance: 30}\n"},
         RUN, expect="within its tolerance 30 m: the episode would end, reached, before its first step"),  # reached in 0 s
    Case("scenario-polygon-closed-ring", {"s.yaml": "robot: {x: 1, y: 1}\ngoal: {x: 18, y: 18}\nobstacles:\n"
                                                    "  - polygon: {points: [[5, 5], [9, 5], [9, 9], [5, 5]]}\n"},
         RUN, expect="obstacles[0].polygon.points[3]: repeats points[0]: a polygon closes itself"),  # 'self-intersecting'
    Case("scenario-small-robot-goal-ok", {"s.yaml": "robot: {x: 1, y: 1, radius: 0.1}\n"
                                                    "goal: {x: 19.8, y: 19.8, tolerance: 0.1}\nmax_time: 1\n"},
         RUN, status=0, expect='"outcome": "timeout"'),
    Case("scenario-target-unreachable", {"s.yaml": ROBOT + "target: {x: 19.95, y: 19.95, tolerance: 0.1}\n"},
         RUN, expect="target: target (19.95, 19.95) cannot be reached"),
    Case("scenario-target-beside-obstacle", {"s.yaml": ROBOT + "target: {x: 12.3, y: 10, tolerance: 0.1}\n"
                                                       "obstacles:\n  - circle: {center: [10, 10], radius: 2.2}\n"},
         RUN, expect="target (12.3, 10) cannot be reached"),
]

ASCII = [
    Case("ascii-terminal-fis-show", python="ascii_terminal(['fis', 'show', 'goal-seeking'])", status=0,
         expect="thesis \\xa7IV.5.1"),
    Case("ascii-terminal-scenario-error", {"s.yaml": "robot: {x: 5, y: 5, max_steering: 2}\ngoal: {x: 15, y: 15}\n"},
         python="ascii_terminal(['run', str(d / 's.yaml'), '--controller', 'goal-seeking'])",
         expect="robot.max_steering: must be below \\u03c0/2"),
]

_DEMO_TRAVERSAL = ("from fuzzynav.cli import main\n"
                   "assert main(['demo', '--scenario', str(d / 's.yaml'), '--controllers', 'goal-seeking', "
                   "'--out', str(d / 'a' / 'b' / 'out')]) == 0\n"
                   "plots = list(d.rglob('*.png'))\n"
                   "assert len(plots) == 1 and (d / 'a' / 'b' / 'out') == plots[0].parent, plots")

NAMES_AND_IMPORTS = [
    Case("run-generated-name-huge-seed", argv=("run", "circles-" + "9" * 5000 + "-000", "--controller", "goal-seeking"),
         expect="its SEED must be a whole number"),
    Case("run-generated-name-seed-2-64", argv=("run", "circles-18446744073709551616-000", "--controller", "goal-seeking"),
         expect="circles-18446744073709551616-000: its SEED must be"),
    Case("run-generated-name-index-too-large", argv=("run", "circles-0-999999", "--controller", "goal-seeking"),
         expect="its world index must be a whole number from 0 to 99,999"),
    Case("import-barn-path-of-strings",
         python="w = barn_world(d); np.save(d / 'path_1.npy', np.array([['a', 'b']])); import_barn(d, w)",
         expect="path_1.npy: must hold grid cells as numbers"),
    Case("import-barn-path-with-nan",
         python="w = barn_world(d); np.save(d / 'path_1.npy', np.array([[1.0, np.nan]])); import_barn(d, w)",
         expect="path_1.npy: grid cells must be finite numbers"),
    Case("import-barn-path-writes-nothing-on-error",
         python="w = barn_world(d); np.save(d / 'path_1.npy', np.array([[1j, 2j]]))\n"
                "try:\n    import_barn(d, w)\nexcept SystemExit as done:\n"
                "    assert not list((d / 'o').glob('*')), list((d / 'o').glob('*'))\n    raise",
         expect="must hold grid cells as numbers, got dtype complex128"),
    Case("import-barn-reference-file-a-list",
         python="(d / 'o').mkdir(); (d / 'o' / 'benchmark.json').write_text(json.dumps({'scenarios': []}))\n"
                "import_barn(d, barn_world(d, 'world_0'))", expect="benchmark.json: scenarios: must be a mapping"),
    Case("import-barn-same-name-twice",
         python="import_barn(d, barn_world(d / 'a', 'world_0'), barn_world(d / 'b', 'world_0'))",
         expect="world_0: given twice"),
    Case("demo-scenario-name-leaves-no-file-outside-out",
         {"s.yaml": "name: ../../escaped\nworld: {width: 10, height: 10}\nrobot: {x: 1, y: 1}\n"
                    "goal: {x: 8, y: 8}\nmax_time: 2\n"},
         python=_DEMO_TRAVERSAL, status=0),
    Case("fis-zero-rules", {"zero.fis": _fis().replace("NumRules=2", "NumRules=0").split("[Rules]")[0] + "[Rules]\n"},
         _eval("zero.fis"), expect="a fuzzy system needs at least one rule"),
    Case("fis-num-rules-disagrees", {"n.fis": _fis().replace("NumRules=2", "NumRules=3")}, _eval("n.fis"),
         expect="line 6 (NumRules): says 3, the file holds 2"),
    Case("fis-num-mfs-disagrees", {"n.fis": _fis().replace("NumMFs=2", "NumMFs=9", 1)}, _eval("n.fis"),
         expect="line 16 (NumMFs): says 9, [Input1] holds 2 MFs"),
    Case("fis-num-inputs-disagrees", {"n.fis": _fis().replace("NumInputs=1", "NumInputs=99999999999999999999")},
         _eval("n.fis"), expect="(NumInputs): says 99999999999999999999, the file holds 1"),
    Case("fis-unknown-type", {"t.fis": _fis().replace("Type='mamdani'", "Type='tsk'")}, _eval("t.fis"),
         expect="line 3 (Type): must be one of mamdani, sugeno, tsukamoto, got 'tsk'"),
    Case("fis-sugeno-with-a-mamdani-defuzzifier", python=(
        "from fuzzynav.cli import main\n"
        "assert main(['fis', 'convert', 'goal-seeking', '--to', 'fis', '-o', str(d / 'gs.fis')]) == 0\n"
        "text = (d / 'gs.fis').read_text().replace(\"DefuzzMethod='wtsum'\", \"DefuzzMethod='mom'\")\n"
        "(d / 'mom.fis').write_text(text)\n"
        "fuzzynav.load_fuzzy_system(d / 'mom.fis')"), expect="(DefuzzMethod): a sugeno system takes wtaver or wtsum"),
    Case("fuzzy-json-triangle-of-two",
         python="edited_system(d, lambda doc: doc['inputs'][0]['terms']['P'].update(params=[0.1, 3.5]))",
         expect="inputs[0].terms.P: a triangle takes 3 parameters (a, b, c), got 2"),
    Case("fuzzy-json-output-no-rule-concludes",
         python="edited_system(d, lambda doc: doc.update(rules=[r.split(' AND v IS')[0] for r in doc['rules']]))",
         expect="outputs.v: no rule concludes on this output"),
    Case("api-save-fuzzy-system-a-name", python="fuzzynav.save_fuzzy_system('goal-seeking', d / 'x.fll')",
         expect="system: must be a FuzzySystem or an Engine"),
    Case("csv-more-values-than-columns", {"in.csv": "drg,theta\n1,0,5\n"},
         ("fis", "eval", "goal-seeking", "--csv", "{d}/in.csv"), expect="in.csv: line 2: 3 values for 2 columns"),
    Case("csv-quoted-newline-is-no-number", {"in.csv": 'drg,theta\n1,"0\n5"\n'},
         ("fis", "eval", "goal-seeking", "--csv", "{d}/in.csv"), expect="is not a number in {'drg'"),
    Case("fis-convert-suffix-against-to", argv=("fis", "convert", "goal-seeking", "--to", "fll", "-o", "{d}/x.json"),
         expect="-o: the file's suffix says json, --to says fll"),
    Case("fis-convert-into-a-folder", argv=("fis", "convert", "goal-seeking", "--to", "fll", "-o", "{d}/out/"),
         expect="is a folder; give a file name"),
    Case("anfis-model-range-reversed",
         python="edited_model(d, ['anfis-tracker', '--episodes', '2'], "
                "lambda doc: doc['model'].update(input_range=[[0.2, -0.2]]), ['fis', 'eval', '--input', 'theta_er=0'])",
         expect="input_range[0]: must be [lo, hi] with lo ≤ hi, got [0.2, -0.2]"),
    Case("run-scenario-lists-an-unknown-controller",
         {"p.yaml": "robot: {x: 1, y: 1}\npath: [[2, 2], [8, 8]]\ncontrollers: [nope]\n"}, ("run", "{d}/p.yaml"),
         expect="p.yaml: controllers[0]: unknown controller 'nope'"),
    Case("demo-scenario-lists-an-unknown-controller",
         {"p.yaml": "robot: {x: 1, y: 1}\npath: [[2, 2], [8, 8]]\ncontrollers: [goal-seeking, nope]\n"},
         ("demo", "--scenario", "{d}/p.yaml", "--out", "{d}/o"), expect="p.yaml: controllers[1]: unknown controller"),
    Case("bench-out-is-a-file", {"f": "x"}, ("bench", "circles:1", "--controllers", "goal-seeking", "--out", "{d}/f"),
         expect="f: is a file, not a folder"),
    Case("worlds-generate-out-is-a-file", {"f": "x"}, ("worlds", "generate", "mixed", "--n", "1", "--out", "{d}/f"),
         expect="f is a file, not a folder: cannot write mixed-0-000.yaml in it"),
    Case("q-goal-model-steering-of-50-rad",
         python="edited_model(d, ['q-goal', '--episodes', '4'], lambda doc: doc.update(steering=[0.0, -50.0, 50.0]), "
                "['run', 'fig-IV-23', '--model'])",
         expect="x.json: steering: steering angles must lie in (-π/2, π/2) rad"),
    Case("train-curve-into-a-folder",
         argv=("train", "q-goal", "--episodes", "4", "--out", "{d}/q.json", "--curve", "{d}"),
         expect="is a folder; give the figure's file name"),
    Case("run-rays-without-a-plot", argv=("run", "fig-IV-23", "--controller", "goal-seeking", "--rays"),
         expect="--rays: draws the sensor rays on the --plot figure"),
    Case("neural-tracker-model-of-two-inputs",
         python="edited_model(d, ['neural-tracker', '--episodes', '2'], "
                "lambda doc: doc['model']['weights'][0].append(doc['model']['weights'][0][0]), "
                "['run', 'fig-V-28', '--model'])",
         expect="x.json: model: a tracker's model reads one input (θ_er), this one reads 2"),
    Case("fuzzy-json-version-true", python="edited_system(d, lambda doc: doc.update(version=True))",
         expect="version: unsupported version True"),
    Case("gym-reset-options-a-list", python="gymnasium.make('fuzzynav/GoalSeeking-v0').reset(options=[1, 2])",
         expect="options: must be a mapping"),
    Case("gym-reset-options-typo", python="gymnasium.make('fuzzynav/GoalSeeking-v0').reset(options={'scenari': 'x'})",
         expect="did you mean 'scenario'"),
    Case("gym-vector-reset-options-a-list",
         python="gymnasium.make_vec('fuzzynav/GoalSeeking-v0', num_envs=2, vectorization_mode='vector_entry_point')"
                ".reset(options=[1])", expect="options: must be a mapping"),
    Case("tune-checkpoint-options-a-list",
         python="tuned_then_resumed(d, lambda a: a.update(options=np.array('[1, 2]')))",
         expect="a.yaml.tune.npz: options: must be a mapping"),
    Case("tune-checkpoint-values-cut",
         python="tuned_then_resumed(d, lambda a: a.update(f=a['f'][:, :3]))", expect="f: must be a float array of"),
    Case("tune-checkpoint-sizes-too-many",
         python="tuned_then_resumed(d, lambda a: a.update(sizes=np.array([2, 2, 200])))",
         expect="sizes: the generations' sizes must be whole numbers ≥ 0 adding up"),
    Case("tune-checkpoint-not-an-archive", {"a.yaml.tune.npz": "PK not a zip"},
         ("tune", "goal-seeking:gsb", "--worlds", "circles:2", "--validation", "none", "--budget", "8",
          "--population", "2", "--out", "{d}/a.yaml", "--resume"),
         expect="a.yaml.tune.npz: cannot read tuning checkpoint (BadZipFile"),
    Case("tune-unknown-controller", argv=("tune", "FUZZY-2b:oab", "--worlds", "mixed:2"),
         expect="unknown controller 'FUZZY-2b'"),
    Case("fis-eval-csv-row-too-short", {"in.csv": "drg,theta\n1.0\n"}, ("fis", "eval", "goal-seeking", "--csv", "{d}/in.csv"),
         expect="in.csv: line 2: has no value for theta (the row is shorter than the header)"),
    Case("run-empty-scenario-file", {"w.yaml": ""}, ("run", "{d}/w.yaml"),
         expect="w.yaml: must be a mapping, got nothing (an empty document)"),
    Case("reproduce-all-and-an-id", argv=("reproduce", "all", "fig-V-7", "--out", "{d}/r"),
         expect="ID: 'all' runs every experiment: give it alone"),
    Case("bench-two-folders-of-one-name", {"a/w/x.yaml": ROBOT + "goal: {x: 9, y: 9}\n", "b/w/x.yaml": ROBOT + "goal: {x: 9, y: 9}\n"},
         ("bench", "{d}/a/w", "{d}/b/w", "--controllers", "goal-seeking", "--out", "{d}/o"),
         expect="are all w (a folder suite is named by its last part: rename one)"),
    Case("numba-threads-signs", python="""
import os
os.environ["NUMBA_NUM_THREADS"] = "+-1"  # numba ignores it (a warning): so do we
try:
    from fuzzynav.cli import main
    raise SystemExit(main(["scenarios"]))
finally:
    del os.environ["NUMBA_NUM_THREADS"]
""", status=0, expect="fig-IV-23"),
    Case("numba-threads-zero", python="""
import os
os.environ["NUMBA_NUM_THREADS"] = "0"
try:
    from fuzzynav.cli import main
    raise SystemExit(main(["scenarios"]))
finally:
    del os.environ["NUMBA_NUM_THREADS"]
""", expect="NUMBA_NUM_THREADS: must be a whole number of threads, at least 1, got '0'"),
]

# a seventh sweep: empty names read as the current folder, ...
SEVENTH = [
    Case("bench-empty-suite", {"w.yaml": ROBOT + "goal: {x: 9, y: 9}\n"},
         ("bench", "", "--controllers", "goal-seeking", "--out", "{d}/o"),
         expect="SUITE: is empty: name a family (mixed:40) or a folder"),  # it ran the working folder's files
    Case("run-empty-model", argv=("run", "fig-IV-23", "--model", ""),
         expect="argument --model: must be a file name of 1 to 4096 characters"),  # a TypeError traceback
    Case("fis-convert-empty-output", argv=("fis", "convert", "goal-seeking", "--to", "fll", "-o", ""),
         expect="argument -o/--output: must be a file name"),  # it wrote to stdout
    Case("fis-eval-empty-csv", argv=("fis", "eval", "goal-seeking", "--csv", ""),
         expect="argument --csv: must be a file name"),  # it said the --input values were missing
    Case("import-barn-empty-world", argv=("import", "barn", "", "--out", "{d}/o"),
         expect="argument WORLD.world: must be a file name"),  # it said '.: is a folder'
    Case("fis-plot-empty-output-variable", argv=("fis", "plot", "goal-seeking", "--surface", "--output-variable", "",
                                                  "-o", "{d}/s.png"),
         expect="--output-variable: unknown output (one of alpha, v)"),  # it drew the first output
    Case("bench-seed-is-not-seeds", argv=("bench", "circles:1", "--controllers", "goal-seeking", "--seed", "3",
                                          "--out", "{d}/o"),
         expect="unrecognized arguments: --seed 3 (did you mean --seeds?)"),  # it ran --seeds 3: three world sets
    Case("run-option-prefix", argv=("run", "fig-IV-23", "--contr", "dwa"),
         expect="unrecognized arguments: --contr dwa (did you mean --controller?)"),  # a prefix was the option
    Case("tune-validation-on-the-training-worlds",
         argv=("tune", "goal-seeking:gsb", "--worlds", "circles:2", "--validation", "circles:2", "--budget", "400",
               "--out", "{d}/t.yaml"),
         expect="--validation: shares 2 worlds with --worlds circles:2:0: the result would be chosen on the worlds"),
    Case("tune-validation-on-the-held-out-worlds",
         argv=("tune", "goal-seeking:gsb", "--worlds", "circles:2", "--validation", "circles:2:7", "--holdout",
               "circles:2:7", "--budget", "400", "--out", "{d}/t.yaml"),
         expect="--validation: shares 2 worlds with --holdout circles:2:7: the held-out numbers would be on worlds"),
    Case("tune-held-out-on-the-default-validation-worlds",  # --validation left to its default, auto
         argv=("tune", "goal-seeking:gsb", "--worlds", "circles:2", "--holdout", "circles:2:500", "--budget", "400",
               "--out", "{d}/t.yaml"),
         expect="--holdout: shares 2 worlds with the default --validation circles:2:500: the held-out numbers"),
    Case("scenarios-show-a-generated-world", argv=("scenarios", "--show", "circles-0-002"), status=0,
         expect="# name: the file's name when absent (this is a copy of the generated world circles-0-002)"),
    Case("tune-empty-validation", argv=("tune", "goal-seeking:gsb", "--worlds", "circles:2", "--validation", "",
                                        "--budget", "400", "--out", "{d}/t.yaml"),
         expect="--validation: is empty: name a family"),  # it validated on the working folder's files
    Case("worlds-generate-over-an-edited-world", python="""
from fuzzynav.cli import main
assert main(["worlds", "generate", "circles", "--n", "2", "--out", str(d / "w")]) == 0
assert main(["worlds", "generate", "circles", "--n", "2", "--out", str(d / "w")]) == 0  # the same files: fine
edited = (d / "w" / "circles-0-001.yaml").read_text().replace("max_time:", "max_time: 30 #")
(d / "w" / "circles-0-001.yaml").write_text(edited)
try:
    raise SystemExit(main(["worlds", "generate", "circles", "--n", "2", "--out", str(d / "w")]))
finally:
    assert (d / "w" / "circles-0-001.yaml").read_text() == edited
""", expect="--out: circles-0-001.yaml already there, with other content (edited?): not overwritten"),  # it was
    Case("api-start-outside-the-world", python=f"fuzzynav.run_episode({_SCENARIO}, {_CONTROLLER}, start=[-5, 1, 0])",
         expect="starts[0]: (-5, 1) is outside the 20 x 20 m world"),  # it ran, as a collision at the start
    Case("api-batch-second-start-outside",
         python=f"fuzzynav.BatchSimulator({_SCENARIO}, {_CONTROLLER}, starts=[[2, 2, 0], [2, 25, 0]])",
         expect="starts[1]: (2, 25) is outside the 20 x 20 m world"),
    Case("scenario-latency-between-two-steps",
         {"s.yaml": "robot: {x: 5, y: 5, actuation: {latency: 0.05}}\ngoal: {x: 15, y: 15}\n"}, RUN,
         expect="s.yaml: robot.actuation.latency: 0.05 s is not a whole number of the simulator's 0.1 s steps"),
    # (it ran as no latency at all; 0.15 s ran as 0.2 s)
    # a typo in a hand-edited model file was read as the key's default
    Case("anfis-model-lookahead-typo",
         python="edited_model(d, ['anfis-tracker', '--episodes', '2'], lambda doc: doc.update(lookahed=doc.pop('lookahead')), "
                "['run', 'path-n', '--model'])", expect="x.json: lookahed: unknown key 'lookahed' (did you mean 'lookahead'?)"),
    Case("anfis-model-inner-unknown-key",
         python="edited_model(d, ['anfis-tracker', '--episodes', '2'], lambda doc: doc['model'].update(premisses=[]), "
                "['run', 'path-n', '--model'])", expect="x.json: premisses: unknown key 'premisses' (did you mean 'premises'?)"),
    Case("neural-model-inner-unknown-key",
         python="edited_model(d, ['neural-tracker', '--episodes', '2'], lambda doc: doc['model'].update(bias=[]), "
                "['run', 'path-n', '--model'])", expect="x.json: bias: unknown key 'bias' (did you mean 'biases'?)"),
    Case("fql-goal-model-speed-typo", python="fuzzy_model(d, 'fql-goal', constant_sped=0.5)",
         expect="m.json: constant_sped: unknown key 'constant_sped' (did you mean 'constant_speed'?)"),
    Case("fql-avoid-model-guard-typo", python="fuzzy_model(d, 'fql-avoid', turn_gaurd=True)",
         expect="m.json: turn_gaurd: unknown key 'turn_gaurd' (did you mean 'turn_guard'?)"),
    Case("fql-wall-model-sensing-typo", python="fuzzy_model(d, 'fql-wall', sensng='rays')",
         expect="m.json: sensng: unknown key 'sensng' (did you mean 'sensing'?)"),
    # MATLAB implies a negated Mamdani conclusion with 1 − μ(term), fuzzylite hedges the degree: the
    # .fis reader gave fuzzylite's answer as MATLAB's, and the writer wrote what MATLAB reads otherwise
    Case("fis-negated-mamdani-conclusion", {"t.fis": _fis().replace("2, 2 (1) : 1", "2, -1 (1) : 1")},
         _eval("t.fis"), expect="t.fis: line 29: MATLAB reads a negated conclusion of a Mamdani output as 1 − μ"),
    Case("fis-negated-premise-ok", {"t.fis": _fis().replace("2, 2 (1) : 1", "-1, 2 (1) : 1")}, _eval("t.fis"),
         status=0, expect='{"v": 0.'),
    Case("fll-negated-conclusion-to-fis", {"t.fll": _fll("then v is hi", "then v is not lo")},
         ("fis", "convert", "{d}/t.fll", "--to", "fis", "-o", "{d}/t.fis"),
         expect="rules: MATLAB reads a negated conclusion of a Mamdani output as 1 − μ of the term, fuzzylite as "
                "the term at 1 − the rule's degree, and the two answer otherwise ('v is not lo'): write it as fll"),
    Case("model-kind-in-capitals", python="fuzzy_model(d, 'FQL-goal')",
         expect="m.json: kind: unknown model kind 'FQL-goal' (did you mean q-goal, fql-goal?)"),
    Case("fuzzy-json-defuzz-for-defuzzifier",
         python="edited_system(d, lambda doc: doc.update(defuzz=doc.pop('defuzzifier')))",
         expect="edited.json: defuzz: unknown key 'defuzz'"),  # ignored: the method's default defuzzifier ran
    Case("fis-role-without-lock-range", python="""
from fuzzynav.cli import main
assert main(["fis", "convert", "goal-seeking", "--to", "fis", "-o", str(d / "g.fis")]) == 0
(d / "g.fis").write_text((d / "g.fis").read_text().replace("% fuzzynav: LockRange=1\\n", ""))
raise SystemExit(main(["run", "circles-0-000", "--controller", "goal-seeking", "--fis", f"gsb={d / 'g.fis'}"]))
""", expect="this one is a fuzzylite engine, its input drg not clipped to its range"),  # it said only what a TS0 needs
    Case("fql-avoid-model-on-a-lidar", python="""
from fuzzynav.cli import main
assert main(["train", "fql-avoid", "--episodes", "8", "--quiet", "--out", str(d / "a.json")]) == 0
raise SystemExit(main(["run", "fig-IV-22a", "--model", str(d / "a.json"), "--sensors", "lidar"]))
""", expect="sensors: this controller reads the 7 range sensors of the thesis' ring (sensors thesis or beam), not 271"),
    Case("fql-goal-model-with-its-keys-ok", python="fuzzy_model(d, 'fql-goal', constant_speed=0.5, training={'task': 'fql-goal'})",
         status=0, expect="fig-IV-23 / fql-goal"),
]

# inputs that gave a silent wrong answer: an angle in degrees read as radians, a learned rule base
# with a rule deleted (the robot stopped wherever only that rule would have fired)
SILENT = [
    Case("scenario-theta-in-degrees", {"s.yaml": "robot: {x: 5, y: 5, theta: 90}\ngoal: {x: 15, y: 15}\n"}, RUN,
         expect="s.yaml: robot.theta: must be in radians, at most 2π = 6.2832 in magnitude, got 90 (if that is "
                "degrees: 1.5708 rad)"),
    Case("scenario-ellipse-angle-in-degrees",
         {"s.yaml": "robot: {x: 2, y: 2}\ngoal: {x: 15, y: 15}\n"
                    "obstacles: [{ellipse: {center: [10, 10], radii: [2, 1], angle: -45}}]\n"}, RUN,
         expect="s.yaml: obstacles[0].ellipse.angle: must be in radians, at most 2π = 6.2832 in magnitude, got -45"),
    Case("api-start-heading-in-degrees",
         python=f"fuzzynav.run_episode({_SCENARIO}, {_CONTROLLER}, start=[2, 2, 90])",
         expect="starts[0].theta: must be in radians, at most 2π = 6.2832 in magnitude, got 90.0 (if that is degrees"),
    Case("scenario-theta-one-turn-ok", {"s.yaml": "robot: {x: 5, y: 5, theta: -6.28}\ngoal: {x: 15, y: 15}\n"}, RUN,
         status=0, expect='"outcome": "reached"'),
    Case("fql-avoid-model-rule-deleted",
         python="edited_model(d, ['fql-avoid', '--episodes', '2', '--quiet'], lambda doc: doc['rules'].pop(0), "
                "['run', 'fig-IV-22a', '--model'])",
         expect="x.json: rules: no rule for the situation front is P and right is P and left is P and open is D: a "
                "learned rule base has a rule for every combination of its input terms (was a rule deleted?)"),
    Case("fql-goal-model-rule-deleted",
         python="edited_model(d, ['fql-goal', '--episodes', '2', '--quiet'], lambda doc: doc['rules'].pop(4), "
                "['run', 'fig-IV-23', '--model'])", expect="x.json: rules: no rule for the situation drg is P and theta is PG"),
]

EIGHTH = [
    # an engine (.fll) took a Linear term of an input, then evaluating it raised numpy's ValueError
    Case("fll-linear-input-term", {"t.fll": _fll("term: lo Triangle 0 0 1\n  term: hi Triangle 0 1 1\nOutput",
                                                 "term: lo Linear 2 0\n  term: hi Triangle 0 1 1\nOutput")},
         _eval("t.fll"), expect="t.fll: x.lo: a linear term concludes a ts1 rule; it cannot describe an input"),
    # numpy's interpolation overflowed between them: a warning on stderr and μ = 0 (the points say 0.5)
    Case("fll-discrete-points-1e308-apart", {"t.fll": _fll("term: lo Triangle 0 0 1\n  term: hi Triangle 0 1 1\nOutput",
                                                           "term: lo Discrete -1e308 1 1e308 0\n  term: hi Triangle 0 1 1\n"
                                                           "Output")},
         _eval("t.fll"), expect="t.fll: x.lo: discrete points must lie at most 1e+300 apart, got x from -1e+308 to 1e+308"),
    # public classes and functions given the wrong types: TypeError, ValueError or matplotlib's errors
    Case("api-variable-universe-of-text", python="fuzzynav.Variable('x', 'ab', {})",
         expect="x.universe: universe must be two numbers (lo, hi), got 'ab'"),
    Case("api-variable-universe-of-three", python="fuzzynav.Variable('x', (0, 1, 2), {})",
         expect="x.universe: universe must be two numbers (lo, hi), got (0, 1, 2)"),
    Case("api-variable-terms-a-list", python="fuzzynav.Variable('x', (0, 1), [1])",
         expect="x: terms must be a mapping of labels to membership functions, got [1]"),
    Case("api-rule-premises-none", python="fuzzynav.Rule(None, (('v', 'F'),))",
         expect="premises: must be (variable, term) pairs, got None"),
    Case("api-rule-conclusion-triple", python="fuzzynav.Rule((('drg', 'Z'),), (('v', 'F', 'G'),))",
         expect="conclusions: must be (variable, term) pairs, got (('v', 'F', 'G'),)"),
    Case("api-rule-weight-text", python="fuzzynav.Rule((('drg', 'Z'),), (('v', 'F'),), '0.5')",  # read as 0.5
         expect="IF drg IS Z THEN v IS F WITH '0.5': rule weight must be a number in [0, 1], got '0.5'"),
    Case("api-learning-curve-text", python="fuzzynav.plot_learning_curve('abc')",
         expect="curve: must be an array of numbers, got 'abc'"),
    Case("api-learning-curve-nan", python="fuzzynav.plot_learning_curve([1.0, float('nan')])",  # drawn with a gap
         expect="curve: must be finite numbers (no NaN or infinity)"),
    Case("api-learning-curve-1e308", python="fuzzynav.plot_learning_curve([1e308, -1e308, 1e308])",
         expect="curve: a learning curve's values must lie within ±1e+15, got 1e+308"),
    Case("api-learning-curve-into-a-text-file", python="fuzzynav.plot_learning_curve([1, 2], path=d / 'c.txt')",
         expect="c.txt': matplotlib cannot write '.txt' files"),
    # a name of control characters: its ESC reached the terminal as a command (run's summary line,
    # fis show), matplotlib warned "Glyph 0 missing" on stderr for a NUL, a line break split the line
    *[Case(f"scenario-name-with-{label}", {"s.yaml": ROBOT + "goal: {x: 15, y: 15}\nname: " + name + "\n"}, RUN,
           expect=f"s.yaml: name: must not hold control characters, got {shown}")
      for label, name, shown in (("an-escape", '"\\e[31mred"', "'\\x1b[31mred'"), ("a-nul", '"a\\0b"', "'a\\x00b'"),
                                 ("a-line-break", '"a\\nb"', "'a\\nb'"))],
    Case("fll-engine-name-with-an-escape", {"t.fll": _fll("Engine: t", "Engine: t\x1b[2J")}, _eval("t.fll"),
         expect="t.fll: line 1: must not hold control characters, got 'Engine: t\\x1b[2J'"),
    Case("fll-variable-name-with-an-escape", {"t.fll": _fll("InputVariable: x\n", "InputVariable: x\x1b[2J\n")},
         _eval("t.fll"), expect="t.fll: line 2: must not hold control characters, got 'InputVariable: x\\x1b[2J'"),
    Case("fll-term-label-with-a-bell", {"t.fll": _fll("term: hi Triangle 0 1 1\nOutput", "term: h\x07i Triangle 0 1 1\nOutput")},
         _eval("t.fll"), expect="t.fll: line 6: must not hold control characters, got '  term: h\\x07i Triangle 0 1 1'"),
    Case("api-engine-variable-name-with-an-escape", python="""
from fuzzynav.fuzzy.io import to_fll
from fuzzynav.fuzzy.io.fll import from_fll_engine
engine = from_fll_engine(to_fll(fuzzynav.thesis_system('goal-seeking')))
engine.inputs[0].name = 'drg\\x1b[2J'  # an engine built in Python, as no file can now give it
type(engine)(engine.inputs, engine.outputs, engine.blocks)""",
         expect="variables: must not hold control characters, got 'drg\\x1b[2J'"),
    Case("fll-discrete-term-on-a-line-of-200000-characters-ok",  # (a line is checked for control characters only)
         {"t.fll": _fll("term: lo Triangle 0 0 1\n  term: hi Triangle 0 1 1\nOutput",
                        "term: lo Discrete " + " ".join(f"{i / 20000:.6f} {1 - i / 20000:.6f}" for i in range(20001))
                        + "\n  term: hi Triangle 0 1 1\nOutput")}, _eval("t.fll"), status=0, expect='{"v": 0.'),
    Case("fis-name-with-an-escape", {"t.fis": _fis().replace("Name='t'", "Name='t\x1b[2J'")}, _eval("t.fis"),
         expect="t.fis: line 2: must not hold control characters, got \"Name='t\\x1b[2J'\""),
    Case("fuzzy-json-name-with-an-escape", python="edited_system(d, lambda doc: doc.update(name='gs\\x1b[2J'))",
         expect="edited.json: name: must not hold control characters, got 'gs\\x1b[2J'"),
    Case("bench-ray-address-empty", argv=("bench", "circles:1", "--controllers", "goal-seeking", "--backend", "ray",
                                          "--ray-address", "", "--out", "{d}/b"),  # started a local Ray instead
         expect="--ray-address: is empty: give HOST:PORT, ray://HOST:PORT, auto or local, or leave it out"),
    # fis eval refused the NaN, fis plot --surface drew it as a hole without a word
    Case("fis-plot-surface-of-nan-answers", python="""
from fuzzynav.cli import main
from fuzzynav.fuzzy.io import to_fll
text = to_fll(fuzzynav.thesis_system('goal-seeking')).replace('term: P Triangle 0.1 3.5 8.0', 'term: P Function alpha')
(d / 'g.fll').write_text(text)
raise SystemExit(main(['fis', 'plot', str(d / 'g.fll'), '--surface', '-o', str(d / 'p.png')]))""",
         expect="g.fll: --surface: alpha: no finite answer for drg=0.0, theta=-3.141592653589793: alpha = nan"),
    # an .npz model whose kind array was edited ran as its document's kind, silently; a document of
    # bytes or a number was read by its str(): "line 1, column 1: invalid JSON"
    Case("npz-model-kind-edited", python="""
from fuzzynav.cli import main
assert main(['train', 'q-goal', '--episodes', '2', '--quiet', '--out', str(d / 'm.npz')]) == 0
with np.load(d / 'm.npz') as data:
    np.savez(d / 'x.npz', kind=np.array('fql-goal'), document=data['document'])
raise SystemExit(main(['run', 'fig-IV-23', '--model', str(d / 'x.npz')]))""",
         expect="x.npz: kind: the archive's kind 'fql-goal' is not its document's 'q-goal' (an edited archive?"),
    Case("npz-model-document-of-bytes",
         python="np.savez(d / 'x.npz', kind=np.array('q-goal'), document=np.array(b'{}'))\n"
                "from fuzzynav.cli import main\nraise SystemExit(main(['run', 'fig-IV-23', '--model', str(d / 'x.npz')]))",
         expect="x.npz: document: must be one text (a 0-d unicode array, as fuzzynav writes it), got an array of |S2"),
    # held-out worlds in a folder were compared with a family's (or another folder's) by path only:
    # the worlds `worlds generate` wrote, or a copy of a training file, were taken as unseen ones
    Case("tune-held-out-folder-of-the-training-family", python="""
from fuzzynav.cli import main
assert main(['worlds', 'generate', 'circles', '--n', '2', '--out', str(d / 'w')]) == 0
raise SystemExit(main(['tune', 'goal-seeking:gsb', '--worlds', 'circles:2', '--holdout', str(d / 'w'),
                       '--budget', '400', '--out', str(d / 't.yaml')]))""",
         expect="--holdout: shares 2 worlds with --worlds circles:2: held-out worlds are worlds the tuner never saw"),
    Case("tune-held-out-folder-of-a-copy", python="""
import shutil
from fuzzynav.cli import main
assert main(['worlds', 'generate', 'circles', '--n', '2', '--out', str(d / 'w')]) == 0
(d / 'h').mkdir()
shutil.copy(d / 'w' / 'circles-0-001.yaml', d / 'h' / 'mine.yaml')
raise SystemExit(main(['tune', 'goal-seeking:gsb', '--worlds', str(d / 'w'), '--holdout', str(d / 'h'),
                       '--validation', 'none', '--budget', '400', '--out', str(d / 't.yaml')]))""",
         expect="--holdout: shares 1 world with --worlds"),
    # import barn overwrote an edited world_0.yaml of its --out (worlds generate refuses to)
    Case("import-barn-over-an-edited-world", python="""
from fuzzynav.cli import main
w = barn_world(d, 'world_0')
assert main(['import', 'barn', str(w), '--out', str(d / 'o')]) == 0
(d / 'o' / 'world_0.yaml').write_text((d / 'o' / 'world_0.yaml').read_text() + '# mine\\n')
import_barn(d, w)""", expect="o: --out: world_0.yaml already there, with other content (edited?): not overwritten"),
    Case("import-barn-again-at-another-scale-ok", python="""
from fuzzynav.cli import main
w = barn_world(d, 'world_0')
assert main(['import', 'barn', str(w), '--out', str(d / 'o'), '--scale', '1.5']) == 0
assert main(['import', 'barn', str(w), '--out', str(d / 'o')]) == 0
print((d / 'o' / 'benchmark.json').read_text())""", status=0, expect='"scale": 1.0'),
    # FQLAgent's own arguments: total_steps=-5 or NaN trained nothing without a word, '100' ended in a
    # TypeError; predict() of three columns read a goal task's two, of NaN answered NaN
    *[Case(f"gym-fql-agent-{label}", python=f"""
from fuzzynav.gym.fql_agent import FQLAgent
env = gymnasium.make_vec('fuzzynav/GoalSeeking-v0', num_envs=2, vectorization_mode='vector_entry_point')
{code}""", expect=expect) for label, code, expect in (
        ("total-steps-negative", "FQLAgent('goal').learn(env, -5)",
         "total_steps: must be an integer in [0, 9007199254740992], got -5"),
        ("total-steps-nan", "FQLAgent('goal').learn(env, float('nan'))", "total_steps: must be an integer, got float nan"),
        ("tolerance-negative", "FQLAgent('goal', tolerance=-1)", "tolerance: must be >= 0, got -1"),
        ("predict-three-columns", "FQLAgent('goal').learn(env, 20).predict(np.zeros((1, 3)))",
         "obs: must be observations of shape (B, 2) of the environment learned on, got shape (1, 3)"),
        ("predict-nan", "FQLAgent('goal').learn(env, 20).predict([[float('nan'), 0.0]])",
         "obs: must be finite numbers (no NaN or infinity)"))],
    # a scenario's own robot, imperfections or sensor ring were ignored by the Gymnasium environments:
    # the episode ran the default robot, noise-free, on the thesis' rays
    *[Case(f"gym-scenario-with-{label}", {"s.yaml": "robot: {x: 2, y: 2" + robot + "}\ngoal: {x: 15, y: 15}\n" + more},
           python="gymnasium.make('fuzzynav/GoalSeeking-v0', scenario=str(d / 's.yaml')).reset(seed=0)", expect=expect)
      for label, robot, more, expect in (
          ("its-own-robot", ", radius: 1.0", "", "s.yaml: scenario: 's' has a robot of its own (radius 1 m), not the "
                                                 "environment's params: pass params=scenario.robot"),
          ("sensor-noise", ", sensor_noise: {range_sigma: 0.1}", "",
           "s.yaml: scenario: 's' sets the robot's imperfections (range_sigma=0.1): the Gymnasium environments read "
           "noise-free sensors"),
          ("a-lidar", "", "sensors: lidar\n", "s.yaml: scenario: 's' names the lidar sensor ring"))],
    Case("gym-scenario-with-its-own-robot-and-params-ok", {"s.yaml": "robot: {x: 2, y: 2, radius: 1.0}\ngoal: {x: 15, y: 15}\n"},
         python="s = fuzzynav.load_scenario(str(d / 's.yaml'))\n"
                "env = gymnasium.make('fuzzynav/GoalSeeking-v0', scenario=s, params=s.robot)\nenv.reset(seed=0)\n"
                "print(env.unwrapped.episodes.batch.params.radius)", status=0, expect="1.0"),
    # tune simulated the perfect robot on a world with a 1 s latency and slip: tuned and measured
    # as 16 s to the goal where `run` takes 24.5 s
    Case("tune-world-with-imperfections",
         {"w/a.yaml": "robot: {x: 2, y: 2, theta: 0.78, actuation: {latency: 1.0, slip: 0.4}}\ngoal: {x: 15, y: 12}\n"},
         ("tune", "goal-seeking:gsb", "--worlds", "{d}/w", "--budget", "2", "--population", "2", "--validation", "none"),
         expect="a.yaml: robot: tuning simulates the perfect robot; this world sets its imperfections (latency=1, "
                "slip=0.4)"),
    Case("tune-one-world-says-1-world", {"w/a.yaml": "robot: {x: 2, y: 2, theta: 0.78}\ngoal: {x: 15, y: 12}\n"},
         ("tune", "goal-seeking:gsb", "--worlds", "{d}/w", "--budget", "2", "--population", "2", "--validation", "none",
          "--quiet"), status=0, expect="mean time 16.00 s over 1 world\n"),  # said "over 1 worlds"
    # numbers of a .fll file (and rule weights) were read by Python's float: '1_0' as 10, '٢' as 2,
    # where fuzzylite, the .fis reader and the command line refuse them; a .fis '٢٨' was read as 28
    Case("fll-term-breakpoint-with-an-underscore", {"t.fll": _fll("term: hi Triangle 0 1 1\nOutput",
                                                                   "term: hi Triangle 0 1_0 1\nOutput")},
         _eval("t.fll"), expect="t.fll: line 6: term hi: '1_0' is not a number"),
    Case("fll-range-of-arabic-indic-digits", {"t.fll": _fll("range: 0.000 1.000", "range: 0.000 \u0661")},
         _eval("t.fll"), expect="t.fll: line 4: range must be a number, got '\u0661'"),
    Case("fll-rule-weight-with-an-underscore", {"t.fll": _fll("then v is hi\n", "then v is hi with 0_1\n")},
         _eval("t.fll"), expect="rule weight '0_1' is not a number"),
    Case("fuzzy-json-rule-weight-with-an-underscore",
         python="edited_system(d, lambda doc: doc.update(rules=[doc['rules'][0] + ' WITH 0_1'] + doc['rules'][1:]))",
         expect="edited.json: rules[0]: rule weight '0_1' is not a number"),
    Case("fis-range-of-arabic-indic-digits", {"t.fis": _fis("[0 \u0661]")}, _eval("t.fis"),
         expect="Range must be [lo hi], got '[0 \u0661]'"),
    Case("fis-mf-parameter-with-an-underscore", {"t.fis": _fis().replace("MF2='hi':'trimf',[0 1 1]\n\n[Output1]",
                                                                          "MF2='hi':'trimf',[0 1_0 1_0]\n\n[Output1]")},
         _eval("t.fis"), expect="t.fis: line 18: hi: '1_0' is not a number"),  # read as [0 10 10]
    # written to .fis, read back renamed: the variable x-y as xy, the system a%b as a (% begins a comment)
    Case("fll-variable-name-to-fis-read-back-otherwise",
         {"t.fll": _FLL.replace("InputVariable: x\n", "InputVariable: x-y\n").replace("if x is", "if x-y is")},
         ("fis", "convert", "{d}/t.fll", "--to", "fis", "-o", "{d}/t.fis"),
         expect="t.fll: x-y: the variable name 'x-y' would read back otherwise from a .fis file"),
    Case("fll-engine-name-to-fis-read-back-otherwise", {"t.fll": _fll("Engine: t\n", "Engine: t%2\n")},
         ("fis", "convert", "{d}/t.fll", "--to", "fis", "-o", "{d}/t.fis"),
         expect="t.fll: name: the name 't%2' would read back otherwise from a .fis file"),
    # a folder, world file or model file named with an ESC: bench printed it to the terminal in its
    # table, and matplotlib warned "Glyph 27 missing" on stderr for each plot
    Case("bench-folder-name-with-an-escape", {"w\x1b[31m/a.yaml": "robot: {x: 2, y: 2}\ngoal: {x: 15, y: 15}\nname: a\n"},
         ("bench", "{d}/w\x1b[31m", "--controllers", "goal-seeking", "--out", "{d}/b"),
         expect="SUITE: must not hold control characters, got 'w\\x1b[31m'"),
    Case("bench-world-file-name-with-an-escape", {"w/a\x1b[2J.yaml": "robot: {x: 2, y: 2}\ngoal: {x: 15, y: 15}\nname: a\n"},
         ("bench", "{d}/w", "--controllers", "goal-seeking", "--out", "{d}/b"),
         expect="SUITE: must not hold control characters, got 'a\\x1b[2J'"),
    Case("bench-model-file-name-with-an-escape", python="""
from fuzzynav.cli import main
assert main(['train', 'q-goal', '--episodes', '2', '--quiet', '--out', str(d / 'm\\x1b[1m.json')]) == 0
raise SystemExit(main(['bench', 'circles:1', '--controllers', str(d / 'm\\x1b[1m.json'), '--out', str(d / 'b')]))""",
         expect="--controllers: must not hold control characters, got 'm\\x1b[1m'"),
    Case("fis-show-training-protocol-with-an-escape",  # printed on the terminal as it was
         python="edited_model(d, ['fql-goal', '--episodes', '2', '--quiet'], "
                "lambda doc: doc['training'].update(protocol='\\x1b[2J'), ['fis', 'show'])",
         expect="x.json: training.protocol: must not hold control characters, got '\\x1b[2J'"),
    # an argument or a file named with an ESC was printed as it is in the error naming it
    Case("run-scenario-argument-with-an-escape", argv=("run", "fig\x1b[2J"),
         expect="fig\\x1b[2J: SCENARIO: no such scenario file or built-in scenario"),
    Case("fis-eval-input-with-an-escape", argv=("fis", "eval", "goal-seeking", "--input", "d\x1b[2Jrg=1"),
         expect="goal-seeking: --input d\\x1b[2Jrg=1: expected NAME=VALUE"),
]

CASES = [*GYM, *API, *COUNTS, *FUZZY, *CAMPAIGN, *CHECKPOINT, *SCENARIOS, *ASCII, *NAMES_AND_IMPORTS, *SEVENTH,
         *SILENT, *EIGHTH]
