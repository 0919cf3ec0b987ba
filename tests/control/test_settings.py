"""Controller options checked where the controllers are made (fuzzynav.settings)."""

from __future__ import annotations

import inspect
import math

import pytest

from fuzzynav.catalog.controllers import CONTROLLERS, make_controller
from fuzzynav.errors import InputError
from fuzzynav.kernels import navigators
from fuzzynav.settings import LENGTH, Range, checked

NAMES = sorted(CONTROLLERS)
BAD = {"bool": ["yes", 3, None], "int": [2.5, -(10**12), 10**30, "10", True], "float": [math.nan, math.inf, -1e300, 1e300, "1", None]}


def _settings(name: str) -> dict[str, str]:
    """The bool, int and float settings of the controller's factory and of the class it builds."""
    from fuzzynav.catalog.controllers import spec_of
    from fuzzynav.lookup import load

    found = {}
    controller = make_controller(name)
    layer = getattr(controller, "layer", None)  # the yield layer round fuzzy-5b-yield: its settings are the options
    for function in (load(spec_of(name).factory), type(controller).__init__, *([type(layer).__init__] if layer else [])):
        for parameter in inspect.signature(function).parameters.values():
            if parameter.annotation in BAD and parameter.default is not parameter.empty:
                found[parameter.name] = parameter.annotation
    return found


@pytest.mark.parametrize("name", NAMES)
def test_an_unknown_option_names_the_controller_and_the_option(name):
    with pytest.raises(InputError, match=rf"{name} options: no_such_setting: no such option"):
        make_controller(name, no_such_setting=1)


@pytest.mark.parametrize("name", NAMES)
def test_every_setting_refuses_a_value_outside_its_kind(name):
    settings = _settings(name)
    assert settings or name == "wall-follow"  # its settings are its rule base's (checked below)
    for setting, kind in settings.items():
        for value in BAD[kind]:
            try:
                make_controller(name, **{setting: value})
            except InputError as error:
                assert f"{name} options" in str(error) and setting in str(error), str(error)
                continue
            except TypeError as error:  # the factory fixes it itself: said so, not a traceback
                pytest.fail(f"{name} {setting}={value!r}: {error}")
            pytest.fail(f"{name} accepted {setting}={value!r}")


@pytest.mark.parametrize(("name", "options", "message"), [
    ("dwa", {"n_steering": 10**9}, "n_steering: must be an integer in"),
    ("vfh", {"prediction": 1e9}, "prediction: must be <= 60"),
    ("vfh", {"prediction_step": 1e-9}, "prediction_step: must be >= 0.01"),
    ("vfh", {"sector": 1e300}, "sector: must be <= 180"),
    ("fuzzy-5b", {"paced": "no"}, "paced: must be true or false"),
    ("fuzzy-5b", {"guidance": 5}, "guidance: must be a mapping"),
    ("fuzzy-5b", {"pace": [1]}, "pace: must be a mapping"),
    ("fuzzy-5b", {"memory": 0}, "memory: must be an integer in"),
    ("fuzzy-5b-thesis", {"d_m": 3.5}, "need 0 < d_m < d_s <= d_max"),
    ("pure-pursuit", {"wheelbase": -0.5}, "wheelbase: must be > 0"),
    ("astar-pp", {"max_steering": math.pi / 2}, "max_steering: must be < 1.5708"),
    ("fuzzy-tracker", {"systems": 5}, "systems: must be a mapping"),
    ("neural-tracker", {"max_steering": 0.5}, "max_steering: is set by the controller itself"),
    ("anfis-tracker", {"seed": None}, "seed: must be an integer"),
    ("fuzzy-5b-yield", {"horizon": 0}, "horizon: must be > 0"),
    ("wall-follow", {"v1": math.nan}, "v1: must be finite"),
    ("wall-follow", {"d_s": "1.6"}, "d_s: must be a number"),
    ("anfis-tracker", {"input_range": [0, 1]}, "input_range: is set by the controller itself"),  # "argument"
])
def test_a_bad_value_is_named_with_what_is_wrong(name, options, message):
    with pytest.raises(InputError, match=rf"^{name} options: .*{message}"):
        make_controller(name, **options)


@pytest.mark.parametrize(("name", "options", "arrived"), [
    ("fuzzy-5b", {"barrier": 0.0, "goal_share": 1.0, "paced": False, "memory": 1},
     lambda c: (c.goal_share, c.navigator.memory) == (1.0, 1)),
    ("dwa", {"n_steering": 1, "n_speeds": 1001, "margin": 0.0}, lambda c: (c.n_speeds, c.margin) == (1001, 0.0)),
    ("vfh", {"sector": 180.0, "prediction": 60.0, "prediction_step": 0.01, "tracks": True},
     lambda c: (c.n, c.width, len(c.ahead), type(c.map).__name__) == (2, math.pi, 6001, "TrackedMap")),
    ("stanley", {"gain": 1e4, "speed": 100.0}, lambda c: (c.gain, c.speed) == (1e4, 100.0)),
    ("fuzzy-5b-thesis", {"layers": ("orbit_guard",), "v_floor": 0.0},
     lambda c: [c.params[i] for i in (navigators.V_TURN, navigators.ORBIT_GUARD, navigators.TURNING_ROOM)] == [0.0, 1.0, 0.0]),
])
def test_values_at_the_ends_of_their_ranges_are_taken(name, options, arrived):
    """Accepted (not refused as out of range) and received."""
    assert arrived(make_controller(name, **options))


def test_a_setting_without_a_range_is_an_error_where_it_is_declared():
    with pytest.raises(TypeError, match=r"no range for \['gain'\]"):
        @checked(size=LENGTH)
        def make(*, size: float = 1.0, gain: float = 2.0):
            return size, gain
    with pytest.raises(TypeError, match=r"ranges for no setting \['speed'\]"):
        @checked(size=LENGTH, speed=LENGTH)
        def other(*, size: float = 1.0):
            return size


def test_only_the_values_given_are_checked_and_a_bad_keyword_stays_the_callers_error():
    @checked(count=Range(1, 3))
    def make(*, count: int = 99, flag: bool = True):
        return count, flag

    assert make() == (99, True)  # the defaults are the author's, not checked
    assert make(count=3, flag=False) == (3, False)
    with pytest.raises(InputError, match="count: must be an integer in"):
        make(count=4)
    with pytest.raises(TypeError, match="unexpected keyword"):
        make(counts=2)
