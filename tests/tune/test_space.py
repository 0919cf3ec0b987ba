"""The search space: the start genes give back the thesis' system, any genes keep the knots in
order and the strong partitions strong, and rule genes pick conclusions by rank."""

import numpy as np
import pytest

from fuzzynav.catalog.roles import default_system
from fuzzynav.errors import InputError
from fuzzynav.fuzzy.partition import check_strong_partition
from fuzzynav.tune.space import SearchSpace

ROLES = [("fuzzy-2b", "oab"), ("goal-seeking", "gsb"), ("wall-follow", "wall"), ("fuzzy-5b", "foa"),
         ("fuzzy-5b", "vrb")]


@pytest.mark.parametrize("controller,role", ROLES)
@pytest.mark.parametrize("what", ["mf", "rules", "both"])
def test_start_genes_decode_to_the_system_itself(controller, role, what):
    system = default_system(controller, role)
    space = SearchSpace(system, what)
    assert space.decode(space.start) == system


@pytest.mark.parametrize("controller,role", ROLES)
def test_any_genes_keep_order_and_strong_partitions(controller, role):
    system = default_system(controller, role)
    space = SearchSpace(system, "both")
    rng = np.random.default_rng(3)
    for genes in [np.zeros(space.size), np.ones(space.size), *rng.random((20, space.size))]:
        tuned = space.decode(genes)
        for before, after in zip(system.inputs, tuned.inputs):
            assert bool(check_strong_partition(after)) == bool(check_strong_partition(before))
            peaks = [mf.params()[1] for mf in after.terms.values()]
            assert peaks == sorted(peaks)
        for after in tuned.outputs:
            values = [mf.value for mf in after.terms.values()]
            assert values == sorted(values) and len(set(values)) == len(values)


def test_extreme_genes_move_the_breakpoints_and_the_conclusions():
    system = default_system("fuzzy-2b", "oab")
    space = SearchSpace(system, "both")
    low = space.decode(np.zeros(space.size))
    assert low.inputs[0].terms["P"].params()[2] < system.inputs[0].terms["P"].params()[2]
    # every rule gene at 0 picks the lowest term: hard right, stopped
    assert all(dict(rule.conclusions) == {"alpha": "NG", "v": "Z"} for rule in low.rules)
    assert space.size == space.n_mf + 2 * len(system.rules)


def test_around_start_is_the_start_and_its_neighbours():
    space = SearchSpace(default_system("fuzzy-2b", "oab"), "both")
    population = space.around_start(8, np.random.default_rng(0))
    assert np.array_equal(population[0], space.start)
    assert not np.array_equal(population[1], space.start)
    moved = np.abs(space.picks(population[1]) - space.picks(space.start))
    assert moved.max() <= 1


def test_bad_what_is_refused():
    with pytest.raises(InputError, match="--what"):
        SearchSpace(default_system("fuzzy-2b", "oab"), "weights")
