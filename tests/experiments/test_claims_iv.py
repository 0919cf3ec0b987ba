"""The claim of Figs IV.13–IV.14 checks what the text says of the steering: "braquage maximale et
positive pour tourner à gauche … puis elle se diminue pour être nulle" — on numbers made up
for each way it can fail (the closed-loop run that passes is in test_chapter4.py)."""

import math

import pytest

from fuzzynav.catalog.experiments import spec

RUN = {"outcome": "reached", "final_speed_mps": 0.05, "max_speed_mps": 3.7, "first_steering_rad": math.pi / 10,
       "largest_steering_rad": math.pi / 10, "aligned_at_s": 2.3, "largest_steering_once_aligned_rad": 0.0,
       "route": [[2.0, 3.0], [16.0, 17.0]]}


def _steering_checks(**changes):
    checks = spec("fig-IV-13").claim.evaluate({**RUN, **changes})[1]
    return {c.name: c.passed for c in checks if "steering" in c.name}


def test_a_first_steering_to_the_left_that_is_the_runs_largest_and_falls_to_zero_passes():
    assert _steering_checks() == {"first steering (°)": True, "largest steering once aligned (°)": True}


@pytest.mark.parametrize(("changes", "failed"), [
    ({"first_steering_rad": -math.pi / 10}, "first steering (°)"),  # to the right
    ({"largest_steering_rad": math.pi / 5}, "first steering (°)"),  # larger later: not "maximale" at first
    ({"aligned_at_s": None, "largest_steering_once_aligned_rad": None}, "largest steering once aligned (°)"),  # never 0
    ({"largest_steering_once_aligned_rad": math.radians(8)}, "largest steering once aligned (°)"),  # swerves again
])
def test_each_way_the_steering_departs_from_the_text_fails(changes, failed):
    checks = _steering_checks(**changes)
    assert not checks[failed] and all(passed for name, passed in checks.items() if name != failed)
