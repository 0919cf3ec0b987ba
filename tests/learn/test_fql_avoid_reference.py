"""The compiled training of the avoider (fuzzynav.kernels.learned, kernels.motion.move_live)
learns exactly what the NumPy implementation it replaced learned: the qualities, fuzzy visits
and learning curve of both phases of a short run (60 episodes, seed 3), compared bit for bit
with ``fql_avoid_reference.json``, written by that NumPy implementation (commit 729cfd7)."""

import json
from pathlib import Path

from fuzzynav.learn.tasks import fql_avoid
from fuzzynav.learn.tasks.common import TrainRequest

REFERENCE = Path(__file__).with_name("fql_avoid_reference.json")


def test_a_short_avoider_training_learns_the_reference_qualities_bit_for_bit(tmp_path):
    out = tmp_path / "avoid.json"
    fql_avoid.train_fql_avoid(TrainRequest(out=out, episodes=60, seed=3, progress=False))
    reference = json.loads(REFERENCE.read_text())
    for phase in ("steering", "speed"):
        saved = json.loads(out.with_name(f"avoid.json.{phase}.checkpoint.json").read_text())
        assert saved["learner"]["q"] == reference[phase]["q"], phase
        assert saved["learner"]["visits"] == reference[phase]["visits"], phase
        assert saved["curve"]["mean_reward"] == reference[phase]["mean_reward"], phase
