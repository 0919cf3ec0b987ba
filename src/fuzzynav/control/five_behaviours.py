"""``fuzzy-5b``: the five-behaviour navigator of thesis §IV.7 (Figs IV.16–IV.23, Tables IV.1,
IV.3–IV.6) on the seven range sensors C1…C7.

Behaviours: GSB (Table IV.1, guarded against orbiting as in
:mod:`fuzzynav.control.goal_seeking`), FOA / ROA / LOA (Tables IV.3–IV.5, steering only) and VRB
(Table IV.6), coordinated by :mod:`fuzzynav.control.supervisor`:

- GSB alone when nothing is sensed: α and V_r from Table IV.1;
- GSB towards a goal in clear view while obstacles are sensed: α from Table IV.1, V_r the
  smaller of Table IV.1's and VRB's;
- an avoider otherwise: α from FOA, ROA or LOA, V_r from VRB.

VRB implements eq IV.9, V_r(k+1) = V_r(k) + V_adjust(k), with V_r(k) the speed applied at the
previous step (:attr:`Observation.speed`) and D_min the smallest of the seven readings; the
result is kept in [``v_floor``, 4 m/s]. ``v_floor`` (default 0.3 m/s) is this package's: at
V_r = 0 near an obstacle Table IV.6 answers "no change" (AC) and a tricycle that does not move
cannot turn, so the navigator would freeze.

**Switching** (the part Fig IV.16 states only in words) is :func:`supervisor.select` on the
readings, held by :class:`supervisor.Switch`: more caution at once when a reading is below
d_m or the full-lock turn is needed, anything else after a dwell of ``dwell`` steps (1 s); goal seeking, once in charge, is kept under the relaxed thresholds of
:func:`supervisor.relaxed`. (Handing the robot back to goal seeking only with the goal within
45° of the heading, a literal reading of Fig IV.23's "vision interval", was tried: on 100 mixed
worlds it turned 4 successes into endless wall following.)

**Turning room** (the robot has no reverse, §IV.4). Slowing down does not shrink the tightest
turn (R = l / tan(π/5) = 0.69 m), so the navigator watches the room left for it
(:class:`fuzzynav.control.turning_room.TurnGuard`, on the range hits of the last second and the
sonar-cone echo of the nearest obstacle point). When the straight lane ahead is blocked within ``lane`` (default d_m = 1.5 m) and the
better of the two full-lock half turns keeps less than ``room_margin`` (0.5 m) from every hit —
both after one more step at the current speed — the front avoider turns at full lock
(α = ±π/5, the extreme FOA singletons) to that side, at ``v_floor``: on the spot of its radius.
The side is chosen when the turn starts (the roomier one; within 0.1 m, the goal's side) and
kept until the turn ends; the turn ends, after the dwell, when lane and room exceed those
thresholds by 0.5 m and 0.2 m. It is labelled ``FOA+VRB`` like the front avoider.

**Safety stop** (this package's; the thesis has none). A thin wall end or a corner can hide
between the rays until the robot is too close for any turn, and in a pocket of obstacles neither
full-lock turn may be free. Then the one step left is to stop: when the body after the next step
(eq IV.2 moves it V Δt straight ahead, whatever the steering) would come within ``stop_margin``
(default 0.02 m) of a remembered hit (:meth:`TurnGuard.clearance`), V = 0. With no reverse gear
the robot stays there, and the episode ends in a timeout instead of a collision. On 100 mixed
worlds of each of the seeds 0–4 it stops in 2–3 worlds per seed (13 in all): 11 of them collide
without the stop; the other 2 pass within 1.1 cm of an obstacle and reach the goal without it, and
time out with it (README, "Measured results"). While stopped the label stays the mode's.

The state (modes, hold counts, turn sides, hits) is kept per robot in arrays, so
:meth:`act_batch` serves any number of robots at once; :meth:`reset` clears it.
Behaviour labels: ``GSB``, ``FOA+VRB``, ``ROA+VRB``, ``LOA+VRB``, ``GSB+VRB`` (goal seeking with
obstacles sensed, speed capped by VRB).
"""

from __future__ import annotations

import numpy as np

from fuzzynav.control import supervisor
from fuzzynav.control.batched import BatchedController, evaluate, evaluate_columns, sensor_columns
from fuzzynav.control.goal_seeking import GuardedGoalSeeking
from fuzzynav.control.turning_room import ALPHA_MAX, TurnGuard
from fuzzynav.fuzzy import systems_navigation as nav
from fuzzynav.robot.tricycle import DEFAULT_PARAMS

GSB_VRB, TURN = 4, 5  # mode codes beyond supervisor.GSB, FOA, ROA, LOA
LABELS = np.array(["GSB", "FOA+VRB", "ROA+VRB", "LOA+VRB", "GSB+VRB", "FOA+VRB"])
RANK = (0, 3, 2, 2, 1, 4)  # caution rank of each mode (supervisor.Switch): FOA above ROA, LOA
# the mode asked for, WANTED[turn?, sensed?, supervisor.select's choice]: the full-lock turn first,
# goal seeking with obstacles sensed is GSB+VRB
WANTED = np.array([[[supervisor.GSB, supervisor.FOA, supervisor.ROA, supervisor.LOA],
                    [GSB_VRB, supervisor.FOA, supervisor.ROA, supervisor.LOA]], [[TURN] * 4, [TURN] * 4]])
SEEKING = np.array([True, False, False, False, True, False, False])  # mode GSB or GSB+VRB; [-1]: none yet
AVOIDERS = (supervisor.FOA, supervisor.ROA, supervisor.LOA)
AVOIDER_COLUMNS = tuple(np.array(cols) for cols in ((0, 1, 2), (1, 3, 5), (2, 4, 6)))  # FOA d1 d2 d3, ROA d2 d4 d6,
# LOA d3 d5 d7 (Tables IV.3-IV.5)


class FiveBehaviourNavigator(BatchedController):
    """GSB, FOA, ROA, LOA and VRB with the supervisor of Fig IV.16."""

    name = "fuzzy-5b"

    def __init__(self, d_m: float = nav.D_M, d_s: float = nav.D_S, d_max: float = nav.D_MAX,
                 v_floor: float = 0.3, v_max: float = DEFAULT_PARAMS.max_speed,
                 params: supervisor.SupervisorParams | None = None, wheelbase: float = DEFAULT_PARAMS.wheelbase,
                 dwell: int = 10, lane: float = nav.D_M, room_margin: float = 0.5, memory: int = 10,
                 stop_margin: float = 0.02):
        self.gsb = GuardedGoalSeeking(wheelbase)
        self.avoiders = (nav.front_avoider(d_m, d_s, d_max), nav.right_avoider(d_m, d_s, d_max),
                         nav.left_avoider(d_m, d_s, d_max))
        self.vrb = nav.velocity_reducer(d1=d_m, d2=d_s, d_max=d_max)
        self.v_floor, self.v_max = float(v_floor), float(v_max)
        self.stop_margin = float(stop_margin)
        self.params = params or supervisor.SupervisorParams(detection=d_s, front=d_m, keep=d_m, clear=d_s)
        self.kept = supervisor.relaxed(self.params)
        self.switch = supervisor.Switch(RANK, dwell)
        self.guard = TurnGuard(lane, room_margin, memory)
        self._columns = None  # sensor columns of C1…C7, found from the first observation's ring

    def reset(self, rng=None) -> None:
        self.switch.reset()
        self.guard.reset()

    def act_batch(self, obs):
        if self._columns is None:
            self._columns = sensor_columns(obs.sensor_angles, supervisor.THESIS_ANGLES_DEG)
        d = np.asarray(obs.ranges, dtype=float)[:, self._columns]  # (N, 7): d1…d7
        distance, bearing = obs.target_distance, obs.target_bearing
        before = self.switch.mode if self.switch.mode is not None and len(self.switch.mode) == len(d) \
            else np.full(len(d), -1)
        seeking = np.count_nonzero(SEEKING[before])
        if seeking in (0, len(d)):  # one set of thresholds for all (always so for one robot)
            choice = supervisor.select(d, distance, bearing, self.kept if seeking else self.params)
        else:
            choice = np.where(SEEKING[before], supervisor.select(d, distance, bearing, self.kept),
                              supervisor.select(d, distance, bearing, self.params))
        dmin = np.minimum.reduce(d, axis=1)
        turn, side = self.guard(obs, before == TURN, bearing)
        wanted = WANTED[turn.astype(np.intp), (dmin < self.params.detection).astype(np.intp), choice]
        mode = self.switch(wanted, True, (dmin < self.params.keep) | turn)

        if len(mode) == 1:
            return self._command_one(int(mode[0]), d[0].tolist(), obs, distance, bearing, float(side[0]))
        # (α, V) of each mode, evaluated only for the modes some robot is in (placeholders elsewhere)
        modes = set(mode.tolist())
        full_lock = side * ALPHA_MAX
        steer_gsb = speed_gsb = v_vrb = full_lock
        if modes & {supervisor.GSB, GSB_VRB}:
            steer_gsb, speed_gsb, _ = self.gsb(distance, bearing)
        if modes & {supervisor.FOA, supervisor.ROA, supervisor.LOA, GSB_VRB}:
            v_now = np.asarray(obs.speed, dtype=float)
            adjust = evaluate_columns(self.vrb, v_now, dmin)[:, 0]
            v_vrb = np.minimum(np.maximum(v_now + adjust, self.v_floor), self.v_max)  # eq IV.9
        avoider_steering = [evaluate(system, d[:, cols])[:, 0] if code in modes else steer_gsb
                            for code, system, cols in zip(AVOIDERS, self.avoiders, AVOIDER_COLUMNS)]
        capped = np.minimum(speed_gsb, v_vrb) if GSB_VRB in modes else speed_gsb
        turning = np.full(len(mode), self.v_floor) if TURN in modes else full_lock
        steering = mode.choose([steer_gsb, *avoider_steering, steer_gsb, full_lock])
        speed = mode.choose([speed_gsb, v_vrb, v_vrb, v_vrb, capped, turning])
        return steering, self.guard.stop(speed, obs.dt, self.stop_margin), LABELS[mode]

    def _command_one(self, mode: int, d: list, obs, distance, bearing, side: float):
        """The command of :meth:`act_batch` for one robot in ``mode``, on floats: the same
        choice as the batch's (only the mode's behaviours are evaluated)."""
        if mode in (supervisor.GSB, GSB_VRB):
            steering, speed, _ = self.gsb(distance, bearing)
            steering, speed = float(steering[0]), float(speed[0])
        elif mode == TURN:
            steering, speed = side * ALPHA_MAX, self.v_floor
        if mode not in (supervisor.GSB, TURN):
            v_now = float(obs.speed[0])
            v_vrb = min(max(v_now + self.vrb.evaluate_one(v_now, min(d))[0], self.v_floor), self.v_max)  # eq IV.9
            if mode == GSB_VRB:
                speed = min(speed, v_vrb)
            else:
                k = AVOIDERS.index(mode)
                steering, speed = self.avoiders[k].evaluate_one(*[d[c] for c in AVOIDER_COLUMNS[k].tolist()])[0], v_vrb
        return np.array([steering]), self.guard.stop(np.array([speed]), obs.dt, self.stop_margin), LABELS[[mode]]


def make(**options) -> FiveBehaviourNavigator:
    """Factory of the ``fuzzy-5b`` entry of :data:`fuzzynav.control.registry.CONTROLLERS`."""
    return FiveBehaviourNavigator(**options)
