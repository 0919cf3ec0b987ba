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
cannot turn, so the navigator would freeze. The navigator is stateless (the speed it adjusts
comes back in the observation), so :meth:`act_batch` serves any number of robots at once.
Behaviour labels: ``GSB``, ``FOA+VRB``, ``ROA+VRB``, ``LOA+VRB`` (``GSB+VRB`` for the second
case).
"""

from __future__ import annotations

import numpy as np

from fuzzynav.control import supervisor
from fuzzynav.control.batched import BatchedController, evaluate, sensor_columns
from fuzzynav.control.goal_seeking import GuardedGoalSeeking
from fuzzynav.fuzzy import systems_navigation as nav
from fuzzynav.robot.tricycle import DEFAULT_PARAMS

LABELS = np.array(["GSB", "FOA+VRB", "ROA+VRB", "LOA+VRB", "GSB+VRB"])


class FiveBehaviourNavigator(BatchedController):
    """GSB, FOA, ROA, LOA and VRB with the supervisor of Fig IV.16."""

    name = "fuzzy-5b"

    def __init__(self, d_m: float = nav.D_M, d_s: float = nav.D_S, d_max: float = nav.D_MAX,
                 v_floor: float = 0.3, v_max: float = DEFAULT_PARAMS.max_speed,
                 params: supervisor.SupervisorParams | None = None, wheelbase: float = DEFAULT_PARAMS.wheelbase):
        self.gsb = GuardedGoalSeeking(wheelbase)
        self.avoiders = (nav.front_avoider(d_m, d_s, d_max), nav.right_avoider(d_m, d_s, d_max),
                         nav.left_avoider(d_m, d_s, d_max))
        self.vrb = nav.velocity_reducer(d1=d_m, d2=d_s, d_max=d_max)
        self.v_floor, self.v_max = float(v_floor), float(v_max)
        self.params = params or supervisor.SupervisorParams(detection=d_s, front=d_m, keep=d_m, clear=d_s)
        self._columns = None  # sensor columns of C1…C7, found from the first observation's ring

    def act_batch(self, obs):
        if self._columns is None:
            self._columns = sensor_columns(obs.sensor_angles, supervisor.THESIS_ANGLES_DEG)
        d = np.asarray(obs.ranges, dtype=float)[:, self._columns]  # (N, 7): d1…d7
        distance, bearing = obs.target_distance, obs.target_bearing
        choice = supervisor.select(d, distance, bearing, self.params)
        steering, speed, _ = self.gsb(distance, bearing)
        dmin = d.min(axis=1)
        sensed = dmin < self.params.detection
        v_now = np.asarray(obs.speed, dtype=float)
        adjust = evaluate(self.vrb, np.column_stack([v_now, dmin]))[:, 0]
        v_vrb = np.clip(v_now + adjust, self.v_floor, self.v_max)  # eq IV.9
        for code, system, cols in ((supervisor.FOA, self.avoiders[0], (0, 1, 2)),
                                   (supervisor.ROA, self.avoiders[1], (1, 3, 5)),
                                   (supervisor.LOA, self.avoiders[2], (2, 4, 6))):
            mine = choice == code
            if mine.any():
                steering = np.where(mine, evaluate(system, d[:, cols])[:, 0], steering)
        avoiding = choice != supervisor.GSB
        speed = np.where(avoiding, v_vrb, np.where(sensed, np.minimum(speed, v_vrb), speed))
        labels = LABELS[np.where(~avoiding & sensed, 4, choice)]
        return steering, speed, labels


def make(**options) -> FiveBehaviourNavigator:
    """Factory of the ``fuzzy-5b`` entry of :data:`fuzzynav.control.registry.CONTROLLERS`."""
    return FiveBehaviourNavigator(**options)
