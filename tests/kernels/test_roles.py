"""The chapter IV controllers take their rule bases by role (``systems={role: system}``), run them
compiled, and refuse unknown roles or systems the compiled evaluator cannot run."""

import numpy as np
import pytest

from fuzzynav.catalog.controllers import make_controller
from fuzzynav.errors import InputError
from fuzzynav.fuzzy import systems_navigation as nav
from fuzzynav.fuzzy.rules import Rule
from fuzzynav.fuzzy.system import FuzzySystem
from fuzzynav.fuzzy.systems import goal_seeking
from fuzzynav.kernels import ts0
from fuzzynav.sim import run_episode
from fuzzynav.world.scenario import load_scenario

FIVE = ("gsb", "foa", "roa", "loa", "vrb")
ROLES = {"goal-seeking": ("gsb",), "fuzzy-2b": ("gsb", "oab"), "fuzzy-5b": FIVE, "fuzzy-5b-gap-robust": FIVE,
         "fuzzy-5b-rays": FIVE, "wall-follow": ("wall",)}


@pytest.mark.parametrize("name, roles", ROLES.items())
def test_role_names(name, roles):
    assert make_controller(name).roles == roles


def test_the_default_tables_given_by_role_drive_as_the_defaults():
    scenario = load_scenario("fig-IV-22a")
    given = {"gsb": goal_seeking(), "foa": nav.front_avoider(), "vrb": nav.velocity_reducer()}
    a = run_episode(scenario, make_controller("fuzzy-5b-rays"))
    b = run_episode(scenario, make_controller("fuzzy-5b-rays", systems=given))
    np.testing.assert_array_equal(a.pose, b.pose)


def _goal_seeking(**options):
    """Table IV.1 as a new system: speeds capped at F (1 m/s), or other ``options``."""
    table = goal_seeking()
    capped = [Rule(rule.premises, tuple((v, "F" if v == "v" and t in ("M", "G", "TG") else t)
                                        for v, t in rule.conclusions)) for rule in table.rules]
    settings = {"method": "ts0", "tnorm": "product", "defuzzifier": "weighted_sum", **options}
    return FuzzySystem(table.inputs, table.outputs, capped, **settings)


def test_an_edited_rule_table_changes_the_drive():
    scenario = load_scenario("fig-IV-22a")
    default = run_episode(scenario, make_controller("goal-seeking"), max_time=5.0)
    edited = run_episode(scenario, make_controller("goal-seeking", systems={"gsb": _goal_seeking()}), max_time=5.0)
    assert default.speed.max() > 2.0 and edited.speed.max() == pytest.approx(1.0)


def test_unknown_role_and_unsupported_system_are_input_errors():
    with pytest.raises(InputError, match="unknown role"):
        make_controller("fuzzy-2b", systems={"foa": nav.front_avoider()})
    with pytest.raises(InputError, match="fuzzy-5b gsb"):  # the min T-norm has no multilinear form
        make_controller("fuzzy-5b-rays", systems={"gsb": _goal_seeking(tnorm="min")})
    with pytest.raises(InputError, match="fuzzy-5b-gap gsb"):  # the navigator inside the default
        make_controller("fuzzy-5b", systems={"gsb": _goal_seeking(tnorm="min")})
    foa = nav.front_avoider()
    four = nav.distance_variable("d4")
    wider = FuzzySystem([*foa.inputs, four], foa.outputs, [Rule((*r.premises, ("d4", "P")), r.conclusions)
                                                          for r in foa.rules], tnorm="product",
                        defuzzifier="weighted_sum")
    with pytest.raises(InputError, match="4 inputs"):
        ts0.pack([wider], ["fuzzy-5b foa"])
