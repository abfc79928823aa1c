"""The asset catalogue commands as a user runs them."""
import json
import subprocess
import sys

import matplotlib.image as mpimg

CLI = [sys.executable, "-m", "indoorgen.cli"]


def run(*args):
    return subprocess.run(CLI + list(args), capture_output=True, text=True, timeout=600)


def test_assets_list_json_describes_every_generator():
    r = run("assets", "list", "--json")
    assert r.returncode == 0, r.stderr
    rows = json.loads(r.stdout)
    names = {row["name"] for row in rows}
    assert {"dining_chair", "sofa", "tv_stand", "bookcase"} <= names
    for row in rows:
        assert set(row) >= {"name", "tags", "n_params", "joints"}
        assert row["n_params"] >= 6 and "object" in row["tags"]
    stand = next(row for row in rows if row["name"] == "tv_stand")
    assert {"door_joint", "drawer_joint"} <= set(stand["joints"])


def test_assets_sheet_draws_a_picture(tmp_path):
    out = tmp_path / "sheet.png"
    r = run("assets", "sheet", "--only", "dining_chair", "tv_stand", "cup", "--cols", "3",
            "--out", str(out))
    assert r.returncode == 0, r.stderr
    img = mpimg.imread(out)
    assert img.shape[0] >= 150 and img.shape[1] >= 450
    # the drawings are there: plenty of pixels are neither white nor transparent
    ink = (img[..., :3].mean(axis=2) < 0.8).mean()
    assert ink > 0.02
    assert [p.name for p in tmp_path.iterdir()] == ["sheet.png"]


def test_assets_sheet_unknown_name_one_line_exit_2(tmp_path):
    r = run("assets", "sheet", "--only", "hovercraft", "--out", str(tmp_path / "s.png"))
    assert r.returncode == 2
    assert len(r.stderr.strip().splitlines()) == 1 and "hovercraft" in r.stderr
    assert not list(tmp_path.iterdir())
