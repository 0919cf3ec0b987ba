"""Same models, same numbers: compare two installations of fuzzynav byte for byte.

A refactoring must not change what the package computes. This script trains every training task
with a small budget and fixed seeds, and runs ``fuzzynav reproduce all --quick``, once with each of
two ``fuzzynav`` executables (e.g. the venv of a worktree at the base commit and the venv of the
working tree), then compares every model file and every reproduce ``<id>.json`` byte for byte.

    python benchmarks/same_results.py --base BASE_DIR/.venv/bin/fuzzynav \
        --new .venv/bin/fuzzynav --out OUT_DIR

Paths inside the run's directory are compared relative to it; fields that measure wall time (any key ending in ``_seconds``, a checkpoint's ``saved_at`` and the
``digest`` that covers it, and an
experiment record's ``seconds`` and ``finished``, ``reproduce <id>/run.json``, and a tuning row's ``wall_s``) are removed
before comparing, since they differ between any two runs; everything else must be identical.
Exit status 0 when every file matches, 1 otherwise.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

from fuzzynav.cli import Parser

# task -> extra arguments of `fuzzynav train` (small budgets, the default seed 0 and seed 3)
TRAININGS = {
    "neural-tracker": [],
    "anfis-tracker": [],
    "q-goal": ["--episodes", "1000"],
    "fql-goal": ["--episodes", "1000"],
    "fql-goal-35": ["--episodes", "600"],
    "fql-goal-traces": ["--episodes", "600"],
    "fql-avoid": ["--episodes", "200"],
    "fql-wall": ["--episodes", "300"],
}
SEEDS = (0, 3)


def run(fuzzynav: str, out: Path) -> None:
    """Train every task and reproduce every experiment into ``out`` with ``fuzzynav``."""
    models = out / "models"
    models.mkdir(parents=True, exist_ok=True)
    for task, extra in TRAININGS.items():
        for seed in SEEDS:
            target = models / f"{task}-seed{seed}.json"
            subprocess.run([fuzzynav, "train", task, "--seed", str(seed), "--out", str(target), "--quiet", *extra],
                           check=True, stdout=subprocess.DEVNULL)
    subprocess.run([fuzzynav, "reproduce", "all", "--quick", "--out", str(out / "reproduce")], check=True,
                   stdout=subprocess.DEVNULL)


# a checkpoint's save time and its digest (which covers the save time; the rest is compared); an
# experiment record's run time and end; a tuning row's wall time
WALL_CLOCK = ("saved_at", "digest", "seconds", "finished", "wall_s")


def _without_timings(value):
    if isinstance(value, dict):
        return {k: _without_timings(v) for k, v in value.items() if not (k.endswith("_seconds") or k in WALL_CLOCK)}
    if isinstance(value, list):
        return [_without_timings(v) for v in value]
    return value


def comparable(path: Path, root: Path) -> bytes:
    """The bytes compared: JSON without timing fields, the run's own directory written as ``<out>``."""
    text = path.read_text().replace(str(root), "<out>")
    return json.dumps(_without_timings(json.loads(text)), sort_keys=True).encode()


def compare(base: Path, new: Path) -> list[str]:
    """Lines ``same|DIFFERENT|missing  relative/path`` for every model and reproduce JSON file."""
    lines = []
    files = sorted({p.relative_to(base) for p in base.rglob("*.json")} | {p.relative_to(new) for p in new.rglob("*.json")})
    for rel in files:
        a, b = base / rel, new / rel
        if not (a.is_file() and b.is_file()):
            lines.append(f"missing    {rel}")
        else:
            lines.append(f"{'same' if comparable(a, base) == comparable(b, new) else 'DIFFERENT':10} {rel}")
    return lines


def main(argv=None) -> int:
    parser = Parser(description=__doc__.splitlines()[0])
    parser.add_argument("--base", required=True, help="fuzzynav executable of the reference installation")
    parser.add_argument("--new", required=True, help="fuzzynav executable of the installation under test")
    parser.add_argument("--out", type=Path, required=True, help="directory for both runs (base/, new/)")
    parser.add_argument("--compare-only", action="store_true", help="compare the existing runs in --out")
    args = parser.parse_args(argv)
    if not args.compare_only:
        run(args.base, args.out / "base")
        run(args.new, args.out / "new")
    lines = compare(args.out / "base", args.out / "new")
    print("\n".join(lines))
    differing = [line for line in lines if not line.startswith("same")]
    print(f"{len(lines) - len(differing)} of {len(lines)} files identical (timing fields removed)")
    return 1 if differing else 0


if __name__ == "__main__":
    sys.exit(main())
