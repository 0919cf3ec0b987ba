"""Chapter VI figures in quick mode: they train, plot and measure real closed-loop numbers."""

import pytest

from fuzzynav.experiments.registry import EXPERIMENTS, experiment


def test_every_chapter6_experiment_is_registered():
    for key in ("fig-VI-1", "fig-VI-4", "table-VI-1", "fig-VI-8", "fig-VI-9", "fig-VI-13", "fig-VI-16",
                "fig-VI-22", "fig-VI-24", "fig-VI-29"):
        assert key in EXPERIMENTS and callable(experiment(key))


@pytest.mark.slow
def test_fig_vi_8_fixed_start_fql_learns_the_goal(tmp_path):
    numbers = experiment("fig-VI-8")(tmp_path, quick=True, seed=0)
    assert (tmp_path / "fig-VI-8.png").stat().st_size > 10_000
    assert numbers["trajectories"] == ["reached"]
    assert numbers["evaluation"]["success"] >= 0.9
    assert len(numbers["rules"]) == 15


@pytest.mark.slow
def test_fig_vi_4_tabular_random_starts(tmp_path):
    numbers = experiment("fig-VI-4")(tmp_path, quick=True, seed=1)
    assert numbers["evaluation"]["success"] >= 0.8
    assert numbers["trajectories"].count("reached") >= 3


@pytest.mark.slow
def test_fig_vi_29_optimised_follower_passes_the_corners_that_the_hand_made_one_hits(tmp_path):
    numbers = experiment("fig-VI-29")(tmp_path, quick=True, seed=0)
    assert numbers["fig-VI-28: wall-follow (Table VI.2)"] == "collision"
    assert numbers["fig-VI-28: FQL-optimised"] != "collision"
    assert numbers["evaluation"]["fql-wall"]["fig-VI-28"] != "collision"
    assert len(numbers["rules"]) == 8
