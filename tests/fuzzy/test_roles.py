"""Edited rule bases drive the robot: export a role's system, edit one cell, run it (--fis ROLE=FILE)."""

import json

import numpy as np
import pytest

from fuzzynav.catalog.controllers import make_controller
from fuzzynav.catalog.roles import ROLES, default_system, load_replacement, systems_from_options
from fuzzynav.cli import main
from fuzzynav.control.base import thesis_angle_error
from fuzzynav.errors import InputError
from fuzzynav.fuzzy import FuzzySystem
from fuzzynav.fuzzy.io import load, save
from fuzzynav.sim import metrics, run_episode
from fuzzynav.world.scenario import load_scenario

CELL = "IF drg IS G AND theta IS PM THEN alpha IS NP AND v IS M"  # Table IV.1, row PM, column G
EDITED = CELL.replace("alpha IS NP", "alpha IS NG")


@pytest.fixture
def edited_gsb(tmp_path):
    path = tmp_path / "gsb.yaml"
    assert main(["fis", "convert", "goal-seeking:gsb", "--to", "yaml", "-o", str(path)]) == 0
    text = path.read_text()
    assert text.count(CELL) == 1
    path.write_text(text.replace(CELL, EDITED))
    return path


def test_edited_cell_changes_the_trajectory(edited_gsb, capsys):
    scenario = load_scenario("fig-IV-12a")  # start (2, 17) heading east, goal (10, 11): 10 m, 37° to the right
    original = run_episode(scenario, make_controller("goal-seeking"), seed=0)
    system = load(edited_gsb)
    edited = run_episode(scenario, make_controller("goal-seeking", systems={"gsb": system}), seed=0)
    # the start reads drg = 10 m (between M and G) and θ = +0.64 rad (between PP and PM): the edited
    # cell (G, PM) concludes NG instead of NP, so the first command steers harder to the right ...
    x, y, heading = original.pose[0]
    distance, bearing = np.hypot(10 - x, 11 - y), np.arctan2(11 - y, 10 - x) - heading
    expected = system.evaluate_one(distance, thesis_angle_error(bearing))[0]
    assert edited.steering[0] == pytest.approx(expected, abs=1e-12)
    assert edited.steering[0] < original.steering[0] - 0.1
    # ... the robot turns towards the goal sooner, and both still reach it
    assert edited.pose[1, 2] < original.pose[1, 2]
    assert not np.allclose(edited.pose[:20], original.pose[:20])
    assert original.outcome == edited.outcome == "reached"
    # the command line does the same
    assert main(["run", "fig-IV-12a", "--controller", "goal-seeking", "--fis", f"gsb={edited_gsb}", "--json"]) == 0
    cli = json.loads(capsys.readouterr().out)
    assert cli["path_length_m"] == pytest.approx(metrics(edited, scenario)["path_length_m"], rel=1e-12)
    assert cli["path_length_m"] != pytest.approx(metrics(original, scenario)["path_length_m"], rel=1e-6)
    assert cli["fis"] == {"gsb": str(edited_gsb.resolve())}  # the numbers say which rule base made them


def test_evaluate_reports_the_replaced_rule_base(edited_gsb, capsys):
    argv = ["evaluate", "--controller", "goal-seeking", "--worlds", "mixed", "--n", "1", "--fis", f"gsb={edited_gsb}"]
    assert main([*argv, "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["fis"] == {"gsb": str(edited_gsb.resolve())}
    assert main(argv) == 0
    assert f"(--fis gsb={edited_gsb.resolve()})" in capsys.readouterr().out.splitlines()[0]


def test_mismatching_replacement_exits_2_naming_the_variable(edited_gsb, tmp_path, capsys):
    bad = tmp_path / "bad.yaml"
    bad.write_text(edited_gsb.read_text().replace("drg", "dist"))
    assert main(["run", "fig-IV-12a", "--controller", "goal-seeking", "--fis", f"gsb={bad}"]) == 2
    err = capsys.readouterr().err
    assert "bad.yaml" in err and "'dist'" in err and "expected 'drg'" in err
    gsb = load(edited_gsb)
    alpha_only = FuzzySystem(gsb.inputs, gsb.outputs[:1], [r.text().split(" AND v IS")[0] for r in gsb.rules])
    save(alpha_only, tmp_path / "alpha.fll")
    with pytest.raises(InputError, match=r"alpha\.fll: output v: output 2 is missing, expected 'v'"):
        load_replacement("goal-seeking", "gsb", str(tmp_path / "alpha.fll"))


def test_role_options_are_checked(edited_gsb, capsys):
    with pytest.raises(InputError, match="no role 'foa'.*gsb"):
        systems_from_options("goal-seeking", [f"foa={edited_gsb}"])
    with pytest.raises(InputError, match="expected ROLE=FILE"):
        systems_from_options("goal-seeking", [str(edited_gsb)])
    with pytest.raises(InputError, match="has no replaceable fuzzy systems"):
        systems_from_options("pure-pursuit", [f"gsb={edited_gsb}"])
    assert main(["evaluate", "--controller", "goal-seeking", "--worlds", "circles", "--n", "1",
                 "--fis", f"gsb={edited_gsb}", "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["n"] == 1


@pytest.mark.parametrize("controller", list(ROLES))
def test_every_role_exports_and_reads_back(controller, tmp_path):
    for role in ROLES[controller]:
        for fmt in ("yaml", "fll", "fis"):
            path = tmp_path / f"{role}.{fmt}"
            assert main(["fis", "convert", f"{controller}:{role}", "--to", fmt, "-o", str(path)]) == 0
            system = load_replacement(controller, role, str(path))  # fits its own role
            default = default_system(controller, role)
            lo = np.array([v.universe[0] for v in default.inputs])
            hi = np.array([v.universe[1] for v in default.inputs])
            X = np.random.default_rng(0).uniform(lo, hi, (200, len(lo)))
            np.testing.assert_allclose(system.evaluate(X), default.evaluate(X), rtol=0, atol=1e-12)



@pytest.mark.parametrize("controller, scenarios, edited", [
    ("fuzzy-2b", ("fig-IV-15a",), None), ("fuzzy-5b-rays", ("fig-IV-22a", "fig-IV-23"), None),
    ("fuzzy-5b", ("fig-IV-22a",), ("gsb",)), ("wall-follow", ("fig-VI-28",), None)])
def test_every_role_drives_the_compiled_navigators(controller, scenarios, edited, tmp_path):
    """Each role's exported system, read back through --fis, drives the compiled navigator along
    the built-in trajectories; and each role of ``edited`` (None: every role) alone, edited so that
    every rule concludes the next term of its output, changes one of them (so the replacement
    really reaches the kernels' tables). `fuzzy-5b-rays` needs fig-IV-23 for its front avoider,
    which its turning-room layer overrides wherever it fires in fig-IV-22a; `fuzzy-5b` steers round
    obstacles by its gap finder, its three avoiders act only where no gap fits (none in these
    worlds), and its pace overrides a speed from `vrb` below the room ahead's (docs/guide/fuzzy.md)."""
    worlds = [load_scenario(scenario) for scenario in scenarios]
    originals = [run_episode(world, make_controller(controller), seed=0) for world in worlds]
    options = []
    for role in ROLES[controller]:
        path = tmp_path / f"{role}.yaml"
        assert main(["fis", "convert", f"{controller}:{role}", "--to", "yaml", "-o", str(path)]) == 0
        options.append(f"{role}={path}")
    for world, original in zip(worlds, originals):
        replaced = run_episode(world, make_controller(controller, systems=systems_from_options(controller, options)),
                               seed=0)
        assert replaced.outcome == original.outcome
        np.testing.assert_allclose(replaced.pose, original.pose, rtol=0, atol=1e-9)
    for role in edited or ROLES[controller]:
        system = load(tmp_path / f"{role}.yaml")
        labels = {output.name: list(output.labels) for output in system.outputs}
        rules = [str(rule).split(" THEN ")[0] + " THEN " + " AND ".join(
            f"{name} IS {labels[name][(labels[name].index(term) + 1) % len(labels[name])]}" for name, term in rule.conclusions)
            for rule in system.rules]
        edited = tmp_path / f"{role}-edited.yaml"
        save(FuzzySystem(system.inputs, system.outputs, rules, method=system.method), edited)
        systems = systems_from_options(controller, [f"{role}={edited}"])
        driven = [run_episode(world, make_controller(controller, systems=systems), seed=0) for world in worlds]
        assert any(d.pose.shape != o.pose.shape or not np.allclose(d.pose, o.pose) for d, o in zip(driven, originals)), role


def _campaign(out, *extra):
    return main(["bench", "circles:3:2", "--controllers", "goal-seeking,fuzzy-2b,dwa", "--workers", "1",
                 "--quiet", "--gallery", "0", "--out", str(out), *extra])


def _runs(out):
    return {(r["world"], r["controller"]): r for r in map(json.loads, (out / "runs.jsonl").read_text().splitlines())}


def test_bench_fis_replaces_the_role_in_every_controller_that_has_it(edited_gsb, tmp_path, capsys):
    assert _campaign(tmp_path / "plain") == 0
    assert _campaign(tmp_path / "edited", "--fis", f"gsb={edited_gsb}") == 0
    plain, edited = _runs(tmp_path / "plain"), _runs(tmp_path / "edited")
    assert plain.keys() == edited.keys()
    changed = {key[1] for key, row in edited.items() if row["path_length_m"] != plain[key]["path_length_m"]}
    assert changed == {"goal-seeking", "fuzzy-2b"}  # both have gsb; dwa has no fuzzy system
    summary = json.loads((tmp_path / "edited" / "summary.json").read_text())
    assert summary["arguments"]["fis"] == {"gsb": str(edited_gsb.resolve())}
    # --resume checks the replacement: other rule bases (or none) cannot be mixed into these runs
    capsys.readouterr()
    assert _campaign(tmp_path / "edited", "--resume") == 2
    assert "no --fis" in capsys.readouterr().err
    other = tmp_path / "other.yaml"
    other.write_text(edited_gsb.read_text().replace("alpha IS NG", "alpha IS NM", 1))
    assert _campaign(tmp_path / "edited", "--resume", "--fis", f"gsb={other}") == 2
    assert "cannot be mixed" in capsys.readouterr().err
    assert _campaign(tmp_path / "plain", "--resume", "--fis", f"gsb={edited_gsb}") == 2
    assert _campaign(tmp_path / "edited", "--resume", "--fis", f"gsb={edited_gsb}") == 0  # the same: nothing to run
    assert _runs(tmp_path / "edited") == edited


def test_bench_fis_is_refused_when_it_does_not_fit(edited_gsb, tmp_path, capsys):
    bad = tmp_path / "bad.yaml"
    bad.write_text(edited_gsb.read_text().replace("drg", "dist"))
    assert _campaign(tmp_path / "o", "--fis", f"gsb={bad}") == 2
    err = capsys.readouterr().err
    assert "bad.yaml" in err and "'dist'" in err and "expected 'drg'" in err
    assert _campaign(tmp_path / "o", "--fis", f"foa={edited_gsb}") == 2
    assert "no controller of the campaign has the role foa (their roles: gsb, oab)" in capsys.readouterr().err
    assert _campaign(tmp_path / "o", "--fis", str(edited_gsb)) == 2
    assert "expected ROLE=FILE" in capsys.readouterr().err
    assert not (tmp_path / "o").exists() or not (tmp_path / "o" / "runs.jsonl").exists()
