"""The published navigators run without this package's layers; each layer is optional and named
(control.batched.LAYERS), and what it changes shows in closed loop."""

import pytest

from fuzzynav.catalog.controllers import make_controller
from fuzzynav.control.batched import LAYERS, layer_flags
from fuzzynav.errors import InputError
from fuzzynav.kernels import navigators
from fuzzynav.sim import run_episode
from fuzzynav.world.scenario import load_scenario, scenario_from_dict

FLAGS = {"orbit_guard": navigators.ORBIT_GUARD, "turning_room": navigators.TURNING_ROOM,
         "safety_stop": navigators.SAFETY_STOP, "hysteresis": navigators.HYSTERESIS}


@pytest.mark.parametrize("name", ["goal-seeking", "fuzzy-2b-thesis", "fuzzy-5b-thesis"])
def test_the_published_navigators_have_no_layer(name):
    params = make_controller(name).params
    assert all(params[index] == 0.0 for index in FLAGS.values())


@pytest.mark.parametrize("name", ["fuzzy-2b-layered", "fuzzy-5b-layered", "fuzzy-5b-gap"])
def test_the_other_variants_keep_every_layer(name):
    params = make_controller(name).params
    assert all(params[index] == 1.0 for index in FLAGS.values())


def test_a_layer_is_chosen_by_name():
    params = make_controller("fuzzy-5b-thesis", layers=("safety_stop",)).params
    assert [params[FLAGS[name]] for name in LAYERS] == [0.0, 0.0, 1.0, 0.0]
    with pytest.raises(InputError, match="unknown layer.*orbit"):
        layer_flags(["orbit"])


def test_table_iv_1_alone_orbits_a_goal_inside_its_turning_circle():
    # the goal 1.04 m away at 73° to the left: Table IV.1's PM/F never turns tight enough (thesis §IV.5.1)
    scenario = scenario_from_dict({"robot": {"x": 10.0, "y": 10.0, "theta": 0.0}, "goal": {"x": 10.3, "y": 11.0},
                                   "max_time": 30})
    bare = run_episode(scenario, make_controller("goal-seeking"))
    assert bare.outcome == "timeout"
    assert run_episode(scenario, make_controller("goal-seeking-guarded")).reached


def test_without_hysteresis_the_switch_of_fig_iv_9_chatters():
    scenario = load_scenario("fig-IV-15a")
    bare = run_episode(scenario, make_controller("fuzzy-2b-thesis"))
    held = run_episode(scenario, make_controller("fuzzy-2b-thesis", layers=("hysteresis",)))
    assert bare.reached and held.reached
    assert len(bare.behaviour_changes()) > 2 * len(held.behaviour_changes())
