"""Seeded random worlds: reproducible, both families, solvable only, bad input named."""

import json

import numpy as np
import pytest

from fuzzynav.cli import main
from fuzzynav.errors import InputError
from fuzzynav.world.generate import connected, generate_worlds, random_world
from fuzzynav.world.scenario import scenario_from_dict


def test_same_seed_same_worlds_and_prefix_stable():
    a = [w.to_dict() for w in generate_worlds("mixed", 4, seed=7)]
    b = [w.to_dict() for w in generate_worlds("mixed", 2, seed=7)]
    assert a[:2] == b
    assert a != [w.to_dict() for w in generate_worlds("mixed", 4, seed=8)]


@pytest.mark.parametrize("kind, shapes", [("circles", {"circle"}), ("mixed", {"circle", "polygon", "wall", "ellipse"})])
def test_families_and_solvability(kind, shapes):
    worlds = generate_worlds(kind, 12, seed=1)
    kinds = {o.kind for w in worlds for o in w.world.obstacles}
    assert kinds == shapes
    for w in worlds:
        assert np.hypot(*(w.goal.position - w.start[:2])) >= 10.0
        assert (w.world.clearance(np.array([w.start[:2], w.goal.position])) >= 1.5).all()
        assert connected(w.world, w.start[:2], w.goal.position, 0.99)
        scenario_from_dict(w.to_dict())  # round-trips through the scenario validator


def test_connectivity_sees_a_wall_across_the_world():
    blocked = scenario_from_dict({"robot": {"x": 5, "y": 2}, "goal": {"x": 5, "y": 18},
                                  "obstacles": [{"wall": {"start": [0, 10], "end": [20, 10], "thickness": 0.4}}]})
    assert not connected(blocked.world, blocked.start[:2], blocked.goal.position, 0.3)
    gap = scenario_from_dict({"robot": {"x": 5, "y": 2}, "goal": {"x": 5, "y": 18},
                              "obstacles": [{"wall": {"start": [0, 10], "end": [17, 10], "thickness": 0.4}}]})
    assert connected(gap.world, gap.start[:2], gap.goal.position, 0.99)  # a 3 m gap at the right
    assert not connected(gap.world, gap.start[:2], gap.goal.position, 1.6)  # too narrow for 1.6 m


def test_bad_family_and_count():
    with pytest.raises(InputError, match="worlds"):
        generate_worlds("squares", 3)
    with pytest.raises(InputError, match="--n"):
        generate_worlds("mixed", 0)
    with pytest.raises(InputError, match="kind"):
        random_world("squares", np.random.default_rng(0))


def test_evaluate_command_json(capsys):
    assert main(["evaluate", "--controller", "fuzzy-2b", "--worlds", "circles", "--n", "3", "--json"]) == 0
    out = capsys.readouterr().out
    result = json.loads(out)
    assert out.count("\n") == 1
    for key in ("success_rate", "collision_rate", "timeout_rate", "mean_time_s", "mean_path_length_m"):
        assert key in result
    assert len(result["episodes"]) == 3
    assert result["success_rate"] + result["collision_rate"] + result["timeout_rate"] == pytest.approx(1.0)


@pytest.mark.parametrize("argv, field", [(["--worlds", "squares"], "--worlds"), (["--n", "0"], "--n"),
                                         (["--controller", "nope"], "--controller")])
def test_evaluate_command_bad_input(capsys, argv, field):
    args = {"--controller": "fuzzy-2b", "--worlds": "circles", "--n": "2"}
    args.update(dict(zip(argv[::2], argv[1::2])))
    try:
        status = main(["evaluate", *[x for kv in args.items() for x in kv]])
    except SystemExit as exit_:  # refused by the option's type (argparse)
        status = exit_.code
    assert status == 2
    assert field in capsys.readouterr().err
