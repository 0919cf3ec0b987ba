"""Import worlds of the BARN benchmark (Benchmark Autonomous Robot Navigation, D. Perille,
A. Truong, X. Xiao, P. Stone, *Benchmarking metric ground navigation*, IEEE SSRR 2020; the
ICRA BARN Challenge) as scenario files.

A BARN world (``world_N.world``, Gazebo SDF) holds static models of one cylinder each (posts of
radius 0.075 m on a 0.15 m grid); the challenge's ``run.py`` starts the robot at (−2.25, 3)
heading π/2 (+y), the goal 10 m ahead at (−2.25, 13), success within 1 m of it with no
collision, a 100 s limit, and scores a run with the optimal path from ``path_N.npy`` (grid cells
(r, c) ↦ (0.15 r − 4.575, 0.15 c + 5.075) m, the start and the goal added at its ends).

Conversion (:func:`barn_scenario`): every post becomes a circle; the world is the post field
(x ∈ [−4.5, 0], y ∈ [0, 9.6]) with the start and goal and a ``MARGIN`` of free space around it,
moved so that its lower-left corner is the origin; everything is then multiplied by ``scale``
(positions, radii, the goal tolerance and the optimal path length; the 100 s limit is kept), so
a robot bigger than BARN's Jackal can be given the same worlds with proportionally wider gaps.
"""

from __future__ import annotations

import io
import re
import xml.etree.ElementTree as ElementTree
from pathlib import Path

import numpy as np

from fuzzynav import validation
from fuzzynav.errors import InputError
from fuzzynav.world import limits
from fuzzynav.world.polylines import path_length

START = (-2.25, 3.0, 1.57)  # run.py, static worlds 0–299
GOAL_OFFSET = (0.0, 10.0)
GOAL_TOLERANCE = 1.0  # m
TIME_LIMIT = 100.0  # s
FIELD = (-4.5, 0.0, 0.0, 9.6)  # x_min, x_max, y_min, y_max of the post field (m)
MARGIN = 1.0  # m of free space around the field, the start and the goal
POST_SPACING = 0.15  # m: run.py's path cell (2 × the post radius 0.075)


def read_posts(path: Path) -> np.ndarray:
    """Posts ``(n, 3)`` (x, y, radius) of a BARN ``.world`` file: the top-level models' poses and
    their collision cylinders (the ``<state>`` block repeats the poses and is not read). A path that
    is not a regular file (a named pipe, a device, a folder) is refused, not read."""
    data = validation.read_bytes(path, source=str(path))  # a named pipe or a folder is refused, not read
    try:
        root = ElementTree.fromstring(data)
    except ElementTree.ParseError as error:
        raise InputError(f"unreadable SDF world ({getattr(error, 'strerror', None) or error})",
                         source=str(path)) from None
    world = root.find("world")
    if world is None:
        raise InputError("no <world> element", source=str(path), field="sdf.world")
    posts = []
    for model in world.findall("model"):
        name = model.get("name", "?")
        if model.find(".//collision/geometry/plane") is not None:
            continue  # the ground plane
        cylinder = model.find(".//collision/geometry/cylinder")
        pose = model.find("pose")
        if cylinder is None or pose is None or cylinder.find("radius") is None:
            raise InputError("model is not a posed cylinder (only BARN's posts are imported)",
                             source=str(path), field=f"world.model[{name}]")
        try:
            x, y = (float(v) for v in pose.text.split()[:2])
            radius = float(cylinder.find("radius").text)
        except (ValueError, AttributeError, TypeError):
            raise InputError("unreadable pose or radius", source=str(path), field=f"world.model[{name}]") from None
        posts.append((x, y, radius))
    if not posts:
        raise InputError("no cylinder models", source=str(path), field="world.model")
    return np.array(posts)


MAX_CELL = 1e6  # |grid cell| of a path file (BARN's grid is 30 × 30 cells)
MAX_PATH_CELLS = 10**6  # cells of a path file (BARN's paths have fewer than 100)


def optimal_path_length(path_file: Path) -> float:
    """Length (m) of BARN's optimal path of ``path_N.npy`` with the start and the goal added (run.py).

    The file must be a regular ``.npy`` file of one ``(n, 2)`` array (1 ≤ n ≤ ``MAX_PATH_CELLS``) of
    finite numbers within ±``MAX_CELL``, read whole (at most ``MAX_MODEL_BYTES``) without pickle,
    so a header declaring more data than the file holds, an ``.npz`` archive, pickled objects, a
    named pipe or an unreadable file are refused (InputError naming the file)."""
    cells = _read_cells(path_file)
    if not np.all(np.isfinite(cells)) or np.abs(cells).max() > MAX_CELL:
        raise InputError(f"grid cells must be finite numbers within ±{MAX_CELL:g}", source=str(path_file))
    half = POST_SPACING / 2
    points = np.column_stack([cells[:, 0] * POST_SPACING - half - 30 * POST_SPACING,
                              cells[:, 1] * POST_SPACING + half + 5.0])
    start, goal = np.array(START[:2]), np.array(START[:2]) + GOAL_OFFSET
    points = np.vstack([start, points, goal])
    return path_length(points)


def _read_cells(path_file: Path) -> np.ndarray:
    """The array of ``path_file``, checked (:func:`optimal_path_length`)."""
    source = str(path_file)
    try:
        data = validation.read_bytes(path_file, max_bytes=validation.MAX_MODEL_BYTES, source=source)
        cells = np.load(io.BytesIO(data), allow_pickle=False)
    except InputError:
        raise
    except Exception as error:  # numpy raises many types on hostile headers (ValueError, OSError, ...)
        raise InputError(f"unreadable path file ({type(error).__name__}: {error})", source=source) from None
    if not isinstance(cells, np.ndarray):
        if hasattr(cells, "close"):
            cells.close()
        raise InputError(f"must be one .npy array of grid cells, got {type(cells).__name__} "
                         "(an .npz archive saved under the .npy name?)", source=source)
    if cells.ndim != 2 or cells.shape[1] != 2 or len(cells) == 0:
        raise InputError(f"must be an (n, 2) array of grid cells, got shape {cells.shape}", source=source)
    if len(cells) > MAX_PATH_CELLS:
        raise InputError(f"must hold at most {MAX_PATH_CELLS} grid cells, got {len(cells)}", source=source)
    if cells.dtype.kind not in "iuf":
        raise InputError(f"must hold grid cells as numbers, got dtype {cells.dtype}", source=source)
    return cells


def world_index(path: Path) -> int | None:
    """N of ``world_N.world`` (None for another name)."""
    match = re.fullmatch(r"world_(\d+)", path.stem)
    return int(match.group(1)) if match else None


GOAL = (START[0] + GOAL_OFFSET[0], START[1] + GOAL_OFFSET[1])
X0, Y0 = FIELD[0] - MARGIN, FIELD[2] - MARGIN  # the world's lower-left corner, before scaling
SIZE = (FIELD[1] + MARGIN - X0, max(FIELD[3], GOAL[1] + GOAL_TOLERANCE) + MARGIN - Y0)  # (m) at scale 1


def check_scale(scale, field: str = "--scale") -> float:
    """``scale`` for :func:`barn_scenario`: a finite number > 0 at which the world fits the world
    size limit (a larger one would make every world too large, or overflow to inf)."""
    return validation.number(scale, field=field, lo=0.0, lo_open=True, hi=limits.MAX_WORLD_SIZE / max(SIZE))


def barn_scenario(posts: np.ndarray, name: str, scale: float = 1.0) -> dict:
    """The scenario document (module docstring) of a BARN world's ``posts`` at ``scale``."""
    move = lambda x, y: [round(float(scale * (x - X0)), 6), round(float(scale * (y - Y0)), 6)]
    return {
        "name": name,
        "description": f"BARN {name} at scale {scale:g} (posts -> circles, the challenge's start, goal and time limit)",
        "world": {"width": round(scale * SIZE[0], 6), "height": round(scale * SIZE[1], 6)},
        "robot": dict(zip(("x", "y"), move(*START[:2])), theta=START[2]),
        "goal": dict(zip(("x", "y"), move(*GOAL)), tolerance=round(scale * GOAL_TOLERANCE, 6)),
        "obstacles": [{"circle": {"center": move(x, y), "radius": round(float(scale * r), 6)}} for x, y, r in posts],
        "max_time": TIME_LIMIT,
    }


def find_path_file(world_file: Path) -> Path | None:
    """BARN's ``path_N.npy`` for ``world_N.world``: beside it or in ``path_files/`` (the repository's layout)."""
    n = world_index(world_file)
    if n is None:
        return None
    for candidate in (world_file.with_name(f"path_{n}.npy"), world_file.parent / "path_files" / f"path_{n}.npy"):
        if candidate.is_file():
            return candidate
    return None
