"""Fitness of candidate rule bases: a whole population × its worlds in compiled calls.

A candidate is a gene vector of a :class:`~fuzzynav.tune.space.SearchSpace`; it becomes the
controller's rule base for the tuned role (the other roles keep theirs), packed as the simulator's
compiled navigators read them (:func:`fuzzynav.kernels.ts0.pack`), and every candidate runs every
world in calls of :func:`fuzzynav.tune.episodes.run_jobs` spread over the process' threads.

The cost of one episode (:func:`episode_cost`, minimised) ranks success first, then time: a
reached goal costs its time over the world's time limit (below 1), a timeout 10 plus the share of
the start distance still to go, a collision 20 plus that share: a timeout outweighs ten arrivals
even at the time limit (about fifty at the times of the thesis' navigators, ~20 s of 120 s), and
any timeout is better than a collision. The scalar fitness is the mean over
the worlds.

A wall follower has no goal (Table VI.2; its worlds are wall courses whose goal it ignores), so
its episode cost (:func:`wall_cost`) is the wall-following score of eqs VI.21–VI.22 made a
number: a collision costs 20 plus the share of the time limit it did not last (an early crash is
worse); an episode lasted costs the share of its steps closer to an obstacle than d_m (eq VI.21's
−1), plus the mean distance (m, at most 1 per step) the body kept outside the band [d_m, d_s]
(closer than d_m, or further than d_s: no longer following), plus the shortfall of its mean speed
below Table VI.2's slow speed P (a follower that stops would otherwise keep its distance for
free). Every part is below 1. A follower that lasts below half of P (:data:`CREEP`) has not
followed the wall — the task of §VI.5.3 is following it without collision at a useful speed — so
it has failed as a collision has: it costs :data:`COLLISION_COST` plus the share of the course it
did not cover (its shortfall below P, above 1 − CREEP), as a collision costs it plus the share of
the time it did not last. Creeping then ranks with an early crash and can never buy the absence of
collisions (priced at a timeout's cost, half a collision's, an ant colony traded 19 collisions of
Table VI.2 for 33 creeping courses); every episode that followed beats every failed one.

The objectives of NSGA-II (:data:`OBJECTIVES`) are the failure rate, the mean time
(the time limit for a failed episode) and minus the mean least clearance.
"""

from __future__ import annotations

import time

import numpy as np

from fuzzynav.fuzzy.systems_navigation import WALL_V1
from fuzzynav.kernels import ts0
from fuzzynav.kernels.step import COLLISION, REACHED, TIMEOUT
from fuzzynav.tune.episodes import (
    CLEARANCE,
    INVALID,
    OFF_BAND,
    OUTCOME,
    PATH,
    REMAINING,
    START_DISTANCE,
    STEPS,
    TOO_CLOSE,
    Worlds,
)

OBJECTIVES = ("success", "time", "clearance")
TIMEOUT_COST, COLLISION_COST, INVALID_COST = 10.0, 20.0, 30.0
CREEP = 0.5  # share of Table VI.2's slow speed P below which a lasted wall episode has not followed


def episode_cost(out: np.ndarray, dt: np.ndarray, max_time: np.ndarray) -> np.ndarray:
    """Cost of each episode row of ``out`` (module docstring); ``dt``, ``max_time`` per row."""
    outcome = out[:, OUTCOME]
    left = np.clip(out[:, REMAINING] / np.maximum(out[:, START_DISTANCE], 1e-9), 0.0, 1.0)
    cost = np.where(outcome == REACHED, out[:, STEPS] * dt / max_time, 0.0)
    cost = np.where(outcome == TIMEOUT, TIMEOUT_COST + left, cost)
    cost = np.where(outcome == COLLISION, COLLISION_COST + left, cost)
    return np.where(outcome == INVALID, INVALID_COST, cost)


def wall_cost(out: np.ndarray, dt: np.ndarray, max_time: np.ndarray) -> np.ndarray:
    """Cost of each wall-following episode row of ``out`` (module docstring)."""
    outcome, steps = out[:, OUTCOME], np.maximum(out[:, STEPS], 1.0)
    lasted = np.clip(out[:, STEPS] * dt / max_time, 0.0, 1.0)
    slow = np.clip(1.0 - out[:, PATH] / (steps * dt * WALL_V1), 0.0, 1.0)
    cost = out[:, TOO_CLOSE] / steps + out[:, OFF_BAND] / steps + slow
    cost = np.where(slow > 1.0 - CREEP, COLLISION_COST + slow, cost)
    cost = np.where(outcome == COLLISION, COLLISION_COST + 1.0 - lasted, cost)
    return np.where(outcome == INVALID, INVALID_COST, cost)


class Fitness:
    """Scores gene vectors of ``space`` for ``controller``'s ``role`` on ``scenarios``; counts the
    candidates and episodes it simulated and the time it took (:attr:`evaluations`,
    :attr:`episodes`, :attr:`seconds`). ``wall``: score episodes as wall following (:func:`wall_cost`)."""

    def __init__(self, controller, role: str, space, scenarios, wall: bool = False):
        self.controller, self.role, self.space, self.wall = controller, role, space, wall
        self.worlds = Worlds(scenarios, controller)
        self.evaluations = self.episodes = 0
        self.seconds = 0.0

    def tables(self, system) -> np.ndarray:
        """The packed rule bases of the controller with ``system`` for the tuned role."""
        systems = self.controller.systems
        return ts0.pack([system if role == self.role else systems[role] for role in self.controller.roles],
                        list(self.controller.roles))

    def simulate(self, population: np.ndarray) -> np.ndarray:
        """``(P, W, N_OUT)`` episode rows of every candidate on every world."""
        started = time.perf_counter()
        population = np.atleast_2d(population)
        tables = np.stack([self.tables(self.space.decode(genes)) for genes in population])
        n, w = len(population), len(self.worlds)
        jobs = np.stack(np.meshgrid(np.arange(n), np.arange(w), indexing="ij"), axis=-1).reshape(-1, 2)
        out = self.worlds.run(tables, jobs).reshape(n, w, -1)
        self.evaluations += n
        self.episodes += n * w
        self.seconds += time.perf_counter() - started
        return out

    def cost(self, rows: np.ndarray) -> np.ndarray:
        """The episode costs of one candidate's rows ``(W, N_OUT)`` on these worlds."""
        score = wall_cost if self.wall else episode_cost
        return score(rows, self.worlds.dt, self.worlds.max_time)

    def summary(self, rows: np.ndarray) -> dict:
        """:func:`summary` of one candidate's rows, with its mean cost."""
        return {**summary(rows, self.worlds.dt, self.wall), "cost": float(self.cost(rows).mean())}

    def objectives(self, population: np.ndarray) -> np.ndarray:
        """``(P, 1 + len(OBJECTIVES))``: the scalar cost, then failure rate, mean time (s, the time
        limit when not reached) and minus the mean least clearance (m), each to be minimised."""
        out = self.simulate(population)
        dt, max_time = self.worlds.dt, self.worlds.max_time
        cost = np.stack([self.cost(rows) for rows in out]).mean(axis=1)
        reached = out[:, :, OUTCOME] == REACHED
        times = np.where(reached, out[:, :, STEPS] * dt, max_time)
        clearance = np.clip(out[:, :, CLEARANCE], -1.0, None)
        return np.column_stack([cost, 1.0 - reached.mean(axis=1), times.mean(axis=1), -clearance.mean(axis=1)])

    @property
    def rate(self) -> float:
        """Candidate evaluations per second of simulation so far."""
        return self.evaluations / self.seconds if self.seconds else 0.0


def summary(out: np.ndarray, dt: np.ndarray, wall: bool = False) -> dict:
    """Success / collision / timeout rates, mean time to the goal and least clearance of one
    candidate's episode rows ``(W, N_OUT)`` (what ``fuzzynav evaluate`` reports). ``wall``: success
    is lasting the episode without collision, and the wall-following measures are added: the
    share of steps closer than d_m, the mean distance outside [d_m, d_s] (m), the mean speed (m/s:
    the distance covered over all the episodes per second of them, reversing counted positive; not
    a run's ``mean_speed_mps``, the signed mean of the commanded speed, :mod:`fuzzynav.sim.metrics`)
    and the share followed: lasted at a mean speed of at least :data:`CREEP` × P (a lasted episode
    below it is the failure :func:`wall_cost` prices as a collision)."""
    outcome = out[:, OUTCOME]
    if wall:
        steps = out[:, STEPS].sum()
        speed = out[:, PATH] / (np.maximum(out[:, STEPS], 1.0) * dt)
        followed = (outcome != COLLISION) & (outcome != INVALID) & (speed >= CREEP * WALL_V1)
        return {"worlds": int(len(out)), "success_rate": float((outcome != COLLISION).mean()),
                "followed_rate": float(followed.mean()),
                "collision_rate": float((outcome == COLLISION).mean()), "collisions": int((outcome == COLLISION).sum()),
                "too_close_share": float(out[:, TOO_CLOSE].sum() / steps), "off_band_m": float(out[:, OFF_BAND].sum() / steps),
                "mean_speed_mps": float(out[:, PATH].sum() / (out[:, STEPS] * dt).sum()),
                "mean_time_s": None, "min_clearance_m": float(out[:, CLEARANCE].min())}
    reached = outcome == REACHED
    return {
        "worlds": int(len(out)),
        "success_rate": float(reached.mean()),
        "collision_rate": float((outcome == COLLISION).mean()),
        "timeout_rate": float((outcome == TIMEOUT).mean()),
        "collisions": int((outcome == COLLISION).sum()),
        "mean_time_s": float((out[reached, STEPS] * dt[reached]).mean()) if reached.any() else None,
        "min_clearance_m": float(out[:, CLEARANCE].min()),
    }
