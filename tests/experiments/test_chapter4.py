"""Chapter IV figures (and Figs VI.27–VI.28): each writes its figure and shows what the thesis shows."""

import pytest

from fuzzynav.catalog.experiments import experiment, spec

pytestmark = pytest.mark.slow


def test_fig_iv_12_and_13(tmp_path):
    result = experiment("fig-IV-12")(tmp_path, True, 0)
    assert result["all_reached"]
    assert all(r["final_speed_mps"] < 0.15 for panel in ("a", "b") for r in result[panel])
    result = experiment("fig-IV-13")(tmp_path, True, 0)
    assert result["outcome"] == "reached" and result["first_steering_rad"] > 0 and result["max_speed_mps"] > 3
    assert (tmp_path / "fig-IV-12.png").is_file() and (tmp_path / "fig-IV-13.png").is_file()


def test_fig_iv_15_22_23(tmp_path):
    for key, names in (("fig-IV-15", ("fig-IV-15a", "fig-IV-15b")), ("fig-IV-22", ("fig-IV-22a", "fig-IV-22b")),
                       ("fig-IV-23", ("fig-IV-23",))):
        result = experiment(key)(tmp_path, True, 0)
        assert all(result[n]["outcome"] == "reached" for n in names)
        assert (tmp_path / f"{key}.png").stat().st_size > 0
    assert experiment("fig-IV-15")(tmp_path, True, 0)["fig-IV-15a"]["behaviour_changes"] >= 2


def test_fig_vi_28_wall_follower(tmp_path):
    result = experiment("fig-VI-28")(tmp_path, True, 0)
    assert result["fig-VI-27"]["outcome"] == "reached"
    assert result["fig-VI-28"]["outcome"] == "collision"


def test_eval_iv_quick(tmp_path, spoiled):
    result = experiment("eval-IV")(tmp_path, True, 0)
    assert result["fuzzy-2b-thesis/circles"]["n"] == 10
    assert {"fuzzy-2b-layered/circles", "fuzzy-5b-layered/mixed"} <= set(result)
    assert result["fuzzy-2b-thesis/circles"]["success_rate"] >= 0.8
    assert result["fuzzy-5b-thesis/mixed"]["success_rate"] >= 0.7
    assert spec("eval-IV").claim.evaluate(result)[0] == "reproduced"
    verdict, checks = spec("eval-IV").claim.evaluate(spoiled(result))  # rates r -> 1 - r
    assert verdict == "not reproduced" and len(checks) == 6


@pytest.mark.parametrize("key", ["fig-IV-12", "fig-IV-13", "fig-IV-15", "fig-IV-22", "fig-IV-23", "fig-VI-28"])
def test_each_claim_holds_with_the_published_tables(tmp_path, key, spoiled):
    numbers = experiment(key)(tmp_path, True, 0)
    verdict, checks = spec(key).claim.evaluate(numbers)
    assert verdict == "reproduced", [c for c in checks if not c.passed]
    assert any(c.source == "package" and "published" in c.name for c in checks)  # it compares with the tables' run
    assert spec(key).claim.evaluate(spoiled(numbers))[0] != "reproduced"  # and it can fail
