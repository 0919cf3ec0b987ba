"""The scenario format as the docs print it is the parser's: every ``yaml`` block of the scenario
pages parses (a whole scenario as it stands, a fragment inside a minimal one), and the key table
of docs/guide/scenarios.md names every key ``scenario_from_dict`` accepts, no other, with the
parser's defaults. The accepted keys are asked of the parser itself (the ``known:`` list of its
unknown-key error), so a key added to the parser and not to the page fails here."""

import math
import re
from pathlib import Path

import pytest
import yaml

from fuzzynav.errors import InputError
from fuzzynav.world.scenario import scenario_from_dict

ROOT = Path(__file__).resolve().parents[2]
GUIDE = ROOT / "docs" / "guide" / "scenarios.md"
PAGES = [GUIDE, ROOT / "docs" / "dynamic.md", ROOT / "docs" / "ARCHITECTURE.md",
         ROOT / "docs" / "results" / "robustness.md", ROOT / "README.md"]
START = {"x": 1.0, "y": 1.0}
MINIMAL = {"robot": START, "goal": {"x": 18.0, "y": 18.0}}
CIRCLE = {"circle": {"center": [5.0, 5.0], "radius": 0.3}}


def yaml_blocks(page: Path) -> list[dict]:
    return [yaml.safe_load(block) for block in re.findall(r"```yaml\n(.*?)```", page.read_text(encoding="utf-8"),
                                                          re.S)]


def whole(document: dict) -> dict:
    """A fragment (no ``robot`` start, or no task) completed with the minimal scenario's."""
    done = {**MINIMAL, **document, "robot": {**START, **document.get("robot", {})}}
    if "path" in document or "target" in document:
        del done["goal"]
    return done


@pytest.mark.parametrize("page", PAGES, ids=lambda page: page.name)
def test_every_yaml_block_of_the_scenario_pages_parses(page):
    blocks = yaml_blocks(page)
    assert blocks, f"no yaml block in {page.name}"
    for k, document in enumerate(blocks):
        assert isinstance(document, dict), (page.name, k)
        scenario = scenario_from_dict(whole(document), source=f"{page.name}, yaml block {k}")
        again = scenario_from_dict(scenario.to_dict())  # what it means, written back, reads the same
        assert again.to_dict() == scenario.to_dict()


def test_the_guide_shows_a_whole_scenario_of_each_task():
    tasks = [scenario_from_dict(document).task for document in yaml_blocks(GUIDE) if "robot" in document]
    assert set(tasks) == {"goal", "path", "target"}


def known(document: dict, field: str) -> list[str]:
    """The keys the parser accepts at ``field``: those its unknown-key error lists for ``document``
    (whose mapping at ``field`` carries the unknown key ``zz``)."""
    with pytest.raises(InputError) as refused:
        scenario_from_dict(document)
    assert refused.value.field == (f"{field}.zz" if field else "zz"), refused.value
    return re.search(r"known: (.*)$", refused.value.problem).group(1).split(", ")


def parser_keys() -> set[str]:
    """Every key path of the scenario format, as the key table writes it (``obstacles[i].circle.radius``,
    ``motion.speed`` for the target's and the obstacles' motions alike)."""
    keys = set(known({**MINIMAL, "zz": 1}, ""))
    keys |= {f"world.{key}" for key in known({**MINIMAL, "world": {"zz": 1}}, "world")}
    robot = known({**MINIMAL, "robot": {**START, "zz": 1}}, "robot")
    keys |= {f"robot.{key}" for key in robot}
    for group in ("sensor_noise", "actuation", "odometry"):
        assert group in robot
        keys |= {f"robot.{group}.{key}" for key in
                 known({**MINIMAL, "robot": {**START, group: {"zz": 1}}}, f"robot.{group}")}
    keys |= {f"goal.{key}" for key in known({"robot": START, "goal": {"x": 18, "y": 18, "zz": 1}}, "goal")}
    target = {"x": 14.0, "y": 10.0}
    keys |= {f"target.{key}" for key in known({"robot": START, "target": {**target, "zz": 1}}, "target")}
    for kind in known({**MINIMAL, "obstacles": [{"zz": {}}]}, "obstacles[0]"):
        keys |= {f"obstacles[i].{kind}.{key}" for key in
                 known({**MINIMAL, "obstacles": [{kind: {"zz": 1}}]}, f"obstacles[0].{kind}")}
    keys.add("obstacles[i].motion")
    for kind in motion_types("target"):
        keys |= {f"motion.{key}" for key in
                 known({"robot": START, "target": {**target, "motion": {"type": kind, "zz": 1}}}, "target.motion")}
    for kind in motion_types("obstacle"):
        keys |= {f"motion.{key}" for key in
                 known({**MINIMAL, "obstacles": [{**CIRCLE, "motion": {"type": kind, "zz": 1}}]}, "obstacles[0].motion")}
    return keys


def motion_types(whose: str) -> list[str]:
    """The ``type`` values the parser accepts for the target's motion or an obstacle's."""
    motion = {"type": "zz"}
    document = ({"robot": START, "target": {"x": 14.0, "y": 10.0, "motion": motion}} if whose == "target"
                else {**MINIMAL, "obstacles": [{**CIRCLE, "motion": motion}]})
    with pytest.raises(InputError) as refused:
        scenario_from_dict(document)
    return re.search(r"known: (.*)$", refused.value.problem).group(1).split(", ")


def key_table() -> dict[str, list[str]]:
    """The rows of the tables of the guide's *Every key* section: each key of the first column ->
    the row's cells."""
    text = GUIDE.read_text(encoding="utf-8")
    section = text[text.index("\n## Every key\n"):]
    section = section[:section.find("\n## ", 1)] if "\n## " in section[1:] else section
    rows = {}
    for line in section.splitlines():
        if not line.startswith("| `"):
            continue
        cells = [cell.strip() for cell in re.split(r"(?<!\\)\|", line)[1:-1]]
        assert len(cells) == 5, line
        for key in re.findall(r"`([^`]+)`", cells[0]):
            assert key not in rows, f"{key} has two rows"
            rows[key] = cells
    return rows


def prefixes(key: str) -> set[str]:
    parts = key.split(".")
    return {".".join(parts[:n]) for n in range(1, len(parts))}


def test_the_key_table_names_every_key_the_parser_accepts_and_no_other():
    documented, accepted = set(key_table()), parser_keys()
    assert accepted - documented == set(), "keys the parser accepts that the table does not name"
    containers = set().union(*map(prefixes, accepted))
    assert documented - accepted - containers == set(), "keys the table names that the parser refuses"


def test_the_key_table_names_every_motion_type():
    types = key_table()["motion.type"][1]
    for kind in {*motion_types("target"), *motion_types("obstacle")}:
        assert f"`{kind}`" in types, kind


def parsed_defaults() -> dict[str, object]:
    """The default of each optional key, read off what the parser made of documents without it."""
    goal = scenario_from_dict(MINIMAL)
    path = scenario_from_dict({"robot": START, "path": [[2, 2], [5, 5]]}).path
    target = scenario_from_dict({"robot": START, "target": {"x": 14.0, "y": 10.0}}).target
    wall, ellipse = scenario_from_dict({**MINIMAL, "obstacles": [{"wall": {"start": [2, 12], "end": [10, 12]}},
                                                                 {"ellipse": {"center": [14, 6], "radii": [2, 1]}}]
                                        }).world.obstacles
    patrol = scenario_from_dict({**MINIMAL, "obstacles": [{**CIRCLE, "motion": {
        "type": "waypoints", "points": [[5, 5], [5, 9]], "speed": 0.5}}]}).world.motions[0]
    defaults = {"world.width": goal.world.width, "world.height": goal.world.height, "robot.theta": goal.start[2],
                "goal.tolerance": goal.goal.tolerance, "max_time": goal.max_time, "description": goal.description,
                "controllers": list(goal.controllers), "sensors": goal.sensors,
                "path_tolerance": path.tolerance, "path_switching": path.switching, "speed": path.speed,
                "target.tolerance": target.tolerance, "target.motion": target.motion.type,
                "obstacles[i].wall.thickness": wall.thickness, "obstacles[i].ellipse.angle": ellipse.angle,
                "motion.loop": patrol.loop}
    for key in ("radius", "wheelbase", "max_steering", "max_speed", "max_reverse_speed"):
        defaults[f"robot.{key}"] = getattr(goal.robot, key)
    imperfections = goal.imperfections
    for group, keys in {"sensor_noise": ("range_sigma", "dropout", "max_range"),
                        "actuation": ("latency", "steering_rate", "acceleration", "slip"),
                        "odometry": ("drift",)}.items():
        for key in keys:
            defaults[f"robot.{group}.{key}"] = getattr(imperfections, key)
    assert scenario_from_dict(MINIMAL).name == "scenario" and imperfections.off
    return defaults


def test_the_key_table_gives_the_parsers_defaults():
    rows = key_table()
    for key, value in parsed_defaults().items():
        cell = rows[key][3]
        if value is None or (key.startswith("robot.") and key.count(".") == 2 and value == 0):
            assert "off" in cell or "controller's own" in cell, (key, cell)
        elif isinstance(value, bool):
            assert f"`{str(value).lower()}`" in cell, (key, cell)
        elif isinstance(value, str):
            assert (value in cell and "`" in cell) if value else cell == "empty", (key, cell)
        elif isinstance(value, list):
            assert cell == f"`{value}`", (key, cell)
        else:
            numbers = [float(n.replace(",", "")) for n in re.findall(r"\d[\d,]*(?:\.\d+)?", cell)]
            assert any(math.isclose(n, value, rel_tol=1e-3, abs_tol=1e-12) for n in numbers), (key, cell, value)


def test_null_is_refused_at_the_top_level_but_where_the_guide_says():
    text = " ".join(GUIDE.read_text(encoding="utf-8").split())
    assert "except `obstacles: null` (no obstacles) and `sensors: null`" in text
    for key in set(known({**MINIMAL, "zz": 1}, "")) - {"robot", "goal", "path", "target"}:
        document = {**MINIMAL, key: None}
        if key in ("obstacles", "sensors"):
            assert scenario_from_dict(document).world is not None
        else:
            with pytest.raises(InputError):
                scenario_from_dict(document)
