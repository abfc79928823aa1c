"""The garage program: a workbench with its tools, a tool chest, steel racks or cube shelves
holding boxes and paint, all standing against the walls, in a scene the validator passes."""
from __future__ import annotations

import collections

import pytest

from indoorgen import GenerateConfig, generate
from indoorgen.validate import validate_scene

#: where each of the workshop's small things may rest
RESTS_ON = {"toolbox": {"workbench", "tool_chest", "storage_rack", "cell_shelf"},
            "paint_can": {"workbench", "tool_chest", "storage_rack", "cell_shelf"}}


@pytest.fixture(scope="module")
def garage():
    return generate(1, GenerateConfig(room_type="garage")).scene


def test_a_garage_is_a_workshop_and_a_store(garage):
    report = validate_scene(garage)
    assert report["ok"], {k: report[k] for k in ("interpenetrating", "unsupported", "hard_violations")}
    made = collections.Counter(o.generator for o in garage.objects.values())
    assert made["workbench"] == 1 and made["tool_chest"] <= 1
    assert made["corner_shelf"] == 0 and made["shoe_rack"] == 0
    assert made["storage_rack"] + made["cell_shelf"] >= 1
    assert len(garage.objects) >= 30, made
    assert made["ceiling_light"] >= 1 and made["pendant_light"] == 0  # lit flush, nothing hangs
    # the workbench is in use: something stands on its top
    bench = next(o for o in garage.objects.values() if o.generator == "workbench")
    on_bench = [o for o in garage.objects.values()
                if any(r.parent == bench.name and r.parent_surface == "top" for r in o.relations)]
    assert on_bench


def test_furniture_stands_against_the_walls_and_tools_rest_on_it(garage):
    for o in garage.objects.values():
        parents = {garage.objects[r.parent].generator for r in o.relations
                   if r.parent in garage.objects}
        if o.generator in RESTS_ON:
            assert parents and parents <= RESTS_ON[o.generator], (o.name, parents)
        if o.generator in ("workbench", "tool_chest", "storage_rack"):
            assert any(r.parent_surface.startswith("wall") for r in o.relations), o.name
