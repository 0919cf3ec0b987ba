"""The compiled training of the avoider (fuzzynav.kernels.learned, the stepping core kernels.worlds)
learns what the NumPy implementation it replaced learned: both phases of a short run (60
episodes, seed 3) against ``fql_avoid_reference.json``, written by that NumPy implementation
(commit 729cfd7) — the learning curve bit for bit (every episode's rewards, so every action the
same), the qualities and fuzzy visits to 1e-12 relative: processors differ in the last bits of
the C library's transcendental functions (on an AMD EPYC, the qualities and visits differ from
the reference by up to 1e-14 relative, the curve not at all)."""

import json
from pathlib import Path

import numpy as np

from fuzzynav.learn.tasks import fql_avoid
from fuzzynav.learn.tasks.common import TrainRequest

REFERENCE = Path(__file__).with_name("fql_avoid_reference.json")


def test_a_short_avoider_training_learns_the_reference_curve_and_qualities(tmp_path):
    out = tmp_path / "avoid.json"
    # the batch learner (10 robots per batch) from the a-priori table, as the reference was written
    fql_avoid.train_fql_avoid(TrainRequest(out=out, episodes=60, seed=3, progress=False,
                                           parallel=fql_avoid.AVOID_BATCH, prior="thesis"))
    reference = json.loads(REFERENCE.read_text())
    for phase in ("steering", "speed"):
        saved = json.loads(out.with_name(f"avoid.json.{phase}.checkpoint.json").read_text())
        assert saved["curve"]["mean_reward"] == reference[phase]["mean_reward"], phase
        for field in ("q", "visits"):
            np.testing.assert_allclose(saved["learner"][field], reference[phase][field], rtol=1e-12, atol=0,
                                       err_msg=f"{phase}: {field}")
