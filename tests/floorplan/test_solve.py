"""Floorplan annealing keeps service rooms from growing past their cap."""
from __future__ import annotations

import pytest

from indoorgen.floorplan.generate import FloorplanConfig, build_plan
from indoorgen.floorplan.rules import service_areas, service_cap
from indoorgen.floorplan.solve import anneal
from indoorgen.programs.floorplan import floorplan
from indoorgen.rng import stream


@pytest.mark.parametrize("seed", [2, 8])
def test_annealing_grows_no_service_room_past_its_cap(seed):
    """A bathroom, closet, utility or staircase room ends no larger than it started or than
    its cap (1.5 times its share of the storey): spare area goes to the rooms one lives in."""
    plan = build_plan(seed, FloorplanConfig())
    start = service_areas(plan)
    anneal(plan, floorplan(), stream(seed, "test", "anneal"))
    for room, area in service_areas(plan).items():
        assert area <= max(start[room], service_cap(plan, room)) + 1e-6, room
