"""Homes a robot can walk through (issue 11), on the session's generated 1- and 2-storey homes
(fast preset): every room reached from the entrance, every door passed, nearly all walkable
floor reached on every storey, and report.json's status saying so."""
from __future__ import annotations

import pytest

from indoorgen.quality.verdict import scene_status

pytestmark = pytest.mark.xdist_group("export_homes")

#: issue 11: at least this share of the walkable floor reached from the entrance
MIN_SHARE = 0.95


@pytest.mark.parametrize("home", ["home1", "home2"])
def test_every_room_and_door_is_reached_from_the_entrance(generated_homes, home):
    nav = generated_homes[home].report["navigation"]
    assert nav["unreachable_rooms"] == [] and nav["unreachable_doors"] == []
    assert nav["passed"] and nav["doors"] >= nav["rooms"] - 1  # a tree of rooms at least


@pytest.mark.parametrize("home", ["home1", "home2"])
def test_nearly_all_walkable_floor_is_reached_on_every_storey(generated_homes, home):
    gen = generated_homes[home]
    nav = gen.report["navigation"]
    levels = {str(r.storey) for r in gen.scene.rooms.values()}
    assert set(nav["storeys"]) == levels
    for s in nav["storeys"].values():
        assert s["reachable_m2"] <= s["walkable_m2"] <= s["free_m2"]
        assert s["reachable_share"] >= MIN_SHARE


@pytest.mark.parametrize("home", ["home1", "home2"])
def test_status_gathers_every_unmet_requirement(generated_homes, home):
    rep = generated_homes[home].report
    assert rep["status"] == scene_status(rep)
    violated = any(v > 1e-9 for r in rep["rooms"].values() for v in r["violations"].values())
    assert rep["status"]["failed"] == (violated or not rep["quality"]["passed"]
                                       or not rep["navigation"]["passed"])
