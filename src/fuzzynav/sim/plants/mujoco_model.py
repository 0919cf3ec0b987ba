"""The MuJoCo model (MJCF text) of a world and its tricycles, for :mod:`.mujoco_plant`.

The robot is the kinematic model's tricycle (thesis §IV.4, Fig IV.15) given a body: its frame
sits at the middle of the rear axle (the kinematic pose (x, y, θ)), two driven rear wheels
``width`` apart, one steered front wheel ``wheelbase`` ahead, all of radius
:attr:`Physique.wheel_radius`, under a chassis box whose centre of mass lies a third of the
wheelbase ahead of the rear axle (about 60 % of the weight on the driven wheels). The
numbers of :class:`Physique` are those of a small indoor tricycle of the thesis' size
(l = D = 0.5 m), chosen here: the thesis gives none.

The world's obstacles are static geoms in geom group :data:`OBSTACLE_GROUP`, built from the
packed scene the kernels read (:mod:`fuzzynav.kernels.layout`), so every obstacle type is
covered: discs as cylinders, ellipses as tall ellipsoids, each polygon edge as a thin box
whose outer face lies on the edge, the world's rectangle as four walls. They are for the
range sensors' ray casting only (no contacts: the simulator's judge stops a robot at the
first touch of its footprint disc, :mod:`fuzzynav.sim.plants`). The robots touch the floor
only, with their wheels (so several robots in one world pass through each other, as in the
kinematic plant).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from fuzzynav.kernels import layout

OBSTACLE_GROUP = 1  # geom group of the obstacles: the only geoms the range sensors see
WALL_HEIGHT = 1.0  # m, every obstacle
SKIN = 1e-3  # m: half thickness of the box of a polygon edge (its outer face on the edge)
TALL = 100.0  # m: vertical semi-axis of an ellipse's ellipsoid (its section at sensor height: ×(1 − 2e-6))


@dataclass(frozen=True)
class Physique:
    """Mass, inertia, tyres and actuators of the simulated tricycle (SI units).

    ``drive_torque`` limits each rear wheel's motor (N·m), whose velocity servo has gain
    ``drive_gain`` (N·m per rad/s); the steering servo is a position servo of stiffness
    ``steer_gain`` (N·m/rad), damping ``steer_damping`` and torque limit ``steer_torque``.
    ``friction`` is the tyres' sliding friction coefficient on the floor (rubber on concrete
    ≈ 0.7–1). The rear wheels turn at the speeds of an ideal differential, V (1 ∓ D tan α / 2l) / r.
    """

    mass: float = 20.0  # kg, chassis
    wheel_mass: float = 0.5  # kg, each wheel
    wheel_radius: float = 0.1  # m
    wheel_half_width: float = 0.025  # m
    friction: float = 0.9
    drive_torque: float = 6.0  # N·m per driven wheel: up to ≈ 5 m/s² on flat ground
    drive_gain: float = 20.0
    steer_gain: float = 600.0
    steer_damping: float = 12.0
    steer_torque: float = 30.0
    sensor_height: float = 0.3  # m above the floor, over the chassis: the rays see obstacles only
    timestep: float = 0.002  # s, MuJoCo's step (Δt of the controller / this = substeps)


def _f(*values) -> str:
    return " ".join(f"{float(v):.9g}" for v in values)


def obstacle_geoms(scene: np.ndarray) -> list[str]:
    """MJCF ``<geom>`` elements of the obstacles and boundary walls of a packed ``scene``."""
    width, height = scene[layout.WIDTH], scene[layout.HEIGHT]
    z, half = 0.5 * WALL_HEIGHT, 0.5 * WALL_HEIGHT
    common = f'group="{OBSTACLE_GROUP}" rgba="0.5 0.5 0.5 1"'
    geoms = []
    thick = 0.5
    for cx, cy, hx, hy in ((-thick, 0.5 * height, thick, 0.5 * height + 2 * thick),
                           (width + thick, 0.5 * height, thick, 0.5 * height + 2 * thick),
                           (0.5 * width, -thick, 0.5 * width + 2 * thick, thick),
                           (0.5 * width, height + thick, 0.5 * width + 2 * thick, thick)):
        geoms.append(f'<geom type="box" pos="{_f(cx, cy, z)}" size="{_f(hx, hy, half)}" {common}/>')
    at = int(scene[layout.AT_CIRCLES])
    for i in range(int(scene[layout.N_CIRCLES])):
        cx, cy, r = scene[at + 3 * i:at + 3 * i + 3]
        geoms.append(f'<geom type="cylinder" pos="{_f(cx, cy, z)}" size="{_f(r, half)}" {common}/>')
    edges = scene[int(scene[layout.AT_EDGES]):int(scene[layout.AT_EDGES]) + 7 * int(scene[layout.N_EDGES])].reshape(-1, 7)
    at = int(scene[layout.AT_POLYGONS])
    for p in range(int(scene[layout.N_POLYGONS])):
        first, end = (int(v) for v in scene[at + 5 * p:at + 5 * p + 2])
        rows = edges[first:end]
        area = 0.5 * float(np.sum(rows[:, 0] * rows[:, 3] - rows[:, 2] * rows[:, 1]))
        inward = 1.0 if area > 0 else -1.0  # interior to the left of each edge of a CCW polygon
        for ax, ay, _, _, ex, ey, length2 in rows:
            length = math.sqrt(length2)
            if length == 0.0:
                continue
            nx, ny = -inward * ey / length, inward * ex / length  # towards the interior
            cx, cy = ax + 0.5 * ex + SKIN * nx, ay + 0.5 * ey + SKIN * ny
            angle = math.atan2(ey, ex)
            geoms.append(f'<geom type="box" pos="{_f(cx, cy, z)}" size="{_f(0.5 * length + SKIN, SKIN, half)}" '
                         f'euler="{_f(0.0, 0.0, angle)}" {common}/>')
    at = int(scene[layout.AT_ELLIPSES])
    for i in range(int(scene[layout.N_ELLIPSES])):
        cx, cy, a, b, c, s, _ = scene[at + 7 * i:at + 7 * i + 7]
        geoms.append(f'<geom type="ellipsoid" pos="{_f(cx, cy, 0.0)}" size="{_f(a, b, TALL)}" '
                     f'euler="{_f(0.0, 0.0, math.atan2(s, c))}" {common}/>')
    return geoms


def robot_body(name: str, pose, params, physique: Physique) -> str:
    """MJCF ``<body>`` of one tricycle called ``name`` at ``pose`` (x, y, θ); ``params`` a
    :class:`~fuzzynav.robot.tricycle.TricycleParams` (wheelbase, width, steering limit)."""
    x, y, theta = (float(v) for v in pose)
    r, w, half_track, l = physique.wheel_radius, physique.wheel_half_width, 0.5 * params.width, params.wheelbase
    tyre = (f'type="cylinder" size="{_f(r, w)}" euler="{_f(math.pi / 2, 0, 0)}" mass="{_f(physique.wheel_mass)}" '
            f'contype="2" conaffinity="1" condim="3" friction="{_f(physique.friction, 0.005, 0.0001)}"')
    chassis_z = r + 0.05
    rear = "".join(f'<body name="{name}_{side}" pos="{_f(0, sign * half_track, 0)}">'
                   f'<joint name="{name}_{side}" type="hinge" axis="0 1 0" damping="0.001"/>'
                   f'<geom {tyre}/></body>' for side, sign in (("left", 1), ("right", -1)))
    return (f'<body name="{name}" pos="{_f(x, y, r)}" quat="{_f(math.cos(theta / 2), 0, 0, math.sin(theta / 2))}">'
            f'<freejoint name="{name}"/>'
            f'<geom type="box" pos="{_f(l / 3, 0, chassis_z - r)}" size="{_f(0.5 * l, half_track - w, 0.04)}" '
            f'mass="{_f(physique.mass)}" rgba="0.2 0.4 0.8 1"/>'
            f'{rear}'
            f'<body name="{name}_fork" pos="{_f(l, 0, 0)}">'
            f'<joint name="{name}_steer" type="hinge" axis="0 0 1" limited="true" '
            f'range="{_f(-params.max_steering, params.max_steering)}" armature="0.01" damping="0.1"/>'
            f'<geom type="box" size="0.02 0.02 0.02" pos="0 0 {_f(r)}" mass="0.2"/>'
            f'<body name="{name}_front"><joint name="{name}_front" type="hinge" axis="0 1 0" damping="0.001"/>'
            f'<geom {tyre}/></body></body></body>')


def robot_actuators(name: str, params, physique: Physique) -> str:
    """The steering servo and the two drive motors of robot ``name`` (actuators 3i … 3i + 2)."""
    p = physique
    return (f'<position name="{name}_steer" joint="{name}_steer" kp="{_f(p.steer_gain)}" kv="{_f(p.steer_damping)}" '
            f'forcelimited="true" forcerange="{_f(-p.steer_torque, p.steer_torque)}" '
            f'ctrllimited="true" ctrlrange="{_f(-params.max_steering, params.max_steering)}"/>'
            + "".join(f'<velocity name="{name}_{side}" joint="{name}_{side}" kv="{_f(p.drive_gain)}" '
                      f'forcelimited="true" forcerange="{_f(-p.drive_torque, p.drive_torque)}"/>'
                      for side in ("left", "right")))


def model_xml(scene: np.ndarray, poses: np.ndarray, params, physique: Physique) -> str:
    """The MJCF text of a world (packed ``scene``) with one tricycle per row of ``poses`` (N, 3)."""
    names = [f"robot{i}" for i in range(len(poses))]
    width, height = scene[layout.WIDTH], scene[layout.HEIGHT]
    floor = (f'<geom name="floor" type="plane" pos="{_f(0.5 * width, 0.5 * height, 0)}" '
             f'size="{_f(0.5 * width + 5, 0.5 * height + 5, 0.1)}" contype="1" conaffinity="2" '
             f'friction="0.1 0.005 0.0001"/>')  # contacts take the larger friction: the tyres'
    return (f'<mujoco model="fuzzynav"><compiler angle="radian"/>'
            f'<option timestep="{_f(physique.timestep)}" integrator="implicitfast"/>'
            f'<default><geom contype="0" conaffinity="0"/></default>'
            f'<worldbody>{floor}{"".join(obstacle_geoms(scene))}'
            f'{"".join(robot_body(name, pose, params, physique) for name, pose in zip(names, poses))}</worldbody>'
            f'<actuator>{"".join(robot_actuators(name, params, physique) for name in names)}</actuator></mujoco>')
