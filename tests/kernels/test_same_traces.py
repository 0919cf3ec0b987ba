"""The compiled core drives exactly as the NumPy/float implementation it replaced: outcomes,
step counts, behaviour labels and poses (within 1e-9) of episodes recorded with that
implementation (tests/kernels/golden.py; the full comparison is benchmarks/trace_compare.py)."""

import json

import numpy as np
import pytest

from tests.kernels.golden import FILE, run_all


@pytest.mark.slow
def test_traces_equal_those_recorded_before_the_compiled_core():
    recorded = np.load(FILE)
    meta = json.loads(str(recorded["meta"]))
    runs = run_all()
    assert set(runs) == set(meta) and len(runs) == 25
    for key, (outcome, steps, labels, poses) in runs.items():
        assert [outcome, steps, labels] == meta[key], key
        np.testing.assert_allclose(poses, recorded[key], rtol=0, atol=1e-9, err_msg=key)
    assert {run[0] for run in runs.values()} == {"reached", "collision", "timeout"}
