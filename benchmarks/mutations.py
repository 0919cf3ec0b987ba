"""Which claims catch which edited rule table or model: the mutation harness of the chapter IV and V claims.

Each mutation edits one published rule base — a sign flip of one cell's steering, a biased cell,
or the whole steering set to zero (``all-Z``) — for every fuzzy role (``gsb`` Table IV.1,
``oab`` Table IV.2, ``foa``/``roa``/``loa`` Tables IV.3–IV.5, ``vrb`` Table IV.6, ``wall`` Table
VI.2, ``tracker`` Table V.1), writes it to a file and runs the experiments that use the role
with it, read back as ``fuzzynav reproduce ID --fis ROLE=FILE`` reads it
(:func:`fuzzynav.experiments.rule_bases.from_options`). For each mutation it prints how far it
moves the figures (the farthest distance of a route from the published tables', the largest
relative change of a tracking error or pursuit time) and which claims it fails; then, per claim,
the mutations that catch it. The goal: every mutation that moves a route by more than 0.5 m or
changes an error by more than 20 % fails a claim, and every claim is caught by some mutation.

The learned trackers (``neural-tracker`` CN, ``anfis-tracker`` CNF) have no rule table: their
model is replaced instead (:func:`fuzzynav.experiments.learned_models.mutations`: output layer
sign-flipped, zeroed or halved, trained on negated or shuffled targets, training stopped early)
in their training figure and every run of theirs, and the runs are compared with those of the
trained models; a validation RMSE over 1e-3 rad (the scale of Figs V.15 / V.23) is significant too.

    PYTHONPATH=src python benchmarks/mutations.py                      # the table (a few minutes)
    PYTHONPATH=src python benchmarks/mutations.py --roles tracker      # one role
    PYTHONPATH=src python benchmarks/mutations.py --roles neural-tracker anfis-tracker   # the models
    PYTHONPATH=src python benchmarks/mutations.py --every-cell         # every cell's sign, one by one
    PYTHONPATH=src python benchmarks/mutations.py --learning           # Figs VI.24, VI.29 (FQL trains first)
    PYTHONPATH=src python benchmarks/mutations.py --write-references   # store the published runs

``--write-references`` runs the experiments with the published tables and stores what their
figures show (:func:`fuzzynav.experiments.routes.published_entries`) in
``src/fuzzynav/experiments/data/published_routes.json``, which the claims compare with.
"""

from __future__ import annotations

import json
import math
import tempfile
from pathlib import Path

import yaml

from fuzzynav.catalog import experiments as registry
from fuzzynav.cli import Parser
from fuzzynav.experiments import learned_models, routes, rule_bases
from fuzzynav.fuzzy.io.files import dumps

# the experiments each role's table reaches (figures with a stored reference, and their claims)
CHAPTER_IV = ("fig-IV-12", "fig-IV-13", "fig-IV-15", "fig-IV-22", "fig-IV-23", "eval-IV")
REACHES = {"gsb": CHAPTER_IV, "oab": ("fig-IV-15", "eval-IV"),
           **{role: ("fig-IV-22", "fig-IV-23", "eval-IV") for role in ("foa", "roa", "loa", "vrb")},
           "wall": ("fig-VI-28",),
           "tracker": ("fig-V-7", "fig-V-10", "fig-V-11", "fig-V-28", "fig-V-29", "fig-V-30", "fig-V-31", "fig-V-32",
                       "fig-V-33", "fig-V-34")}
# the figures that train an FQL controller first (--quick setting), then run a published table beside it
LEARNING_REACHES = {"gsb": ("fig-VI-24",), "oab": ("fig-VI-24",), "wall": ("fig-VI-29",)}
# the learned trackers' models (CN, CNF: no rule table) reach their training figure and their runs
PURSUITS = ("fig-V-28", "fig-V-29", "fig-V-30", "fig-V-31", "fig-V-32", "fig-V-33", "fig-V-34")
LEARNED_REACHES = {"neural-tracker": ("fig-V-15", "fig-V-18", "fig-V-19", *PURSUITS),
                   "anfis-tracker": ("fig-V-23", "fig-V-26", "fig-V-27", *PURSUITS)}
VALIDATION_BOUND_RAD = 1e-3  # the scale of Figs V.15 / V.23's error: a larger validation RMSE is visible
REFERENCED = tuple(dict.fromkeys(i for ids in REACHES.values() for i in ids if i not in ("eval-IV", "fig-V-7")))
MIRROR = {"NG": "PG", "NM": "PM", "NP": "PP", "PP": "NP", "PM": "NM", "PG": "NG", "DI": "AI", "D": "A", "A": "D",
          "AI": "DI"}
ZERO = {"v_adjust": "AC"}  # the zero term of an output (Z otherwise)
BIAS = {"v_adjust": "A"}  # the term a biased cell is set to (PM otherwise)
# the two cells of Table IV.1 an audit flipped by hand: (θ_rg PP, d_rg P) NM → PM, (NM, G) PP → NP
NAMED_FLIPS = {"gsb": ("drg IS P AND theta IS PP", "drg IS G AND theta IS NM")}


def _conclusion(rule: str) -> tuple[str, str, str]:
    """(text before the first conclusion's term, its variable, its term) of a rule's text."""
    head, _, tail = rule.partition(" THEN ")
    variable, _, rest = tail.partition(" IS ")
    term = rest.split(" ")[0]
    return f"{head} THEN {variable} IS ", variable, term


def _with_term(rule: str, term: str) -> str:
    head, _, old = _conclusion(rule)
    tail = rule[len(head) + len(old):]
    return f"{head}{term}{tail}"


def mutations(role: str, every_cell: bool = False) -> list[tuple[str, dict]]:
    """(name, edited document) of every mutation of ``role``'s published system: two sign flips
    (the audited cells for ``gsb``; else the first rule and the middle one that steer; with
    ``every_cell``, one flip per steering cell), a biased zero cell and the all-zero table."""
    document = yaml.safe_load(dumps(rule_bases.system(role), "yaml"))
    rules = document["rules"]
    steering = [k for k, rule in enumerate(rules) if _conclusion(rule)[2] in MIRROR]
    if every_cell:
        flips = steering
    elif role in NAMED_FLIPS:
        flips = [next(k for k, rule in enumerate(rules) if cell in rule) for cell in NAMED_FLIPS[role]]
    else:
        flips = [steering[0], steering[len(steering) // 2]]
    edited = []
    for k in flips:
        term = _conclusion(rules[k])[2]
        edited.append((f"{role}: flip rule {k + 1} ({term} -> {MIRROR[term]})",
                       {k: _with_term(rules[k], MIRROR[term])}))
    variable = _conclusion(rules[0])[1]
    zero, bias = ZERO.get(variable, "Z"), BIAS.get(variable, "PM")
    zeros = [k for k, rule in enumerate(rules) if _conclusion(rule)[2] == zero]
    if zeros:
        k = zeros[len(zeros) // 2]
        edited.append((f"{role}: biased rule {k + 1} ({zero} -> {bias})", {k: _with_term(rules[k], bias)}))
    edited.append((f"{role}: all-{zero}", {k: _with_term(rule, zero) for k, rule in enumerate(rules)}))
    return [(name, {**document, "name": f"{role}-mutated",
                    "rules": [changes.get(k, rule) for k, rule in enumerate(rules)]}) for name, changes in edited]


def run(ids, out: Path, systems: dict | None = None, models: dict | None = None) -> dict:
    """The numbers of experiments ``ids`` (quick settings: eval-IV on 10 worlds) with ``systems``
    ({role: fuzzy system}) and ``models`` ({learned tracker: model document})."""
    with rule_bases.replaced(systems or {}), learned_models.replaced(models or {}):
        return {key: registry.experiment(key)(out / key, quick=True, seed=0) for key in ids}


def run_mutated(role: str, document: dict, ids, out: Path) -> dict:
    """The numbers of experiments ``ids`` with ``role``'s system replaced by ``document``, written
    to a file and read back as ``fuzzynav reproduce ID --fis ROLE=FILE`` reads it."""
    path = out / f"{role}.yaml"
    path.write_text(yaml.safe_dump(document, sort_keys=False, allow_unicode=True))
    return run(ids, out, rule_bases.from_options([f"{role}={path}"]))


def every_run(numbers: dict) -> dict:
    """The entries of every run of ``numbers`` that reports a route, the learned trackers' included."""
    return {name: entry for key, value in numbers.items()
            for name, entry in routes.published_entries(key, value, skip=()).items()}


def moved(numbers: dict, stored: dict | None = None) -> tuple[float, float]:
    """(farthest route distance from the reference runs (m), largest relative change of an error or
    pursuit time) over the runs of ``numbers`` that have a reference: ``stored`` ({entry name:
    entry}, e.g. :func:`every_run` of an unmutated run), by default the published tables' runs."""
    gap, change = 0.0, 0.0
    if stored is None:
        stored = routes.references()
        runs = {name: entry for key, value in numbers.items()
                for name, entry in routes.published_entries(key, value).items()}
    else:
        runs = every_run(numbers)
    for name, entry in runs.items():
        if name in stored:
            reference = stored[name]
            gap = max(gap, routes.deviation(entry["route"], reference["route"]))
            for field in ("max_cross_track_m", "mean_cross_track_m", "capture_time_s"):
                if field in reference:
                    ours, theirs = entry[field], reference[field]
                    if ours is None or theirs is None:
                        change = max(change, 0.0 if ours == theirs else math.inf)
                    elif theirs > routes.ERROR_FLOOR_M:
                        change = max(change, abs(ours - theirs) / theirs)
    return gap, change


def failing(numbers: dict) -> list[str]:
    """The ids whose claim is not reproduced on ``numbers``."""
    return [key for key, value in numbers.items() if registry.spec(key).claim.evaluate(value)[0] != "reproduced"]


def write_references(out: Path) -> Path:
    """Store the published tables' runs of :data:`REFERENCED` beside the claims."""
    entries = {}
    for key, value in run(REFERENCED, out).items():
        entries.update(routes.published_entries(key, value))
    path = Path(__file__).resolve().parents[1] / "src" / "fuzzynav" / "experiments" / "data" / routes.REFERENCES
    path.parent.mkdir(exist_ok=True)
    temporary = path.with_suffix(".tmp")
    temporary.write_text(json.dumps(entries, separators=(",", ":")) + "\n")
    temporary.replace(path)
    return path


def _row(name: str, failed: list[str], gap: float, change: float, rmse: float | None = None) -> tuple[str, bool]:
    """The table row of one mutation, and whether it is significant."""
    significant = (gap > routes.ROUTE_TOLERANCE_M or change > routes.ERROR_TOLERANCE
                   or (rmse is not None and rmse > VALIDATION_BOUND_RAD))
    cells = [name, *([f"{rmse:.1e}"] if rmse is not None else []), f"{gap:.2f}", f"{change:.0%}",
             "yes" if significant else "no", ", ".join(failed) or ("**none**" if significant else "none")]
    return "| " + " | ".join(cells) + " |", significant


def learned_rows(kind: str, out: Path, stored: dict):
    """(table row, claims failed, significant) of every wrong model of learned tracker ``kind``,
    against ``stored``, the runs of the trained models (:func:`every_run`)."""
    training = LEARNED_REACHES[kind][0]
    for name, document in learned_models.mutations(kind):
        numbers = run(LEARNED_REACHES[kind], out, models={kind: document})
        failed = failing(numbers)
        row, significant = _row(name, failed, *moved(numbers, stored), numbers[training]["validation_rmse_rad"])
        yield name, row, failed, significant


def hand_made(numbers: dict) -> str:
    """What the navigator of the published table did in Figs VI.24 / VI.29 (the FQL controller
    beside it reads no edited table)."""
    parts = []
    for name, run in numbers.get("fig-VI-24", {}).items():
        if name.startswith("fuzzy-2b-thesis"):
            evaluation = run["evaluation"]
            parts.append(f"fuzzy-2b-thesis: blocked world {run['outcome']}, {evaluation['success']:.0%} of "
                         f"{evaluation['runs']} random worlds reached")
    if "fig-VI-29" in numbers:
        corners, evaluation = numbers["fig-VI-29"]["corners"], numbers["fig-VI-29"]["evaluation"]["wall-follow"]
        parts.append(f"wall-follow: corners {', '.join(corners['wall-follow'].values())}; "
                     f"{evaluation['collisions']} collisions on {evaluation['courses']} wall courses")
    return "; ".join(parts)


def learning_table(roles, every_cell: bool, out: Path) -> None:
    """Print what each mutation of ``roles`` does to Figs VI.24 / VI.29 and which claims it fails."""
    published = run(sorted({key for role in roles for key in LEARNING_REACHES[role]}), out)
    print(f"published tables: claims not reproduced: {failing(published) or 'none'}; {hand_made(published)}\n")
    print("| mutation | the published table's navigator | changed | claims failed |")
    print("|---|---|---|---|")
    for role in roles:
        before = hand_made({key: published[key] for key in LEARNING_REACHES[role]})
        for name, document in mutations(role, every_cell):
            numbers = run_mutated(role, document, LEARNING_REACHES[role], out)
            after = hand_made(numbers)
            print(f"| {name} | {after} | {'yes' if after != before else 'no'} | {', '.join(failing(numbers)) or 'none'} |",
                  flush=True)


def main() -> None:
    parser = Parser(description=__doc__.splitlines()[0])
    roles = [*REACHES, *LEARNED_REACHES]
    parser.add_argument("--roles", nargs="*", default=roles, choices=roles,
                        help="fuzzy roles (rule tables) and learned trackers (their models) to mutate")
    parser.add_argument("--every-cell", action="store_true", help="flip the sign of every steering cell, one at a time")
    parser.add_argument("--learning", action="store_true",
                        help="run the chapter VI figures that train FQL first (Figs VI.24, VI.29) instead")
    parser.add_argument("--write-references", action="store_true")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        out = Path(folder)
        if args.write_references:
            print(f"wrote {write_references(out)}")
            return
        caught: dict[str, list[str]] = {}
        if args.learning:
            learning_table([role for role in args.roles if role in LEARNING_REACHES], args.every_cell, out)
            return
        reaches = {**REACHES, **LEARNED_REACHES}
        baseline = sorted({key for role in args.roles for key in reaches[role]})
        published = run(baseline, out)
        print(f"published tables, trained models: claims not reproduced: {failing(published) or 'none'}\n")
        misses = 0
        roles = [role for role in args.roles if role in REACHES]
        if roles:
            print("| mutation | route moved (m) | error / time change | significant | claims failed |")
            print("|---|---|---|---|---|")
        for role in roles:
            for name, document in mutations(role, args.every_cell):
                numbers = run_mutated(role, document, REACHES[role], out)
                failed = failing(numbers)
                row, significant = _row(name, failed, *moved(numbers))
                misses += significant and not failed
                for key in failed:
                    caught.setdefault(key, []).append(name)
                print(row, flush=True)
        kinds = [role for role in args.roles if role in LEARNED_REACHES]
        if kinds:
            print("\n| mutation | validation RMSE (rad) | route moved (m) | error / time change | significant | "
                  "claims failed |")
            print("|---|---|---|---|---|---|")
        for kind in kinds:
            for name, row, failed, significant in learned_rows(kind, out, every_run(published)):
                misses += significant and not failed
                for key in failed:
                    caught.setdefault(key, []).append(name)
                print(row, flush=True)
        print(f"\nsignificant mutations no claim caught: {misses}\n")
        print("| claim | caught by |")
        print("|---|---|")
        for key in baseline:
            print(f"| {key} | {len(caught.get(key, []))} mutations: {'; '.join(caught.get(key, [])) or '**none**'} |")


if __name__ == "__main__":
    main()
