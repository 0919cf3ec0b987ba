"""A trained anfis-tracker model file (JSON or NPZ) reads as a fuzzy system: fis show / eval / convert."""

import json

import numpy as np
import pytest

from fuzzynav.cli import main
from fuzzynav.learn.anfis import ANFIS
from fuzzynav.learn.tasks.trackers import default_document
from fuzzynav.storage import save_document


@pytest.mark.parametrize("suffix", [".json", ".npz"])
def test_fis_reads_the_trained_anfis_as_its_exported_system(tmp_path, capsys, suffix):
    document = default_document("anfis-tracker")
    path = tmp_path / f"anfis{suffix}"
    save_document(path, document)
    anfis = ANFIS.from_dict(document["model"])
    for theta in (-0.15, -0.02, 0.0, 0.07, 0.18):
        assert main(["fis", "eval", str(path), "--input", f"theta_er={theta}"]) == 0
        alpha = json.loads(capsys.readouterr().out)["alpha"]
        np.testing.assert_allclose(alpha, anfis.predict(np.array([[theta]]))[0], atol=1e-12)
    assert main(["fis", "convert", str(path), "--to", "fll", "-o", str(tmp_path / "anfis.fll")]) == 0
    assert "InputVariable: theta_er" in (tmp_path / "anfis.fll").read_text()
    assert main(["fis", "show", str(path)]) == 0
    assert "ts1" in capsys.readouterr().out
