"""Generated homes over many seeds keep every rule of the issue (see floorplan.check), meet
required counts, areas and outlines, and are deterministic."""
from __future__ import annotations

import pytest
import shapely.geometry as sg

from indoorgen.errors import ConfigError
from indoorgen.floorplan.check import floorplan_problems
from indoorgen.floorplan.generate import FloorplanConfig, generate_floorplan
from indoorgen.floorplan.solve import FloorplanAnnealConfig
from indoorgen.model.floorplan_io import dumps

#: The slow test runs fewer seeds than the benchmark (benchmarks/floorplan.py runs 100 of each),
#: within CI's time
SLOW_SEEDS = {1: range(0, 20), 2: range(100, 110), 3: range(200, 206)}


@pytest.mark.slow
@pytest.mark.parametrize("floors", [1, 2, 3])
def test_homes_keep_every_rule(floors):
    for seed in SLOW_SEEDS[floors]:
        fp = generate_floorplan(seed, FloorplanConfig(
            floors=floors, anneal=FloorplanAnnealConfig(steps_per_storey=60)))
        assert floorplan_problems(fp, fp.info["contours"]) == [], seed
        assert len(fp.storeys) == floors


def test_quick_homes_keep_every_rule():
    for floors, seed in ((1, 5), (2, 6), (3, 7)):
        fp = generate_floorplan(seed, FloorplanConfig(
            floors=floors, anneal=FloorplanAnnealConfig(steps_per_storey=20)))
        assert floorplan_problems(fp, fp.info["contours"]) == []


def test_required_rooms_and_counts():
    counts = {"bedroom": 3, "bathroom": 2, "kitchen": 1}
    fp = generate_floorplan(9, FloorplanConfig(floors=2, rooms="bedroom=3,bathroom=2,kitchen=1",
                                               anneal=FloorplanAnnealConfig(steps_per_storey=30)))
    assert floorplan_problems(fp, fp.info["contours"], counts) == []


def test_same_seed_same_plan_bytes():
    cfg = FloorplanConfig(floors=2, anneal=FloorplanAnnealConfig(steps_per_storey=40))
    assert dumps(generate_floorplan(21, cfg)) == dumps(generate_floorplan(21, cfg))
    other = dumps(generate_floorplan(22, cfg))
    assert other != dumps(generate_floorplan(21, cfg))


def test_fixed_area_and_contour():
    fp = generate_floorplan(4, FloorplanConfig(area=140.0,
                                               anneal=FloorplanAnnealConfig(steps_per_storey=30)))
    assert fp.storeys[0].contour().area == pytest.approx(140.0, rel=0.1)
    outline = [[0, 0], [12, 0], [12, 6], [7, 6], [7, 10], [0, 10]]
    fp = generate_floorplan(4, FloorplanConfig(contour=outline,
                                               anneal=FloorplanAnnealConfig(steps_per_storey=30)))
    assert fp.storeys[0].contour().symmetric_difference(sg.Polygon(outline)).area < 1e-6
    assert floorplan_problems(fp, fp.info["contours"]) == []


@pytest.mark.parametrize("cfg, needle", [
    (FloorplanConfig(slab=-1.0), r"slab -1.0 is out of range \[0.05, 0.5\]"),
    (FloorplanConfig(open_prob=7.0), "open_prob 7.0"),
    (FloorplanConfig(exterior_wall=float("nan")), "exterior wall nan"),
    (FloorplanConfig(anneal=FloorplanAnnealConfig(steps_per_storey=10**9)), "steps per storey"),
    (FloorplanConfig(area=float("inf")), "--area inf is out of range"),
])
def test_settings_out_of_range_are_refused_before_any_work(cfg, needle):
    with pytest.raises(ConfigError, match=needle):
        generate_floorplan(0, cfg)
