"""The simulator, the training environment and the Gymnasium environment step robots alike: the
same commands on the same world give the same poses at every step and the same end, at the
same step — what a learner trains on is what it is evaluated on."""

from dataclasses import replace

import numpy as np
import pytest

from fuzzynav.gym import FuzzynavEnv
from fuzzynav.learn.envs import RobotEnv
from fuzzynav.learn.envs.layouts import FixedGoal
from fuzzynav.sim import BatchSimulator
from fuzzynav.world.scenario import scenario_from_dict

OBSTACLES = [{"circle": {"center": [9, 6], "radius": 1.0}},
             {"polygon": {"points": [[12, 12], [14, 12], [14, 15], [12, 15]]}}]
CROSSER = {"circle": {"center": [4, 10], "radius": 0.5}, "motion": {"type": "line", "velocity": [0.75, 0.0]}}
CASES = {  # name: (scenario, steering, speed as the normalised actions of the Gymnasium env, the end)
    "into-an-obstacle": ({"robot": {"x": 3, "y": 5, "theta": 0.1}, "goal": {"x": 18, "y": 18},
                          "obstacles": OBSTACLES}, 0.05, 0.0, "collision"),
    "to-the-goal": ({"robot": {"x": 3, "y": 3, "theta": 0.7}, "goal": {"x": 4.6, "y": 14.3},
                     "obstacles": OBSTACLES}, 0.125, -0.25, "reached"),
    "into-the-boundary": ({"robot": {"x": 15, "y": 4, "theta": 0.0}, "goal": {"x": 4, "y": 16}},
                          -0.5, 0.5, "collision"),
    "hit-by-a-moving-obstacle": ({"robot": {"x": 10, "y": 2, "theta": 1.5708}, "goal": {"x": 10, "y": 18},
                                  "obstacles": [CROSSER]}, 0.0, -0.5, "collision"),
}
STEPS = 400


class Replay:
    """Gives the simulator the commands of its list, one per step."""

    def __init__(self, commands):
        self.commands, self.k = commands, 0

    def reset(self, rng=None):
        self.k = 0

    def act_batch(self, obs):
        steering, speed = self.commands[self.k]
        self.k += 1
        return np.array([steering]), np.array([speed])


def _actions(steering: float, speed: float) -> np.ndarray:
    """The Gymnasium env's normalised actions of every step: a steering that changes sign a while."""
    actions = np.tile(np.array([steering, speed], dtype=np.float32), (STEPS, 1))
    actions[40:60, 0] *= -1.0
    return actions


def _commands(steering: float, speed: float) -> np.ndarray:
    """(α, V) of every step, as the Gymnasium env decodes its actions."""
    decode = FuzzynavEnv("goal").episodes.decode
    return np.array([np.concatenate(decode(action, single=True)) for action in _actions(steering, speed)])


def _simulator(scenario, commands):
    sim = BatchSimulator(scenario, Replay(commands), seed=0, max_time=STEPS * 0.1).run()
    trace = sim.trace(0)
    return trace.pose, trace.outcome


def _gym(scenario, steering, speed):
    env = FuzzynavEnv("goal", scenario=scenario, decision_steps=1, max_steps=STEPS)
    env.reset(seed=0)
    poses, info = [env.episodes.batch.pose[0]], {}
    for action in _actions(steering, speed):
        *_, terminated, truncated, info = env.step(action)
        poses.append(env.episodes.batch.pose[0])
        if terminated or truncated:
            break
    return np.array(poses), "collision" if info["collision"] else "reached" if info["success"] else "timeout"


def _training(scenario, commands):
    layout = FixedGoal(tuple(scenario.start), tuple(scenario.goal.position), scenario.world)
    env = RobotEnv(layout, lambda state: state.goal, lambda action, state: (action[:, 0], action[:, 1]),
                   lambda before, after, collided, reached: np.zeros(1), batch=1, max_steps=STEPS,
                   tolerance=scenario.goal.tolerance)
    env.reset(np.random.default_rng(0))
    poses, info = [env.state.pose[0]], {}
    for command in commands:
        _, _, terminated, truncated, info = env.step(command[None], np.random.default_rng(0))
        poses.append(env.state.pose[0])
        if terminated[0] or truncated[0]:
            break
    return np.array(poses), "collision" if info["collision"][0] else "reached" if info["success"][0] else "timeout"


@pytest.mark.parametrize("case", CASES)
def test_the_three_loops_step_the_same_robot_to_the_same_end(case):
    document, steering, speed, end = CASES[case]
    scenario = scenario_from_dict(document, source=f"{case}.yaml")
    commands = _commands(steering, speed)
    poses, outcome = _simulator(scenario, commands)
    assert outcome == end and 20 < len(poses) < STEPS  # the case ends as it says, before the commands run out
    for name, (other, other_outcome) in {"gym": _gym(scenario, steering, speed),
                                         "training": _training(scenario, commands)}.items():
        assert other_outcome == outcome, name
        np.testing.assert_array_equal(other, poses, err_msg=name)


def test_a_path_is_tracked_alike_from_its_first_waypoint():
    """On a path that starts on its first waypoint, the simulator and the Gymnasium env aim at
    the same waypoint at every step — the second from the start — and switch alike."""
    scenario = scenario_from_dict({"robot": {"x": 4, "y": 4, "theta": 0.9},
                                   "path": [[4, 4], [8, 9], [13, 9], [16, 14]]}, source="path.yaml")
    env = FuzzynavEnv("path", scenario=scenario, max_steps=STEPS)
    obs, _ = env.reset(seed=0)
    batch = env.episodes.batch
    poses, targets, commands = [batch.pose[0]], [batch.target[0]], []
    for _ in range(STEPS):
        action = np.array([-np.clip(obs[1] / (np.pi / 4), -1.0, 1.0)], dtype=np.float32)  # aim at the waypoint
        commands.append(np.concatenate(env.episodes.decode(action, single=True)))
        obs, _, terminated, truncated, _ = env.step(action)
        poses.append(batch.pose[0])
        targets.append(batch.target[0])
        if terminated or truncated:
            break
    trace = BatchSimulator(scenario, Replay(commands), seed=0, max_time=len(commands) * 0.1).run().trace(0)
    np.testing.assert_array_equal(trace.pose, poses)
    np.testing.assert_array_equal(trace.target, targets)
    assert list(targets[0]) == [8.0, 9.0] and trace.outcome == "reached"


def test_a_robot_drawn_in_collision_ends_without_moving_in_all_three():
    """The stop tests run at the start too: a robot placed touching an obstacle ends in a
    collision at step 0 in the simulator, and at its first decision, unmoved, in the environments."""
    scenario = replace(scenario_from_dict({"robot": {"x": 3, "y": 6, "theta": 0.0}, "goal": {"x": 18, "y": 18},
                                           "obstacles": OBSTACLES}, source="touching.yaml"),
                       start=np.array([7.8, 6.0, 0.0]))  # scenario files refuse such starts; generators may not
    commands = _commands(0.0, 0.5)
    poses, outcome = _simulator(scenario, commands)
    assert outcome == "collision" and len(poses) == 1
    for name, (other, other_outcome) in {"gym": _gym(scenario, 0.0, 0.5),
                                         "training": _training(scenario, commands)}.items():
        assert other_outcome == "collision", name
        np.testing.assert_array_equal(other, [poses[0], poses[0]], err_msg=name)
