"""The hostile inputs of the validation review, one :class:`Case` each: files to write, a command
line (or Python code) to run, and what must happen — exit status 2 (or an InputError) with the
expected text in the message, or, for inputs that are fine, exit 0.

Used by ``test_hostile_inputs.py`` (in process) and by ``hostile_subprocesses.py`` (each case
a subprocess with a 10 s timeout: tracebacks, hangs and silent wrong answers counted).
"""

from __future__ import annotations

import io
import json
import zipfile
from dataclasses import dataclass, field

import numpy as np

from fuzzynav.fuzzy.io import to_document
from fuzzynav.fuzzy.systems import get_system

ROBOT = "robot: {x: 1, y: 1, theta: 0}\n"
GOAL = "goal: {x: 18, y: 18}\n"


@dataclass(frozen=True)
class Case:
    """``argv`` (``{d}`` is the case's directory) or ``python`` code run with ``d`` bound to it;
    ``status`` expected (2: refused, 0: accepted) and ``expect`` text in the message / output."""

    name: str
    files: dict = field(default_factory=dict)
    argv: tuple = ()
    python: str = ""
    status: int = 2
    expect: str = ""


def _fis(**changes) -> str:
    return json.dumps({**to_document(get_system("goal-seeking")), **changes})


def _mamdani(resolution) -> str:
    doc = to_document(get_system("goal-seeking"))
    doc["outputs"] = [{"name": "alpha", "universe": [-1, 1], "terms": {"N": {"kind": "triangle", "params": [-1, -1, 0]},
                                                                        "P": {"kind": "triangle", "params": [0, 1, 1]}}}]
    doc.update(method="mamdani", defuzzifier="centroid", rules=["IF drg IS Z THEN alpha IS N",
                                                                  "IF drg IS P THEN alpha IS P"])
    return json.dumps({**doc, "resolution": "__R__"}).replace('"__R__"', resolution)


def _grid(**grid) -> str:
    doc = to_document(get_system("goal-seeking"))
    doc["rules"] = {"grid": {"rows": "theta", "columns": "drg", "outputs": ["alpha", "v"], **grid}}
    return json.dumps(doc)


def _linear_input() -> str:
    doc = to_document(get_system("goal-seeking"))
    doc["inputs"][0]["terms"]["Z"] = {"kind": "linear", "params": [1.0, 0.0, 0.0]}
    return json.dumps(doc)


def _fql_gap() -> str:
    doc = {"kind": "fql-goal", **to_document(get_system("goal-seeking")), "constant_speed": 1.0}
    doc["inputs"][0]["terms"]["P"]["params"] = [0.1, 3.5, 6.0]  # P ends at 6 m, M starts at 6.5 m: a gap
    doc["inputs"][0]["terms"]["M"]["params"] = [6.5, 8.0, 13.0]
    return json.dumps(doc)


def _npz_declaring(shape) -> bytes:
    """An .npz whose one member's header declares ``shape`` (float64) over a few bytes of data."""
    header = io.BytesIO()
    np.lib.format.write_array_header_1_0(header, {"descr": "<f8", "fortran_order": False, "shape": shape})
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w") as archive:
        archive.writestr("kind.npy", header.getvalue() + b"\0" * 64)
    return buffer.getvalue()


def _aliases(n: int) -> str:
    return "anchors: &a [1, 2]\nmany: [" + ", ".join(["*a"] * n) + "]\n" + ROBOT + GOAL


def _polygon(n: int) -> str:
    t = np.linspace(0, 2 * np.pi, n, endpoint=False)
    points = np.column_stack([10 + 3 * np.cos(t), 10 + 3 * np.sin(t)]).round(6).tolist()
    return ROBOT + GOAL + "obstacles:\n  - polygon: {points: " + json.dumps(points) + "}\n"


def _nested_yaml(depth: int) -> str:
    return ROBOT + GOAL + "description: " + "[" * depth + "]" * depth + "\n"


RUN = ("run", "{d}/s.yaml", "--controller", "goal-seeking", "--json")
BIG = "1" + "0" * 400

CASES = [
    Case("scenario-400-digit-integer", {"s.yaml": f"robot: {{x: {BIG}, y: 1}}\n" + GOAL}, RUN, expect="robot.x"),
    Case("scenario-max-time-1e308", {"s.yaml": ROBOT + GOAL + "max_time: 1e308\n"}, RUN, expect="max_time"),
    Case("scenario-max-time-1e6", {"s.yaml": ROBOT + GOAL + "max_time: 1e6\n"}, RUN, expect="max_time"),
    Case("scenario-deep-nesting", {"s.yaml": _nested_yaml(100_000)}, RUN, expect="nest"),
    Case("scenario-list-key", {"s.yaml": ROBOT + GOAL + "[1, 2]: 3\n"}, RUN, expect="a key must be a plain value"),
    Case("scenario-integer-key", {"s.yaml": ROBOT + GOAL + "7: 3\n"}, RUN, expect="keys must be strings"),
    Case("scenario-extreme-ellipse", {"s.yaml": ROBOT + GOAL + "obstacles:\n  - ellipse: {center: [10, 10], "
                                                                "radii: [1e-300, 1e300]}\n"}, RUN, expect="radii[0]"),
    Case("scenario-10000-vertex-polygon", {"s.yaml": _polygon(10_000)}, RUN, expect="at most 1000 points"),
    Case("scenario-30000-vertex-polygon", {"s.yaml": _polygon(30_000)}, RUN, expect="at most 1000 points"),
    Case("scenario-200000-aliases", {"s.yaml": _aliases(200_000)}, RUN, expect="more than 1000 aliases"),
    Case("scenario-base-60", {"s.yaml": "world: {width: 1:20, height: 20}\n" + ROBOT + GOAL}, RUN,
         expect="world.width: must be a number, got '1:20'"),
    Case("scenario-goal-unreachable-corner", {"s.yaml": ROBOT + "goal: {x: 20, y: 20, tolerance: 0.3}\n"}, RUN,
         expect="goal: goal (20, 20) cannot be reached"),
    Case("scenario-obstacle-outside-world", {"s.yaml": ROBOT + GOAL + "obstacles:\n  - circle: {center: [50, 50], "
                                                                      "radius: 1}\n"}, RUN,
         expect="obstacles[0]: circle lies wholly outside"),
    Case("scenario-non-utf8", {"s.yaml": b"robot: {x: 1, y: 1}\n# \xff\xfe\n"}, RUN, expect="not UTF-8"),
    Case("fis-non-utf8", {"g.fll": b"Engine: x\n\xff\xfe\n"}, ("fis", "show", "{d}/g.fll"), expect="not UTF-8"),
    Case("fis-deep-json", {"g.json": "[" * 100_000 + "]" * 100_000}, ("fis", "show", "{d}/g.json"),
         expect="nested deeper"),
    *[Case(f"fis-resolution-{label}", {"g.json": _mamdani(value)}, ("fis", "show", "{d}/g.json"), expect="resolution")
      for label, value in (("abc", '"abc"'), ("list", "[200]"), ("nan", "NaN"), ("inf", "Infinity"), ("1e14", "1e14"),
                           ("1e9", "1000000000"))],
    Case("fis-grid-integer-cells", {"g.json": _grid(cells=[1, 2, 3, 4, 5, 6, 7])}, ("fis", "show", "{d}/g.json"),
         expect="rules.grid.cells[0]"),
    Case("fis-grid-integer-row-labels", {"g.json": _grid(cells=["Z"] * 7, row_labels=[1, 2, 3, 4, 5, 6, 7])},
         ("fis", "show", "{d}/g.json"), expect="rules.grid.row_labels[0]"),
    Case("fis-linear-input-term", {"g.json": _linear_input()}, ("fis", "show", "{d}/g.json"),
         expect="inputs.drg.Z"),
    Case("fis-kind-as-list", {"g.json": _fis(inputs=[{"name": "drg", "universe": [0, 1],
                                                       "terms": {"Z": {"kind": ["triangle"], "params": [0, 0, 1]}}}])},
         ("fis", "show", "{d}/g.json"), expect="kind"),
    Case("model-kind-as-list", {"m.json": json.dumps({"kind": ["fql-goal"]})},
         ("run", "example-goal", "--model", "{d}/m.json"), expect="kind: must be a string"),
    Case("model-tracker-400-digit-speed", {"m.json": json.dumps({"kind": "neural-tracker", "input_range": [-3, 3],
                                                                  "model": {}}).replace('"model"', f'"speed": {BIG}, "model"')},
         ("run", "example-path", "--model", "{d}/m.json"), expect="speed"),
    Case("model-tracker-activation", {"m.json": json.dumps({"kind": "neural-tracker", "input_range": [-3, 3], "model": {
        "format": "fuzzynav-mlp", "version": 1, "activation": "relu", "weights": [[[1.0]]], "biases": [[0.0]]}})},
         ("run", "example-path", "--model", "{d}/m.json"), expect="activation: must be 'tanh'"),
    Case("model-npz-8-tib-member", {"m.npz": _npz_declaring((2**40,))}, ("run", "example-goal", "--model", "{d}/m.npz"),
         expect="declares an array of 8796093022208 bytes"),
    Case("model-fql-gap-between-terms", {"m.json": _fql_gap()}, ("run", "example-goal", "--model", "{d}/m.json"),
         expect="m.json: inputs.drg: no term covers drg = 6 "),
    Case("evaluate-n-1e20", {}, ("evaluate", "--controller", "goal-seeking", "--worlds", "circles", "--n", "1" + "0" * 20),
         expect="--n: must be an integer in [1, 100000]"),
    Case("csv-duplicate-header", {"in.csv": "drg,theta,drg\n1,0,5\n"}, ("fis", "eval", "goal-seeking", "--csv", "{d}/in.csv"),
         expect="'drg' appear more than once"),
    Case("csv-utf8-bom", {"in.csv": "\ufeffdrg,theta\r\n1,0\r\n"}, ("fis", "eval", "goal-seeking", "--csv", "{d}/in.csv"),
         status=0, expect="drg,theta,alpha,v\n1.0,0.0,"),
    Case("python-world-nan", python="World(float('nan'), 20)", expect="world.width: must be finite"),
    Case("python-circle-negative-radius", python="Circle([1, 1], -1)", expect="radius: must be > 0"),
    Case("python-two-point-polygon", python="Polygon([[0, 0], [1, 1]])", expect="points: needs 3 to 1000 points"),
    Case("python-zero-length-wall", python="Wall([1, 1], [1, 1])", expect="end: must differ from start"),
    Case("python-nan-command", status=0,
         python="trace = run_episode(load_scenario('example-goal'), Constant(float('nan'), 1.0))\n"
                "print(trace.outcome, trace.invalid_command)",
         expect="invalid_command step 0: steering nan, speed 1.0"),
    Case("python-checkpoint-rng-out-of-range",
         python="resume_changed(d, lambda doc: doc['rng']['state'].update(state=-1))", expect="rng: bad RNG state"),
    Case("python-checkpoint-string-curve-rows",
         python="resume_changed(d, lambda doc: doc['curve'].update(mean_reward=[['0.5']]))",
         expect="curve.mean_reward[0]: must hold numbers"),
    Case("python-none-command", python="run_episode(load_scenario('example-goal'), Constant(None, None))",
         expect="controller constant: step 0: returned None"),
]

# Python cases run with these names bound (and ``d``, the case's directory)
PYTHON_PRELUDE = """
from fuzzynav.control.base import Command, Controller
from fuzzynav.sim.simulator import run_episode
from fuzzynav.world.scenario import load_scenario
from fuzzynav.world.shapes import Circle, Polygon, Wall
from fuzzynav.world.world import World

def resume_changed(d, change):
    # write a checkpoint, apply change to its document, then load and restore it
    import json
    import numpy as np
    from fuzzynav.learn.checkpoint import load_checkpoint, restore, save_checkpoint
    from fuzzynav.learn.tabular import TabularLearner
    path = d / "run.checkpoint.json"
    curve = {"mean_reward": [[0.0]], "steps": [[1]], "success": [[False]]}
    save_checkpoint(path, TabularLearner(4, 2), np.random.default_rng(0), 1, curve)
    document = json.loads(path.read_text())
    change(document)
    path.write_text(json.dumps(document))
    restore(TabularLearner(4, 2), np.random.default_rng(), load_checkpoint(path), str(path))

class Constant(Controller):
    name = "constant"
    def __init__(self, steering, speed):
        self.command = None if steering is None else Command(steering, speed)
    def act(self, obs):
        return self.command
"""


def write_files(case: Case, directory) -> None:
    """Write the files of ``case`` into ``directory``."""
    for name, content in case.files.items():
        path = directory / name
        path.parent.mkdir(parents=True, exist_ok=True)
        if isinstance(content, bytes):
            path.write_bytes(content)
        else:
            path.write_text(content, encoding="utf-8")


def argv_of(case: Case, directory) -> list[str]:
    return [arg.replace("{d}", str(directory)) for arg in case.argv]

