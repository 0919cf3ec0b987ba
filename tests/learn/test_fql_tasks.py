"""The chapter VI sensor tasks of learn/tasks/: the avoider's openness input (16 rules),
the turning-room guard of the learned navigator, and the wall follower rewarded on the distances it reads."""

import math

import numpy as np
import pytest

from fuzzynav.catalog.tasks import load_controller
from fuzzynav.control import learned
from fuzzynav.control.learned import LearnedAvoidanceNavigator
from fuzzynav.errors import InputError
from fuzzynav.experiments import evaluation
from fuzzynav.fuzzy.io.document import to_document
from fuzzynav.learn.envs import RobotState
from fuzzynav.learn.tasks import fql_avoid, fql_wall
from fuzzynav.sim.simulator import BatchSimulator
from fuzzynav.storage import save_json_atomic
from fuzzynav.world.shapes import Circle
from fuzzynav.world.world import World


def wall_ahead(open_left: bool) -> np.ndarray:
    """Readings of C1…C7 (0°, −30°, +30°, −60°, +60°, −90°, +90°) with a wall 1 m ahead that
    ends on one side: front, right and left all near, one side more open."""
    ranges = np.array([[1.0, 1.1, 1.1, 1.6, 1.6, 2.5, 2.5]])
    ranges[0, [4, 6] if open_left else [3, 5]] = 4.0
    return ranges


def prior_navigator(open_side: bool, **options) -> LearnedAvoidanceNavigator:
    """The navigator with the a-priori conclusions of every rule (fql_avoid.avoid_prior), speed low."""
    n = fql_avoid.free_rules(open_side)[0]
    return LearnedAvoidanceNavigator(fql_avoid.avoid_system(fql_avoid.avoid_prior(open_side)[:n], np.zeros(n, int),
                                                           open_side), **options)


def test_openness_is_the_left_module_mean_minus_the_right_one():
    assert learned.openness(wall_ahead(True))[0] > 0 > learned.openness(wall_ahead(False))[0]
    assert learned.avoidance_inputs(wall_ahead(True), True).shape == (1, 4)
    with pytest.raises(InputError, match="reads the 7 range sensors of the thesis. ring .sensors thesis or beam., not 5 readings"):
        learned.openness(np.ones((1, 5)))


def test_with_the_openness_input_all_near_turns_to_the_open_side_the_thesis_rules_cannot():
    assert fql_avoid.free_rules(True).tolist() == [14, 15] and fql_avoid.free_rules(False).tolist() == [7]
    goal = np.array([[0.0, 1.0]])
    for open_left in (True, False):
        ranges = wall_ahead(open_left)
        sixteen, eight = prior_navigator(True), prior_navigator(False)
        assert len(sixteen.avoidance.rules) == 14 and len(eight.avoidance.rules) == 7
        alpha16 = sixteen.blend(learned.avoidance_inputs(ranges, True), goal)[0][0]
        alpha8 = eight.blend(learned.avoidance_inputs(ranges, False), goal)[0][0]
        assert alpha16 == pytest.approx((1 if open_left else -1) * math.pi / 5, abs=0.05)
        assert alpha8 == pytest.approx(-math.pi / 5)  # the thesis' PPP rule: right, whichever side is open


def test_the_turn_guard_saves_a_navigator_whose_avoider_drives_straight():
    world = World(20.0, 20.0, (Circle((8.0, 10.0), 1.0),))
    scenario = evaluation.scenario_of(world, (4.0, 10.0, 0.0), (16.0, 10.0), "post ahead", 30.0)
    straight = fql_avoid.avoid_system(np.ones(14, int), np.zeros(14, int))  # every avoid rule: Z, slow
    runs = {}
    for guard in (False, True):
        navigator = LearnedAvoidanceNavigator(straight, turn_guard=guard)
        sim = BatchSimulator(scenario, navigator, record=True).run()
        runs[guard] = sim.trace(0)
    assert runs[False].outcome == "collision" and "turn guard" not in runs[False].behaviour
    assert runs[True].outcome != "collision" and "turn guard" in runs[True].behaviour


def test_a_model_file_says_whether_its_navigator_is_guarded(tmp_path):
    system = fql_avoid.avoid_system(np.ones(14, int), np.zeros(14, int))
    path = tmp_path / "avoid.json"
    for guard in (False, True):
        save_json_atomic(path, {"kind": "fql-avoid", **to_document(system), "turn_guard": guard})
        assert (load_controller(path).guard is not None) is guard
    save_json_atomic(path, {"kind": "fql-avoid", **to_document(system), "turn_guard": "yes"})
    with pytest.raises(InputError, match="turn_guard"):
        load_controller(path)


@pytest.mark.parametrize("sensing", ["rays", "modules"])
def test_wall_follower_is_rewarded_on_the_distances_it_reads(tmp_path, sensing):
    """Eqs VI.21–VI.22's d_i are the follower's own three distances (§VI.5.3.1)."""
    steering = next(fql_wall.fql_wall_phases(tmp_path / "wall.json", 100, batch=2, sensing=sensing))
    env = steering.env
    far = np.full((1, 7), 4.0)
    tip = far.copy()
    tip[0, 1] = 0.5  # a corner tip at −30° (C2), between the single rays (Fig VI.28)
    wall = far.copy()
    wall[0, 6] = 0.5  # a wall on the left, on the +90° ray

    def state(ranges):
        return RobotState(World(), np.zeros((1, 3)), np.ones(1), np.zeros(1), ranges=ranges, sides=env.sides(ranges))

    no = np.zeros(1, dtype=bool)
    seen = sensing == "modules"  # the right and front modules' nearest sensors see the tip, the single rays miss it
    assert env.observe(state(tip)).tolist() == [[0.5, 0.5, 4.0] if seen else [4.0, 4.0, 4.0]]
    assert env.reward(state(far), state(tip), no, no).tolist() == [-1.0 if seen else 0.0]  # eq VI.21
    assert env.observe(state(wall)).tolist() == [[4.0, 4.0, 0.5]]  # (d_d, d_f, d_g)
    assert env.reward(state(far), state(wall), no, no).tolist() == [-1.0]  # some d_i < d_m
    assert env.reward(state(far), state(far), no, no).tolist() == [0.0]


def test_the_avoider_is_credited_only_where_it_acts(tmp_path):
    """Where the supervisor hands the robot to goal seeking, the learner sees "all far" (the free
    rules), so the avoider's rules are not credited for the goal seeker's decisions."""
    steering = next(fql_avoid.fql_avoid_phases(tmp_path / "avoid.json", 100, batch=2))
    ranges = np.full((2, 7), 4.0)
    ranges[:, 6] = 2.0  # a wall on the left, 2 m away, beside a clear path to the goal ahead
    ranges[1, :3] = 1.0  # and for the second robot an obstacle dead ahead, 1 m
    goal = np.array([[10.0, 0.0], [10.0, 0.0]])  # (d_rg, θ_r − θ_d): the goal straight ahead
    state = RobotState(World(), np.zeros((2, 3)), np.ones(2), np.zeros(2), ranges=ranges, goal=goal,
                       sides=learned.side_distances(ranges))
    x = steering.env.observe(state)
    assert x[0, :3].tolist() == [fql_avoid.D_MAX] * 3  # goal seeking acts: the free rules
    assert x[1, :3].tolist() == learned.side_distances(ranges)[1].tolist()  # the avoider acts
    w = steering.learner.strengths(x)
    assert w[0, fql_avoid.free_rules()].sum() == pytest.approx(1.0) and w[1, fql_avoid.free_rules()].sum() == 0.0


@pytest.mark.slow
def test_a_short_training_gives_a_navigator_that_drives_around_a_post_and_a_wall(tmp_path):
    from fuzzynav.learn.tasks.common import TrainRequest
    from fuzzynav.world.shapes import Wall

    out = tmp_path / "avoid.json"
    # from the thesis' a-priori table (--prior thesis), one robot at a time: a smoke run of the task
    fql_avoid.train_fql_avoid(TrainRequest(out=out, episodes=200, seed=0, progress=False, prior="thesis"))
    navigator = load_controller(out)
    assert navigator.avoidance.input_names == ["front", "right", "left", "open"]
    assert len(navigator.avoidance.rules) == 14 and navigator.guard is None  # the learned avoider alone
    for obstacle in (Circle((8.0, 10.0), 0.3), Wall((8.0, 7.0), (8.0, 11.5), 0.3)):
        scenario = evaluation.scenario_of(World(20.0, 20.0, (obstacle,)), (4.0, 10.0, 0.0), (16.0, 10.0), "o", 40.0)
        trace = BatchSimulator(scenario, navigator, record=True).run().trace(0)
        assert trace.outcome == "reached" and "obstacle avoidance" in trace.behaviour
