"""Shared by the claim tests: the numbers of a run turned against its claim."""

import pytest


def _spoiled(value):
    """``value`` with every flag negated and every number v replaced by 1 − v (routes move, errors
    and rates leave their bounds, steering changes sign); strings and None kept."""
    if isinstance(value, bool):
        return not value
    if isinstance(value, (int, float)):
        return 1 - value
    if isinstance(value, dict):
        return {key: _spoiled(inner) for key, inner in value.items()}
    if isinstance(value, list):
        return [_spoiled(inner) for inner in value]
    return value


@pytest.fixture
def spoiled():
    """The function that spoils a run's numbers: a claim must not hold on them."""
    return _spoiled
