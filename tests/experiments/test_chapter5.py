"""Chapter V figures: every experiment writes its figure and measures what the thesis shows."""

import pytest

from fuzzynav.catalog.experiments import experiment, spec

pytestmark = pytest.mark.slow


def test_control_surface_spans_the_steering_range(tmp_path):
    result = experiment("fig-V-7")(tmp_path, True, 0)
    assert result["alpha_min_rad"] == pytest.approx(-0.7854, abs=1e-3)
    assert result["alpha_max_rad"] == pytest.approx(0.7854, abs=1e-3)
    assert (tmp_path / "fig-V-7.png").stat().st_size > 0


def test_training_figures(tmp_path):
    assert experiment("fig-V-15")(tmp_path, True, 0)["validation_rmse_rad"] < 2e-3
    assert experiment("fig-V-23")(tmp_path, True, 0)["validation_rmse_rad"] < 1e-3
    assert (tmp_path / "fig-V-15.png").is_file() and (tmp_path / "fig-V-23.png").is_file()


# the pursuit claims check that CF, CN and CNF all capture, CN and CNF no later than CF (Figs V.32–V.34:
# test_chapter5_figures.py)
@pytest.mark.parametrize("key", ["fig-V-7", "fig-V-10", "fig-V-11", "fig-V-19", "fig-V-28", "fig-V-29", "fig-V-30",
                                 "fig-V-31"])
def test_each_claim_holds_with_the_published_table(tmp_path, key, spoiled):
    numbers = experiment(key)(tmp_path, True, 0)
    verdict, checks = spec(key).claim.evaluate(numbers)
    assert verdict == "reproduced", [c for c in checks if not c.passed]
    assert spec(key).claim.evaluate(spoiled(numbers))[0] != "reproduced"  # and it can fail
    assert any(tmp_path.glob("*.png"))
