"""Time of ``fuzzynav train TASK --seed S`` (default budget), CPU and wall, per seed — optionally
interleaved with another version of the package, whose model files must then be identical.

Each run is a fresh process (start-up, imports and loading the compiled kernels included); CPU
time is the child's user + system time, which a shared machine does not inflate as it does the
wall clock. ``--peer-src DIR`` (or ``FUZZYNAV_PEER_SRC``) names the ``src`` folder of another
checkout (e.g. ``git worktree add BEFORE_DIR <commit>``, then ``BEFORE_DIR/src``): every seed
is then trained by the peer and by this package in turn, with the same Python, and the two model
files are compared byte for byte. The first run of a version may include compiling its kernels
(``--warm`` runs one short training of each first, untimed).

Run:  python benchmarks/train_time.py [--task fql-avoid] [--seeds 5] [--peer-src DIR] [--warm] [--json]
"""

from __future__ import annotations

import json
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from fuzzynav.cli import Parser


def train(task: str, seed: int, out: Path, src: str | None, episodes: int | None = None) -> dict:
    """One ``fuzzynav train`` in a child process: CPU (user + sys) and wall seconds."""
    env = {**os.environ, **({"PYTHONPATH": src} if src else {})}
    command = [sys.executable, "-c", "from fuzzynav.cli import main; main()", "train", task, "--seed", str(seed),
               "--out", str(out), "--quiet"]
    if episodes:
        command += ["--episodes", str(episodes)]
    before, start = resource.getrusage(resource.RUSAGE_CHILDREN), time.perf_counter()
    subprocess.run(command, check=True, env=env, stdout=subprocess.DEVNULL)
    wall, after = time.perf_counter() - start, resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return {"cpu_s": round(cpu, 2), "wall_s": round(wall, 2)}


def main() -> None:
    parser = Parser(description=__doc__.splitlines()[0])
    parser.add_argument("--task", default="fql-avoid")
    parser.add_argument("--seeds", type=int, default=5)
    parser.add_argument("--peer-src", default=os.environ.get("FUZZYNAV_PEER_SRC") or None,
                        help="src folder of another version, trained in turn with this one (env FUZZYNAV_PEER_SRC)")
    parser.add_argument("--warm", action="store_true", help="one short untimed training per version first")
    parser.add_argument("--json", action="store_true", help="print only one JSON object")
    args = parser.parse_args()
    versions = {"this": None, **({"peer": args.peer_src} if args.peer_src else {})}
    rows = []
    with tempfile.TemporaryDirectory() as folder:
        if args.warm:
            for name, src in versions.items():
                train(args.task, 0, Path(folder, f"warm-{name}.json"), src, episodes=20)
        for seed in range(args.seeds):
            row = {"seed": seed}
            for name, src in reversed(versions.items()):
                row[name] = train(args.task, seed, Path(folder, f"{name}-{seed}.json"), src)
            if args.peer_src:
                row["identical_model"] = Path(folder, f"this-{seed}.json").read_bytes() == \
                    Path(folder, f"peer-{seed}.json").read_bytes()
                row["cpu_ratio"] = round(row["peer"]["cpu_s"] / row["this"]["cpu_s"], 2)
            rows.append(row)
            if not args.json:
                print(json.dumps(row), flush=True)
    result = {"task": args.task, "runs": rows}
    print(json.dumps(result) if args.json else f"{args.task}: CPU {min(r['this']['cpu_s'] for r in rows)}–"
          f"{max(r['this']['cpu_s'] for r in rows)} s, wall {min(r['this']['wall_s'] for r in rows)}–"
          f"{max(r['this']['wall_s'] for r in rows)} s")


if __name__ == "__main__":
    main()
