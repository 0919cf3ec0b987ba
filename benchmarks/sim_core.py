"""Simulator-core step rate: sensing (7 rays), nearest obstacle (D_ro, θ_o),
kinematics, task and stop tests, for 1, 64 and 1,024 robots (spread over the free space) stepped
together in a world of 15 mixed obstacles — and IR-SIM's headless step rate for one robot in the
same world, measured in the same run (``benchmarks/irsim_peer.py`` in a subprocess).

By default the controller is a trivial vectorised law (``act_batch``: constant speed and steering,
the robots drive circles), so the numbers measure the simulator, not a fuzzy controller; IR-SIM gets
the same command. ``--controller fuzzy-5b`` (any registered name) puts that controller in the loop
instead (goal at (19, 19); only robots still running count, and a batch whose robots have all
finished starts again), while IR-SIM keeps its constant command. Rates are medians of 7 timed chunks, wall clock and this process's CPU time
(the latter is steadier on a busy machine). The one-robot chunks alternate with IR-SIM's, so both
see the same load, and the ratio is the median of the per-chunk ratios. Run:

    python benchmarks/sim_core.py [--json] [--controller fuzzy-5b] [--irsim-python /work/venv-irsim/bin/python]

``--profile`` instead runs the one-robot loop under cProfile and prints where a step's time goes
(µs per step by function, cumulative; cProfile inflates each Python call, so read the shares).

``--json`` prints only one JSON object. Without a usable IR-SIM interpreter (or with
``--irsim-python ''``) the IR-SIM column is reported as unavailable.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

from fuzzynav.catalog.controllers import make_controller
from fuzzynav.robot.tricycle import DEFAULT_PARAMS
from fuzzynav.sim import BatchSimulator
from fuzzynav.world.geometry import wrap_angle
from fuzzynav.world.scenario import scenario_from_dict

COMMAND = (0.5, 0.4)  # V (m/s), α (rad): circles of radius l / tan α ≈ 1.2 m
COUNTS = ((1, 2000), (64, 100), (1024, 10))  # robots, steps per timed chunk
DEFAULT_IRSIM_PYTHON = "/work/venv-irsim/bin/python"


class Circling:
    """Constant command for every robot (they drive circles until they hit something); the
    command arrays are built once (the simulator clips them into new arrays)."""

    name = "circling"

    def reset(self, rng=None):
        self.command = None

    def act_batch(self, obs):
        if self.command is None or len(self.command[0]) != obs.n:
            self.command = np.full(obs.n, COMMAND[1]), np.full(obs.n, COMMAND[0])
        return self.command


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
                               "obstacles": obstacles_of_15(seed), "max_time": 1e9}, source="benchmark")


def start_poses(scenario, n: int, clearance: float = 0.5) -> np.ndarray:
    """``n`` seeded start poses with at least ``clearance`` (m) to every obstacle and wall."""
    rng = np.random.default_rng(1)
    free = rng.uniform(0.5, 19.5, (40 * n + 400, 2))
    free = free[scenario.world.clearance(free) > clearance][:n]
    return np.column_stack([free, wrap_angle(rng.uniform(-4, 4, n))])


class IrSim:
    """IR-SIM's side: a subprocess that steps one robot in the same world on request."""

    def __init__(self, python: str, start):
        job = {"obstacles": obstacles_of_15(), "start": [float(v) for v in start], "command": list(COMMAND),
               "dt": DEFAULT_PARAMS.dt, "max_range": 4.0, "wheelbase": DEFAULT_PARAMS.wheelbase}
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

    def chunk(self, steps: int) -> tuple[float, float]:
        """Steps per second over ``steps`` steps: (wall clock, CPU time of the peer)."""
        times = self._ask(str(steps))
        return steps / times["wall"], steps / max(times["cpu"], 1e-9)

    def close(self) -> None:
        self.process.stdin.close()
        self.process.wait(timeout=60)


def chunks(scenario, starts, steps: int, count: int = 7, between=None, controller=None) -> list[tuple[float, float]]:
    """``count`` timed chunks of ``steps`` steps: running-robot steps per second (wall clock, CPU
    time of this process) each; ``between()`` runs after every chunk (IR-SIM's interleaved chunk).
    ``controller`` defaults to :class:`Circling`; a batch whose robots have all finished restarts."""
    sim = BatchSimulator(scenario, controller or Circling(), starts=starts, record=False)
    for _ in range(3):
        sim.step()
    rates = []
    for _ in range(count):
        done, wall, cpu = 0, 0.0, 0.0
        for _ in range(steps):
            if sim.done:
                sim.reset()
            running = int(sim.active.sum())
            w0, c0 = time.perf_counter(), time.process_time()
            sim.step()
            wall += time.perf_counter() - w0
            cpu += time.process_time() - c0
            done += running
        rates.append((done / wall, done / max(cpu, 1e-9)))
        if between is not None:
            between()
    return rates


def profile(scenario, start, controller, steps: int = 3000, top: int = 25) -> None:
    """Print µs per step (cumulative, own) of the ``top`` costliest fuzzynav functions in the
    one-robot loop, under cProfile (``--profile``)."""
    import cProfile
    import pstats

    sim = BatchSimulator(scenario, controller or Circling(), starts=start, record=False)

    def loop():
        for _ in range(steps):
            if sim.done:
                sim.reset()
            sim.step()

    loop()  # warm up: caches, first-call set-up
    profiler = cProfile.Profile()
    profiler.runcall(loop)
    stats = pstats.Stats(profiler).stats
    rows = sorted(((cum, own, f"{Path(file).name}:{line}({name})") for (file, line, name), (_, _, own, cum, _)
                   in stats.items() if "fuzzynav" in file), reverse=True)
    print(f"{'µs/step cumulative':>18} {'own':>7}  function (cProfile, {steps} steps, one robot)")
    for cum, own, where in rows[:top]:
        print(f"{cum / steps * 1e6:18.1f} {own / steps * 1e6:7.1f}  {where}")


def median_pair(rates) -> tuple[float, float]:
    return statistics.median(r[0] for r in rates), statistics.median(r[1] for r in rates)


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--json", action="store_true", help="print only one JSON object")
    parser.add_argument("--irsim-python", default=DEFAULT_IRSIM_PYTHON,
                        help="Python of a venv with ir-sim installed ('' to skip)")
    parser.add_argument("--controller", metavar="NAME",
                        help="a registered controller in the loop (e.g. fuzzy-5b) instead of the constant command")
    parser.add_argument("--profile", action="store_true", help="where the one-robot step's time goes (cProfile)")
    args = parser.parse_args(argv)
    make = (lambda: make_controller(args.controller)) if args.controller else (lambda: None)
    scenario = world_of_15()
    one = start_poses(scenario, 1, clearance=3.0)  # room for the circle of diameter 2.4 m
    if args.profile:
        profile(scenario, one, make())
        return
    irsim, irsim_rates = None, []
    if args.irsim_python and os.path.exists(args.irsim_python):
        try:
            irsim = IrSim(args.irsim_python, one[0])
        except (OSError, RuntimeError, ValueError) as error:
            print(f"IR-SIM unavailable: {error}", file=sys.stderr)
    between = (lambda: irsim_rates.append(irsim.chunk(300))) if irsim is not None else None
    single = chunks(scenario, one, COUNTS[0][1], between=between, controller=make())
    results = {1: median_pair(single)}
    for n, steps in COUNTS[1:]:
        results[n] = median_pair(chunks(scenario, start_poses(scenario, n), steps, controller=make()))
    report = {
        "benchmark": "sim_core", "controller": args.controller or "circling", "obstacles": 15, "sensors": 7,
        "robot_steps_per_s_wall": {str(n): round(w) for n, (w, _) in results.items()},
        "robot_steps_per_s_cpu": {str(n): round(c) for n, (_, c) in results.items()},
        "irsim": None,
    }
    if irsim is not None:
        irsim.close()
        wall, cpu = median_pair(irsim_rates)
        report["irsim"] = {
            "version": irsim.info["version"], "beams": irsim.info["beams"],
            "steps_per_s_wall": round(wall), "steps_per_s_cpu": round(cpu),
            "ratio_1_robot_wall": round(statistics.median(a[0] / b[0] for a, b in zip(single, irsim_rates)), 1),
            "ratio_1_robot_cpu": round(statistics.median(a[1] / b[1] for a, b in zip(single, irsim_rates)), 1),
            "ratio_1024_robots_cpu": round(results[1024][1] / cpu, 1),
        }
    if args.json:
        print(json.dumps(report))
        return
    print(f"{'robots':>7} {'robot-steps/s (wall)':>21} {'robot-steps/s (CPU)':>20} {'steps/s (wall)':>15}")
    for n, (wall, cpu) in results.items():
        print(f"{n:7d} {wall:21,.0f} {cpu:20,.0f} {wall / n:15,.0f}")
    if irsim is None:
        print("IR-SIM: unavailable (see --irsim-python)")
    else:
        r = report["irsim"]
        print(f"IR-SIM {r['version']} (1 robot, {r['beams']} beams, headless): {r['steps_per_s_wall']:,} steps/s wall, "
              f"{r['steps_per_s_cpu']:,} CPU; fuzzynav / IR-SIM: {r['ratio_1_robot_wall']}x wall, "
              f"{r['ratio_1_robot_cpu']}x CPU (1 robot), {r['ratio_1024_robots_cpu']}x CPU (1,024 robots)")
    print(json.dumps(report))


if __name__ == "__main__":
    main()
