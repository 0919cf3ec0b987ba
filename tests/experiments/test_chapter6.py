"""Chapter VI figures in quick mode: they train, plot and measure real closed-loop numbers."""

import pytest

from fuzzynav.catalog.experiments import available, experiment


def test_every_chapter6_experiment_is_registered():
    for key in ("fig-VI-1", "fig-VI-4", "table-VI-1", "fig-VI-8", "fig-VI-9", "fig-VI-13", "fig-VI-16",
                "fig-VI-22", "fig-VI-24", "fig-VI-29"):
        assert key in available() and callable(experiment(key))


@pytest.mark.slow
def test_fig_vi_8_fixed_start_fql_learns_the_goal(tmp_path):
    numbers = experiment("fig-VI-8")(tmp_path, quick=True, seed=0)
    assert (tmp_path / "fig-VI-8.png").stat().st_size > 10_000
    assert numbers["trajectories"] == ["reached"]  # the trained start (a fixed-start policy, Fig VI.7)
    assert numbers["converged_at"] == {"steering": None}  # 200 episodes: shorter than a window + the hold
    assert len(numbers["rules"]) == 15
    assert numbers["q_learning"]["episodes"] == 500  # tabular Q-learning from the same start, beside it


@pytest.mark.slow
def test_fig_vi_4_tabular_random_starts(tmp_path):
    numbers = experiment("fig-VI-4")(tmp_path, quick=True, seed=1)
    assert numbers["evaluation"]["success"] >= 0.8
    assert numbers["trajectories"].count("reached") >= 3


@pytest.mark.slow
def test_fig_vi_29_hand_made_follower_hits_both_corners_and_the_learned_one_reads_the_same_rays(tmp_path):
    # a smoke run (300 episodes): what the learned follower does is measured by the full protocol
    # (docs/results/chapter-vi.md)
    numbers = experiment("fig-VI-29")(tmp_path, quick=True, seed=0)
    assert numbers["corners"]["wall-follow"] == {"fig-VI-28": "collision", "fig-VI-28b": "collision"}
    assert numbers["evaluation"]["wall-follow"]["collisions"] >= 1
    assert numbers["sensing"] == "rays"
    assert len(numbers["rules"]) == 8
