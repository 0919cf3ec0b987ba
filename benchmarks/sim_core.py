"""Simulator-core step rate against IR-SIM, in one run: sensing (7 rays), nearest obstacle (D_ro,
θ_o), the controller, kinematics, task and stop tests, in a world of 15 mixed obstacles.

One robot is timed with a constant command (the compiled open-loop :class:`ConstantCommand`: the
numbers measure the simulator) and, with ``--controller NAME``, with that controller in the loop
(goal at (19, 19); an episode that ends starts again); their chunks alternate with IR-SIM's
headless chunks of one robot under the same constant command (``benchmarks/irsim_peer.py`` in a
subprocess) — ``irsim`` with a lidar of the thesis' 7 beams over 180°, ``irsim_lidar`` with the
271 beams over 270° of ``fuzzy-5b``'s lidar (compare ``fuzzy-5b`` with that one) —, so every
ratio compares chunks run under the same load (the ratio is the median of the per-chunk ratios). Then batches of 64, 1,024 and 8,192 robots spread over the free space
(only robots still running count). Rates are medians of 7 chunks, wall clock and this process's
CPU time (steadier on a busy machine).

``moving_20`` times moving obstacles: the world of 15 plus 20 discs that move (lines reflecting at
the border, circles, sinusoids, waypoint loops; :func:`moving_world`) against the same world with
those 20 discs standing where they start, one robot and 64 robots, chunks alternating; its
``slowdown`` is the median of the per-chunk ratios static / moving (the target: at most 2).

IR-SIM lives in its own virtual environment (it pins its own NumPy): give its Python with
``--irsim-python PATH`` or the ``IRSIM_PYTHON`` environment variable, or let ``--setup-peers``
create one (``pip install ir-sim`` into ``--peers-dir``, default ``benchmarks/.peers/irsim``) and
use it. Without IR-SIM the ratios are reported as unavailable. Run:

    python benchmarks/sim_core.py --controller fuzzy-5b-thesis --json [--irsim-python PATH | --setup-peers]
"""

from __future__ import annotations

import json
import math
import os
import statistics
import subprocess
import sys
import time
import venv
from pathlib import Path

import numpy as np

from fuzzynav.catalog.controllers import make_controller
from fuzzynav.cli import Parser
from fuzzynav.control.batched import ConstantCommand
from fuzzynav.kernels.angles import wrap_angle
from fuzzynav.robot.tricycle import DEFAULT_PARAMS
from fuzzynav.sim import BatchSimulator
from fuzzynav.world.scenario import scenario_from_dict

COMMAND = (0.5, 0.4)  # V (m/s), α (rad): circles of radius l / tan α ≈ 1.2 m
ONE_ROBOT_STEPS, IRSIM_STEPS, CHUNKS = 2000, 300, 7
BATCHES = ((64, 100), (1024, 10), (8192, 3))  # robots, steps per timed chunk
PEERS_DIR = Path(__file__).with_name(".peers")
# IR-SIM peers: name in the JSON, lidar beams, field (rad) — the thesis' 7 rays over 180°, and the
# 271-beam lidar over 270° of fuzzy-5b (compare fuzzy-5b with irsim_lidar)
PEERS = (("irsim", 7, math.pi), ("irsim_lidar", 271, 1.5 * math.pi))


def obstacles_of_15(seed: int = 0) -> list[dict]:
    """15 obstacles in scenario-file form, cycling circle, triangle, wall, ellipse."""
    rng = np.random.default_rng(seed)
    shapes = []
    for i in range(15):
        x, y = (float(v) for v in rng.uniform(3, 17, 2))
        shapes.append([
            {"circle": {"center": [x, y], "radius": 0.6}},
            {"polygon": {"points": [[x - 0.5, y - 0.5], [x + 0.5, y - 0.5], [x, y + 0.5]]}},
            {"wall": {"start": [x, y], "end": [x + 1.5, y], "thickness": 0.2}},
            {"ellipse": {"center": [x, y], "radii": [0.8, 0.4], "angle": 0.5}},
        ][i % 4])
    return shapes


def world_of_15(seed: int = 0):
    return scenario_from_dict({"name": "bench-15", "robot": {"x": 1, "y": 1}, "goal": {"x": 19, "y": 19},
                               "obstacles": obstacles_of_15(seed), "max_time": 3600.0}, source="benchmark")


MOVES = (
    {"type": "line", "velocity": [0.8, 0.3]},
    {"type": "circle", "center": [10.0, 10.0], "speed": 0.7},
    {"type": "sinusoid", "velocity": [0.0, 0.5], "amplitude": 1.0, "period": 6.0},
    {"type": "waypoints", "points": [[2.0, 2.0], [18.0, 2.0], [18.0, 18.0]], "speed": 1.2, "loop": True},
)


def moving_world(move: bool = True, seed: int = 2):
    """The world of 15 plus 20 discs of radius 0.3 m, moving (cycling the motions of :data:`MOVES`)
    or, with ``move=False``, standing where they start."""
    rng = np.random.default_rng(seed)
    discs = []
    for i in range(20):
        disc = {"circle": {"center": [float(v) for v in rng.uniform(2, 18, 2)], "radius": 0.3}}
        if move:
            motion = dict(MOVES[i % len(MOVES)])
            if motion["type"] == "waypoints":
                motion["points"] = [disc["circle"]["center"], *motion["points"][1:]]
            disc["motion"] = motion
        discs.append(disc)
    return scenario_from_dict({"name": "bench-15+20", "robot": {"x": 1, "y": 1}, "goal": {"x": 19, "y": 19},
                               "obstacles": obstacles_of_15() + discs, "max_time": 3600.0}, source="benchmark")


def moving_case(make) -> dict:
    """Steps per second with 20 moving obstacles and with the same 20 standing (module docstring)."""
    static, moving = moving_world(False), moving_world(True)
    report = {}
    for n, steps in ((1, ONE_ROBOT_STEPS), (64, 100)):
        starts = start_poses(static, n, clearance=3.0 if n == 1 else 0.5)
        pair = (Timed(static, starts, make()), Timed(moving, starts, make()))
        rates = [[timed.chunk(steps) for timed in pair] for _ in range(CHUNKS)]
        report[str(n)] = {"static_steps_per_s_cpu": round(statistics.median(r[0][1] for r in rates)),
                          "moving_steps_per_s_cpu": round(statistics.median(r[1][1] for r in rates)),
                          "slowdown": round(statistics.median(r[0][1] / r[1][1] for r in rates), 2)}
    return report


def start_poses(scenario, n: int, clearance: float = 0.5) -> np.ndarray:
    """``n`` seeded start poses with at least ``clearance`` (m) to every obstacle and wall."""
    rng = np.random.default_rng(1)
    free = rng.uniform(0.5, 19.5, (40 * n + 400, 2))
    free = free[scenario.world.clearance(free) > clearance][:n]
    return np.column_stack([free, wrap_angle(rng.uniform(-4, 4, n))])


class IrSim:
    """IR-SIM's side: a subprocess that steps one robot in the same world on request."""

    def __init__(self, python: str, start, beams: int = 7, field: float = math.pi):
        job = {"obstacles": obstacles_of_15(), "start": [float(v) for v in start], "command": list(COMMAND),
               "dt": DEFAULT_PARAMS.dt, "max_range": 4.0, "wheelbase": DEFAULT_PARAMS.wheelbase, "beams": beams,
               "field": field}
        self.process = subprocess.Popen([python, str(Path(__file__).with_name("irsim_peer.py"))], text=True,
                                        stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                        env={**os.environ, "MPLBACKEND": "Agg"})
        self.info = self._ask(json.dumps(job))

    def _ask(self, line: str) -> dict:
        self.process.stdin.write(line + "\n")
        self.process.stdin.flush()
        answer = self.process.stdout.readline()
        if not answer:
            raise RuntimeError("the IR-SIM peer stopped (see its stderr above)")
        return json.loads(answer)

    def chunk(self, steps: int = IRSIM_STEPS) -> tuple[float, float]:
        """Steps per second over ``steps`` steps: (wall clock, CPU time of the peer)."""
        times = self._ask(str(steps))
        return steps / times["wall"], steps / max(times["cpu"], 1e-9)

    def close(self) -> None:
        self.process.stdin.close()
        self.process.wait(timeout=60)


def setup_irsim(peers: Path) -> str:
    """The Python of a virtual environment with ``ir-sim`` in ``peers / "irsim"``, created if missing."""
    home = peers / "irsim"
    python = home / ("Scripts/python.exe" if os.name == "nt" else "bin/python")
    if not python.exists():
        print(f"creating the IR-SIM peer environment in {home} (pip install ir-sim) ...", file=sys.stderr)
        venv.create(home, with_pip=True)
        subprocess.run([str(python), "-m", "pip", "install", "--quiet", "ir-sim"], check=True)
    return str(python)


class Timed:
    """One simulator whose steps are timed in chunks (an ended episode or batch starts again)."""

    def __init__(self, scenario, starts, controller):
        self.sim = BatchSimulator(scenario, controller, starts=starts, record=False)
        for _ in range(3):
            self.sim.step()  # compiled kernels loaded, first-step work done

    def chunk(self, steps: int) -> tuple[float, float]:
        """Running-robot steps per second over ``steps`` steps: (wall clock, CPU time)."""
        sim, done, wall, cpu = self.sim, 0, 0.0, 0.0
        for _ in range(steps):
            if sim.done:
                sim.reset()
            running = int(np.count_nonzero(sim.active)) if sim.n > 1 else 1
            w0, c0 = time.perf_counter(), time.process_time()
            sim.step()
            wall += time.perf_counter() - w0
            cpu += time.process_time() - c0
            done += running
        return done / wall, done / max(cpu, 1e-9)


def median(rates, k: int) -> float:
    return statistics.median(r[k] for r in rates)


def ratio(mine, peer, k: int) -> float:
    """Median over the chunks of mine / peer (wall k = 0, CPU k = 1)."""
    return round(statistics.median(a[k] / b[k] for a, b in zip(mine, peer)), 1)


def main(argv=None) -> None:
    parser = Parser(description=__doc__.splitlines()[0])
    parser.add_argument("--json", action="store_true", help="print only one JSON object")
    parser.add_argument("--controller", metavar="NAME", help="a registered controller timed besides the constant "
                                                             "command (e.g. fuzzy-5b-thesis)")
    parser.add_argument("--irsim-python", default=os.environ.get("IRSIM_PYTHON", ""),
                        help="Python of a virtual environment with ir-sim installed (default: $IRSIM_PYTHON)")
    parser.add_argument("--setup-peers", action="store_true", help="create the IR-SIM environment if needed, use it")
    parser.add_argument("--peers-dir", type=Path, default=PEERS_DIR, help=f"where --setup-peers puts it ({PEERS_DIR})")
    parser.add_argument("--also", metavar="JSON", action="append", default=[],
                        help="the same controller built with these options too, timed beside it in the same run "
                             "(e.g. '{\"guidance\": {\"guide_car_reuse\": 0}}'); repeatable")
    args = parser.parse_args(argv)
    irsim_python = setup_irsim(args.peers_dir) if args.setup_peers else args.irsim_python
    scenario = world_of_15()
    one = start_poses(scenario, 1, clearance=3.0)  # room for the circle of diameter 2.4 m
    controllers = {"constant": lambda: ConstantCommand(COMMAND[1], COMMAND[0])}
    if args.controller:
        controllers[args.controller] = lambda: make_controller(args.controller)
        for text in args.also:
            options = json.loads(text)
            controllers[f"{args.controller} {text}"] = lambda options=options: make_controller(args.controller, **options)
    peers = {}
    if irsim_python:
        for name, beams, field in PEERS:
            try:
                peers[name] = IrSim(irsim_python, one[0], beams, field)
            except (OSError, RuntimeError, ValueError) as error:
                print(f"IR-SIM ({name}) unavailable: {error}", file=sys.stderr)
    single = {name: Timed(scenario, one, make()) for name, make in controllers.items()}
    rates = {name: [] for name in single}
    peer = {name: [] for name in peers}
    for _ in range(CHUNKS):
        for name, irsim in peers.items():
            peer[name].append(irsim.chunk())
        for name, timed in single.items():
            rates[name].append(timed.chunk(ONE_ROBOT_STEPS))
    report = {"benchmark": "sim_core", "obstacles": 15, "sensors": 7, "one_robot": {}, "robot_steps_per_s": {},
              **{name: None for name, _, _ in PEERS}}
    for name, r in rates.items():
        row = {"steps_per_s_wall": round(median(r, 0)), "steps_per_s_cpu": round(median(r, 1))}
        for peer_name, times in peer.items():
            row.update({f"x_{peer_name}_wall": ratio(r, times, 0), f"x_{peer_name}_cpu": ratio(r, times, 1)})
        report["one_robot"][name] = row
    for name, make in controllers.items():
        report["robot_steps_per_s"][name] = {}
        for n, steps in BATCHES:
            timed = Timed(scenario, start_poses(scenario, n), make())
            r = [timed.chunk(steps) for _ in range(5)]
            report["robot_steps_per_s"][name][str(n)] = {"wall": round(median(r, 0)), "cpu": round(median(r, 1))}
    report["moving_20"] = {name: moving_case(make) for name, make in controllers.items()}
    for name, irsim in peers.items():
        irsim.close()
        report[name] = {"version": irsim.info["version"], "beams": irsim.info["beams"],
                        "steps_per_s_wall": round(median(peer[name], 0)),
                        "steps_per_s_cpu": round(median(peer[name], 1))}
    if args.json:
        print(json.dumps(report))
        return
    for name, row in report["one_robot"].items():
        ratios = "".join(f"  {row[f'x_{peer_name}_wall']}x {peer_name} wall, {row[f'x_{peer_name}_cpu']}x CPU"
                         for peer_name in peers)
        print(f"1 robot, {name:12s} {row['steps_per_s_wall']:>10,} steps/s wall {row['steps_per_s_cpu']:>10,} CPU{ratios}")
    for name, rows in report["robot_steps_per_s"].items():
        for n, row in rows.items():
            print(f"{n:>5} robots, {name:10s} {row['wall']:>10,} robot-steps/s wall {row['cpu']:>10,} CPU")
    for name, rows in report["moving_20"].items():
        for n, row in rows.items():
            print(f"{n:>5} robots, {name:10s} 20 moving obstacles: {row['moving_steps_per_s_cpu']:>10,} steps/s CPU, "
                  f"static {row['static_steps_per_s_cpu']:>10,}: {row['slowdown']}x slower")
    if not peers:
        print("IR-SIM: unavailable (--irsim-python, IRSIM_PYTHON or --setup-peers)")
    for name in peers:
        print(f"{name}: IR-SIM {report[name]['version']} ({report[name]['beams']} beams, 1 robot, headless): "
              f"{report[name]['steps_per_s_wall']:,} steps/s wall, {report[name]['steps_per_s_cpu']:,} CPU")
    print(json.dumps(report))


if __name__ == "__main__":
    main()
