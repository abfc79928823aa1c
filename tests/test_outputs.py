"""Atomic outputs that never replace or delete a file indoorgen did not write."""
import os
import subprocess
import sys
from pathlib import Path

import pytest

from indoorgen.errors import OutputError
from indoorgen.outputs import (
    PROBE_PREFIX,
    RECORD,
    atomic_dir,
    check_writable,
    clean_stale,
    output_lock,
    written_by_indoorgen,
)


def _write(out, files, **kw):
    with atomic_dir(out, **kw) as tmp:
        for name, text in files.items():
            (tmp / name).write_text(text)


def test_new_directory_gets_the_files_and_a_record(tmp_path):
    out = tmp_path / "scene"
    _write(out, {"scene.json": "{}", "plan.png": "x"})
    assert sorted(p.name for p in out.iterdir()) == [RECORD, "plan.png", "scene.json"]
    assert written_by_indoorgen(out) == {"plan.png", "scene.json"}


def test_rewrite_keeps_the_users_files_and_drops_only_stale_outputs(tmp_path):
    out = tmp_path / "scene"
    _write(out, {"scene.json": "1", "scene.glb": "old format"})
    (out / "notes.txt").write_text("mine")
    (out / "mine").mkdir()
    (out / "mine" / "a.txt").write_text("mine too")
    _write(out, {"scene.json": "2"})
    assert (out / "scene.json").read_text() == "2"
    assert (out / "notes.txt").read_text() == "mine"
    assert (out / "mine" / "a.txt").read_text() == "mine too"
    assert not (out / "scene.glb").exists()  # indoorgen's own output of the earlier run
    assert written_by_indoorgen(out) == {"scene.json"}
    assert not [p for p in tmp_path.iterdir() if p.name.startswith(".")]


def test_merge_keeps_earlier_outputs(tmp_path):
    out = tmp_path / "scene"
    _write(out, {"scene.json": "1", "scene.xml": "mjcf"})
    _write(out, {"scene.glb": "glb"}, merge=True)
    assert {p.name for p in out.iterdir()} == {RECORD, "scene.json", "scene.xml", "scene.glb"}
    assert written_by_indoorgen(out) == {"scene.json", "scene.xml", "scene.glb"}


def test_a_foreign_directory_with_scene_files_is_refused_before_any_work(tmp_path):
    out = tmp_path / "mine"
    out.mkdir()
    (out / "scene.json").write_text("the user's")
    with pytest.raises(OutputError, match="scene.json, which indoorgen did not write"), \
            atomic_dir(out) as _:
        pytest.fail("the body must not run")
    assert (out / "scene.json").read_text() == "the user's"


def test_a_clash_found_at_the_end_changes_nothing(tmp_path):
    out = tmp_path / "mine"
    out.mkdir()
    (out / "scene.usdc").write_text("the user's")
    with pytest.raises(OutputError, match="scene.usdc"):
        _write(out, {"scene.usdc": "ours", "scene.json": "{}"}, overwrite=True)
    assert [p.name for p in out.iterdir()] == ["scene.usdc"]
    assert (out / "scene.usdc").read_text() == "the user's"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["mine"]


def test_an_error_inside_leaves_the_old_directory(tmp_path):
    out = tmp_path / "scene"
    _write(out, {"scene.json": "1"})
    with pytest.raises(RuntimeError), atomic_dir(out) as tmp:
        (tmp / "scene.json").write_text("2")
        raise RuntimeError("solver died")
    assert (out / "scene.json").read_text() == "1"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["scene"]


def _dead_pid() -> int:
    p = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"],
                       capture_output=True, text=True, check=True)
    return int(p.stdout)


def test_leftovers_of_a_killed_run_are_cleaned_and_user_files_restored(tmp_path):
    out = tmp_path / "scene"
    _write(out, {"scene.json": "new"})
    pid = _dead_pid()
    tmp = tmp_path / f".scene.tmp-{pid}-abc"
    tmp.mkdir()
    (tmp / "scene.json").write_text("half")
    old = tmp_path / f".scene.old-{pid}"
    old.mkdir()
    (old / "scene.json").write_text("old")
    (old / "notes.txt").write_text("mine")
    (old / RECORD).write_text('{"entries": ["scene.json"]}')
    live = tmp_path / f".scene.tmp-{os.getpid()}-xyz"  # this process: still running
    live.mkdir()
    clean_stale(out)
    assert not tmp.exists() and not old.exists() and live.exists()
    assert (out / "notes.txt").read_text() == "mine"
    assert (out / "scene.json").read_text() == "new"


def test_a_killed_runs_writability_probe_is_removed_and_a_running_ones_kept(tmp_path):
    """A batch killed with SIGKILL between making and removing its probe left it among the
    scenes; the next run beside it removes it, never another run's or a non-empty one."""
    out = tmp_path / "scene"
    dead = tmp_path / f"{PROBE_PREFIX}{_dead_pid()}-abc"
    live = tmp_path / f"{PROBE_PREFIX}{os.getpid()}-xyz"
    full = tmp_path / f"{PROBE_PREFIX}{_dead_pid()}-def"
    for d in (dead, live, full):
        d.mkdir()
    (full / "notes.txt").write_text("not a probe's")
    _write(out, {"scene.json": "new"})
    assert not dead.exists() and live.exists() and (full / "notes.txt").exists()


@pytest.mark.parametrize("name", [".", "..", ""])
def test_the_current_directory_is_never_replaced(tmp_path, monkeypatch, name):
    (tmp_path / "work").mkdir()
    monkeypatch.chdir(tmp_path / "work")
    with pytest.raises(OutputError, match="current directory"):
        _write(Path(name), {"scene.json": "{}"})
    assert os.listdir(tmp_path / "work") == []


def test_a_non_empty_directory_not_indoorgens_needs_overwrite(tmp_path):
    out = tmp_path / "photos"
    out.mkdir()
    (out / "cat.jpg").write_text("the user's")
    with pytest.raises(OutputError, match="--overwrite"), atomic_dir(out) as _:
        pytest.fail("the body must not run")
    with pytest.raises(OutputError, match="--overwrite"):
        check_writable(out, replacing=False)
    _write(out, {"scene.json": "{}"}, overwrite=True)  # beside the user's file, never over it
    assert (out / "cat.jpg").read_text() == "the user's"
    assert written_by_indoorgen(out) == {"scene.json"}
    _write(out, {"scene.json": "2"})  # now indoorgen's: rewritten without --overwrite
    assert (out / "cat.jpg").read_text() == "the user's"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["photos"]


def test_an_empty_directory_is_written_without_overwrite(tmp_path):
    out = tmp_path / "empty"
    out.mkdir()
    _write(out, {"scene.json": "{}"})
    assert written_by_indoorgen(out) == {"scene.json"}


def test_the_lock_excludes_a_second_writer_and_goes_away(tmp_path):
    out = tmp_path / "scene"
    with output_lock(out):
        assert (tmp_path / ".scene.lock").exists()
        with pytest.raises(OutputError, match="another indoorgen run is writing"):
            check_writable(out)
        with pytest.raises(OutputError, match="another indoorgen run is writing"):
            _write(out, {"scene.json": "{}"})
    assert not out.exists()
    _write(out, {"scene.json": "{}"})
    assert sorted(p.name for p in tmp_path.iterdir()) == ["scene"]


def test_a_lock_left_by_a_killed_run_does_not_block(tmp_path):
    (tmp_path / ".scene.lock").write_text("")  # a file nobody holds a lock on
    _write(tmp_path / "scene", {"scene.json": "{}"})
    assert sorted(p.name for p in tmp_path.iterdir()) == ["scene"]
