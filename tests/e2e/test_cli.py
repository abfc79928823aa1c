"""The CLI as a user runs it: outputs, determinism and one-line errors with exit status 2."""
import hashlib
import json
import subprocess
import sys
from pathlib import Path

import matplotlib.image as mpimg
import pytest
from pxr import Usd, UsdGeom

CLI = [sys.executable, "-m", "indoorgen.cli"]
DIGESTS = Path(__file__).resolve().parents[1] / "data" / "scene_digests.json"


def run(*args, cwd=None):
    return subprocess.run(CLI + list(args), capture_output=True, text=True, cwd=cwd, timeout=300)


def test_generate_writes_every_output(tmp_path):
    out = tmp_path / "scene"
    r = run("generate", "--seed", "3", "--room", "dining_room", "--out", str(out))
    assert r.returncode == 0, r.stderr
    # the default formats: USD, URDF (per object + whole scene) and MJCF, with their meshes
    # and baked textures
    assert sorted(p.name for p in out.iterdir()) == [
        ".indoorgen-outputs.json", "meshes", "plan.png", "report.json", "scene.json",
        "scene.urdf", "scene.usdc", "scene.xml", "textures", "urdf"]
    scene = json.loads((out / "scene.json").read_text())
    report = json.loads((out / "report.json").read_text())
    assert len(scene["objects"]) == report["objects"] > 10
    # the layout-quality report: every rule with its counts, hard failures named
    quality = report["quality"]
    assert quality["passed"] == (not quality["failures"])
    assert {"room_has_light", "dining_chairs_face_table"} <= set(quality["rules"])
    assert "layout quality" in r.stdout
    assert {"large", "medium", "small"} == {s["stage"] for s in report["stages"]}
    for s in report["stages"]:
        assert s["steps"] > 0 and s["seconds"] > 0
    stage = Usd.Stage.Open(str(out / "scene.usdc"))
    assert UsdGeom.GetStageUpAxis(stage) == "Z"
    assert stage.GetDefaultPrim().GetPath() == "/World"
    for o in scene["objects"]:
        prim = stage.GetPrimAtPath(f"/World/Objects/{o['name']}")
        assert prim.IsValid(), o["name"]
        assert prim.GetAttribute("indoorgen:generator").Get() == o["generator"]
    img = mpimg.imread(out / "plan.png")
    assert img.shape[0] > 300 and (img[..., :3] < 0.9).any()
    v = run("validate", str(out))
    assert v.returncode == 0, v.stdout[-2000:]


@pytest.mark.slow
def test_default_command_writes_a_furnished_home(tmp_path):
    """What a user types first: a whole furnished home in ./scene_0, valid and deterministic."""
    r = run("generate", "--seed", "0", "-q", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    out = tmp_path / "scene_0"
    scene = json.loads((out / "scene.json").read_text())
    assert len(scene["rooms"]) >= 4 and len(scene["objects"]) >= 40
    assert scene["floorplan"]["storeys"][0]["rooms"]
    types = {r["type"] for r in scene["rooms"]}
    assert {"living_room", "bedroom", "bathroom"} <= types
    assert not [p for p in tmp_path.iterdir() if p.name.startswith(".")]
    # the very scene pinned for home seed 0 (test_pinned_scenes.py writes this key too)
    digest = hashlib.sha256((out / "scene.json").read_bytes()).hexdigest()
    assert digest == json.loads(DIGESTS.read_text())["home1/0"]
    v = run("validate", str(out))
    assert v.returncode == 0, v.stdout[-3000:]
    # and it stands still in MuJoCo: things on shelves, in cubbies and on tables stay put
    from indoorgen.export.stability import simulate, stability
    st = stability(simulate(out / "scene.xml"))
    assert st.free >= 40 and st.passes, st


def test_same_seed_same_scene_json_bytes(tmp_path):
    for d in ("a", "b"):
        assert run("generate", "--seed", "7", "--room", "bathroom", "-q", "--formats", "usd",
                   "--out", str(tmp_path / d)).returncode == 0
    assert (tmp_path / "a" / "scene.json").read_bytes() == (tmp_path / "b" / "scene.json").read_bytes()


BAD_PROGRAM = """
from indoorgen.constraints import Problem, scene
def bad_range(room):
    return Problem(constraints={{"x": scene().count().in_range(5, 2)}})
def bad_generator(room):
    return Problem(constraints={{"x": scene().of_generator("hovercraft").count() >= 1}})
def raises(room):
    return 1 / 0
def not_a_problem(room):
    return 42
def nan_bound(room):
    return Problem(constraints={{"x": scene().count().in_range(float("nan"), 2)}})
"""


@pytest.mark.parametrize("args, words", [
    (["--room", "ballroom"], "unknown room type 'ballroom'"),
    (["--room", "bedroom", "--floors", "2"], "give options of one kind only"),
    (["--floors", "0"], "floors"),
    (["--rooms", "bedroom=2,ballroom=1"], "ballroom"),
    (["--doors", "ajar"], "doors 'ajar' is not a door state; valid: open, closed, random"),
    (["--room", "bedroom", "--doors", "open"], "give options of one kind only"),
    (["--floorplan", "{prog}"], "is not readable JSON"),
    (["--polygon", "[[0,0],[1,1],[2,2]]"], "area"),
    (["--polygon", "[[0,0],[5,0],[5,NaN],[0,4]]"], "finite number"),
    (["--polygon", "[[0,0],[1e6,0],[1e6,1e6],[0,1e6]]"], "less than or equal to 1000"),
    (["--polygon", "[[0,0],[100,0],[100,100],[0,100]]"], "between 2 and 30 m"),
    (["--polygon", "[" * 50_000 + "]" * 50_000], "nests brackets 50000 deep"),
    (["--area", "1e9"], "at most 2000 m^2"),
    (["--size", "100", "4"], "between 2 and 30 m"),
    (["--program", "{prog}:raises"], "raised ZeroDivisionError: division by zero"),
    (["--program", "{prog}:not_a_problem"], "must return a Problem"),
    (["--program", "{prog}:bad_range"], "in_range(5, 2)"),
    (["--program", "{prog}:bad_generator"], "prog.py:bad_generator': unknown generator 'hovercraft'"),
    (["--program", "{prog}:nan_bound"], "in_range's lower bound must be a finite number, got nan"),
    (["--seed", str(2**63)], "--seed must be an integer from 0 to"),
    (["--out", "/proc/indoorgen_cannot_write_here"], "cannot write"),
    (["--preset", "turbo"], "unknown preset 'turbo'; valid: fast, default, dense"),
])
def test_bad_input_one_line_exit_2_no_output(tmp_path, args, words):
    prog = tmp_path / "prog.py"
    prog.write_text(BAD_PROGRAM.format())
    args = [a.replace("{prog}", str(prog)) for a in args]
    if "--out" not in args:
        args += ["--out", str(tmp_path / "out")]
    r = run("generate", "--seed", "0", *args)
    assert r.returncode == 2
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1, r.stderr
    assert words in lines[0]
    assert not (tmp_path / "out").exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["prog.py"]


def test_debug_shows_the_traceback(tmp_path):
    prog = tmp_path / "prog.py"
    prog.write_text(BAD_PROGRAM.format())
    r = run("--debug", "generate", "--program", f"{prog}:raises", "--out", str(tmp_path / "o"))
    assert r.returncode != 0 and "Traceback" in r.stderr and "ZeroDivisionError" in r.stderr


def test_asset_refuses_a_negative_texture_resolution(tmp_path):
    r = run("asset", "sofa", "--out", str(tmp_path / "s.glb"), "--texture-resolution", "-5")
    assert r.returncode == 2 and "--texture-resolution -5 is invalid" in r.stderr, r.stderr
    assert list(tmp_path.iterdir()) == []


def test_generate_never_replaces_the_users_files(tmp_path):
    """A directory holding the user's own scene.json is refused before any work, in one line;
    a scene directory the user added notes to keeps them when regenerated."""
    mine = tmp_path / "mine"
    mine.mkdir()
    (mine / "scene.json").write_text("the user's")
    r = run("generate", "--seed", "0", "--room", "bedroom", "--out", str(mine))
    assert r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1, r.stderr
    assert "indoorgen did not write" in r.stderr
    assert (mine / "scene.json").read_text() == "the user's"
    out = tmp_path / "scene"
    args = ("generate", "--seed", "0", "--room", "bedroom", "--preset", "fast", "-q", "--formats", "mjcf",
            "--out", str(out))
    assert run(*args).returncode == 0
    (out / "notes.txt").write_text("mine")
    assert run(*args).returncode == 0
    assert (out / "notes.txt").read_text() == "mine"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["mine", "scene"]
    photos = tmp_path / "photos"  # not indoorgen's: refused, then written beside with --overwrite
    photos.mkdir()
    (photos / "cat.jpg").write_text("the user's")
    args = args[:-1] + (str(photos),)
    r = run(*args)
    assert r.returncode == 2 and "--overwrite" in r.stderr, r.stderr
    assert run(*args, "--overwrite").returncode == 0
    assert (photos / "cat.jpg").read_text() == "the user's" and (photos / "scene.json").exists()


def test_nav_image_and_navigation_report(tmp_path):
    """--nav-image adds a picture per storey; report.json says what a robot can reach."""
    out = tmp_path / "scene"
    r = run("generate", "--seed", "2", "--room", "bedroom", "--nav-image", "--formats", "mjcf",
            "--out", str(out))
    assert r.returncode == 0, r.stderr
    assert (out / "nav_0.png").is_file()
    report = json.loads((out / "report.json").read_text())
    nav = report["navigation"]
    assert 0.0 < nav["reachable_share"] <= 1.0
    assert nav["passed"] == (not nav["unreachable_rooms"] and not nav["unreachable_doors"])
    assert "navigation" in r.stdout
    # the scene's status: failed with its reasons, or ok; printed as one line
    assert report["status"]["failed"] == bool(report["status"]["reasons"])
    assert ("status FAILED" if report["status"]["failed"] else "status ok") in r.stdout
