"""Chapter V's experiments (trajectory tracking and target pursuit by the fuzzy, neural and
ANFIS trackers CF, CN, CNF, §V.3–V.5) with the thesis' claim of each."""

from __future__ import annotations

import math

from fuzzynav.catalog.experiments import Experiment
from fuzzynav.experiments.claims import Check, Claim

MODULE = "fuzzynav.experiments.chapter5"
TRACKERS = {"fuzzy-tracker": "CF", "neural-tracker": "CN", "anfis-tracker": "CNF"}
VALIDATION_RMSE_RAD = 1e-3  # "an error of about 1e-3" (Fig V.23)


def _fig_v_7(numbers):
    low, high = numbers["alpha_min_rad"], numbers["alpha_max_rad"]
    return [Check("smallest steering (°)", round(math.degrees(low), 3), "−45°",
                  math.isclose(low, -math.pi / 4, abs_tol=1e-9)),
            Check("largest steering (°)", round(math.degrees(high), 3), "+45°",
                  math.isclose(high, math.pi / 4, abs_tol=1e-9))]


def _star_lines(numbers):
    lines = numbers["lines"]
    done = sum(bool(r["completed"]) for r in lines.values())
    return [Check("lines completed", done, f"all {len(lines)}", done == len(lines))]


def _polygon_paths(numbers):
    checks = []
    for name in ("path-n", "path-trapezoid"):
        thesis, ours = numbers[name]["thesis"], numbers[name]["anticipation"]
        checks.append(Check(f"{name}: completed", bool(thesis["completed"]), "true", bool(thesis["completed"])))
        checks.append(Check(f"{name}: completed with corner anticipation", bool(ours["completed"]), "true",
                            bool(ours["completed"]), "package"))
    return checks


def _training(numbers):
    rmse = numbers["validation_rmse_rad"]
    return [Check("validation RMSE (rad)", rmse, f"≤ {VALIDATION_RMSE_RAD:g}", rmse <= VALIDATION_RMSE_RAD)]


def _fig_v_28(numbers):
    error = {key: numbers[key]["max_cross_track_m"] for key in TRACKERS}
    checks = [Check(f"{short}: completed", bool(numbers[key]["completed"]), "true", bool(numbers[key]["completed"]))
              for key, short in TRACKERS.items()]
    return checks + [Check(f"{TRACKERS[key]} max cross-track error (m)", error[key],
                           f"< CF's {error['fuzzy-tracker']:.3f} m", error[key] < error["fuzzy-tracker"])
                     for key in ("neural-tracker", "anfis-tracker")]


def _captured(*panels: str):
    def test(numbers):
        groups = {panel: numbers[panel] for panel in panels} if panels else {"": numbers}
        return [Check(f"{panel + ' ' if panel else ''}{short}: captured", runs[key]["capture_time_s"],
                      "captured", bool(runs[key]["captured"]))
                for panel, runs in groups.items() for key, short in TRACKERS.items()]
    return test


_PURSUIT = "The robot (start (4, 4), heading 0) pursues a target that starts at (4, 12)"
_ALL_CAPTURE = "All three trackers capture the target."


def _spec(key: str, description: str, reference: str, thesis: str, asserted: str, test) -> Experiment:
    return Experiment(key, f"{MODULE}:{key.lower().replace('-', '_')}", description, reference,
                      Claim(thesis, asserted, test))


EXPERIMENTS = [
    _spec("fig-V-7", "control surface of the fuzzy tracker, Table V.1", "§V.3.1, Fig V.7, Table V.1",
          "The control surface of the 25-rule fuzzy tracker (Table V.1) spans the steering range ±π/4.",
          "The surface spans exactly −45° … +45°.", _fig_v_7),
    _spec("fig-V-10", "fuzzy tracker CF on six straight lines from (10,10)", "§V.3.1, Fig V.10",
          "The fuzzy tracker CF follows six straight lines leaving (10, 10) in all directions, the robot heading 0.",
          "Every line is completed.", _star_lines),
    _spec("fig-V-11", "fuzzy tracker CF on the N and trapezoid paths", "§V.3.1, Fig V.11",
          "CF tracks the N-shaped and trapezoidal paths; the error appears at the direction changes.",
          "Both paths are completed.", _polygon_paths),
    _spec("fig-V-15", "MLP tracker: validation on unseen pairs and training loss", "§V.3.2, Fig V.15",
          "The neural inverse model (MLP, tanh, generalized learning) is validated on about 100 unseen pairs.",
          "Validation RMSE ≤ 1e-3 rad.", _training),
    _spec("fig-V-18", "neural tracker CN on six straight lines from (10,10)", "§V.3.2, Fig V.18",
          "The neural tracker CN follows the six straight lines from (10, 10).", "Every line is completed.",
          _star_lines),
    _spec("fig-V-19", "neural tracker CN on the N and trapezoid paths", "§V.3.2, Fig V.19",
          "CN tracks the N-shaped and trapezoidal paths.", "Both paths are completed.", _polygon_paths),
    _spec("fig-V-23", "ANFIS tracker: validation and training curve", "§V.3.5, Fig V.23, Table V.2",
          "ANFIS hybrid learning (Table V.2) reaches a training error of about 1e-3.",
          "Validation RMSE ≤ 1e-3 rad.", _training),
    _spec("fig-V-26", "ANFIS tracker CNF on six straight lines from (10,10)", "§V.3.5, Fig V.26",
          "The ANFIS tracker CNF follows the six straight lines from (10, 10).", "Every line is completed.",
          _star_lines),
    _spec("fig-V-27", "ANFIS tracker CNF on the N and trapezoid paths", "§V.3.5, Fig V.27",
          "CNF tracks the N-shaped and trapezoidal paths.", "Both paths are completed.", _polygon_paths),
    _spec("fig-V-28", "V path by CF, CN, CNF with a zoom on the corner", "§V.4, Fig V.28",
          "On the V path the error of CF, CN and CNF appears at the direction change and is smallest for CN and "
          "CNF.", "All three complete the path; CN and CNF have a smaller max cross-track error than CF.", _fig_v_28),
    _spec("fig-V-29", "pursuit of a target on a line by CF, CN, CNF", "§V.5, Fig V.29",
          f"{_PURSUIT} moving on a straight line; CF, CN and CNF all reach it.", _ALL_CAPTURE, _captured()),
    _spec("fig-V-30", "pursuit of a target on a circle by CF, CN, CNF", "§V.5, Fig V.30",
          f"{_PURSUIT} moving on a circle; CF, CN and CNF all reach it.", _ALL_CAPTURE, _captured()),
    _spec("fig-V-31", "pursuit of a target on a sinusoid by CF, CN, CNF", "§V.5, Fig V.31",
          f"{_PURSUIT} moving on a sinusoid; CF, CN and CNF all reach it.", _ALL_CAPTURE, _captured()),
    _spec("fig-V-32", "pursuit of a target on a line, CF/CN/CNF compared at the capture", "§V.5.1, Fig V.32",
          "A target on a straight line is caught by CF, CN and CNF; their trajectories compared near the capture.",
          _ALL_CAPTURE, _captured()),
    _spec("fig-V-33", "pursuit of targets on two straight lines by CF, CN, CNF", "§V.5.1, Fig V.33",
          "Targets on two other straight lines are caught by the three controllers.",
          "All three trackers capture both targets.", _captured("fig-V-33a", "fig-V-33b")),
    _spec("fig-V-34", "pursuit of a circular and a sinusoidal target by CF, CN, CNF", "§V.5.1, Fig V.34",
          "A circular and a sinusoidal target are caught by the three controllers.",
          "All three trackers capture both targets.", _captured("fig-V-34a", "fig-V-34b")),
]
