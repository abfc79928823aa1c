"""`indoorgen floorplan` as a user runs it: outputs, determinism, one-line errors (exit 2)."""
from __future__ import annotations

import json
import subprocess
import sys

import matplotlib.image as mpimg
import pytest
from pxr import Usd, UsdGeom

from support.plans import APARTMENT_PATH

CLI = [sys.executable, "-m", "indoorgen.cli", "floorplan"]


def run(*args, cwd=None):
    return subprocess.run(CLI + list(args), capture_output=True, text=True, cwd=cwd, timeout=600)


def test_floorplan_writes_every_output(tmp_path):
    out = tmp_path / "home"
    r = run("--seed", "4", "--floors", "2", "--rooms", "bedroom=3,bathroom=2", "--steps", "60",
            "--out", str(out))
    assert r.returncode == 0, r.stderr
    assert "objective" in r.stdout
    assert sorted(p.name for p in out.iterdir()) == [".indoorgen-outputs.json", "architecture.usda",
                                                     "floorplan.json", "plan.png"]
    plan = json.loads((out / "floorplan.json").read_text())
    assert len(plan["storeys"]) == 2 and len(plan["stairs"]) == 1
    types = [r["type"] for s in plan["storeys"] for r in s["rooms"]]
    assert types.count("bedroom") == 3 and types.count("bathroom") == 2
    stage = Usd.Stage.Open(str(out / "architecture.usda"))
    assert UsdGeom.GetStageUpAxis(stage) == "Z"
    assert stage.GetDefaultPrim().GetPath() == "/World"
    assert stage.GetPrimAtPath("/World/Architecture/storey_1").IsValid()
    img = mpimg.imread(out / "plan.png")
    assert img.shape[0] > 300 and (img[..., :3] < 0.5).any()
    assert not [p for p in tmp_path.iterdir() if p.name.startswith(".")]


def test_same_seed_same_floorplan_json(tmp_path):
    for d in ("a", "b"):
        r = run("--seed", "11", "--steps", "40", "-q", "--out", str(tmp_path / d))
        assert r.returncode == 0, r.stderr
    assert (tmp_path / "a" / "floorplan.json").read_bytes() == \
        (tmp_path / "b" / "floorplan.json").read_bytes()


def test_predefined_plan_and_contour(tmp_path):
    src = APARTMENT_PATH
    r = run("--plan", str(src), "--out", str(tmp_path / "apt"))
    assert r.returncode == 0, r.stderr
    assert json.loads((tmp_path / "apt" / "floorplan.json").read_text())["storeys"][0]["rooms"]
    contour = tmp_path / "contour.json"
    contour.write_text(json.dumps([[0, 0], [12, 0], [12, 6], [7, 6], [7, 10], [0, 10]]))
    r = run("--seed", "2", "--contour", str(contour), "--steps", "40", "--out",
            str(tmp_path / "c"))
    assert r.returncode == 0, r.stderr


BAD = [
    (["--floors", "0"], "--floors 0"),
    (["--floors", "4"], "--floors 4"),
    (["--rooms", "bedroom=2,ballroom=1"], "ballroom"),
    (["--rooms", "bedroom=8,bathroom=4", "--area", "45"], "area"),
    (["--area", "-5"], "--area"),
    (["--seed", "-1"], "--seed"),
    (["--contour", "SELF_INTERSECTING"], "self-intersecting"),
    (["--contour", "MISSING"], "does not exist"),
]


@pytest.mark.parametrize("args, needle", BAD)
def test_bad_input_is_one_line_exit_2_and_no_output(tmp_path, args, needle):
    bad = tmp_path / "bow.json"
    bad.write_text(json.dumps([[0, 0], [10, 10], [10, 0], [0, 10]]))
    args = [str(bad) if a == "SELF_INTERSECTING" else
            str(tmp_path / "nope.json") if a == "MISSING" else a for a in args]
    out = tmp_path / "out"
    r = run(*args, "--out", str(out))
    assert r.returncode == 2, r.stderr
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("indoorgen: error:"), r.stderr
    assert needle in lines[0]
    assert "Traceback" not in r.stderr
    assert not out.exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bow.json"]
