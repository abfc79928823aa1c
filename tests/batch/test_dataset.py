"""`indoorgen batch` as a user runs it: a dataset of 6 scenes on 2 local workers, one seed
failing inside generation, the same scenes as `indoorgen generate` alone, resumes, and the
same batch on a Dask LocalCluster."""
from __future__ import annotations

import json

import pytest

from indoorgen.batch.manifest import read_manifest
from indoorgen.cli import main
from support.batch import BAD_SEED, GENERATE, batch

pytestmark = pytest.mark.xdist_group("batch")


def _leftovers(directory):
    """Every hidden entry (temporary directories, locks) under a dataset directory and beside it."""
    return sorted(str(p) for p in [*directory.rglob(".*"), *directory.parent.glob(".*")]
                  if p.name != ".indoorgen-outputs.json")


def test_batch_makes_every_seed_and_records_the_failing_one(local_batch):
    out, printed = local_batch
    records = read_manifest(out)
    assert sorted(rec["seed"] for rec in records) == list(range(6))
    by_seed = {rec["seed"]: rec for rec in records}
    bad = by_seed.pop(BAD_SEED)
    assert bad["status"] == "failed" and f"seed {BAD_SEED} fails on purpose" in bad["reason"]
    assert not (out / "scenes" / str(BAD_SEED)).exists()
    for seed, rec in by_seed.items():
        assert rec["status"] == "ok" and rec["reason"] == ""
        assert rec["version"] and rec["objects"] > 0 and rec["rooms"] == 1
        assert {"solve", "export", "total", "wall"} <= set(rec["seconds"])
        assert 0 <= rec["quality"]["share"] <= 1 and 0 < rec["navigation"]["reachable_share"] <= 1
        scene = json.loads((out / "scenes" / str(seed) / "scene.json").read_text())
        assert scene["seed"] == seed and len(scene["objects"]) == rec["objects"]
        assert (out / "scenes" / str(seed) / "scene.xml").is_file()
    assert json.loads((out / "batch.json").read_text())["generate"]["room"] == "hallway"
    assert "5 of 6 scenes made" in printed and "1 failed" in printed
    assert _leftovers(out) == []


def test_a_seed_gives_the_same_scene_in_a_batch_or_alone(local_batch, program, tmp_path):
    out, _ = local_batch
    assert main(["generate", "--seed", "4", *GENERATE, "--program", program, "-q",
                 "--out", str(tmp_path / "alone")]) == 0
    assert (tmp_path / "alone" / "scene.json").read_bytes() == \
        (out / "scenes" / "4" / "scene.json").read_bytes()


def test_a_resume_skips_what_is_done_and_retries_failures_only_when_asked(local_batch, program):
    out, _ = local_batch
    before = len(read_manifest(out))
    code, printed = batch("--count", "6", "--workers", "2", "--out", str(out), *GENERATE,
                          "--program", program)
    assert code == 0
    assert "0 of 0 scenes made" in printed and "6 already done" in printed
    assert len(read_manifest(out)) == before
    code, _ = batch("--seeds", str(_seeds_file(out.parent, "3\n")), "--out", str(out),
                    *GENERATE, "--program", program, "--retry-failed")
    assert code == 0
    assert [(rec["seed"], rec["status"]) for rec in read_manifest(out)[before:]] == \
        [(BAD_SEED, "failed")]


def _seeds_file(directory, text):
    path = directory / "seeds.txt"
    path.write_text(text)
    return path


def test_the_same_batch_on_a_dask_local_cluster(local_batch, program, tmp_path, capfd):
    pytest.importorskip("distributed", reason="the dask extra is not installed")
    out, _ = local_batch
    dask_out = tmp_path / "dask"
    code, _ = batch("--count", "6", "--workers", "2", "--scheduler", "local",
                    "--out", str(dask_out), *GENERATE, "--program", program)
    assert code == 0
    assert "INFO" not in capfd.readouterr().err
    status = {rec["seed"]: rec["status"] for rec in read_manifest(dask_out)}
    assert status == {rec["seed"]: rec["status"] for rec in read_manifest(out)}
    for seed, st in status.items():
        if st == "ok":
            assert (dask_out / "scenes" / str(seed) / "scene.json").read_bytes() == \
                (out / "scenes" / str(seed) / "scene.json").read_bytes()
    assert _leftovers(dask_out) == []
