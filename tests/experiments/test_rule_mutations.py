"""``fuzzynav reproduce ID --fis ROLE=FILE``: an edited rule table fails the claim of its figure,
the published one passes (the harness of benchmarks/mutations.py, on two small cases)."""

import json
from pathlib import Path

import pytest

from fuzzynav.cli import main
from fuzzynav.experiments import routes

pytestmark = pytest.mark.slow


def _edited(tmp_path, role: str, rule: str, term: str) -> str:
    """The published system of ``role`` with the conclusion of ``rule`` (its text up to ``THEN``
    the first output) set to ``term``, written as YAML by ``fuzzynav fis convert``."""
    controller = {"gsb": "goal-seeking", "tracker": "fuzzy-tracker"}[role]
    path = tmp_path / f"{role}.yaml"
    assert main(["fis", "convert", f"{controller}:{role}", "--to", "yaml", "-o", str(path)]) == 0
    lines = path.read_text().splitlines()
    hits = [k for k, line in enumerate(lines) if line.startswith(f"- {rule} IS ")]
    assert len(hits) == 1, rule
    head, _, tail = lines[hits[0]].partition(f"{rule} IS ")
    lines[hits[0]] = f"{head}{rule} IS {term}{tail[tail.find(' '):] if ' ' in tail else ''}"
    path.write_text("\n".join(lines) + "\n")
    return str(path)


def _claim(out, key) -> dict:
    return json.loads((out / key / "claim.json").read_text())


def test_published_table_iv_1_passes_and_a_wrong_sign_cell_fails(tmp_path, capsys):
    assert main(["reproduce", "fig-IV-15", "--quick", "--out", str(tmp_path / "published")]) == 0
    assert _claim(tmp_path / "published", "fig-IV-15")["verdict"] == "reproduced"
    # Table IV.1, θ_rg NM and d_rg G: PP (turn left, towards the goal) -> NP, as an audit did by hand
    edited = _edited(tmp_path, "gsb", "IF drg IS G AND theta IS NM THEN alpha", "NP")
    assert main(["reproduce", "fig-IV-15", "--quick", "--fis", f"gsb={edited}", "--out", str(tmp_path / "m")]) == 0
    claim = _claim(tmp_path / "m", "fig-IV-15")
    assert claim["verdict"] != "reproduced"
    failed = [c["name"] for c in claim["checks"] if not c["pass"]]
    assert any("published tables" in name for name in failed)  # the route or the switch points moved
    numbers = json.loads((tmp_path / "m" / "fig-IV-15" / "fig-IV-15.json").read_text())
    assert numbers["replaced_rule_bases"] == {"gsb": edited} and "unused_rule_bases" not in numbers
    assert "with gsb=" in capsys.readouterr().out


def test_a_table_given_by_a_relative_path_is_recorded_absolute(tmp_path, monkeypatch):
    edited = Path(_edited(tmp_path, "gsb", "IF drg IS G AND theta IS NM THEN alpha", "NP"))
    monkeypatch.chdir(edited.parent)
    assert main(["reproduce", "fig-IV-15", "--quick", "--quiet", "--fis", f"gsb={edited.name}", "--out", "r"]) == 0
    numbers = json.loads((tmp_path / "r" / "fig-IV-15" / "fig-IV-15.json").read_text())
    assert numbers["replaced_rule_bases"] == {"gsb": str(edited.resolve())}


def test_a_table_the_experiment_never_reads_is_reported_unused(tmp_path, capsys):
    """fig-V-7 (the tracker) reads no Table IV.1: its numbers with ``--fis gsb=FILE`` are the
    published ones, and the report says so rather than credit the claim to the edited table; in
    worker processes too, beside an experiment that does read it."""
    edited = _edited(tmp_path, "gsb", "IF drg IS G AND theta IS NM THEN alpha", "NP")
    assert main(["reproduce", "fig-V-7", "fig-IV-15", "--quick", "--fis", f"gsb={edited}", "--workers", "2",
                 "--out", str(tmp_path / "r")]) == 0
    out = capsys.readouterr().out
    line = next(line for line in out.splitlines() if line.startswith("fig-V-7:"))
    assert "does not use gsb" in line
    numbers = {key: json.loads((tmp_path / "r" / key / f"{key}.json").read_text()) for key in ("fig-V-7", "fig-IV-15")}
    assert numbers["fig-V-7"]["unused_rule_bases"] == ["gsb"]
    assert "unused_rule_bases" not in numbers["fig-IV-15"]


def test_a_biased_table_v_1_cell_fails_the_tracking_claims(tmp_path):
    # the centre cell Z/Z: Z -> PM doubles the errors of CF (the published claims checked completion only)
    edited = _edited(tmp_path, "tracker", "IF theta_er IS Z AND dtheta_er IS Z THEN alpha", "PM")
    ids = ["fig-V-7", "fig-V-11", "fig-V-29"]
    # in three worker processes: the replacement reaches each of them
    assert main(["reproduce", *ids, "--quick", "--fis", f"tracker={edited}", "--workers", "3",
                 "--out", str(tmp_path)]) == 0
    for key in ids:
        claim = _claim(tmp_path, key)
        assert claim["verdict"] != "reproduced", key
    surface = _claim(tmp_path, "fig-V-7")["checks"][-1]
    assert surface["value"] == ["θ_er Z, dθ_er Z: 22.5° (Table V.1: Z)"]
    errors = [c for c in _claim(tmp_path, "fig-V-11")["checks"] if "max cross-track" in c["name"]]
    assert errors and not all(c["pass"] for c in errors)


def test_fis_of_reproduce_is_checked(tmp_path, capsys):
    assert main(["reproduce", "fig-V-7", "--fis", "steering=x.yaml", "--out", str(tmp_path)]) == 2
    assert "unknown role 'steering'" in capsys.readouterr().err
    wrong = tmp_path / "vrb.yaml"
    assert main(["fis", "convert", "vrb", "--to", "yaml", "-o", str(wrong)]) == 0
    assert main(["reproduce", "fig-V-7", "--fis", f"tracker={wrong}", "--out", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert str(wrong) in err and "theta_er" in err and "Traceback" not in err


def test_a_route_moved_by_more_than_half_a_metre_fails_its_check():
    published = routes.reference("fig-IV-13")
    moved = {"route": [[x + 0.6, y] for x, y in published["route"]]}
    assert routes.route_check("run", published, "fig-IV-13").passed
    check = routes.route_check("run", moved, "fig-IV-13")
    assert not check.passed and check.value == pytest.approx(0.6, abs=0.11) and check.source == "package"
    assert routes.deviation([[0, 0], [1, 0]], [[0, 0]]) == routes.deviation([[0, 0]], [[0, 0], [1, 0]]) == 1.0
