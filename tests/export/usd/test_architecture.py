"""`architecture.usda`: a solidified home's stage layout and its elements' attributes."""
from __future__ import annotations

import pytest
from pxr import Usd, UsdGeom

from indoorgen.architecture.solidify import solidify
from indoorgen.export.usd.architecture import build_architecture_stage, write_architecture_usd
from support.plans import two_storey_home


@pytest.fixture(scope="module")
def two_storeys():
    return two_storey_home()


def test_usd_stage_layout(two_storeys):
    fp, arch = two_storeys
    stage = build_architecture_stage(arch)
    assert UsdGeom.GetStageUpAxis(stage) == "Z"
    assert UsdGeom.GetStageMetersPerUnit(stage) == 1.0
    assert stage.GetDefaultPrim().GetPath() == "/World"
    for storey in fp.storeys:
        for r in storey.rooms:
            for part in ("floor", "ceiling", "walls"):
                prim = stage.GetPrimAtPath(f"/World/Architecture/storey_{storey.level}/"
                                           f"{r.name}/{part}")
                assert prim.IsValid(), (r.name, part)
                assert prim.GetAttribute("indoorgen:room").Get() == r.name
        for d in storey.doors:
            assert stage.GetPrimAtPath(f"/World/Architecture/storey_{storey.level}/doors/"
                                       f"{d.name}").IsValid()
        for w in storey.windows:
            assert stage.GetPrimAtPath(f"/World/Architecture/storey_{storey.level}/windows/"
                                       f"{w.name}").IsValid()
    assert stage.GetPrimAtPath("/World/Architecture/stairs/stair_0_1").IsValid()


def test_catalogue_elements_name_their_generator(two_storeys):
    fp, _ = two_storeys
    stage = build_architecture_stage(solidify(fp, seed=5))
    d = fp.storeys[0].doors[0]
    prim = stage.GetPrimAtPath(f"/World/Architecture/storey_0/doors/{d.name}")
    assert prim.GetAttribute("indoorgen:generator").Get() == "interior_door"


def test_written_file_opens_as_the_same_stage(two_storeys, tmp_path):
    _, arch = two_storeys
    write_architecture_usd(arch, tmp_path / "architecture.usda")
    stage = Usd.Stage.Open(str(tmp_path / "architecture.usda"))
    assert stage.GetPrimAtPath("/World/Architecture/stairs/stair_0_1").IsValid()
