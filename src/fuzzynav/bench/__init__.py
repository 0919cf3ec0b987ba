"""The evaluator: controllers run on worlds and their outcomes counted — campaigns, every navigator on
the same worlds under the same metrics (``fuzzynav bench``), and one controller's quick evaluation
(``fuzzynav evaluate``).

- :mod:`.suites` — what a SUITE argument names (a folder of scenario files or a generated family);
- :mod:`.measures` — the numbers of one run (path ratio to the shortest path of the disc, BARN score);
- :mod:`.cells` — one unit of work (a world × seed, all its controllers), run in a worker, and the
  controllers of every evaluation (:class:`.cells.controller_maker`);
- :mod:`.evaluate` — one controller on one generated family, summarised in memory (``fuzzynav evaluate``);
- :mod:`.backends` — local process pool or Ray tasks, the same cells and results;
- :mod:`.campaign` — runs.csv / runs.jsonl appended as cells finish, resume, final order;
- :mod:`.stats` and :mod:`.report` — rates with Wilson intervals, medians, summary, plots, index.html,

every file written atomically by :mod:`fuzzynav.storage`.
"""
