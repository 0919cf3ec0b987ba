"""IR-SIM side of ``benchmarks/sim_core.py``: headless step rate of one robot in the same world.

Run by ``sim_core.py`` in a subprocess with the Python of a virtualenv where the PyPI package
``ir-sim`` is installed (it pins its own NumPy, so it never goes into the project's venv). Reads
one JSON line on stdin — ``obstacles`` (scenario-file shapes), ``start`` (x, y, θ), ``command``
(V, α), ``dt``, ``max_range``, ``wheelbase`` and optionally the lidar's ``beams`` and ``field``
(rad; default 7 over π) —, builds the world, prints one JSON line with
IR-SIM's version and the beam count, then for every line ``N`` on stdin runs N steps and prints
``{"wall": s, "cpu": s}`` (so the caller can interleave its own timed chunks with IR-SIM's).

The world is built to match: 20 m × 20 m, one Ackermann (car-like, the tricycle's kinematics)
robot, a 2-D lidar of 7 beams over [−90°, +90°] (the thesis layout of §IV.7), or the beams and
field asked (271 over 270°: the lidar of ``fuzzy-5b``), with the same range, rendering off (``headless``), IR-SIM's own collision checks on. IR-SIM has no ellipse,
so ellipses become 32-gons; walls become their rectangles.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import tempfile
import time
from pathlib import Path

import yaml


def _polygon(shape: dict) -> list[list[float]]:
    """Vertices of a polygon, wall rectangle or ellipse 32-gon (absolute coordinates)."""
    kind, spec = next(iter(shape.items()))
    if kind == "polygon":
        return [list(map(float, p)) for p in spec["points"]]
    if kind == "wall":
        (x0, y0), (x1, y1) = spec["start"], spec["end"]
        length = math.hypot(x1 - x0, y1 - y0)
        nx, ny = -(y1 - y0) / length * spec["thickness"] / 2, (x1 - x0) / length * spec["thickness"] / 2
        return [[x0 - nx, y0 - ny], [x1 - nx, y1 - ny], [x1 + nx, y1 + ny], [x0 + nx, y0 + ny]]
    (cx, cy), (a, b), angle = spec["center"], spec["radii"], spec.get("angle", 0.0)
    c, s = math.cos(angle), math.sin(angle)
    points = []
    for k in range(32):
        u, v = a * math.cos(2 * math.pi * k / 32), b * math.sin(2 * math.pi * k / 32)
        points.append([cx + c * u - s * v, cy + s * u + c * v])
    return points


def world_yaml(job: dict) -> dict:
    obstacles = []
    for shape in job["obstacles"]:
        if "circle" in shape:
            spec = shape["circle"]
            obstacles.append({"shape": {"name": "circle", "radius": float(spec["radius"])},
                              "state": [float(spec["center"][0]), float(spec["center"][1]), 0.0]})
        else:
            obstacles.append({"shape": {"name": "polygon", "vertices": _polygon(shape)}})
    x, y, theta = job["start"]
    return {
        "world": {"height": 20.0, "width": 20.0, "step_time": job["dt"], "sample_time": job["dt"],
                  "offset": [0.0, 0.0], "collision_mode": "stop", "control_mode": "auto"},
        "robot": [{
            "kinematics": {"name": "acker"},
            "shape": {"name": "rectangle", "length": 0.6, "width": 0.5, "wheelbase": job["wheelbase"]},
            "state": [x, y, theta, 0.0],
            "goal": [19.0, 19.0, 0.0],
            "vel_max": [4.0, 1.0],
            "sensors": [{"name": "lidar2d", "range_min": 0.0, "range_max": job["max_range"],
                         "angle_range": job.get("field", math.pi), "number": job.get("beams", 7)}],
        }],
        "obstacle": obstacles,
    }


def main() -> None:
    argparse.ArgumentParser(description=__doc__.split("\n\n")[0]).parse_args()  # --help; the job comes on stdin
    answers, sys.stdout = sys.stdout, sys.stderr  # IR-SIM's own messages stay off the answers
    import irsim
    import numpy as np

    job = json.loads(sys.stdin.readline())
    with tempfile.NamedTemporaryFile("w", suffix=".yaml", delete=False) as handle:
        yaml.safe_dump(world_yaml(job), handle)
    try:
        env = irsim.make(handle.name, headless=True, log_level="ERROR")
    finally:
        Path(handle.name).unlink()  # IR-SIM has read the world; no file left behind
    action = np.array([[job["command"][0]], [job["command"][1]]])
    for _ in range(3):
        env.step(action)
    print(json.dumps({"version": irsim.__version__, "beams": int(len(env.get_lidar_scan()["ranges"]))}),
          file=answers, flush=True)
    for line in sys.stdin:
        w0, c0 = time.perf_counter(), time.process_time()
        for _ in range(int(line)):
            env.step(action)
        print(json.dumps({"wall": time.perf_counter() - w0, "cpu": time.process_time() - c0,
                          "collided": bool(env.robot.collision_flag)}), file=answers, flush=True)


if __name__ == "__main__":
    main()
