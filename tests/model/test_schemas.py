"""The data files' schemas: real files pass, hostile ones are refused in one line naming the
problem, caps hold before parsing, and docs/schemas/ matches the models."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from indoorgen.errors import IndoorGenError
from indoorgen.model.schemas import (
    MAX_DEPTH,
    MAX_ITEMS,
    FloorplanFile,
    HomeContour,
    RoomGraph,
    RoomPolygon,
    SceneFile,
    SchemaError,
    json_schemas,
    nesting_depth,
    parse,
    read_json_file,
    read_json_text,
)
from support.scenefiles import minimal_scene

DOCS = Path(__file__).resolve().parents[2] / "docs" / "schemas"
APARTMENT = Path(__file__).resolve().parents[1] / "data" / "apartment.json"


def test_docs_schemas_match_the_models():
    """docs/schemas/NAME.schema.json is the model's JSON Schema; to refresh it run
    `python -c "from indoorgen.model.schemas import write_json_schemas as w; w('docs/schemas')"`."""
    for name, schema in json_schemas().items():
        committed = json.loads((DOCS / f"{name}.schema.json").read_text())
        assert committed == json.loads(json.dumps(schema)), name


def test_real_files_pass():
    parse(FloorplanFile, read_json_file(APARTMENT, "apartment", "floorplan"), "apartment")
    parse(SceneFile, minimal_scene(), "scene")
    parse(RoomPolygon, {"polygon": [[0, 0], [5, 0], [5, 4], [0, 4]]}, "--polygon")
    parse(HomeContour, {"contour": [[0, 0], [12, 0], [12, 9], [0, 9]]}, "--contour")
    parse(RoomGraph, {"storeys": [{"rooms": ["living_room_0", "kitchen_0"],
                                   "edges": [["living_room_0", "kitchen_0"]]}]}, "--graph")


@pytest.mark.parametrize("text, needle", [
    ("[" * 100_000 + "]" * 100_000, "nests brackets 100000 deep"),
    ('{"a": "' + "[" * 1000 + '"}', None),  # brackets inside a string do not count
    ("[[0, 0], [5, 0], [5, NaN], [0, 4]]", "finite"),
    ("[[0, 0], [5, 0], [5, 1e308], [0, 4]]", "less than or equal to 1000"),
    ("[[0, 0], [5, 0], [5, 4]", "not readable JSON"),
])
def test_polygon_text(text, needle):
    if needle is None:
        assert read_json_text(text, "--polygon", "polygon") == {"a": "[" * 1000}
        return
    with pytest.raises(SchemaError, match=needle):
        parse(RoomPolygon, {"polygon": read_json_text(text, "--polygon", "polygon")}, "--polygon")


def test_nesting_depth_ignores_strings_and_escapes():
    assert nesting_depth('{"a": [1, {"b": "]]]\\"[["}]}') == 3
    assert nesting_depth("[" * (MAX_DEPTH + 1) + "]" * (MAX_DEPTH + 1)) == MAX_DEPTH + 1


@pytest.mark.parametrize("polygon, needle", [
    ([[0, 0], [1e6, 0], [1e6, 1e6], [0, 1e6]], "less than or equal to 1000"),
    ([[0, 0], [100, 0], [100, 100], [0, 100]], "between 2 and 30 m"),
    ([[0, 0], [1, 0], [1, 1], [0, 1]], "between 2 and 30 m"),
    ([[0, 0], [5, 0]], "at least 3 items"),
    ([[0, 0], [5, 0], [5, 4], [0, "4"]], "valid number"),
    ([[0, 0], [5, 0], [5, 4], [0, True]], "valid number"),
    ([[0, 0]] * 100_000, "at most 256 items"),
])
def test_polygon_ranges_are_those_of_size(polygon, needle):
    with pytest.raises(SchemaError, match=needle):
        parse(RoomPolygon, {"polygon": polygon}, "--polygon")


def test_big_files_are_refused_from_stat(tmp_path):
    big = tmp_path / "big.json"
    with big.open("wb") as f:
        f.truncate(2 << 20)  # sparse: nothing is read
    with pytest.raises(SchemaError, match="holds at most"):
        read_json_file(big, "--contour file", "contour")


def _scene(mutate):
    d = minimal_scene()
    d["objects"] = [{"name": "sofa_0", "generator": "sofa", "params": {}, "seed": 1,
                     "pose": {"position": [1, 1, 0], "yaw": 0}, "tags": [],
                     "room": "living_room_0", "stage": "large",
                     "relations": [{"relation": "StableAgainst(bottom, floor, 0.0)",
                                    "parent": "living_room_0", "child_surface": "bottom",
                                    "parent_surface": "floor", "margin": 0}]}]
    mutate(d)
    return d


@pytest.mark.parametrize("mutate, needle", [
    (lambda d: d["objects"][0]["pose"].update(position=[float("nan"), 0, 0]), "finite"),
    (lambda d: d["objects"][0]["pose"].update(position=[1, 2]), "lacks item 2"),
    (lambda d: d["objects"][0].update(room="attic_0"), "'attic_0', which is not in the scene"),
    (lambda d: d["objects"][0]["relations"][0].update(parent="ghost"), "'ghost'"),
    (lambda d: d["objects"][0].update(seed=-1), "greater than or equal to 0"),
    (lambda d: d["rooms"][0].update(type="ballroom"), "'ballroom', which is unknown"),
    (lambda d: d["rooms"][0]["polygon"][1].__setitem__(0, 1e308), "less than or equal to 1000"),
    (lambda d: d["rooms"][0]["doors"][0].update(wall=9), "walls 0 to 3"),
    (lambda d: d["rooms"][0].update(polygon=[[0, 0], [4, 3], [4, 0], [0, 3]]), "not a simple polygon"),
    (lambda d: d.update(format_version=2), "format_version"),
    (lambda d: d.pop("rooms"), "has no 'rooms'"),
    (lambda d: d["objects"][0].update(colour="red"), "Extra inputs"),
    # found by the long fuzz run: an integer too large for a float
    (lambda d: d["objects"][0]["params"].update(width=10**60), "params.width"),
])
def test_bad_scenes_name_the_entry(mutate, needle):
    with pytest.raises(SchemaError, match=needle) as e:
        parse(SceneFile, _scene(mutate), "scene.json")
    assert "\n" not in str(e.value)


def test_a_custom_program_may_name_its_own_room_type():
    d = _scene(lambda d: d["rooms"][0].update(type="ballroom"))
    d["config"] = {"program": "my_room"}
    parse(SceneFile, d, "scene.json")


@pytest.mark.parametrize("data, needle", [
    ({"storeys": [{"rooms": ["a_0"], "edges": [["a_0", "b_0"]]}]}, "not on storey 0"),
    ({"storeys": []}, "at least 1 item"),
    ({"storeys": [{}]}, "has no 'rooms'"),  # found by the long fuzz run: a storey of no rooms
    ({"storeys": [{"rooms": "living_room_0"}]}, "valid list"),
])
def test_bad_graphs(data, needle):
    with pytest.raises(IndoorGenError, match=needle):
        parse(RoomGraph, data, "--graph")


def test_huge_contours_are_refused():
    with pytest.raises(SchemaError, match="a home fits in 100 x 100 m"):
        parse(HomeContour, {"contour": [[0, 0], [1e3, 0], [1e3, 1e3], [0, 1e3]]}, "--contour")
    with pytest.raises(SchemaError, match="at most 2000 m"):
        parse(HomeContour, {"contour": [[0, 0], [99, 0], [99, 99], [0, 99]]}, "--contour")


def test_values_are_capped_before_parsing():
    """A flat list of millions of numbers is refused from a scan, never parsed."""
    flat = "[" + ",".join(["0.1"] * (MAX_ITEMS["polygon"] + 1)) + "]"
    with pytest.raises(SchemaError, match="values and keys"):
        read_json_text(flat, "--polygon", "polygon")
    scene = "[" + ",".join(["0"] * (MAX_ITEMS["scene"] + 1)) + "]"
    with pytest.raises(SchemaError, match="values and keys; a scene file holds at most"):
        read_json_text(scene, "scene.json", "scene")


def test_a_million_errors_are_described_by_the_first():
    """20,000 objects of 50 unknown keys each: one line naming objects[0], its key and value,
    and the count of the others, without listing them all."""
    d = _scene(lambda d: None)
    bad = {**d["objects"][0], **{f"k{i}": i for i in range(50)}}
    d["objects"] = [{**bad, "name": f"o{j}"} for j in range(20_000)]
    with pytest.raises(SchemaError) as e:
        parse(SceneFile, d, "scene.json")
    assert str(e.value) == ("scene.json: objects[0]: k0: Extra inputs are not permitted (got 0) "
                            "(and 49 more problem(s))")


def test_a_huge_value_is_shown_short():
    with pytest.raises(SchemaError) as e:
        parse(RoomPolygon, {"polygon": {"x": list(range(1_000_000))}}, "--polygon")
    assert len(str(e.value)) < 200
