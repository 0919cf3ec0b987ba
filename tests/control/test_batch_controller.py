"""One controller adapter: a BatchController implements act_batch and inherits the one-robot act."""

import numpy as np
import pytest

from fuzzynav.catalog.controllers import make_controller
from fuzzynav.control.base import BatchController, Command, Observation
from fuzzynav.sim.simulator import BatchSimulator
from fuzzynav.world.scenario import load_scenario


class Proportional(BatchController):
    """Steers proportionally to the bearing of the target, at a constant speed."""

    name = "proportional"

    def act_batch(self, obs):
        pose, target = np.atleast_2d(obs.pose), np.atleast_2d(obs.target)
        bearing = np.arctan2(target[:, 1] - pose[:, 1], target[:, 0] - pose[:, 0]) - pose[:, 2]
        return 0.5 * bearing, np.full(len(pose), 1.0), ["seek"] * len(pose)


def test_a_new_controller_gets_its_one_robot_call():
    obs = Observation(t=0.0, dt=0.1, pose=np.array([0.0, 0.0, 0.0]), speed=0.0, steering=0.0,
                      target=np.array([0.0, 2.0]))
    command = Proportional().act(obs)
    assert command == Command(pytest.approx(0.25 * np.pi), 1.0, "seek")
    assert isinstance(command.steering, float) and isinstance(command.behaviour, str)


@pytest.mark.parametrize("name, scenario", [
    ("pure-pursuit", "path-v"), ("stanley", "path-n"), ("fuzzy-tracker", "path-trapezoid"),
    ("anfis-tracker", "path-v"),
])
def test_act_is_the_batch_decision_for_one_robot(name, scenario):
    """On the observations of a real run, act(robot i) of a fresh controller equals row i of
    act_batch of another fresh one (fresh: the trackers remember the previous error)."""
    starts = np.array([[1.0, 1.0, 0.0], [3.0, 2.0, 1.0], [5.0, 9.0, -2.0]])
    sim = BatchSimulator(load_scenario(scenario), make_controller(name), starts=starts, record=False)
    for _ in range(30):
        steering, speed, labels = make_controller(name).act_batch(sim.observation)
        for i in range(sim.n):
            controller = make_controller(name)
            assert isinstance(controller, BatchController)
            command = controller.act(sim.observation.single(i))
            assert (command.speed, command.behaviour) == (float(speed[i]), str(labels[i]))
            assert command.steering == pytest.approx(float(steering[i]), rel=1e-12, abs=1e-15)  # ANFIS: rounding of the batch sums
        sim.step()
