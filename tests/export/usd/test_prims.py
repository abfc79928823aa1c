"""USD building blocks (indoorgen.export.usd.prims)."""
from __future__ import annotations

import numpy as np
import pytest
import trimesh
from pxr import Usd, UsdGeom, UsdPhysics

from indoorgen.errors import OutputError
from indoorgen.export.usd.prims import (
    ATTR_GENERATOR,
    ATTR_SEMANTICS,
    define_mesh,
    export_stage,
    new_stage,
    sanitize_name,
    tag_prim,
    unique_names,
)


def test_names():
    assert sanitize_name("bedroom-0 lamp") == "bedroom_0_lamp"
    assert sanitize_name("3d") == "_3d" and sanitize_name("") == "_"
    assert unique_names(["a-b", "a_b", "c"]) == {"a-b": "a_b", "a_b": "a_b_1", "c": "c"}


def test_new_stage_tags_and_meshes(tmp_path):
    stage = new_stage(kilograms_per_unit=1.0)
    assert UsdGeom.GetStageUpAxis(stage) == "Z" and UsdGeom.GetStageMetersPerUnit(stage) == 1.0
    assert UsdPhysics.GetStageKilogramsPerUnit(stage) == 1.0
    assert stage.GetDefaultPrim().GetPath() == "/World"
    prim = UsdGeom.Xform.Define(stage, "/World/box").GetPrim()
    tag_prim(prim, name="box", generator="test", room="r", parent="", semantics=["b", "a", "a"])
    assert prim.GetAttribute(ATTR_GENERATOR).Get() == "test"
    assert list(prim.GetAttribute(ATTR_SEMANTICS).Get()) == ["a", "b"]
    box = trimesh.creation.box((1.0, 2.0, 3.0))
    mesh = define_mesh(stage, prim.GetPath().AppendChild("mesh"), box)
    assert len(mesh.GetFaceVertexCountsAttr().Get()) == len(box.faces)
    assert np.allclose(np.asarray(mesh.GetExtentAttr().Get()), box.bounds)
    export_stage(stage, tmp_path / "s.usda")
    again = Usd.Stage.Open(str(tmp_path / "s.usda"))
    assert again.GetPrimAtPath("/World/box/mesh").IsValid()


def test_unwritable_place_is_an_output_error(tmp_path):
    (tmp_path / "a_file").write_text("")
    with pytest.raises(OutputError, match="cannot write USD"):
        export_stage(new_stage(), tmp_path / "a_file" / "s.usda")
