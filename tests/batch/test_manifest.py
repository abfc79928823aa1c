"""The batch directory's files: a manifest a crash cut mid-line, the seeds still to run, and the
leftovers of killed attempts (only those of dead processes) cleaned."""
from __future__ import annotations

import json
import os
import subprocess
import sys

from indoorgen.batch.manifest import Manifest, clean_leftovers, read_manifest, seeds_to_run


def test_a_line_cut_by_a_crash_is_dropped_and_the_next_record_starts_clean(tmp_path):
    (tmp_path / "manifest.jsonl").write_text('{"seed": 1, "status": "ok"}\n{"seed": 2, "sta')
    assert [r["seed"] for r in read_manifest(tmp_path)] == [1]
    with Manifest(tmp_path) as m:
        m.append({"seed": 3, "status": "failed"})
    lines = (tmp_path / "manifest.jsonl").read_text().splitlines()
    assert [json.loads(line)["seed"] for line in lines] == [1, 3]


def test_seeds_to_run(tmp_path):
    (tmp_path / "scenes" / "1").mkdir(parents=True)
    with Manifest(tmp_path) as m:
        for seed, status in [(1, "ok"), (2, "ok"), (3, "failed"), (4, "timeout"), (5, "failed"),
                             (5, "ok")]:
            m.append({"seed": seed, "status": status})
    (tmp_path / "scenes" / "5").mkdir()
    # 2's scene went missing: it is made again; 3 and 4 only when failures are retried
    assert seeds_to_run(range(7), tmp_path, retry_failed=False) == [0, 2, 6]
    assert seeds_to_run(range(7), tmp_path, retry_failed=True) == [0, 2, 3, 4, 6]


def test_only_the_leftovers_of_dead_processes_are_cleaned(tmp_path):
    dead = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"],
                          capture_output=True, text=True).stdout.strip()
    scenes = tmp_path / "scenes"
    for name in [f".4.tmp-{dead}-abc", f".5.old-{dead}", f".6.tmp-{os.getpid()}-x", "7"]:
        (scenes / name).mkdir(parents=True)
    (scenes / ".4.lock").write_text("")
    (scenes / "notes.txt").write_text("mine")
    assert sorted(clean_leftovers(tmp_path)) == [".4.lock", f".4.tmp-{dead}-abc", f".5.old-{dead}"]
    assert sorted(p.name for p in scenes.iterdir()) == [f".6.tmp-{os.getpid()}-x", "7", "notes.txt"]
