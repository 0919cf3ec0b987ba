"""The recovery's barrier step (``fuzzy-5b`` version 8: ``barrier=0.5`` during the first
``barrier_within=0.05`` m of a back-up, :func:`fuzzynav.kernels.recovery.may_step`): on BARN world
130 at the BARN robot's 2 m/s a paced arc leaves the robot wedged between two posts, each within the
recovery's margin; version 7 (``barrier=0``) backs one step at a time, gives up, and the loop escape
then stands still to the time limit; the barrier lets it back out and arrive."""

import itertools
from pathlib import Path

import numpy as np
import pytest
import yaml

WORLD_130 = Path(__file__).parents[1] / "data" / "barn" / "world_130.yaml"  # BARN world 130, MIT


def _run(**options):
    from fuzzynav.catalog.controllers import make_controller
    from fuzzynav.sim import run_episode
    from fuzzynav.world.scenario import scenario_from_dict

    document = yaml.safe_load(WORLD_130.read_text())
    document["robot"]["max_speed"] = 2.0  # BARN's Jackal
    return run_episode(scenario_from_dict(document, source=str(WORLD_130)), make_controller("fuzzy-5b", **options),
                       seed=0)


@pytest.mark.slow
def test_the_default_backs_out_of_the_wedge_where_version_7_stands_still():
    then = {"guidance": {"guide_car_tight": 0.5, "guide_off_heading": 0.0},  # the car route's arcs driven in tight places only,
            "pace": {"pace_horizon": 1.5}}  # and version 14's pace, as then
    wedged, freed = _run(barrier=0.0, **then), _run(**then)
    assert wedged.outcome == "timeout"
    stuck = wedged.speed[-200:]  # the last 20 s: the escape stands still
    assert abs(stuck).max() == 0.0 and set(wedged.behaviour[-200:]) == {"BF"}
    assert freed.outcome == "reached" and freed.t[-1] < 20.0
    today = _run()  # the default as it is (version 15's pace) gets out too
    assert today.outcome == "reached" and not today.collision
    assert _back_ups(wedged) == [1] * 19  # one step each, 19 times over
    assert _back_ups(freed) == [2, 2]  # two steps each: 6 cm backed frees the body
    backing = [k for k, b in enumerate(freed.behaviour) if b == "REC-BACK"]
    assert all(freed.speed[k] < 0 for k in backing)
    assert _run().outcome == "reached"  # today's default


def _back_ups(run) -> list[int]:
    """The steps of each back-up (``REC-BACK`` run) of ``run``."""
    return [len(list(steps)) for behaviour, steps in itertools.groupby(run.behaviour) if behaviour == "REC-BACK"]


def _wedged_back_up(backed: float, barrier_within: float):
    """One ``recovery.command`` step of a back-up that has covered ``backed`` m, the body 0.02 m from
    a post behind it on the right that the backing step nears (so only the barrier allows it)."""
    from fuzzynav.kernels import recovery
    from fuzzynav.kernels.layers import BACK, PARAM, STATE
    from fuzzynav.kernels.records import Pose, Sightings

    params = np.zeros(max(PARAM) + 1)
    params[[PARAM.radius, PARAM.margin, PARAM.back_distance, PARAM.recovery_time]] = 0.3, 0.05, 0.8, 10.0
    params[PARAM.barrier], params[PARAM.barrier_within] = 0.5, barrier_within
    params[PARAM.max_reverse_speed], params[PARAM.v_back] = 0.3, 0.3
    state = np.zeros(max(STATE) + 1)
    state[STATE.phase], state[STATE.start_x], state[STATE.t_recovery] = BACK, backed, 0.0
    state[STATE.back_speed], state[STATE.back_steering] = -0.3, 0.0
    post = np.array([[-0.1, -0.305]])  # 0.021 m from the body; a step back leaves 0.013 m
    seen = Sightings(points=post, count=1)
    return recovery.command(state, params, seen, Pose(x=0.0, y=0.0, theta=0.0), np.array([4.0]), np.array([0.0]),
                            0.1, 1.0)


def test_the_barrier_holds_only_within_the_first_centimetres_of_a_back_up():
    moving, _, speed, _ = _wedged_back_up(backed=0.02, barrier_within=0.05)
    assert moving and speed < 0  # within 5 cm: the step that closes part of the gap is taken
    assert not _wedged_back_up(backed=0.10, barrier_within=0.05)[0]  # beyond: only safe steps
    assert _wedged_back_up(backed=0.10, barrier_within=0.0)[0]  # 0: the barrier holds throughout


@pytest.mark.parametrize("option, bad", [("barrier", -0.1), ("barrier", 1.0), ("barrier", "half"),
                                         ("barrier_within", -0.01), ("barrier_within", "far")])
def test_a_barrier_option_out_of_range_is_refused_naming_the_option(option, bad):
    from fuzzynav.catalog.controllers import make_controller
    from fuzzynav.errors import InputError

    with pytest.raises(InputError, match=option):
        make_controller("fuzzy-5b", **{option: bad})
