"""`indoorgen dataset-stats` on a small dataset: what it prints and plots."""
from __future__ import annotations

import matplotlib.image as mpimg
import pytest

from indoorgen.batch.stats import dataset_stats
from indoorgen.cli import main

pytestmark = pytest.mark.xdist_group("batch")


def test_dataset_stats_prints_and_plots_what_the_dataset_holds(local_batch, capsys):
    out, _ = local_batch
    assert main(["dataset-stats", str(out)]) == 0
    text = capsys.readouterr().out
    assert "scenes: 5 ok (1 failed, 0 timed out)" in text
    assert "room types: hallway 5" in text and "diversity:" in text and "disk per scene" in text
    img = mpimg.imread(out / "stats.png")
    assert img.shape[0] > 500 and (img[..., :3] < 0.5).any()
    stats = dataset_stats(out)
    assert stats["room_types"] == {"hallway": 5}
    assert sum(stats["categories"].values()) == sum(stats["series"]["objects_per_room"]["hallway"])
    assert stats["diversity"]["generators"] >= 2 and stats["disk_mb_per_scene"]["min"] > 0
