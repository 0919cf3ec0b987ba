"""The MuJoCo plant: the tricycle as a rigid body in the MuJoCo physics engine (E. Todorov,
T. Erez, Y. Tassa, *MuJoCo: a physics engine for model-based control*, IROS 2012), its range
sensors by MuJoCo's ray casting (``mj_multiRay``). Needs the optional extra ``physics``.

Each step Δt of the controller, the clipped commands (α, V) become the set points of the
steering servo (α) and of the two rear wheels' velocity servos (the ideal differential's wheel
speeds, :class:`.mujoco_model.Physique`), held for Δt / timestep physics steps; the robot's
pose is then its rear-axle frame's position and yaw. So the robot accelerates and steers within
its motors' torques, its tyres may slip, and the pose follows. The readings are the first hits
of horizontal rays at the sensor height against the obstacle geoms; a sensor with a beam
(``beam_width`` > 0) reads the nearest of a fan of rays at most :data:`FAN_STEP` apart across its
cone. The world's moving obstacles are not modelled: a scenario with some is refused.
"""

from __future__ import annotations

import math

import mujoco
import numpy as np

from fuzzynav.errors import InputError
from fuzzynav.kernels.step import SPEED, STEERING, THETA, X, Y
from fuzzynav.sim.plants import Plant
from fuzzynav.sim.plants.mujoco_model import OBSTACLE_GROUP, Physique, model_xml

FAN_STEP = math.radians(1.0)  # rad between the rays of a beam sensor's fan
DEFAULT_PHYSIQUE = Physique()


class MujocoPlant(Plant):
    """The tricycles of one scenario in one MuJoCo model (:mod:`.mujoco_model`)."""

    name = "mujoco"
    in_kernel = False

    def __init__(self, scenario, params, sensors, n: int, physique: Physique = DEFAULT_PHYSIQUE):
        super().__init__(scenario, params, sensors, n)
        world = scenario.world
        if len(world.movers):
            raise InputError(f"the mujoco plant simulates static worlds; scenario {scenario.name!r} has "
                             f"{len(world.movers)} moving obstacles", field="--plant")
        self.physique = physique
        self.model = mujoco.MjModel.from_xml_string(model_xml(world.scene, np.zeros((n, 3)), params, physique))
        self.data = mujoco.MjData(self.model)
        self.substeps = max(1, round(params.dt / physique.timestep))
        self._joints = [self.model.joint(f"robot{i}").qposadr[0] for i in range(n)]
        self._fan = _fan(sensors.angles, sensors.beam_width)
        self._group = np.zeros(6, dtype=np.uint8)
        self._group[OBSTACLE_GROUP] = 1
        rays = len(self._fan)
        self._vec, self._dist = np.zeros((rays, 3)), np.zeros(rays)
        self._geom = np.zeros(rays, dtype=np.int32)

    def reset(self, state: np.ndarray, ranges: np.ndarray, rows: np.ndarray) -> None:
        mujoco.mj_resetData(self.model, self.data)
        qpos = self.data.qpos
        for i, at in enumerate(self._joints):
            x, y, theta = state[i, X:THETA + 1]
            qpos[at:at + 7] = x, y, self.physique.wheel_radius, math.cos(theta / 2), 0.0, 0.0, math.sin(theta / 2)
        mujoco.mj_forward(self.model, self.data)
        self.sense(state, ranges, rows)

    def move(self, state: np.ndarray, rows: np.ndarray) -> None:
        ctrl = self.data.ctrl
        half_track, wheelbase, r = 0.5 * self.params.width, self.params.wheelbase, self.physique.wheel_radius
        broken = np.zeros(self.n, dtype=bool)
        for i in range(self.n):
            steering, speed = state[i, STEERING], state[i, SPEED]
            if not rows[i] or not (math.isfinite(steering) and math.isfinite(speed)):
                broken[i] = rows[i]
                steering, speed = 0.0, 0.0  # finished robots brake; a non-finite command is not applied
            turn = half_track * math.tan(steering) / wheelbase
            ctrl[3 * i:3 * i + 3] = steering, speed * (1.0 - turn) / r, speed * (1.0 + turn) / r
        mujoco.mj_step(self.model, self.data, nstep=self.substeps)
        qpos = self.data.qpos
        for i, at in enumerate(self._joints):
            if broken[i]:
                state[i, X:THETA + 1] = math.nan  # the simulator's check reports the command
            elif rows[i]:
                w, qx, qy, qz = qpos[at + 3:at + 7]
                state[i, X], state[i, Y] = qpos[at], qpos[at + 1]
                state[i, THETA] = math.atan2(2.0 * (w * qz + qx * qy), 1.0 - 2.0 * (qy * qy + qz * qz))

    def sense(self, state: np.ndarray, ranges: np.ndarray, rows: np.ndarray) -> None:
        max_range = self.sensors.max_range
        point = np.zeros(3)
        for i in np.flatnonzero(rows):
            x, y, theta = state[i, X:THETA + 1]
            if not (math.isfinite(x) and math.isfinite(y) and math.isfinite(theta)):
                continue
            point[:] = x, y, self.physique.sensor_height
            headings = theta + self._fan[:, 1]
            self._vec[:, 0], self._vec[:, 1] = np.cos(headings), np.sin(headings)
            mujoco.mj_multiRay(self.model, self.data, point, self._vec.ravel(), self._group, 1, -1, self._geom,
                               self._dist, None, len(self._fan), max_range)
            hits = np.where(self._dist < 0.0, max_range, np.minimum(self._dist, max_range))
            ranges[i] = max_range
            np.minimum.at(ranges[i], self._fan[:, 0].astype(int), hits)


def _fan(angles: np.ndarray, beam_width: float) -> np.ndarray:
    """Rows (sensor index, ray angle) of the rays cast for each sensor: its own direction, or a
    fan across its cone of ``beam_width``."""
    if beam_width <= 0.0:
        return np.column_stack([np.arange(len(angles)), angles])
    count = 1 + math.ceil(beam_width / FAN_STEP)
    offsets = np.linspace(-0.5 * beam_width, 0.5 * beam_width, count)
    return np.array([(j, a + o) for j, a in enumerate(angles) for o in offsets])
