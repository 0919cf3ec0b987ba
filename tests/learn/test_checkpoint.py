"""Checkpoints: an interrupted-then-resumed run equals the uninterrupted one bit for bit."""

import json

import numpy as np
import pytest
from test_fql import LineEnv, make
from test_tabular import GAMMA, N_STATES, ChainEnv

from fuzzynav.errors import InputError
from fuzzynav.learn.checkpoint import load_checkpoint, save_checkpoint, train_loop
from fuzzynav.learn.exploration import EpsilonGreedy
from fuzzynav.learn.schedules import ExponentialDecay, InverseVisits
from fuzzynav.learn.tabular import TabularLearner

EPISODES, CRASH_AT, EVERY = 24, 17, 5


class CrashingEnv:
    """Wraps an environment and raises KeyboardInterrupt (Ctrl-C) mid-episode number ``crash_at``."""

    def __init__(self, env, crash_at):
        self.env, self.crash_at, self.resets = env, crash_at, 0

    def reset(self, rng):
        self.resets += 1
        return self.env.reset(rng)

    def step(self, action, rng):
        if self.resets == self.crash_at and getattr(self.env, "t", 0) == 2:
            raise KeyboardInterrupt
        return self.env.step(action, rng)


def tabular():
    return TabularLearner(N_STATES, 2, method="q_lambda", lam=0.7, gamma=GAMMA, n_tables=3,
                          alpha=InverseVisits(power=0.8),
                          policy=EpsilonGreedy(ExponentialDecay(0.5, 0.9, 0.05)))


CASES = {
    "tabular-json": (tabular, lambda: ChainEnv(3), "run.json"),
    "fql-npz": (lambda: make(rows=4, lam=0.6), lambda: LineEnv(4), "run.npz"),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_resume_equals_uninterrupted(tmp_path, case):
    new_learner, new_env, name = CASES[case]
    reference = new_learner()
    reference_rng = np.random.default_rng(7)
    expected = train_loop(new_env(), reference, EPISODES, reference_rng)

    path = tmp_path / name
    learner = new_learner()
    with pytest.raises(KeyboardInterrupt):
        train_loop(CrashingEnv(new_env(), CRASH_AT), learner, EPISODES, np.random.default_rng(7),
                   checkpoint=path, checkpoint_every=EVERY)
    saved = load_checkpoint(path)
    assert saved["episode"] == (CRASH_AT - 1) // EVERY * EVERY  # the last complete checkpoint
    assert [p.name for p in tmp_path.iterdir()] == [name]  # no temporary file left behind

    resumed_learner, rng = new_learner(), np.random.default_rng(999)  # state comes from the file
    result = train_loop(new_env(), resumed_learner, EPISODES, rng, checkpoint=path,
                        checkpoint_every=EVERY, resume=True)
    assert result.resumed_from == saved["episode"] and result.episode == EPISODES
    assert np.array_equal(resumed_learner.q, reference.q)
    assert np.array_equal(resumed_learner.visits, reference.visits)
    assert resumed_learner.episode == reference.episode == EPISODES
    assert result.curve == expected.curve
    assert rng.bit_generator.state == reference_rng.bit_generator.state
    assert load_checkpoint(path)["episode"] == EPISODES


def test_resume_refuses_another_runs_checkpoint(tmp_path):
    path = tmp_path / "run.json"
    train_loop(ChainEnv(3), tabular(), 2, np.random.default_rng(0), checkpoint=path)
    other = TabularLearner(N_STATES, 2, method="q_lambda", lam=0.7, gamma=0.5, n_tables=3,
                           alpha=InverseVisits(power=0.8),
                           policy=EpsilonGreedy(ExponentialDecay(0.5, 0.9, 0.05)))
    with pytest.raises(InputError, match="learner.gamma"):
        train_loop(ChainEnv(3), other, 4, np.random.default_rng(0), checkpoint=path, resume=True)


def test_checkpoint_files_are_plain_json_and_checked(tmp_path):
    learner = tabular()
    rng = np.random.default_rng(1)
    save_checkpoint(tmp_path / "c.json", learner, rng, 3, {"mean_reward": [[0.5]]}, extra={"task": "toy"})
    document = json.loads((tmp_path / "c.json").read_text())
    assert document["kind"] == "fuzzynav-checkpoint" and document["extra"] == {"task": "toy"}
    assert document["rng"] == rng.bit_generator.state
    (tmp_path / "model.json").write_text(json.dumps({"kind": "fuzzy-controller"}))
    with pytest.raises(InputError, match="not a training checkpoint"):
        load_checkpoint(tmp_path / "model.json")
    with pytest.raises(InputError, match="no such checkpoint"):
        load_checkpoint(tmp_path / "missing.json")
    (tmp_path / "folder.json").mkdir()
    with pytest.raises(InputError, match="is a folder, not a checkpoint"):
        load_checkpoint(tmp_path / "folder.json")
    (tmp_path / "cut.json").write_text('{"kind": "fuzzynav-checkpoint", "episode":')  # a write cut short
    with pytest.raises(InputError, match="cannot read checkpoint: not a valid JSON document"):
        load_checkpoint(tmp_path / "cut.json")
    with pytest.raises(InputError, match="episodes"):
        train_loop(ChainEnv(3), learner, -1, rng)


def test_progress_bar_counts_single_episodes_across_a_smaller_last_batch(tmp_path, monkeypatch):
    """3 batches of 4 episodes, then (resumed) 1 batch of 2: the bar runs 12 → 14 of 14."""
    from fuzzynav import progress

    bars = []

    class Bar:
        def __init__(self, *, total, initial, **options):
            self.total, self.n = total, initial
            bars.append(self)

        def update(self, n):
            self.n += n

        def set_postfix(self, **values):
            """Not recorded: the test reads the bar's totals only."""

        def close(self):
            """Nothing to release."""

    monkeypatch.setattr(progress, "bar", Bar)
    path, learner, rng = tmp_path / "run.json", make(rows=4, learners=1), np.random.default_rng(3)
    train_loop(LineEnv(4), learner, 3, rng, checkpoint=path, progress=True, batch_size=4)
    train_loop(LineEnv(2), learner, 4, rng, checkpoint=path, resume=True, progress=True, batch_size=2)
    assert [(bar.total, bar.n) for bar in bars] == [(12, 12), (14, 14)]
