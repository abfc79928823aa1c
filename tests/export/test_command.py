"""`indoorgen export`, `indoorgen asset` and `--formats` as a user runs them."""
from __future__ import annotations

import json
import subprocess
import sys

import pytest
import trimesh

from indoorgen.errors import IndoorGenError
from indoorgen.export import parse_formats, write_formats
from indoorgen.export.scene_files import export_scene

CLI = [sys.executable, "-m", "indoorgen.cli"]


def run(*args, cwd=None):
    return subprocess.run(CLI + list(args), capture_output=True, text=True, cwd=cwd, timeout=600)


def test_parse_formats():
    assert parse_formats(None) == ["usd", "urdf", "mjcf"]
    assert parse_formats("glTF, usd,usd") == ["glb", "usd"]
    with pytest.raises(IndoorGenError, match="'fbx'.*valid: usd"):
        parse_formats("usd,fbx")


def test_export_reexports_a_saved_scene(exported, tmp_path):
    bundle, d, _ = exported["dining_room"]
    src = tmp_path / "src"
    src.mkdir()
    (src / "scene.json").write_text(bundle.scene.dumps())
    out, timings = export_scene(src / "scene.json", tmp_path / "again", "mjcf,glb",
                                texture_resolution=32)
    assert sorted(p.name for p in out.iterdir()) == ["meshes", "scene.glb", "scene.json",
                                                     "scene.xml", "textures"]
    # same objects, same materials (deterministic from each object's seed)
    text = (out / "scene.xml").read_text()
    for o in bundle.objects:
        assert f'name="{o.name}"' in text
    from indoorgen.export.bundle import bundle_from_scene
    from indoorgen.model.scene import Scene
    again = bundle_from_scene(Scene.from_json(json.loads((out / "scene.json").read_text())))
    assert again.materials == bundle.materials
    assert {"assets", "mjcf", "glb"} <= set(timings)


def test_export_is_atomic(exported, tmp_path, monkeypatch):
    bundle, _, _ = exported["dining_room"]
    (tmp_path / "scene.json").write_text(bundle.scene.dumps())
    import indoorgen.export.formats as formats

    def boom(*a, **k):
        raise KeyboardInterrupt

    monkeypatch.setattr("indoorgen.export.mjcf.write_mjcf", boom)
    with pytest.raises(KeyboardInterrupt):
        export_scene(tmp_path / "scene.json", tmp_path / "out", "usd,mjcf", texture_resolution=16)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["scene.json"]
    assert formats.write_formats is write_formats


@pytest.mark.parametrize("args, needle", [
    (["export", "missing/scene.json"], "does not exist"),
    (["export", "bad.json"], "corrupt"),
    (["export", "scene.json", "--formats", "usd,fbx"], "fbx"),
    (["export", "scene.json", "--out", "afile"], "afile"),
    (["asset", "hovercraft", "--out", "a.glb"], "hovercraft"),
    (["asset", "cabinet", "--param", "legs=9", "--out", "a.glb"], "legs"),
    (["asset", "cabinet", "--param", "height=99", "--out", "a.glb"], "height"),
    (["asset", "cabinet", "--out", "a.fbx"], "a.fbx"),
    (["generate", "--formats", "usd,stl", "--out", "x"], "stl"),
])
def test_bad_input_one_line_exit_2(tmp_path, args, needle):
    (tmp_path / "bad.json").write_text("{not json")
    (tmp_path / "scene.json").write_text(json.dumps({"seed": 0, "rooms": [], "objects": []}))
    (tmp_path / "afile").write_text("x")
    r = run(*args, cwd=tmp_path)
    assert r.returncode == 2, r.stderr
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and needle in lines[0], r.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["afile", "bad.json", "scene.json"]


def test_asset_command_writes_textured_files(tmp_path):
    r = run("asset", "cabinet", "--seed", "3", "--param", "n_doors=2", "--out",
            str(tmp_path / "cab.glb"), "--texture-resolution", "64")
    assert r.returncode == 0, r.stderr
    s = trimesh.load(tmp_path / "cab.glb")
    assert all(g.visual.material.baseColorTexture is not None for g in s.geometry.values())
    r = run("asset", "cabinet", "--seed", "3", "--out", str(tmp_path / "cab.usda"),
            "--texture-resolution", "64")
    assert r.returncode == 0, r.stderr
    from pxr import Usd
    stage = Usd.Stage.Open(str(tmp_path / "cab.usda"))
    files = [p.GetAttribute("inputs:file").Get() for p in stage.Traverse()
             if p.GetAttribute("inputs:file")]
    assert files and all(f.resolvedPath for f in files)
