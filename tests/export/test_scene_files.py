"""Saved scenes re-exported without solving: same objects and materials, atomic, and bad input
reported in one line."""
from __future__ import annotations

import json

import pytest

from indoorgen.architecture.solidify import room_geometries, solidify
from indoorgen.errors import ConfigError
from indoorgen.export import formats, write_formats
from indoorgen.export.bundle import bundle_from_scene
from indoorgen.export.scene_files import SceneFileError, export_scene, read_scene
from indoorgen.model.floorplan_io import from_json, to_json
from indoorgen.model.scene import Scene
from indoorgen.outputs import RECORD
from support.cli import run
from support.plans import apartment
from support.scenefiles import minimal_scene


def test_export_reexports_a_saved_scene(exported, tmp_path):
    bundle, d, _ = exported["dining_room"]
    src = tmp_path / "src"
    src.mkdir()
    (src / "scene.json").write_text(bundle.scene.dumps())
    out, timings = export_scene(src / "scene.json", tmp_path / "again", "mjcf,glb",
                                texture_resolution=32)
    assert sorted(p.name for p in out.iterdir()) == [RECORD, "meshes", "scene.glb", "scene.json",
                                                     "scene.xml", "textures"]
    # same objects, same materials (deterministic from each object's seed)
    text = (out / "scene.xml").read_text()
    for o in bundle.objects:
        assert f'name="{o.name}"' in text
    again = bundle_from_scene(Scene.from_json(json.loads((out / "scene.json").read_text())))
    assert again.materials == bundle.materials
    assert {"assets", "mjcf", "glb"} <= set(timings)


def test_export_into_the_scene_directory_keeps_what_is_there(exported, tmp_path):
    """Exporting one more format beside a scene keeps its other formats and the user's files."""
    bundle, _, _ = exported["dining_room"]
    d = tmp_path / "scene"
    export_scene_dir = export_scene(_saved(bundle, tmp_path), d, "mjcf", texture_resolution=16)[0]
    (d / "notes.txt").write_text("mine")
    export_scene(d, None, "glb", texture_resolution=16)
    names = {p.name for p in export_scene_dir.iterdir()}
    assert {"scene.xml", "scene.glb", "scene.json", "notes.txt", "meshes"} <= names
    assert (d / "notes.txt").read_text() == "mine"


def _saved(bundle, tmp_path):
    src = tmp_path / "saved"
    src.mkdir()
    (src / "scene.json").write_text(bundle.scene.dumps())
    return src / "scene.json"


def test_export_is_atomic(exported, tmp_path, monkeypatch):
    bundle, _, _ = exported["dining_room"]
    (tmp_path / "scene.json").write_text(bundle.scene.dumps())
    def boom(*a, **k):
        raise KeyboardInterrupt

    monkeypatch.setattr("indoorgen.export.formats.write_mjcf", boom)
    with pytest.raises(KeyboardInterrupt):
        export_scene(tmp_path / "scene.json", tmp_path / "out", "usd,mjcf", texture_resolution=16)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["scene.json"]
    assert formats.write_formats is write_formats


def test_read_scene_finds_scene_json_in_a_directory(tmp_path):
    (tmp_path / "scene.json").write_text(json.dumps(minimal_scene(seed=4)))
    scene, path = read_scene(tmp_path)
    assert scene.seed == 4 and path == tmp_path / "scene.json"
    with pytest.raises(SceneFileError, match="does not exist"):
        read_scene(tmp_path / "nowhere")
    (tmp_path / "bad.json").write_text("{not json")
    with pytest.raises(SceneFileError, match="not readable JSON"):
        read_scene(tmp_path / "bad.json")


@pytest.mark.parametrize("args, needle", [
    (["export", "missing/scene.json"], "does not exist"),
    (["export", "bad.json"], "not readable JSON"),
    (["export", "scene.json", "--formats", "usd,fbx"], "fbx"),
    (["export", "scene.json", "--out", "afile"], "afile"),
    (["generate", "--formats", "usd,stl", "--out", "x"], "stl"),
])
def test_bad_input_one_line_exit_2(tmp_path, args, needle):
    (tmp_path / "bad.json").write_text("{not json")
    (tmp_path / "scene.json").write_text(json.dumps(minimal_scene()))
    (tmp_path / "afile").write_text("x")
    r = run(*args, cwd=tmp_path)
    assert r.returncode == 2, r.stderr
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and needle in lines[0], r.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["afile", "bad.json", "scene.json"]


def test_export_restands_a_homes_doors(tmp_path):
    """`--doors` on re-export: the leaves stand as asked in the files, scene.json records the
    new states, and a single room (whose door has no leaf) is refused."""
    plan = from_json(apartment())
    rooms = {n: g.room for n, g in room_geometries(solidify(plan, seed=5)).items()}
    scene = Scene(seed=5, config={"home": True, "doors": "open"}, rooms=rooms,
                  floorplan=to_json(plan),
                  doors={"d0": 1.570796, "d1": 1.570796, "d2": 1.570796, "entrance": 1.570796})
    (tmp_path / "scene.json").write_text(scene.dumps())
    (tmp_path / "report.json").write_text("{}")
    out, _ = export_scene(tmp_path, tmp_path / "shut", "mjcf", texture_resolution=0,
                          doors="closed")
    saved = json.loads((out / "scene.json").read_text())
    assert saved["config"]["doors"] == "closed"
    assert saved["doors"] == {"d0": 0.0, "d1": 0.0, "d2": 0.0, "entrance": 0.0}
    assert not (out / "report.json").exists()  # its navigation measured the open doors
    text = (out / "scene.xml").read_text()
    assert text.count('name="d0__leaf_joint"') == 1 and 'ref="0"' in text
    # without --doors the recorded states are kept
    out2, _ = export_scene(tmp_path, tmp_path / "kept", "mjcf", texture_resolution=0)
    assert (out2 / "scene.json").read_bytes() == (tmp_path / "scene.json").read_bytes()
    assert 'ref="1.5708"' in (out2 / "scene.xml").read_text()
    (tmp_path / "room").mkdir()
    (tmp_path / "room" / "scene.json").write_text(json.dumps(minimal_scene()))
    with pytest.raises(ConfigError, match="single room"):
        export_scene(tmp_path / "room", None, "mjcf", doors="open")
    with pytest.raises(ConfigError, match="'ajar'"):
        export_scene(tmp_path, None, "mjcf", doors="ajar")
