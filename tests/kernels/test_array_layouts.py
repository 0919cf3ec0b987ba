"""The index constants the kernels read their flat arrays with are the positions of the names
those arrays are documented (and filled by name) with: a name added, removed or moved in one
list but not in the constants fails here, not as a kernel reading the wrong number."""

import pytest

from fuzzynav.kernels import layers, motion, step

LAYOUTS = [  # (module, the names of the array's fields, their constants' names where not NAME.upper())
    (layers, layers.PARAM_NAMES, {}),
    (layers, layers.STATE_NAMES, {"places": "PLACES_KEPT"}),
    (step, step.STATE_FIELDS, {}),
    (motion, motion.ROBOT_FIELDS, {}),
]


@pytest.mark.parametrize(("module", "names", "renamed"), LAYOUTS,
                         ids=["layer params", "layer state", "step state", "robot"])
def test_every_field_constant_is_its_names_position(module, names, renamed):
    wrong = {name: getattr(module, renamed.get(name, name.upper()), None) for name in names}
    wrong = {name: index for position, (name, index) in enumerate(wrong.items()) if index != position}
    assert wrong == {}
    assert len(set(names)) == len(names)


def test_the_step_set_up_fields_follow_the_robots():
    assert step.SETUP_FIELDS[:len(motion.ROBOT_FIELDS)] == motion.ROBOT_FIELDS
    task = step.SETUP_FIELDS[len(motion.ROBOT_FIELDS):]
    assert [getattr(step, name.upper()) for name in task] == list(range(len(motion.ROBOT_FIELDS), len(step.SETUP_FIELDS)))
    assert step.ANGLES == len(step.SETUP_FIELDS)


def test_the_blocks_of_the_layer_arrays_follow_their_named_fields():
    assert layers.TABLES_AT == len(layers.PARAM_NAMES) and layers.PLACES_AT == len(layers.STATE_NAMES)
