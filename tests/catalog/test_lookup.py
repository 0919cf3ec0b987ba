"""The three name registries (controllers, training tasks, experiments) share one lookup."""

import pytest

from fuzzynav.catalog import experiments as registry
from fuzzynav.catalog.controllers import CONTROLLERS, make_controller
from fuzzynav.catalog.tasks import trainer
from fuzzynav.errors import InputError
from fuzzynav.lookup import descriptions, resolve


def test_resolve_imports_the_registered_object():
    table = {"wrap": ("fuzzynav.world.geometry:wrap_angle", "wrap an angle")}
    assert resolve(table, "wrap", what="thing", field="F")(4.0) == pytest.approx(4.0 - 2 * 3.141592653589793)
    assert descriptions(table) == {"wrap": "wrap an angle"}


@pytest.mark.parametrize("call, message", [
    (lambda: make_controller("fuzzy-5"), "--controller: unknown controller 'fuzzy-5' (did you mean fuzzy-5b"),
    (lambda: trainer("fql-gaol"), "TASK: unknown training task 'fql-gaol' (did you mean fql-goal"),
    (lambda: registry.experiment("fig-V-2"), "ID: unknown experiment 'fig-V-2' (did you mean"),
])
def test_unknown_names_suggest_close_ones(call, message):
    with pytest.raises(InputError) as error:
        call()
    assert str(error.value).startswith(message)


def test_controller_listing_names_every_controller():
    with pytest.raises(InputError) as error:
        make_controller("zzz")
    assert str(error.value).endswith("known: " + ", ".join(sorted(CONTROLLERS)))
    assert "see 'fuzzynav reproduce --list'" in str(pytest.raises(InputError, registry.experiment, "zzz").value)
