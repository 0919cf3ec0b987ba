"""The counts of docs/results/reproduce.md agree with ``fuzzynav reproduce --list`` and with the
per-seed verdicts of docs/results/claims-mutations.md."""

import re
from pathlib import Path

from fuzzynav.catalog import experiments as registry

RESULTS = Path(__file__).resolve().parents[2] / "docs" / "results"


def text(name: str) -> str:
    return " ".join((RESULTS / name).read_text(encoding="utf-8").split())


def test_the_run_counts_every_experiment_and_the_chapters_iv_and_v_ids():
    page, ids = text("reproduce.md"), list(registry.available())
    assert f"for the {len(ids)} experiments" in page
    reproduced, partly = map(int, re.search(r"(\d+) of \d+ `reproduced`, (\d+) `partly`", page).groups())
    assert f"{reproduced} of {len(ids)} `reproduced`" in page and reproduced + partly == len(ids)
    chapters_iv_v = [key for key in ids if key.split("-")[1] in ("IV", "V")]
    assert f"chapters IV and V ({len(chapters_iv_v)} ids: {chapters_iv_v[0]} … " in page


def test_the_seeds_0_to_4_count_is_the_claims_pages_experiments():
    claims = text("claims-mutations.md")
    command = re.search(r"for S in 0 1 2 3 4; do nice -n 10 fuzzynav reproduce (.*?) --seed", claims).group(1)
    ran = command.replace("\\ ", "").split()
    ids = list(registry.available())
    assert set(ran) == {key for key in ids if key.split("-")[1] in ("IV", "V")} | {"fig-VI-28"}
    assert f"{5 * len(ran)} of {5 * len(ran)} ({len(ran)} experiments × 5 seeds" in claims
    page = text("reproduce.md")
    counted = int(re.search(r"all (\d+) reproduced on seeds 0–4", page).group(1))
    assert counted == len(ran)
    assert f"the {len(ran) - 1} ids of chapters IV and V with fig-VI-28" in page
