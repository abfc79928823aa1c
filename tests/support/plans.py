"""Floorplans for tests: the hand-drawn apartment of tests/data/apartment.json and a generated
two-storey home, solidified."""
from __future__ import annotations

import functools
import json
from pathlib import Path

from indoorgen.architecture.solidify import Architecture, solidify
from indoorgen.floorplan.generate import FloorplanConfig, generate_floorplan
from indoorgen.floorplan.solve import FloorplanAnnealConfig
from indoorgen.model.floorplan import Floorplan

#: A hand-drawn five-room apartment with doors, an open kitchen, windows and a front door.
APARTMENT_PATH = Path(__file__).parents[1] / "data" / "apartment.json"


def apartment() -> dict:
    """A fresh copy of the apartment's floorplan.json object (tests may mutate it)."""
    return json.loads(APARTMENT_PATH.read_text())


@functools.cache
def two_storey_home() -> tuple[Floorplan, Architecture]:
    """Seed 1's two-storey home (short annealing) and its solids without the catalogue, built
    once per test process: treat both as read-only."""
    fp = generate_floorplan(1, FloorplanConfig(floors=2,
                                               anneal=FloorplanAnnealConfig(steps_per_storey=60)))
    return fp, solidify(fp)
