"""Re-run the hostile inputs of the validation review through the installed ``fuzzynav`` and count
what goes wrong: tracebacks, hangs past the timeout (10 s), silent wrong answers.

Each case of :mod:`hostile_cases` (beside this script; ``test_hostile_inputs.py`` runs the same
cases in process) runs in its own subprocess (a command line, or
its Python code for the constructor and simulator cases) in a fresh temporary directory:

- traceback: ``Traceback`` on stderr, or an exit status other than 0 / 2;
- hang: still running after ``--timeout`` seconds (killed);
- silent wrong answer: the expected status or message is not there (e.g. exit 0 where the input
  must be refused, or a refusal that does not name the field).

Also two end-to-end checks of ``train --resume``: a seed-0 checkpoint resumed with ``--seed 1``, and
with fewer ``--episodes`` than done, must exit 2 naming the field. Run:

    python tests/validation/hostile_subprocesses.py [--timeout 10] [--json]
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from tests.validation.hostile_cases import CASES, PYTHON_PRELUDE, Case, argv_of, write_files  # noqa: E402

FUZZYNAV = [sys.executable, "-m", "fuzzynav"]


def run(command: list[str], cwd: Path, timeout: float) -> tuple[int | None, str, str, float]:
    """(status or None on timeout, stdout, stderr, seconds) of ``command``."""
    start = time.perf_counter()
    try:
        done = subprocess.run(command, cwd=cwd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, "", "", time.perf_counter() - start
    return done.returncode, done.stdout, done.stderr, time.perf_counter() - start


def command_of(case: Case, directory: Path) -> list[str]:
    if not case.python:
        return FUZZYNAV + argv_of(case, directory)
    code = (PYTHON_PRELUDE + "\nimport sys\nfrom pathlib import Path\nfrom fuzzynav.errors import InputError\n"
            "d = Path.cwd()\ntry:\n"
            f"    {case.python}\nexcept InputError as error:\n    print(error, file=sys.stderr)\n    sys.exit(2)\n")
    return [sys.executable, "-c", code]


def verdict(case: Case, status, out: str, err: str) -> str:
    if status is None:
        return "hang"
    if "Traceback" in err or status not in (0, 2):
        return "traceback"
    if status != case.status or case.expect not in (err if status else out):
        return "silent-wrong"
    return "ok"


def resume_cases(directory: Path, timeout: float) -> list[dict]:
    """Train q-goal for 40 episodes (seed 0, checkpoint), then resume with another seed / fewer episodes."""
    out = str(directory / "q.json")
    base = FUZZYNAV + ["train", "q-goal", "--out", out, "--quiet"]
    run(base + ["--episodes", "40"], directory, 120)
    rows = []
    for name, extra, expect in (("resume-other-seed", ["--episodes", "40", "--seed", "1"], ": seed: "),
                                ("resume-fewer-episodes", ["--episodes", "20"], ": episodes: ")):
        status, stdout, stderr, seconds = run(base + ["--resume"] + extra, directory, timeout)
        case = Case(name, status=2, expect=expect)
        rows.append({"case": name, "status": status, "seconds": round(seconds, 2),
                     "verdict": verdict(case, status, stdout, stderr), "message": stderr.strip()[-200:]})
    return rows


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--timeout", type=float, default=10.0, help="seconds before a case counts as a hang")
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    args = parser.parse_args()
    rows = []
    for case in CASES:
        with tempfile.TemporaryDirectory() as tmp:
            directory = Path(tmp)
            write_files(case, directory)
            status, out, err, seconds = run(command_of(case, directory), directory, args.timeout)
            rows.append({"case": case.name, "status": status, "seconds": round(seconds, 2),
                         "verdict": verdict(case, status, out, err), "message": (err or out).strip()[-200:]})
    with tempfile.TemporaryDirectory() as tmp:
        rows += resume_cases(Path(tmp), args.timeout)
    counts = {key: sum(row["verdict"] == key for row in rows) for key in ("ok", "traceback", "hang", "silent-wrong")}
    if args.json:
        print(json.dumps({"cases": len(rows), **counts, "rows": rows}))
    else:
        for row in rows:
            print(f"{row['verdict']:12s} {row['seconds']:6.2f} s  {row['case']}")
        print(f"{len(rows)} cases: " + ", ".join(f"{key} {value}" for key, value in counts.items()))
    return 0 if counts["ok"] == len(rows) else 1


if __name__ == "__main__":
    sys.exit(main())
