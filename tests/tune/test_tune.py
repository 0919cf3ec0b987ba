"""``fuzzynav tune``: short runs that change the rule base and do no worse than the start on the
training worlds, a killed run resumed to the same end, the tuned file read back by ``run``,
``fis convert`` and the C export, and bad options refused before any simulation."""

import json
import re

import numpy as np
import pytest

from fuzzynav.catalog.controllers import make_controller
from fuzzynav.cli import main
from fuzzynav.errors import InputError
from fuzzynav.fuzzy.io import load
from fuzzynav.fuzzy.io.files import dumps, loads
from fuzzynav.fuzzy.systems import get_system
from fuzzynav.sim import metrics, run_episode
from fuzzynav.tune import session
from fuzzynav.tune.fitness import Fitness
from fuzzynav.tune.session import TuneRequest, tune
from fuzzynav.world.scenario import load_scenario
from fuzzynav.world.scenario_file import open_scenario

WORLDS = "mixed:4"  # four generated worlds; the held-out ones: mixed:4:1000
SMALL = dict(worlds=WORLDS, population=4, budget=4 * 4 * 3, seed=0)


def _no_worse_and_changed(result, budget):
    start, tuned = result["start"]["training"], result["tuned"]["training"]
    assert result["changed"]
    assert tuned["cost"] <= start["cost"]
    assert (tuned["success_rate"], -tuned["collisions"]) >= (start["success_rate"], -start["collisions"])
    assert result["episodes"] == budget and result["evaluations"] == budget // 4


# the ant colony stays near the start (q0 = 0.9, the heuristic leans on the start's conclusions):
# on four worlds it needs six iterations, and seed 1, to find a better walk
@pytest.mark.parametrize("method,what,budget,seed", [("ga", "both", 48, 0), ("pso", "mf", 48, 0), ("de", "both", 48, 0),
                                                     ("cmaes", "mf", 48, 0), ("aco", "rules", 96, 1)])
def test_a_short_tune_changes_the_rule_base_and_is_no_worse_on_its_worlds(method, what, budget, seed):
    result = tune(TuneRequest(target="fuzzy-2b:oab", method=method, what=what,
                              **{**SMALL, "budget": budget, "seed": seed}))
    _no_worse_and_changed(result, budget)
    assert result["curve"][0][1] <= result["start"]["training"]["cost"]  # the start is in the first generation
    assert result["curve"][-1][1] <= result["curve"][0][1]
    assert set(result["tuned"]["holdout"]) >= {"success_rate", "collisions", "mean_time_s"}


def test_aco_changes_only_rule_conclusions():
    result = tune(TuneRequest(target="fuzzy-2b:oab", method="aco", what="rules", **{**SMALL, "budget": 96, "seed": 1}))
    start = session.check(TuneRequest(target="fuzzy-2b:oab", **SMALL))[1]
    assert result["system"].inputs == start.inputs and result["system"].outputs == start.outputs
    assert result["system"].rules != start.rules


def test_replaced_systems_are_the_start_and_the_fixed_roles():
    text = dumps(get_system("obstacle-avoidance"), "yaml")
    zeroed = loads(re.sub(r"alpha IS \w+", "alpha IS Z", text), "yaml")  # Table IV.2 steering all Z
    controller, start, _, _ = session.check(TuneRequest(target="fuzzy-2b:oab", systems={"oab": zeroed}, **SMALL))
    assert start is zeroed and controller.systems["oab"] is zeroed
    assert controller.systems["gsb"].rules == get_system("goal-seeking").rules  # the other role stays as published
    with pytest.raises(session.InputError, match="no role wall"):
        session.check(TuneRequest(target="fuzzy-2b:oab", systems={"wall": zeroed}, **SMALL))


def test_nsga2_gives_a_front_of_non_dominated_files(tmp_path, capsys):
    out = tmp_path / "oab.yaml"
    assert main(["tune", "fuzzy-2b:oab", "--method", "nsga2", "--objectives", "success,time", "--worlds", WORLDS,
                 "--population", "4", "--budget", "48", "--out", str(out), "--json"]) == 0
    result = json.loads(capsys.readouterr().out)
    front = [(-m["objectives"]["success"], m["objectives"]["time"]) for m in result["front"]]  # both minimised
    assert front and all(not (a <= c and b <= d and (a, b) != (c, d)) for a, b in front for c, d in front)
    for member in result["front"]:
        assert load(member["file"]).input_names == ["dro", "theta_o"]


def _validation_choice_is_the_lowest_cost(result, start_system):
    chosen = result["validation"]
    costs = [chosen["start"]["cost"]] + [c["cost"] for c in chosen["candidates"]]
    assert len(chosen["candidates"]) == session.VALIDATED and chosen["worlds"] == "mixed:4:500"
    assert result["episodes"] <= SMALL["budget"] + 16
    if chosen["kept"] == "start":
        assert min(costs) == costs[0] and not result["changed"] and result["system"].rules == start_system.rules
    else:
        k = int(chosen["kept"].split()[-1])
        assert costs[k] == min(costs) < costs[0] and result["changed"]
    return chosen


def test_the_result_is_chosen_on_validation_worlds_the_start_unless_beaten():
    request = TuneRequest(target="fuzzy-2b:oab", validation="auto", **{**SMALL, "budget": 48 + 16})
    start = session.check(request)[1]
    _validation_choice_is_the_lowest_cost(tune(request), start)
    text = dumps(get_system("obstacle-avoidance"), "yaml")
    zeroed = loads(re.sub(r"alpha IS \w+", "alpha IS Z", text), "yaml")  # never steers away: collides
    result = tune(TuneRequest(target="fuzzy-2b:oab", validation="auto", what="rules", systems={"oab": zeroed},
                              **{**SMALL, "budget": 48 + 16}))
    assert _validation_choice_is_the_lowest_cost(result, zeroed)["kept"] != "start"


def test_a_killed_run_resumed_ends_as_an_uninterrupted_one(tmp_path, monkeypatch):
    whole = tune(TuneRequest(target="fuzzy-2b:oab", method="ga", out=str(tmp_path / "whole.yaml"), **SMALL))
    calls = []
    original = Fitness.objectives

    def killed_at_the_third_generation(self, population):
        calls.append(1)
        if len(calls) == 3:
            raise KeyboardInterrupt
        return original(self, population)

    monkeypatch.setattr(Fitness, "objectives", killed_at_the_third_generation)
    request = TuneRequest(target="fuzzy-2b:oab", method="ga", out=str(tmp_path / "cut.yaml"), **SMALL)
    with pytest.raises(KeyboardInterrupt):
        tune(request)
    assert (tmp_path / "cut.yaml.tune.npz").is_file()
    monkeypatch.setattr(Fitness, "objectives", original)
    simulated = []
    monkeypatch.setattr(Fitness, "objectives", lambda self, p: simulated.append(len(p)) or original(self, p))
    resumed = tune(TuneRequest(target="fuzzy-2b:oab", method="ga", out=str(tmp_path / "cut.yaml"), resume=True,
                               **SMALL))
    assert simulated == [4]  # the two stored generations were replayed, not simulated
    assert resumed["system"].rules == whole["system"].rules
    assert resumed["system"].inputs == whole["system"].inputs
    assert resumed["curve"] == whole["curve"]


def test_a_run_resumed_with_a_larger_budget_ends_as_one_run_with_that_budget(tmp_path):
    longer = {**SMALL, "budget": 80}
    whole = tune(TuneRequest(target="fuzzy-2b:oab", out=str(tmp_path / "whole.yaml"), **longer))
    cut = {**SMALL, "budget": 40}  # two generations and half of the third
    tune(TuneRequest(target="fuzzy-2b:oab", out=str(tmp_path / "more.yaml"), **cut))
    resumed = tune(TuneRequest(target="fuzzy-2b:oab", out=str(tmp_path / "more.yaml"), resume=True, **longer))
    assert resumed["curve"] == whole["curve"] and resumed["system"] == whole["system"]
    assert resumed["episodes"] == whole["episodes"] == 80


def test_resume_refuses_a_checkpoint_of_other_options(tmp_path):
    tune(TuneRequest(target="fuzzy-2b:oab", method="ga", out=str(tmp_path / "a.yaml"), **SMALL))
    with pytest.raises(session.InputError, match="seed"):
        tune(TuneRequest(target="fuzzy-2b:oab", method="ga", out=str(tmp_path / "a.yaml"), resume=True,
                         **{**SMALL, "seed": 1}))


def test_resume_refuses_a_checkpoint_made_on_other_worlds(tmp_path):
    """A folder of worlds edited between a run and its resumption: the checkpoint's values were
    measured on the old worlds, so resuming would mix two runs (bench refuses it the same way)."""
    worlds = tmp_path / "worlds"
    worlds.mkdir()
    world = worlds / "a.yaml"
    world.write_text("robot: {x: 2, y: 2}\ngoal: {x: 15, y: 15}\nmax_time: 30\n")
    held = tmp_path / "held"
    held.mkdir()
    (held / "b.yaml").write_text("robot: {x: 3, y: 2}\ngoal: {x: 15, y: 12}\nmax_time: 30\n")
    options = dict(target="goal-seeking:gsb", worlds=str(worlds), holdout=str(held), population=3, budget=6,
                   validation=None, out=str(tmp_path / "t.yaml"), progress=False)
    tune(TuneRequest(**options))
    world.write_text("robot: {x: 2, y: 2}\ngoal: {x: 15, y: 15}\nmax_time: 30\n"
                     "obstacles:\n  - circle: {center: [8, 8], radius: 2}\n")
    with pytest.raises(session.InputError, match="--worlds: the training worlds of .* are not the ones"):
        tune(TuneRequest(**{**options, "budget": 12, "resume": True}))


def test_the_tuned_file_drives_run_and_round_trips_through_convert_and_c(tmp_path, capsys):
    out = tmp_path / "oab.yaml"
    # without validation the search's best is written (with it, these 32 episodes keep the start)
    assert main(["tune", "fuzzy-2b:oab", "--worlds", WORLDS, "--population", "4", "--budget", "32",
                 "--validation", "none", "--out", str(out), "--curve", str(tmp_path / "curve.png"), "--quiet"]) == 0
    assert (tmp_path / "curve.png").stat().st_size > 0
    assert load(out) != get_system("obstacle-avoidance")  # a tuned table, not Table IV.2
    capsys.readouterr()
    assert main(["run", "mixed-1000-000", "--controller", "fuzzy-2b", "--fis", f"oab={out}", "--json"]) == 0
    result = json.loads(capsys.readouterr().out)
    tuned = load(out)
    scenario = open_scenario("mixed-1000-000")
    expected = metrics(run_episode(scenario, make_controller("fuzzy-2b", systems={"oab": tuned})), scenario)
    published = metrics(run_episode(scenario, make_controller("fuzzy-2b")), scenario)
    assert result["path_length_m"] > 1.0 and result["fis"] == {"oab": str(out)}
    assert {key: result[key] for key in ("outcome", "time_s", "path_length_m")} == {
        key: expected[key] for key in ("outcome", "time_s", "path_length_m")}  # the tuned table drove it
    assert result["path_length_m"] != published["path_length_m"]  # not Table IV.2 as published
    X = np.random.default_rng(0).uniform([0, -3.2], [4.5, 3.2], (500, 2))
    for suffix in ("fll", "fis"):
        assert main(["fis", "convert", str(out), "--to", suffix, "-o", str(tmp_path / f"oab.{suffix}")]) == 0
        np.testing.assert_allclose(load(tmp_path / f"oab.{suffix}").evaluate(X), tuned.evaluate(X), atol=1e-9)
    assert main(["fis", "export-c", str(out), "-o", str(tmp_path / "oab.c")]) == 0
    from tests.fuzzy.test_export_c import _compile, _run

    ours, _ = _run(_compile(tuned, None, tmp_path), X, 2, None)
    np.testing.assert_allclose(ours, tuned.evaluate(X), atol=1e-12)


BAD = [
    (["fuzzy-2b"], "CONTROLLER:ROLE"),
    (["fuzzy-2b:wall"], "no role 'wall'"),
    (["dwa:x"], "no replaceable"),
    (["fuzzy-2b:oab", "--method", "annealing"], "--method"),
    (["fuzzy-2b:oab", "--what", "weights"], "--what"),
    (["fuzzy-2b:oab", "--method", "aco"], "rule conclusions only"),
    (["fuzzy-2b:oab", "--budget", "10"], "do not cover one generation"),
    (["fuzzy-2b:oab", "--budget", "-5"], "--budget"),
    (["fuzzy-2b:oab", "--population", "1"], "--population"),
    (["fuzzy-2b:oab", "--objectives", "success,time"], "needs --method nsga2"),
    (["fuzzy-2b:oab", "--method", "nsga2", "--objectives", "success,speed"], "--objectives"),
    (["fuzzy-2b:oab", "--method", "nsga2"], "two or more"),
    (["fuzzy-2b:oab", "--out", "tuned.docx"], "--out"),
    (["fuzzy-2b:oab", "--worlds", "swamp:3"], "--worlds: 'swamp:3' is neither"),
    (["fuzzy-2b:oab", "--validation", "swamp:3"], "--validation"),
    (["fuzzy-2b:oab", "--population", "4", "--budget", "20"], "+ 16 validation episodes"),
    (["fuzzy-tracker:tracker", "--population", "4", "--budget", "64"], "fuzzy-tracker has no compiled step"),
    (["fuzzy-2b:oab", "--holdout", "swamp:3"], "--holdout: "),
    (["fuzzy-2b:oab", "--holdout", " "], "--holdout: is empty"),
    (["fuzzy-2b:oab", "--worlds", "mixed:4", "--holdout", "mixed:2"], "--holdout: shares 2 worlds with --worlds mixed:4"),
]


def test_worlds_of_a_task_the_controller_cannot_do_are_refused_by_name(tmp_path, capsys):
    """A goal seeker tuned on path scenarios would time out on every one and report a tuned table:
    the world is refused, naming its file, before any generation runs."""
    from fuzzynav.world.scenario_file import save_scenario

    path = load_scenario("path-n")
    save_scenario(path, tmp_path / "p.yaml")
    held = tmp_path / "held"
    held.mkdir()
    save_scenario(load_scenario("example-goal"), held / "g.yaml")
    assert main(["tune", "goal-seeking:gsb", "--worlds", str(tmp_path), "--holdout", str(held),
                 "--validation", "none", "--population", "2", "--budget", "4", "--quiet"]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and f"{tmp_path / 'p.yaml'}: task: goal-seeking cannot do a path task" in err, err


@pytest.mark.parametrize("argv,message", BAD, ids=[" ".join(a) for a, _ in BAD])
def test_bad_options_are_one_line_errors_before_any_simulation(argv, message, capsys, monkeypatch):
    monkeypatch.setattr(Fitness, "__init__", lambda *a, **k: pytest.fail("simulated despite a bad option"))
    worlds = [] if "--worlds" in argv else ["--worlds", WORLDS]
    assert main(["tune", *argv, *worlds]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and message in err, err


def test_a_damaged_checkpoint_is_a_one_line_error(tmp_path, capsys):
    out = tmp_path / "oab.yaml"
    (tmp_path / "oab.yaml.tune.npz").write_bytes(b"not a checkpoint")
    assert main(["tune", "fuzzy-2b:oab", "--worlds", WORLDS, "--population", "4", "--budget", "32", "--out", str(out),
                 "--resume", "--quiet"]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "oab.yaml.tune.npz" in err, err


def test_a_folder_in_the_checkpoints_place_is_refused_before_tuning(tmp_path, capsys, monkeypatch):
    monkeypatch.setattr(Fitness, "__init__", lambda *a, **k: pytest.fail("simulated despite the folder"))
    (tmp_path / "oab.yaml.tune.npz").mkdir()
    assert main(["tune", "fuzzy-2b:oab", "--worlds", WORLDS, "--population", "4", "--budget", "32",
                 "--out", str(tmp_path / "oab.yaml"), "--resume", "--quiet"]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "oab.yaml.tune.npz" in err and "is a directory" in err, err


def test_resume_without_a_checkpoint_says_it_tunes_from_the_start(tmp_path, capsys):
    argv = ["tune", "fuzzy-2b:oab", "--worlds", WORLDS, "--population", "4", "--budget", "32",
            "--out", str(tmp_path / "oab.yaml"), "--resume", "--quiet"]
    assert main(argv) == 0
    assert "--resume: no checkpoint at" in capsys.readouterr().err
    assert main(argv) == 0
    assert "no checkpoint" not in capsys.readouterr().err


def test_a_wall_follower_is_tuned_on_wall_courses_by_its_wall_cost(tmp_path):
    from fuzzynav.experiments.tuning import wall_worlds

    train, held = wall_worlds(tmp_path / "train", 0, 3), wall_worlds(tmp_path / "held", 1000, 2)
    result = tune(TuneRequest(target="wall-follow:wall", worlds=str(train), holdout=str(held), population=3,
                              budget=3 * 3 * 3, seed=0))
    start, tuned = result["start"]["training"], result["tuned"]["training"]
    assert result["task"] == "wall" and tuned["cost"] <= start["cost"]
    assert start["mean_time_s"] is None and 0.0 <= start["too_close_share"] <= 1.0 and start["mean_speed_mps"] > 0
    assert set(result["tuned"]["holdout"]) >= {"success_rate", "collisions", "off_band_m"}
    with pytest.raises(InputError, match="no goal"):
        session.check(TuneRequest(target="wall-follow:wall", worlds=str(train), method="nsga2",
                                  objectives=("success", "time")))
