"""floorplan.json: round trips, the schema's exact keys, and errors naming the entry at fault."""
from __future__ import annotations

import json

import pytest

from indoorgen.errors import ConfigError, IndoorGenError, InvalidGeometryError
from indoorgen.floorplan.check import floorplan_problems
from indoorgen.floorplan.generate import FloorplanConfig, generate_floorplan
from indoorgen.floorplan.solve import FloorplanAnnealConfig
from indoorgen.model.floorplan_io import dumps, from_json, read_floorplan, to_json, write_floorplan
from support.plans import apartment


def test_predefined_plan_round_trips(tmp_path):
    fp = from_json(apartment())
    assert floorplan_problems(fp) == []
    write_floorplan(fp, tmp_path / "floorplan.json")
    again = read_floorplan(tmp_path / "floorplan.json")
    assert dumps(again) == dumps(fp)
    assert to_json(again)["storeys"][0]["rooms"][2]["polygon"] == [[0, 5], [5, 5], [5, 8], [0, 8]]


def test_schema_keys_are_exactly_the_contract():
    fp = generate_floorplan(2, FloorplanConfig(floors=2,
                                               anneal=FloorplanAnnealConfig(steps_per_storey=30)))
    d = json.loads(dumps(fp))
    # vehicle_doors is written only when the home has a garage (this one does)
    assert set(d) == {"format_version", "storeys", "stairs", "entrance", "vehicle_doors"}
    assert d["format_version"] == 1
    assert "format_version" not in to_json(fp)  # the plan scene.json embeds is unchanged
    assert set(d["entrance"]) == {"room", "center"}
    assert all(set(v) == {"room", "center", "width", "height"} for v in d["vehicle_doors"])
    for s in d["storeys"]:
        assert set(s) == {"level", "elevation", "height", "rooms", "doors", "windows", "openings"}
        assert all(set(r) == {"name", "type", "polygon"} for r in s["rooms"])
        assert all(set(x) == {"name", "rooms", "center", "width", "height"}
                   for x in s["doors"] + s["openings"])
        assert all(set(w) == {"name", "room", "center", "width", "height", "sill"}
                   for w in s["windows"])
    assert [set(st) for st in d["stairs"]] == [{"from_level", "to_level", "polygon"}]
    # a generated plan round-trips too
    assert dumps(from_json(d)) == dumps(fp)


@pytest.mark.parametrize("mutate, err, match", [
    (lambda d: d["storeys"][0]["rooms"][1].update(polygon=[[5, 0], [10, 0], [10, 5], [5, 5]]),
     InvalidGeometryError, "overlap"),
    (lambda d: d["storeys"][0]["rooms"][0].update(type="ballroom"), IndoorGenError, "ballroom"),
    (lambda d: d["storeys"][0]["doors"][0].update(rooms=["living_room_0", "attic_0"]),
     ConfigError, "attic_0"),
    (lambda d: d["storeys"][0].pop("rooms"), ConfigError, "no 'rooms'"),
    (lambda d: d["storeys"][0]["windows"][0].update(width="wide"), ConfigError, "number"),
    (lambda d: d["storeys"][0]["rooms"][0].update(polygon=[[0, 0], [6, 5], [6, 0], [0, 5]]),
     InvalidGeometryError, "simple polygon"),
])
def test_bad_predefined_plans_say_what_is_wrong(mutate, err, match):
    d = apartment()
    mutate(d)
    with pytest.raises(err, match=match):
        from_json(d)


def test_missing_or_unreadable_files_are_config_errors(tmp_path):
    with pytest.raises(ConfigError, match="does not exist"):
        read_floorplan(tmp_path / "nope.json")
    (tmp_path / "bad.json").write_text("{not json")
    with pytest.raises(ConfigError, match="not readable JSON"):
        read_floorplan(tmp_path / "bad.json")
