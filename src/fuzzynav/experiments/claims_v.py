"""Chapter V's experiments (trajectory tracking and target pursuit by the fuzzy, neural and
ANFIS trackers CF, CN, CNF, §V.3–V.5) with the thesis' claim of each.

Besides what the thesis says (lines and paths followed, targets caught, CN and CNF faster and
closer on the V path), the claims check what Table V.1 does: the control surface at the 25
peaks of its partition, and each run of CF against the run of the published table
(:mod:`fuzzynav.experiments.routes`: max and mean cross-track error and pursuit time within
20 %, route within 0.5 m). The learned trackers use no rule table; their errors are bounded by
this package's targets, measured on seeds 0–4 (docs/results/claims-mutations.md)."""

from __future__ import annotations

import math

from fuzzynav.catalog.experiments import Experiment
from fuzzynav.experiments.claims import Check, Claim
from fuzzynav.experiments.routes import change_check, route_check
from fuzzynav.fuzzy.systems import TABLE_V_1

MODULE = "fuzzynav.experiments.chapter5"
TRACKERS = {"fuzzy-tracker": "CF", "neural-tracker": "CN", "anfis-tracker": "CNF"}
VALIDATION_RMSE_RAD = 1e-3  # "an error of about 1e-3" (Fig V.23)
ALPHA = {"NG": -math.pi / 4, "NM": -math.pi / 8, "Z": 0.0, "PM": math.pi / 8, "PG": math.pi / 4}  # Fig V.6
LABELS = ("NG", "NM", "Z", "PM", "PG")
# this package's bounds on the learned trackers' max cross-track error (m), measured on seeds 0–4 + 20 %
LEARNED_BOUNDS_M = {"lines": 1.25, "segment": 0.85, "path-n": 0.35, "path-trapezoid": 0.65}


def _fig_v_7(numbers):
    low, high = numbers["alpha_min_rad"], numbers["alpha_max_rad"]
    grid = numbers["alpha_at_peaks_rad"]
    wrong = [f"θ_er {LABELS[i]}, dθ_er {LABELS[j]}: {math.degrees(grid[i][j]):.1f}° (Table V.1: {cell})"
             for i, row in enumerate(TABLE_V_1) for j, cell in enumerate(row.split())
             if not math.isclose(grid[i][j], ALPHA[cell], abs_tol=1e-6)]
    return [Check("smallest steering (°)", round(math.degrees(low), 3), "−45°",
                  math.isclose(low, -math.pi / 4, abs_tol=1e-9)),
            Check("largest steering (°)", round(math.degrees(high), 3), "+45°",
                  math.isclose(high, math.pi / 4, abs_tol=1e-9)),
            Check("surface at the 25 peaks of the partition that differ from Table V.1", wrong, "none", not wrong)]


def _cf_run(label: str, run: dict, key: str) -> list[Check]:
    """CF's run against the published Table V.1's run of the same figure."""
    return [change_check(f"{label}: max cross-track error", run["max_cross_track_m"], key, "max_cross_track_m", "m"),
            change_check(f"{label}: mean cross-track error", run["mean_cross_track_m"], key, "mean_cross_track_m",
                         "m"),
            route_check(label, run, key)]


def _learned_bound(label: str, value: float, bound: float) -> Check:
    return Check(f"{label}: max cross-track error (m)", round(value, 3), f"≤ {bound}", value <= bound, "package")


def _star_lines(figure: str, fuzzy: bool):
    """The lines T1…T6 and the two single segments (Figs V.8, V.16, V.24) completed; CF as the
    published Table V.1, the learned trackers under this package's bounds."""
    def test(numbers):
        lines, segments = numbers["lines"], numbers["segments"]
        done = sum(bool(r["completed"]) for r in lines.values())
        checks = [Check("lines completed", done, f"all {len(lines)}", done == len(lines))]
        checks += [Check(f"segment ({panel}) completed", bool(run["completed"]), "true", bool(run["completed"]))
                   for panel, run in segments.items()]
        if fuzzy:
            runs = [(name, run, f"{figure}/lines/{name}") for name, run in lines.items()]
            runs += [(f"segment ({panel})", run, f"{figure}/segments/{panel}") for panel, run in segments.items()]
            return checks + [check for label, run, key in runs for check in _cf_run(label, run, key)]
        return checks + [_learned_bound("worst line", numbers["worst_max_cross_track_m"], LEARNED_BOUNDS_M["lines"])] + [
            _learned_bound(f"segment ({panel})", run["max_cross_track_m"], LEARNED_BOUNDS_M["segment"])
            for panel, run in segments.items()]
    return test


def _polygon_paths(figure: str, fuzzy: bool):
    def test(numbers):
        checks = []
        for name in ("path-n", "path-trapezoid"):
            thesis, ours = numbers[name]["thesis"], numbers[name]["anticipation"]
            checks.append(Check(f"{name}: completed", bool(thesis["completed"]), "true", bool(thesis["completed"])))
            checks.append(Check(f"{name}: completed with corner anticipation", bool(ours["completed"]), "true",
                                bool(ours["completed"]), "package"))
            checks += (_cf_run(name, thesis, f"{figure}/{name}/thesis") if fuzzy else
                       [_learned_bound(name, thesis["max_cross_track_m"], LEARNED_BOUNDS_M[name])])
        return checks
    return test


def _training(numbers):
    rmse = numbers["validation_rmse_rad"]
    return [Check("validation RMSE (rad)", rmse, f"≤ {VALIDATION_RMSE_RAD:g}", rmse <= VALIDATION_RMSE_RAD)]


def _fig_v_28(numbers):
    error = {key: numbers[key]["max_cross_track_m"] for key in TRACKERS}
    checks = [Check(f"{short}: completed", bool(numbers[key]["completed"]), "true", bool(numbers[key]["completed"]))
              for key, short in TRACKERS.items()]
    return checks + [Check(f"{TRACKERS[key]} max cross-track error (m)", error[key],
                           f"< CF's {error['fuzzy-tracker']:.3f} m", error[key] < error["fuzzy-tracker"])
                     for key in ("neural-tracker", "anfis-tracker")] + _cf_run("CF", numbers["fuzzy-tracker"],
                                                                                "fig-V-28/fuzzy-tracker")


def _captured(figure: str, *panels: str):
    """Every tracker captures every target, CN and CNF no later than CF ("la tâche est rapide"
    with them, §V.5), and CF as the published Table V.1 does (time within 20 %, route within 0.5 m)."""
    def test(numbers):
        groups = {panel: numbers[panel] for panel in panels} if panels else {"": numbers}
        checks = []
        for panel, runs in groups.items():
            prefix = f"{panel} " if panel else ""
            cf_key = f"{figure}/{panel}/fuzzy-tracker" if panel else f"{figure}/fuzzy-tracker"
            checks += [Check(f"{prefix}{short}: captured", runs[name]["capture_time_s"], "captured",
                             bool(runs[name]["captured"])) for name, short in TRACKERS.items()]
            cf = runs["fuzzy-tracker"]["capture_time_s"]
            checks += [Check(f"{prefix}{TRACKERS[name]}: capture time (s)", runs[name]["capture_time_s"],
                             f"≤ CF's {cf} s", None not in (cf, runs[name]["capture_time_s"])
                             and runs[name]["capture_time_s"] <= cf) for name in ("neural-tracker", "anfis-tracker")]
            checks += [change_check(f"{prefix}CF: capture time", cf, cf_key, "capture_time_s", "s"),
                       route_check(f"{prefix}CF", runs["fuzzy-tracker"], cf_key)]
        return checks
    return test


_PURSUIT = "The robot (start (4, 4), heading 0) pursues a target that starts at (4, 12)"
_ALL_CAPTURE = ("All three trackers capture the target, CN and CNF no later than CF; CF's capture time is within 20 % "
                "and its route within 0.5 m of the published Table V.1's.")
_CF_RUNS = ("; CF's max and mean cross-track errors are within 20 % and its routes within 0.5 m of the published "
            "Table V.1's")
_LEARNED = "; the max cross-track error stays under this package's bound"


def _spec(key: str, description: str, reference: str, thesis: str, asserted: str, test) -> Experiment:
    return Experiment(key, f"{MODULE}:{key.lower().replace('-', '_')}", description, reference,
                      Claim(thesis, asserted, test))


EXPERIMENTS = [
    _spec("fig-V-7", "control surface of the fuzzy tracker, Table V.1", "§V.3.1, Fig V.7, Table V.1",
          "The control surface of the 25-rule fuzzy tracker (Table V.1) spans the steering range ±π/4.",
          "The surface spans exactly −45° … +45° and equals Table V.1's singleton at each of the 25 peaks of its "
          "partition.", _fig_v_7),
    _spec("fig-V-10", "fuzzy tracker CF on one segment (V.8, commands V.9) and six lines from (10,10)",
          "§V.3.1, Figs V.8–V.10",
          "The fuzzy tracker CF joins and follows a straight segment (Figs V.8–V.9) and six straight lines leaving "
          "(10, 10) in all directions, the robot heading 0 (Fig V.10).",
          "Every segment and line is completed" + _CF_RUNS + ".", _star_lines("fig-V-10", True)),
    _spec("fig-V-11", "fuzzy tracker CF on the N and trapezoid paths", "§V.3.1, Fig V.11",
          "CF tracks the N-shaped and trapezoidal paths; the error appears at the direction changes.",
          "Both paths are completed" + _CF_RUNS + ".", _polygon_paths("fig-V-11", True)),
    _spec("fig-V-15", "MLP tracker: validation on unseen pairs and training loss", "§V.3.2, Fig V.15",
          "The neural inverse model (MLP, tanh, generalized learning) is validated on about 100 unseen pairs.",
          "Validation RMSE ≤ 1e-3 rad.", _training),
    _spec("fig-V-18", "neural tracker CN on one segment (V.16, commands V.17) and six lines from (10,10)",
          "§V.3.2, Figs V.16–V.18",
          "The neural tracker CN follows a straight segment (Figs V.16–V.17) and the six straight lines from (10, 10).",
          "Every segment and line is completed" + _LEARNED + ".", _star_lines("fig-V-18", False)),
    _spec("fig-V-19", "neural tracker CN on the N and trapezoid paths", "§V.3.2, Fig V.19",
          "CN tracks the N-shaped and trapezoidal paths.", "Both paths are completed" + _LEARNED + ".",
          _polygon_paths("fig-V-19", False)),
    _spec("fig-V-23", "ANFIS tracker: validation and training curve", "§V.3.5, Fig V.23, Table V.2",
          "ANFIS hybrid learning (Table V.2) reaches a training error of about 1e-3.",
          "Validation RMSE ≤ 1e-3 rad.", _training),
    _spec("fig-V-26", "ANFIS tracker CNF on one segment (V.24, commands V.25) and six lines from (10,10)",
          "§V.3.5, Figs V.24–V.26",
          "The ANFIS tracker CNF follows a straight segment (Figs V.24–V.25) and the six straight lines from "
          "(10, 10).", "Every segment and line is completed" + _LEARNED + ".", _star_lines("fig-V-26", False)),
    _spec("fig-V-27", "ANFIS tracker CNF on the N and trapezoid paths", "§V.3.5, Fig V.27",
          "CNF tracks the N-shaped and trapezoidal paths.", "Both paths are completed" + _LEARNED + ".",
          _polygon_paths("fig-V-27", False)),
    _spec("fig-V-28", "V path by CF, CN, CNF with a zoom on the corner", "§V.4, Fig V.28",
          "On the V path the error of CF, CN and CNF appears at the direction change and is smallest for CN and "
          "CNF.", "All three complete the path; CN and CNF have a smaller max cross-track error than CF" + _CF_RUNS + ".",
          _fig_v_28),
    _spec("fig-V-29", "pursuit of a target on a line by CF, CN, CNF", "§V.5, Fig V.29",
          f"{_PURSUIT} moving on a straight line; CF, CN and CNF all reach it, the task is fast with CN and CNF.",
          _ALL_CAPTURE, _captured("fig-V-29")),
    _spec("fig-V-30", "pursuit of a target on a circle by CF, CN, CNF", "§V.5, Fig V.30",
          f"{_PURSUIT} moving on a circle; CF, CN and CNF all reach it.", _ALL_CAPTURE, _captured("fig-V-30")),
    _spec("fig-V-31", "pursuit of a target on a sinusoid by CF, CN, CNF", "§V.5, Fig V.31",
          f"{_PURSUIT} moving on a sinusoid; CF, CN and CNF all reach it.", _ALL_CAPTURE, _captured("fig-V-31")),
    _spec("fig-V-32", "pursuit of a target on a line, CF/CN/CNF compared at the capture", "§V.5.1, Fig V.32",
          "A target on a straight line is caught by CF, CN and CNF; their trajectories compared near the capture.",
          _ALL_CAPTURE, _captured("fig-V-32")),
    _spec("fig-V-33", "pursuit of targets on two straight lines by CF, CN, CNF", "§V.5.1, Fig V.33",
          "Targets on two other straight lines are caught by the three controllers.",
          "All three trackers capture both targets" + _ALL_CAPTURE[len("All three trackers capture the target"):],
          _captured("fig-V-33", "fig-V-33a", "fig-V-33b")),
    _spec("fig-V-34", "pursuit of a circular and a sinusoidal target by CF, CN, CNF", "§V.5.1, Fig V.34",
          "A circular and a sinusoidal target are caught by the three controllers.",
          "All three trackers capture both targets" + _ALL_CAPTURE[len("All three trackers capture the target"):],
          _captured("fig-V-34", "fig-V-34a", "fig-V-34b")),
]
