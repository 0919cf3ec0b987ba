"""A variable's universe must be one a double can sample: finite ends, lo < hi, and a width
across which a centroid grid of the largest resolution stays finite."""

import pytest

from fuzzynav.errors import InputError
from fuzzynav.fuzzy.membership import Triangular
from fuzzynav.fuzzy.variable import Variable


@pytest.mark.parametrize("universe", [(1.0, 1.0), (2.0, 1.0), (float("nan"), 1.0), (0.0, float("inf")),
                                      (-1e308, 1e308), (-1e300, 1e300)])
def test_unsampleable_universes_are_refused_naming_the_field(universe):
    with pytest.raises(InputError, match="x.universe"):
        Variable("x", universe, {})


def test_a_wide_but_representable_universe_is_accepted():
    term = {"zero": Triangular(-1.0, 0.0, 1.0)}
    assert Variable("x", (-1e299, 1e299), term).universe == (-1e299, 1e299)
