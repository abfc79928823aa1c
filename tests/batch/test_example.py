"""examples/make_dataset.py runs as its docstring says, on a Dask LocalCluster."""
from __future__ import annotations

import runpy
import sys
from pathlib import Path

import pytest

from indoorgen.batch.manifest import read_manifest

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "make_dataset.py"

pytestmark = pytest.mark.xdist_group("batch")


def test_the_make_dataset_example_on_a_local_cluster(tmp_path, monkeypatch, capsys):
    pytest.importorskip("distributed", reason="the dask extra is not installed")
    monkeypatch.setattr(sys, "argv", [str(EXAMPLE), "--out", str(tmp_path / "data"), "--count",
                                      "1", "--room", "hallway", "--formats", "mjcf",
                                      "--dask-local", "1"])
    runpy.run_path(str(EXAMPLE), run_name="__main__")
    assert "1 of 1 scenes made" in capsys.readouterr().out
    (rec,) = read_manifest(tmp_path / "data")
    assert rec["status"] == "ok" and (tmp_path / "data" / "scenes" / "0" / "scene.xml").is_file()
