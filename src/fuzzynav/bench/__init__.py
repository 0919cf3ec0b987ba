"""Benchmark campaigns: every navigator on the same worlds, under the same metrics (``fuzzynav bench``).

- :mod:`.suites` — what a SUITE argument names (a folder of scenario files or a generated family);
- :mod:`.measures` — the numbers of one run (path ratio to the shortest path of the disc, BARN score);
- :mod:`.cells` — one unit of work (a world × seed, all its controllers), run in a worker;
- :mod:`.backends` — local process pool or Ray tasks, the same cells and results;
- :mod:`.campaign` — runs.csv / runs.jsonl appended as cells finish, resume, final order;
- :mod:`.stats` and :mod:`.report` — rates with Wilson intervals, medians, summary, plots, index.html,

every file written atomically by :mod:`fuzzynav.storage`.
"""
