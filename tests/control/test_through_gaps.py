"""The gap-aware navigators inside the recovery and loop-escape layers, guided by a route round
what they have seen (fuzzynav.control.through_gaps, kernels.guidance): they back out of a pocket
of posts too narrow to turn in, and the route leads round a wall of posts to its opening."""

import numpy as np
import pytest

from fuzzynav.catalog.controllers import make_controller
from fuzzynav.errors import InputError
from fuzzynav.kernels import guidance, layers
from fuzzynav.kernels.records import Robot, Sightings
from fuzzynav.sim import run_episode
from fuzzynav.world.scenario import scenario_from_dict

POST = 0.075


def pocket() -> dict:
    """A dead end of 15 cm posts 0.3 m apart, 1.6 m wide (too narrow for a full-lock turn of the
    car, 2 × 0.69 m + its 0.6 m body), the robot inside facing its closed end, the goal beyond it."""
    left, right, end = 9.2, 10.8, 9.6
    posts = [(x, y) for y in np.arange(7.0, end, 0.3) for x in (left, right)]
    posts += [(float(x), end) for x in np.linspace(left, right, 7)]
    return {"name": "pocket", "world": {"width": 20.0, "height": 20.0},
            "robot": {"x": 10.0, "y": 7.6, "theta": float(np.pi / 2)}, "goal": {"x": 10.0, "y": 15.0},
            "obstacles": [{"circle": {"center": [float(x), float(y)], "radius": POST}} for x, y in posts],
            "max_time": 60.0}


def test_the_combined_navigator_backs_out_of_a_pocket_and_reaches_the_goal():
    world = scenario_from_dict(pocket())
    stuck = run_episode(world, make_controller("fuzzy-5b-gap"), seed=0)
    assert stuck.outcome == "timeout"  # forwards only, the gap navigator cannot leave
    trace = run_episode(world, make_controller("fuzzy-5b-gap-robust"), seed=0)
    assert trace.reached and not trace.collision
    reversing = trace.speed < 0
    assert reversing.any()
    assert set(trace.behaviour[reversing].tolist()) == {"CAR-BACK"}  # the car route's backward arcs
    assert world.world.clearance(trace.pose[:, :2]).min() > world.robot.radius


def test_fuzzy_5b_is_the_navigator_also_named_fuzzy_5b_gap_robust():
    default, alias = make_controller("fuzzy-5b"), make_controller("fuzzy-5b-gap-robust")
    assert type(default) is type(alias) and type(default.navigator) is type(alias.navigator)
    np.testing.assert_array_equal(default.params, alias.params)
    assert default.sensors.count == alias.sensors.count == 271  # the lidar ring
    world = scenario_from_dict(pocket())
    a, b = run_episode(world, default, seed=0), run_episode(world, alias, seed=0)
    assert a.reached and a.steps == b.steps
    np.testing.assert_array_equal(a.pose, b.pose)
    np.testing.assert_array_equal(np.column_stack([a.steering, a.speed]), np.column_stack([b.steering, b.speed]))
    assert a.behaviour.tolist() == b.behaviour.tolist()
    assert (a.controller, b.controller) == ("fuzzy-5b", "fuzzy-5b-gap-robust")  # each run named as asked


def _aim(points, pose=(0.0, 0.0, np.pi / 2), car=True, tight=0.5, state=None, off_heading=np.pi / 6) -> np.ndarray:
    """The target fuzzy-5b-gap-robust's route guidance (its car route, or the grid route only)
    gives a robot at ``pose`` that has seen ``points``, the goal at (0, 10), at its first plan
    (the layer driving the car route's arcs where they pass within ``tight`` m beyond the radius,
    planning a route to a goal more than ``off_heading`` off the heading; ``state``: the state row
    it plans in, if given)."""
    params = make_controller("fuzzy-5b-gap-robust", guidance={"guide_car": float(car), "guide_car_tight": tight,
                                                               "guide_off_heading": off_heading}).params
    state = layers.fresh_state(1, params)[0] if state is None else state
    points = np.asarray(points, dtype=float)
    return np.array(guidance.aim(state, params, Sightings(points, len(points)), Robot(*pose, 0.0, 0.0, 10.0), 0.0,
                                 params[layers.PARAM.radius]))


@pytest.mark.parametrize("car", [True, False])
@pytest.mark.parametrize("side", [1.0, -1.0])
def test_route_guidance_leads_round_a_wall_of_posts_on_the_side_of_its_opening(side, car):
    given = _aim([(side * x, 2.0) for x in np.arange(-4.0, 1.01, 0.1)], car=car)  # open beyond x = ±1
    assert np.hypot(*given) == pytest.approx(10.0)  # the goal's distance kept
    assert side * given[0] > 1.0  # towards the opening, not straight at the goal


def test_the_default_drives_the_car_route_itself_where_it_passes_within_2_m_of_what_was_seen():
    """Version 12 (``guide_car_tight`` 2.0): round the wall of posts the layer drives the route's
    first arc itself (the navigator is given the goal meanwhile); with 0.5 m (version 11) the
    route passes far enough from the posts for the navigator to drive towards its point."""
    wall = [(x, 2.0) for x in np.arange(-4.0, 1.01, 0.1)]
    default = make_controller("fuzzy-5b")
    state = layers.fresh_state(1, default.params)[0]
    assert default.params[layers.PARAM.guide_car_tight] == 2.0
    np.testing.assert_allclose(_aim(wall, tight=2.0, state=state), [0.0, 10.0])
    assert state[layers.STATE.guide_gear] != 0.0  # an arc of the layer's to drive
    state = layers.fresh_state(1, default.params)[0]
    assert _aim(wall, tight=0.5, state=state)[0] > 1.0 and state[layers.STATE.guide_gear] == 0.0


def test_a_goal_behind_the_car_gets_a_route_though_the_line_to_it_is_free():
    """Version 13 (``guide_off_heading`` 30°): facing away from the goal with nothing seen in the
    way, the car route turns the car round; version 12 (0) steers straight at the goal."""
    behind, nothing = (0.0, 0.0, -np.pi / 2), np.empty((0, 2))
    state = layers.fresh_state(1, make_controller("fuzzy-5b").params)[0]
    routed = _aim(nothing, pose=behind, state=state)
    assert state[layers.STATE.guide_made] == 0.0 and state[layers.STATE.guide_poses] > 1  # a car route searched
    assert not np.allclose(routed, [0.0, 10.0])  # its point, not the goal
    np.testing.assert_allclose(_aim(nothing, pose=behind, off_heading=0.0), [0.0, 10.0])
    np.testing.assert_allclose(_aim(nothing, pose=(0.0, 0.0, np.pi / 2 + 0.5)), [0.0, 10.0])  # within 30°: the goal


def test_version_13_turns_round_to_a_goal_behind_instead_of_swinging_wide():
    """``office-0-007`` starts with its goal behind the car: version 12 steered straight at it
    (a free line), swung wide into the rooms behind and took 53.6 s; version 13 plans the car
    route and arrives in 10.7 s (``astar-pp``, which knows the map: 11.5 s)."""
    from fuzzynav.world.scenario_file import open_scenario

    scenario = open_scenario("office-0-007")
    then = {"pace": {"pace_horizon": 1.5}}  # version 14's pace, as then
    version_12 = run_episode(scenario, make_controller("fuzzy-5b", guidance={"guide_off_heading": 0.0}, **then), seed=0)
    version_13 = run_episode(scenario, make_controller("fuzzy-5b", **then), seed=0)
    assert version_12.reached and version_13.reached and not version_13.collision
    assert version_13.time < 0.5 * version_12.time
    assert make_controller("fuzzy-5b").params[layers.PARAM.guide_off_heading] == pytest.approx(np.pi / 6)


def test_version_15_paced_with_less_time_ahead_reaches_the_office_version_14_times_out_in():
    """``office-0-079`` (a tuning world of version 15): with 1.5 s of travel left ahead by the pace,
    version 14 times out there; with 1.25 s the default reaches it, without a collision."""
    from fuzzynav.world.generate import generate_world

    scenario = generate_world("office", 0, 79)
    version_14 = run_episode(scenario, make_controller("fuzzy-5b", pace={"pace_horizon": 1.5}), seed=0)
    version_15 = run_episode(scenario, make_controller("fuzzy-5b"), seed=0)
    assert version_14.outcome == "timeout"
    assert version_15.reached and not version_15.collision and version_15.time < 20.0
    assert make_controller("fuzzy-5b").params[layers.PARAM.pace_horizon] == 1.25


def test_route_guidance_gives_the_goal_where_the_straight_line_is_free():
    given = _aim([(x, 2.0) for x in np.arange(-4.0, -0.99, 0.1)])  # left of the line only
    np.testing.assert_allclose(given, [0.0, 10.0])


def test_route_guidance_keeps_its_route_point_until_it_plans_again():
    params = make_controller("fuzzy-5b-gap-robust").params
    state = layers.fresh_state(1, params)[0]
    wall = np.array([(x, 2.0) for x in np.arange(-4.0, 1.01, 0.1)])
    radius = params[layers.PARAM.radius]
    pose = (0.0, 0.0, np.pi / 2)
    robot = Robot(*pose, 0.0, 0.0, 10.0)
    first = guidance.aim(state, params, Sightings(wall, len(wall)), robot, 0.0, radius)
    assert guidance.aim(state, params, Sightings(wall, 0), robot, 0.5, radius) == first  # not re-planned yet
    assert guidance.aim(state, params, Sightings(wall, 0), robot, 1.0, radius) == (0.0, 10.0)  # nothing seen


def test_route_guidance_options_are_checked_and_on_in_the_default_navigator_only():
    assert make_controller("fuzzy-5b-rays").params[layers.PARAM.guide] == 0.0
    assert make_controller("fuzzy-2b").params[layers.PARAM.guide] == 0.0
    assert make_controller("fuzzy-5b").params[layers.PARAM.guide] == 1.0
    assert make_controller("fuzzy-5b-gap-robust").params[layers.PARAM.guide] == 1.0
    with pytest.raises(InputError, match="guide_lookahead"):
        make_controller("fuzzy-5b-gap-robust", guidance={"guide_lookahead": 2.0})


@pytest.mark.parametrize(("option", "value", "says"), [
    ("guide_off_heading", -0.1, "must be >= 0"), ("guide_off_heading", 4.0, "must be <= 3.14"),
    ("guide_off_heading", float("nan"), "must be finite"), ("guide_car_weight", -1.0, "must be >= 0"),
    ("guide_car_shot", -5.0, "must be >= 0"),
    ("guide_car_step", "0.2", "must be a number"), ("pace_horizon", float("inf"), "must be finite"),
    # each of these ran before and drove nonsense: an invalid command at once, or a timeout
    ("guide_car_cell", 0.0, "must be > 0"), ("guide_car_cell", -0.1, "must be > 0"),
    ("guide_car_step", 0.0, "must be > 0"),
    ("guide_car_node", 0.0, "must be > 0"), ("guide_car_reach", -1.0, "must be > 0"), ("pace_goal", 0.0, "must be > 0"),
    ("guide_car_budget", 0, "must be >= 1"), ("guide_car_budget", 1.5, "must be a whole number"),
    ("guide_car_budget", 1e12, "must be <= 1e"), ("guide_car_headings", 0, "must be >= 1"),
    ("guide_car_steerings", 1, "must be >= 2"), ("guide_car_shot", 2.5, "must be a whole number"),
    ("guide_car_steering", 2.0, "must be < 1.57"), ("guide_car_comfort", -0.3, "must be >= 0"),
])
def test_a_bad_guidance_or_pace_value_is_a_clear_error_naming_the_option(option, value, says):
    group = "pace" if option.startswith("pace") else "guidance"
    with pytest.raises(InputError, match=f"{group}.{option}: {says}"):
        make_controller("fuzzy-5b", **{group: {option: value}})


def test_the_pace_drives_faster_through_posts_without_contact():
    """The pace (kernels.pace) where the way ahead is clear: the same world reached sooner than at
    the thesis' speeds (paced=False), above their top speed, with no collision."""
    from fuzzynav.world.generate import generate_world

    world = generate_world("mixed", 0, 0)
    version_12 = {"guidance": {"guide_off_heading": 0.0}}  # its start steered straight at the goal, as then
    slow = run_episode(world, make_controller("fuzzy-5b", paced=False, **version_12), seed=0)
    fast = run_episode(world, make_controller("fuzzy-5b", **version_12), seed=0)
    assert slow.reached and fast.reached and not fast.collision
    assert fast.steps < 0.7 * slow.steps
    assert fast.speed.max() > slow.speed.max()
    assert world.world.clearance(fast.pose[:, :2]).min() > world.robot.radius


def test_the_car_routes_forward_arcs_are_paced_where_clear():
    """The pace on the car route's forward arcs (``pace_car``): in a maze the layer's ``CAR-FWD``
    steps go above ``guide_car_speed`` (never below it), the goal is reached sooner than with the
    arcs at that fixed speed (``pace_car`` 0, version 5), with no collision."""
    from fuzzynav.world.generate import generate_world

    world = generate_world("maze", 0, 0)
    fixed = run_episode(world, make_controller("fuzzy-5b", pace={"pace_car": 0}), seed=0)
    paced = run_episode(world, make_controller("fuzzy-5b"), seed=0)
    floor = make_controller("fuzzy-5b").params[layers.PARAM.guide_car_speed]
    assert fixed.reached and paced.reached and not paced.collision
    assert np.all(fixed.speed[fixed.behaviour == "CAR-FWD"] == pytest.approx(floor))
    arcs = paced.speed[paced.behaviour == "CAR-FWD"]
    assert arcs.size and arcs.min() >= floor - 1e-9 and arcs.max() > 1.5 * floor
    assert paced.steps < 0.9 * fixed.steps
    assert world.world.clearance(paced.pose[:, :2]).min() > world.robot.radius


def back_ups(trace) -> int:
    """How many runs of ``CAR-BACK`` steps the trace holds (each a back-up the layer drove)."""
    backing = trace.behaviour == "CAR-BACK"
    return int(np.count_nonzero(backing[1:] & ~backing[:-1]) + backing[0])


def test_a_back_up_of_the_car_route_is_followed_by_the_next_plan_not_undone():
    """``guide_car_chain``: when a backward arc of the car route ends, the route is planned again in
    the same step, so the next arc starts at once. Without it (version 9) the navigator drove that
    step, at the pace's speed on its full-lock steering, forward over the 0.21 m just backed, and
    the next plan backed again: on Fig IV.23 about twenty back-ups in place before the loop escape
    took the robot out. With it, the route's forward arc follows the first back-up."""
    from fuzzynav.world.scenario import load_scenario

    scenario = load_scenario("fig-IV-23")
    then = {"guide_car_tight": 0.5, "guide_off_heading": 0.0}
    paced = {"pace_horizon": 1.5}  # version 14's pace, as then
    undone = run_episode(scenario, make_controller("fuzzy-5b", guidance={"guide_car_chain": 0, **then}, pace=paced), seed=0)
    chained = run_episode(scenario, make_controller("fuzzy-5b", guidance=then, pace=paced), seed=0)
    assert undone.reached and chained.reached and not chained.collision
    assert back_ups(undone) >= 15 and back_ups(chained) <= 2
    assert chained.steps < 0.6 * undone.steps
    assert scenario.world.clearance(chained.pose[:, :2]).min() > scenario.robot.radius


def test_the_car_route_ends_inside_the_goals_tolerance():
    """Version 11: the car route's search ends within ``GOAL_SHARE`` of the goal's tolerance
    (``for_goal``, told by the simulator), never beyond ``guide_car_reach``. Version 10's ended
    0.5 m from the goal whatever the tolerance. In ``office-0-033`` (tolerance 0.3 m) its route
    took the robot past the goal 0.43 m off, declared the route done, and left the goal beside and
    then behind a car that cannot turn that tightly forwards: back-ups and the loop escape's
    boundary following until the time limit."""
    from fuzzynav.world.scenario_file import open_scenario

    scenario = open_scenario("office-0-033")
    goal = scenario.goal.position
    version_11 = {"guidance": {"guide_car_tight": 0.5, "guide_off_heading": 0.0}, "pace": {"pace_horizon": 1.5}}
    beside = run_episode(scenario, make_controller("fuzzy-5b", goal_share=0, **version_11), seed=0)
    inside = run_episode(scenario, make_controller("fuzzy-5b", **version_11), seed=0)
    assert beside.outcome == "timeout" and inside.reached and not inside.collision
    assert np.hypot(*(beside.pose[:, :2] - goal).T).min() < 0.5  # it passed within the old reach
    assert inside.time < 0.3 * beside.time
    assert scenario.world.clearance(inside.pose[:, :2]).min() > scenario.robot.radius


def test_the_goals_tolerance_bounds_the_car_routes_reach_and_nothing_else():
    controller = make_controller("fuzzy-5b")
    reach = layers.PARAM.guide_car_reach
    controller.for_goal(0.3)
    assert controller.params[reach] == pytest.approx(0.24)
    controller.for_goal(1.0)  # BARN's tolerance: the search's own 0.5 m is inside it
    assert controller.params[reach] == pytest.approx(0.5)
    assert make_controller("fuzzy-5b", goal_share=0).for_goal(0.3).params[reach] == pytest.approx(0.5)
    assert make_controller("fuzzy-5b-rays").for_goal(0.3).params[reach] == 0.0  # no car route, nothing to end
    with pytest.raises(InputError, match="goal_share"):
        make_controller("fuzzy-5b", goal_share=1.5)


def test_a_scenario_without_a_goal_leaves_the_car_route_its_own_reach():
    """The simulator tells every scenario's goal, none included, so the reach does not depend on
    what the navigator ran before."""
    from fuzzynav.sim import BatchSimulator
    from fuzzynav.world.scenario import load_scenario

    controller = make_controller("fuzzy-5b")
    controller.for_goal(0.3)
    BatchSimulator(load_scenario("example-path"), controller, seed=0)
    assert controller.params[layers.PARAM.guide_car_reach] == pytest.approx(0.5)
