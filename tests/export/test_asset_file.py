"""One asset written to a textured file (`indoorgen asset`), and bad input reported in one line."""
from __future__ import annotations

import pytest
import trimesh
from pxr import Usd

from support.cli import run


@pytest.mark.parametrize("args, needle", [
    (["asset", "hovercraft", "--out", "a.glb"], "hovercraft"),
    (["asset", "cabinet", "--param", "legs=9", "--out", "a.glb"], "legs"),
    (["asset", "cabinet", "--param", "height=99", "--out", "a.glb"], "height"),
    (["asset", "cabinet", "--out", "a.fbx"], "a.fbx"),
])
def test_bad_input_one_line_exit_2(tmp_path, args, needle):
    r = run(*args, cwd=tmp_path)
    assert r.returncode == 2, r.stderr
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and needle in lines[0], r.stderr
    assert list(tmp_path.iterdir()) == []


def test_asset_command_writes_textured_files(tmp_path):
    r = run("asset", "cabinet", "--seed", "3", "--param", "n_doors=2", "--out",
            str(tmp_path / "cab.glb"), "--texture-resolution", "64")
    assert r.returncode == 0, r.stderr
    s = trimesh.load(tmp_path / "cab.glb")
    assert all(g.visual.material.baseColorTexture is not None for g in s.geometry.values())
    r = run("asset", "cabinet", "--seed", "3", "--out", str(tmp_path / "cab.usda"),
            "--texture-resolution", "64")
    assert r.returncode == 0, r.stderr
    stage = Usd.Stage.Open(str(tmp_path / "cab.usda"))
    files = [p.GetAttribute("inputs:file").Get() for p in stage.Traverse()
             if p.GetAttribute("inputs:file")]
    assert files and all(f.resolvedPath for f in files)
