"""Floorplans for tests: the hand-drawn apartment of tests/data/apartment.json."""
from __future__ import annotations

import json
from pathlib import Path

#: A hand-drawn five-room apartment with doors, an open kitchen, windows and a front door.
APARTMENT_PATH = Path(__file__).parents[1] / "data" / "apartment.json"


def apartment() -> dict:
    """A fresh copy of the apartment's floorplan.json object (tests may mutate it)."""
    return json.loads(APARTMENT_PATH.read_text())
