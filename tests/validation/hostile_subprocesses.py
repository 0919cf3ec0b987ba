"""Re-run the hostile inputs of the validation reviews through the installed ``fuzzynav`` and count
what goes wrong: tracebacks, hangs past the timeout (10 s), silent wrong answers.

Each case of ``tests/validation/hostile_cases.py`` and of the corpus ``tests/hostile/cases.py``
(Gym actions and options, Python API arguments, counts, fuzzy files, tampered campaign and
checkpoint folders, reachability, ASCII terminals) runs in its own subprocess (a command line, or
its Python code for the constructor and simulator cases) in a fresh temporary directory:

- traceback: ``Traceback`` on stderr, or an exit status other than 0 / 2;
- hang: still running after ``--timeout`` seconds (killed);
- silent wrong answer: the expected status or message is not there (e.g. exit 0 where the input
  must be refused, or a refusal that does not name the field);
- wrong exit: refused (exit 2) where the input is fine.

Also two end-to-end checks of ``train --resume``: a seed-0 checkpoint resumed with ``--seed 1``, and
with fewer ``--episodes`` than done, must exit 2 naming the field. Run from the clone's root with
the Python of the environment ``fuzzynav`` is installed in (each case is a fresh process: several
minutes in all; each case is printed as it ends):

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

import textwrap  # noqa: E402

from tests.hostile import cases as corpus  # noqa: E402
from tests.validation.hostile_cases import CASES, PYTHON_PRELUDE, Case, argv_of, write_files  # noqa: E402

# (case, the Python prelude its code runs after)
ALL_CASES = [(case, PYTHON_PRELUDE) for case in CASES] + [(case, corpus.PRELUDE) for case in corpus.CASES]

FUZZYNAV = [sys.executable, "-m", "fuzzynav"]


def run(command: list[str], cwd: Path, timeout: float) -> tuple[int | None, str, str, float]:
    """(status or None on timeout, stdout, stderr, seconds) of ``command``."""
    start = time.perf_counter()
    try:
        done = subprocess.run(command, cwd=cwd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, "", "", time.perf_counter() - start
    return done.returncode, done.stdout, done.stderr, time.perf_counter() - start


def command_of(case: Case, directory: Path, prelude: str = PYTHON_PRELUDE) -> list[str]:
    if not case.python:
        return FUZZYNAV + argv_of(case, directory)
    code = (prelude + "\nimport sys\nfrom pathlib import Path\nfrom fuzzynav.errors import InputError\n"
            "d = Path.cwd()\ntry:\n" + textwrap.indent(case.python, "    ") +
            "\nexcept InputError as error:\n    print(error, file=sys.stderr)\n    sys.exit(2)\n")
    return [sys.executable, "-c", code]


def verdict(case: Case, status, out: str, err: str) -> str:
    if status is None:
        return "hang"
    if "Traceback" in err or status not in (0, 2):
        return "traceback"
    if status == 2 and case.status == 0:
        return "wrong-exit"
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
    parser.add_argument("--only", default="", help="run only the cases whose name contains this text")
    args = parser.parse_args()
    rows = []
    chosen = [(case, prelude) for case, prelude in ALL_CASES if args.only in case.name]

    def show(row: dict) -> None:  # each case as it ends (on stderr under --json): a run takes minutes
        print(f"[{len(rows)}/{len(chosen) + 2}] {row['verdict']:12s} {row['seconds']:6.2f} s  {row['case']}",
              file=sys.stderr if args.json else sys.stdout, flush=True)

    for case, prelude in chosen:
        with tempfile.TemporaryDirectory() as tmp:
            directory = Path(tmp)
            write_files(case, directory)
            status, out, err, seconds = run(command_of(case, directory, prelude), directory, args.timeout)
            rows.append({"case": case.name, "status": status, "seconds": round(seconds, 2),
                         "verdict": verdict(case, status, out, err), "message": (err or out).strip()[-200:]})
        show(rows[-1])
    with tempfile.TemporaryDirectory() as tmp:
        for row in resume_cases(Path(tmp), args.timeout):
            rows.append(row)
            show(row)
    counts = {key: sum(row["verdict"] == key for row in rows)
              for key in ("ok", "traceback", "hang", "wrong-exit", "silent-wrong")}
    if args.json:
        print(json.dumps({"cases": len(rows), **counts, "rows": rows}))
    else:
        print(f"{len(rows)} cases: " + ", ".join(f"{key} {value}" for key, value in counts.items()))
    return 0 if counts["ok"] == len(rows) else 1


if __name__ == "__main__":
    sys.exit(main())
