"""`indoorgen batch` and `dataset-stats` on bad input: one line on stderr and exit status 2,
before anything is written; and the statistics of a small dataset."""
from __future__ import annotations

import json

import pytest

from indoorgen import __version__
from indoorgen.cli import main
from indoorgen.cli.batch import generate_options, parse_size, read_seeds
from indoorgen.errors import BatchConfigError

BATCH = ["batch", "--room", "hallway", "--preset", "fast", "--formats", "mjcf"]


def _fails(capsys, argv, *words):
    assert main(argv) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and err.startswith("indoorgen: error:"), err
    for w in words:
        assert w in err, err
    return err


def test_count_zero(tmp_path, capsys):
    _fails(capsys, [*BATCH, "--count", "0", "--out", str(tmp_path / "d")], "--count")
    assert not (tmp_path / "d").exists()


@pytest.mark.parametrize("text", ["1 2 x3\n", "-4\n", "1.5", "", "# only a comment\n"])
def test_a_seeds_file_that_does_not_parse(tmp_path, capsys, text):
    (tmp_path / "seeds.txt").write_text(text)
    _fails(capsys, [*BATCH, "--seeds", str(tmp_path / "seeds.txt"), "--out", str(tmp_path / "d")],
           "--seeds")
    assert not (tmp_path / "d").exists()


def test_seeds_files_parse_into_distinct_seeds_in_order(tmp_path):
    (tmp_path / "s").write_text("5, 3 # the first ones\n\n3 9\n10,11")
    assert read_seeds(tmp_path / "s") == [5, 3, 9, 10, 11]


def test_a_scheduler_that_does_not_answer(tmp_path, capsys):
    pytest.importorskip("distributed", reason="the dask extra is not installed")
    _fails(capsys, [*BATCH, "--count", "2", "--out", str(tmp_path / "d"),
                    "--scheduler", "tcp://127.0.0.1:9", "--scheduler-timeout", "1"],
           "did not answer", "tcp://127.0.0.1:9")
    assert not (tmp_path / "d").exists()


@pytest.mark.parametrize("change, words", [
    ({"generate": generate_options(room="kitchen", preset="fast", formats="mjcf")},
     ("other generate options", "room='kitchen'")),
    ({"indoorgen_version": "0.0.1"}, ("written by indoorgen 0.0.1",)),
])
def test_a_directory_made_with_other_options_or_another_version(tmp_path, capsys, change, words):
    out = tmp_path / "d"
    out.mkdir()
    same = generate_options(room="hallway", preset="fast", formats="mjcf")
    batch = {"indoorgen_version": __version__, "generate": same, **change}
    (out / "batch.json").write_text(json.dumps(batch))
    _fails(capsys, [*BATCH, "--count", "1", "--out", str(out)], *words)
    assert [p.name for p in out.iterdir()] == ["batch.json"]


def test_a_directory_that_is_not_a_batchs(tmp_path, capsys):
    (tmp_path / "mine.txt").write_text("keep")
    _fails(capsys, [*BATCH, "--count", "1", "--out", str(tmp_path)], "not a batch's directory")


def test_a_bad_generate_option_fails_once_before_any_scene(tmp_path, capsys):
    _fails(capsys, [*BATCH, "--count", "1", "--out", str(tmp_path / "d"), "--formats", "fbx"],
           "fbx")
    assert not (tmp_path / "d").exists()


def test_memory_sizes():
    assert parse_size("4G") == 4 * 2**30 and parse_size("1500M") == 1500 * 2**20
    assert parse_size("512mb") == 512 * 2**20 and parse_size("2048") == 2048 * 2**20
    with pytest.raises(BatchConfigError):
        parse_size("lots")


def test_dataset_stats_of_a_directory_without_a_batch(tmp_path, capsys):
    _fails(capsys, ["dataset-stats", str(tmp_path)], "manifest")
