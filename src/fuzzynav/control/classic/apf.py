"""``apf``: artificial potential field navigation (O. Khatib, *Real-time obstacle avoidance for
manipulators and mobile robots*, IJRR 5(1), 1986) with a steering mapping for the tricycle.

The goal attracts with a force of constant magnitude ``attraction`` towards it (the conic
well; Khatib's quadratic well grows with the distance and would swamp the obstacles far from
the goal); every remembered range hit at clearance ρ (distance minus the body radius) below
the influence distance ρ₀ repels along the line from it with Khatib's force (eq 19 of the paper)

    F = η (1/ρ − 1/ρ₀) / ρ².

The robot steers onto the arc through the point ``lookahead`` metres along the resultant force
(α = atan(2 l sin φ / L), the pure-pursuit arc, Coulter 1992; a car cannot follow the force
direction on the spot) and slows with the clearance ahead and the turn: V = V_max ·
min(1, ρ_min / ρ₀) · max(cos φ, 0.2). The potential field's known weakness stays: local minima
where attraction and repulsion cancel (a U-shaped obstacle, a gap narrower than ρ₀ allows).
"""

from __future__ import annotations

import math

import numpy as np

from fuzzynav.control.base import Command, Controller
from fuzzynav.control.classic.local_map import Body, LocalMap
from fuzzynav.settings import BODY, LENGTH, MEMORY, RATE, checked


class PotentialField(Controller):
    """APF (module docstring). Options: robot ``radius``/``wheelbase``/``max_steering``/``max_speed``,
    ``attraction``, ``repulsion`` η, ``influence`` ρ₀ (m), ``lookahead`` (m), ``memory`` (steps)."""

    name = "apf"

    @checked(**BODY, attraction=RATE, repulsion=RATE, influence=LENGTH, lookahead=LENGTH, memory=MEMORY)
    def __init__(self, *, radius: float = Body.radius, wheelbase: float = Body.wheelbase,
                 max_steering: float = Body.max_steering, max_speed: float = Body.max_speed,
                 attraction: float = 1.0, repulsion: float = 0.3, influence: float = 1.5, lookahead: float = 1.0,
                 memory: int = 10):
        self.body = Body(radius, wheelbase, max_steering, max_speed)
        self.attraction, self.repulsion = float(attraction), float(repulsion)
        self.influence, self.lookahead = float(influence), float(lookahead)
        self.map = LocalMap(memory)

    def reset(self, rng=None) -> None:
        self.map.reset()

    def act(self, obs) -> Command:
        points = self.map.points(obs)
        bearing = obs.target_bearing
        force = self.attraction * np.array([math.cos(bearing), math.sin(bearing)])
        closest = self.influence
        if len(points):
            distance = np.hypot(points[:, 0], points[:, 1])
            rho = np.maximum(distance - self.body.radius, 0.05)
            near = rho < self.influence
            closest = float(rho.min())
            if near.any():
                magnitude = self.repulsion * (1.0 / rho[near] - 1.0 / self.influence) / rho[near] ** 2
                force -= (magnitude / distance[near]) @ points[near]  # away from each hit
        phi = math.atan2(force[1], force[0])
        steering = self.body.steer_towards(phi, self.lookahead)
        speed = self.body.max_speed * min(1.0, closest / self.influence) * max(math.cos(phi), 0.2)
        return Command(steering, speed, "APF")


def make(**options) -> PotentialField:
    """Factory of ``apf`` (options: see :class:`PotentialField`)."""
    return PotentialField(**options)
