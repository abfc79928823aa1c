"""The batch's supervision as a user meets it: a batch killed with SIGKILL in the middle and
resumed ends with every seed done once and nothing half-written; a scene over its time or
memory limit is killed and recorded, and the batch goes on."""
from __future__ import annotations

import json
import os
import signal
import subprocess
import time
from collections import Counter

import pytest

from indoorgen.batch.dataset import make_dataset
from indoorgen.batch.manifest import read_manifest
from indoorgen.cli.batch import generate_options
from indoorgen.cli.generate import run_generate
from support.batch import GENERATE, batch, record_blas_threads
from support.cli import CLI

pytestmark = pytest.mark.xdist_group("batch")


def test_a_batch_killed_with_sigkill_resumes_to_every_seed_once(tmp_path):
    out = tmp_path / "data"
    args = ["batch", "--count", "4", "--workers", "2", "--out", str(out), *GENERATE]
    proc = subprocess.Popen(CLI + args, start_new_session=True, stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL)
    try:
        deadline = time.monotonic() + 300
        while not read_manifest(out) and proc.poll() is None and time.monotonic() < deadline:
            time.sleep(0.05)
        assert proc.poll() is None, "the batch ended before it could be killed"
    finally:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.wait()
    assert 1 <= len(read_manifest(out)) < 4
    assert batch(*args[1:])[0] == 0
    records = read_manifest(out)
    assert Counter(rec["seed"] for rec in records if rec["status"] == "ok") == \
        dict.fromkeys(range(4), 1)
    assert sorted(p.name for p in (out / "scenes").iterdir()) == ["0", "1", "2", "3"]
    assert not [p for p in tmp_path.rglob(".*") if p.name != ".indoorgen-outputs.json"]


def test_a_scene_over_its_time_or_memory_limit_is_killed_and_recorded(tmp_path):
    options = generate_options(room="hallway", preset="fast", formats="mjcf")
    s = make_dataset(tmp_path / "t", [7], run_generate, options, workers=1, timeout=0.05,
                     progress=False)
    assert (s["attempted"], s["timeout"]) == (1, 1)
    s = make_dataset(tmp_path / "m", [7], run_generate, options, workers=1, max_memory=2**20,
                     progress=False)
    assert (s["attempted"], s["failed"]) == (1, 1)
    (rec,) = read_manifest(tmp_path / "m")
    assert rec["status"] == "failed" and "--max-memory-per-worker" in rec["reason"]
    assert read_manifest(tmp_path / "t")[0]["status"] == "timeout"
    assert not [p for p in tmp_path.rglob(".*") if p.name != ".indoorgen-outputs.json"]


def test_each_scene_runs_with_one_blas_thread(tmp_path):
    """A batch's parallelism is its workers: a scene's process keeps BLAS to one thread, so two
    workers on two cores do not spin on each other's core."""
    s = make_dataset(tmp_path / "d", [0, 1], record_blas_threads, {}, workers=2, progress=False)
    assert s["ok"] == 2
    for seed in (0, 1):
        pools = json.loads((tmp_path / "d" / "scenes" / str(seed) / "blas_threads.json").read_text())
        assert pools and set(pools) == {1}
