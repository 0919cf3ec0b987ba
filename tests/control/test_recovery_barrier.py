"""The recovery's barrier step (``fuzzy-5b`` with ``barrier=0.5``, :func:`fuzzynav.kernels.recovery.may_step`):
on BARN world 130 at the BARN robot's 2 m/s a paced arc leaves the robot wedged between two posts,
each within the recovery's margin; the default (``barrier=0``) backs one step at a time, gives up,
and the loop escape then stands still to the time limit; the barrier lets it back out and arrive."""

from pathlib import Path

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
def test_the_barrier_backs_out_of_the_wedge_where_the_default_stands_still():
    wedged, freed = _run(), _run(barrier=0.5)
    assert wedged.outcome == "timeout"
    stuck = wedged.speed[-200:]  # the last 20 s: the escape stands still
    assert abs(stuck).max() == 0.0 and set(wedged.behaviour[-200:]) == {"BF"}
    assert freed.outcome == "reached" and freed.t[-1] < 20.0
    backing = [k for k, b in enumerate(freed.behaviour) if b == "REC-BACK"]
    assert len(backing) > 5 and all(freed.speed[k] < 0 for k in backing)  # backed on, not one step


@pytest.mark.parametrize("bad", [-0.1, 1.0, "half"])
def test_a_barrier_outside_0_to_1_is_refused_naming_the_option(bad):
    from fuzzynav.catalog.controllers import make_controller
    from fuzzynav.errors import InputError

    with pytest.raises(InputError, match="barrier"):
        make_controller("fuzzy-5b", barrier=bad)
