"""The index constants the kernels read their flat arrays with are the positions of the names
those arrays are documented (and filled by name) with: a name added, removed or moved in one
list but not in the constants fails here, not as a kernel reading the wrong number. The layers'
arrays are generated from one dataclass per layer (kernels.layers): their positions are the
dataclasses' fields in order, and every field says its unit or meaning."""

import math
from dataclasses import fields

import numpy as np
import pytest

from fuzzynav.control.escape import FOLLOW, LOOP
from fuzzynav.control.recovery import RECOVERY
from fuzzynav.control.through_gaps import GUIDANCE, PACE
from fuzzynav.errors import InputError
from fuzzynav.kernels import layers, motion, row_blocks, step

LAYOUTS = [  # (module, the names of the array's fields)
    (step, step.STATE_FIELDS),
    (motion, motion.ROBOT_FIELDS),
]


@pytest.mark.parametrize(("module", "names"), LAYOUTS, ids=["step state", "robot"])
def test_every_field_constant_is_its_names_position(module, names):
    wrong = {name: getattr(module, name.upper(), None) for name in names}
    wrong = {name: index for position, (name, index) in enumerate(wrong.items()) if index != position}
    assert wrong == {}
    assert len(set(names)) == len(names)


def test_the_step_set_up_fields_follow_the_robots():
    assert step.SETUP_FIELDS[:len(motion.ROBOT_FIELDS)] == motion.ROBOT_FIELDS
    task = step.SETUP_FIELDS[len(motion.ROBOT_FIELDS):]
    assert [getattr(step, name.upper()) for name in task] == list(range(len(motion.ROBOT_FIELDS), len(step.SETUP_FIELDS)))
    assert step.ANGLES == len(step.SETUP_FIELDS)


def test_the_layer_positions_are_the_fields_of_the_layer_dataclasses_in_order():
    names = [field.name for record in layers.PARAMETERS for field in fields(record)]
    assert list(layers.PARAM._fields) == names and list(layers.PARAM) == list(range(len(names)))
    assert list(layers.STATE._fields) == [field.name for field in fields(layers.RobotState)]
    assert set(layers.NEW_EPISODE) <= set(layers.STATE_NAMES)  # no value for a field that is not there
    assert len(set(names)) == len(names)  # no field in two layers
    assert layers.TABLES_AT == len(layers.PARAM) and layers.PLACES_AT == len(layers.STATE)


@pytest.mark.parametrize("record", [*layers.PARAMETERS, layers.RobotState], ids=lambda record: record.__name__)
def test_every_layer_field_has_a_docstring(record):
    import ast
    import inspect

    body = ast.parse(inspect.getsource(record)).body[0].body
    documented = {node.target.id for node, after in zip(body, body[1:])
                  if isinstance(node, ast.AnnAssign) and isinstance(after, ast.Expr)
                  and isinstance(after.value, ast.Constant) and isinstance(after.value.value, str)}
    assert documented == {field.name for field in fields(record)}


def test_pack_writes_each_record_by_name_and_leaves_a_layer_not_given_off():
    params = layers.pack(RECOVERY, LOOP, FOLLOW, GUIDANCE, PACE)
    assert params[layers.PARAM.v_back] == RECOVERY.v_back and params[layers.PARAM.horizon] == LOOP.horizon
    assert params[layers.PARAM.guide] == 1.0 and params[layers.PARAM.pace] == 1.0
    assert params[layers.PARAM.guide_car_steering] == GUIDANCE.guide_car_steering
    assert params[layers.PARAM.on] == 0.0 and params[layers.PARAM.radius] == 0.0  # Supervisor, Body not given
    assert layers.pack(RECOVERY)[layers.PARAM.guide] == 0.0


def test_a_fresh_state_row_holds_a_new_episodes_values_then_zeroed_blocks():
    params = layers.pack(layers.Slots(places_slots=3, route_slots=5, points_slots=4, cell_slots=8))
    state = layers.fresh_state(2, params)
    assert state.shape == (2, layers.PLACES_AT + 3 * 3 + 4 * 5 + 2 * 4 + 8)
    assert row_blocks.route_of(params, state[0]).shape == (5, 4) and row_blocks.points_of(params, state[0]).shape == (4, 2)
    np.testing.assert_array_equal(state[:, layers.PLACES_AT:], 0.0)
    assert math.isnan(state[1, layers.STATE.guide_x]) and state[0, layers.STATE.best] == math.inf
    assert state[0, layers.STATE.planned] == -math.inf and state[0, layers.STATE.phase] == layers.NO_PHASE


def test_an_unknown_guidance_or_pace_option_is_refused_with_its_name():
    from fuzzynav.catalog.controllers import make_controller

    with pytest.raises(InputError, match="pace_lookahead"):
        make_controller("fuzzy-5b", pace={"pace_lookahead": 2.0})
    assert make_controller("fuzzy-5b", pace={"pace_goal": 2.0}).params[layers.PARAM.pace_goal] == 2.0
