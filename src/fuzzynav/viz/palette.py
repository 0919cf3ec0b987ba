"""One palette for every plot: a behaviour, a controller, the rays keep their colour everywhere.

A behaviour label recorded in a trace (``GSB``, ``FOA+VRB``, ``OA``…) maps to one colour and one
legend text in every panel and figure (:func:`behaviour_style`), whatever order the behaviours
appear in; a label this table does not know gets a colour from its name (stable across runs).
Sensor rays (:data:`RAY_COLOUR`) and the goal (:data:`GOAL_COLOUR`) use colours no behaviour uses.
"""

from __future__ import annotations

import zlib

# a behaviour's code -> (colour, what it means, with its table in the thesis): legend "CODE: meaning"
_CODES: dict[str, tuple[str, str]] = {
    "GSB": ("#1f77b4", "goal seeking (Table IV.1)"),
    "GSB+VRB": ("#17becf", "goal seeking, speed reduced near obstacles (VRB, Table IV.6)"),
    "FOA+VRB": ("#d62728", "front obstacle avoidance (Table IV.3) + VRB"),
    "ROA+VRB": ("#ff7f0e", "obstacle on the right, turn left (Table IV.4) + VRB"),
    "LOA+VRB": ("#9467bd", "obstacle on the left, turn right (Table IV.5) + VRB"),
    "OA": ("#d62728", "obstacle avoidance by distance and angle (Table IV.2)"),
    "WF": ("#8c564b", "wall following (Table VI.2)"),
    "REC-BACK": ("#e7298a", "recovery, backing out on a safe arc after the safety stop held"),
    "REC-TURN": ("#a6761d", "recovery, turning the other way before handing back"),
    "BF": ("#000080", "loop escape, following the boundary until the goal is free (Bug algorithms)"),
    "CAR-BACK": ("#66a61e", "car route (hybrid A* on what was seen), backing along its arc"),
    "CAR-FWD": ("#1b9e77", "car route (hybrid A* on what was seen), driving its arc where it is tight"),
    "GAP+VRB": ("#e377c2", "through the gap that fits the body (Table IV.1 towards it) + VRB"),
    "GAP": ("#e377c2", "through the gap that fits the body (Table IV.1 towards it)"),
    "YIELD": ("#ff9896", "yield / evade rules on the time to collision with a moving obstacle"),
    "EVADE": ("#c5b0d5", "evasive command sampled against the moving obstacles' predicted tracks"),
}
# label -> (colour, legend text): the codes, then the labels that are words already
BEHAVIOURS: dict[str, tuple[str, str]] = {
    **{code: (colour, f"{code}: {meaning}") for code, (colour, meaning) in _CODES.items()},
    "track": ("#1f77b4", "tracking the path / target"),
    "goal seeking": ("#1f77b4", "goal seeking (learned rules)"),
    "obstacle avoidance": ("#d62728", "obstacle avoidance (learned rules)"),
}
FALLBACK_COLOURS = ("#e377c2", "#7f7f7f", "#393b79", "#637939", "#843c39", "#7b4173")
RAY_COLOUR = "#bcbd22"  # sensor rays: olive, no behaviour's colour
GOAL_COLOUR = "#2ca02c"  # goal, target and its course
CHANGE_LEGEND = "A, B, …: where the behaviour changes"

# the chapter V trackers, by controller name: (colour, short name used in the thesis' figures)
TRACKERS: dict[str, tuple[str, str]] = {
    "fuzzy-tracker": ("#1f77b4", "CF"),
    "neural-tracker": ("#d62728", "CN"),
    "anfis-tracker": ("#9467bd", "CNF"),
}


def behaviour_style(label: str) -> tuple[str, str]:
    """(colour, legend text) of a behaviour label; unknown labels get a stable colour of their own."""
    if label in BEHAVIOURS:
        return BEHAVIOURS[label]
    colour = FALLBACK_COLOURS[zlib.crc32(label.encode()) % len(FALLBACK_COLOURS)]
    return colour, label or "robot"


def legend_order(label: str) -> tuple[int, str]:
    """Sort key listing behaviours in the order of :data:`BEHAVIOURS`, unknown ones after, by name."""
    known = list(BEHAVIOURS)
    return (known.index(label), "") if label in known else (len(known), str(label))
