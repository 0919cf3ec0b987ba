"""Options whose value is a finite number the command cannot use, refused by the option's name
before any file is read or any run: ``import barn --scale 1e308`` overflowed to an infinite world
(a numpy RuntimeWarning on stderr, then an error blaming the world file's ``world.width``);
``reproduce --seed 4294967296`` ran every experiment up to the first that trains an MLP.

The cases run as those of ``cases.py`` do (``test_hostile_corpus.py``)."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.validation.hostile_cases import Case

from .test_hostile_corpus import test_hostile_case as run_case

BARN_WORLD = str(Path(__file__).resolve().parent.parent / "data" / "barn" / "world_0.world")


def _import(scale: str) -> tuple:
    return ("import", "barn", BARN_WORLD, "--out", "{d}/o", "--scale", scale)


CASES = [
    # BARN's world is 6.5 x 16 m at scale 1: 625 makes it 10,000 m high, the world size limit
    *[Case(f"import-barn-scale-{scale}", argv=_import(scale), expect=f"--scale: must be <= 625, got {shown}")
      for scale, shown in (("1e308", "1e+308"), ("1e200", "1e+200"), ("626", "626.0"))],
    Case("import-barn-scale-625-ok", argv=_import("625"), status=0),
    # scikit-learn's MLP takes seeds below 2**32: fig-V-15 failed on its own "seed" once it ran, and
    # `reproduce all` only when it reached it, after the chapter VI experiments' minutes
    Case("reproduce-seed-2-32", argv=("reproduce", "fig-V-15", "--quick", "--quiet", "--seed", "4294967296",
                                      "--out", "{d}/r"),
         expect="argument --seed: must be an integer in [0, 4294967295], got 4294967296"),
]


@pytest.mark.parametrize("case", CASES, ids=[case.name for case in CASES])
def test_option_bound_case(case, tmp_path, capsys):
    run_case(case, tmp_path, capsys)
