"""Collision pieces go out as box primitives where they are boxes, as STL files otherwise."""
from __future__ import annotations

from xml.etree import ElementTree as ET

import numpy as np
import trimesh

from indoorgen.export.obj import collision_geoms


def test_boxes_become_primitives_and_the_rest_stl(tmp_path):
    box = trimesh.creation.box([0.4, 0.2, 0.9])
    box.apply_translation([1.0, -2.0, 0.45])
    cyl = trimesh.creation.cylinder(0.1, 0.3, sections=16).convex_hull
    turned = trimesh.creation.box([0.4, 0.2, 0.9])
    turned.apply_transform(trimesh.transformations.rotation_matrix(0.3, [0, 0, 1]))
    geoms = collision_geoms([box, cyl, turned], tmp_path, "p", "meshes")
    assert geoms[0].is_box
    assert np.allclose(geoms[0].center, [1.0, -2.0, 0.45]) and np.allclose(geoms[0].size,
                                                                          [0.4, 0.2, 0.9])
    for g, piece in zip(geoms[1:], (cyl, turned)):  # not axis-aligned boxes: STL files
        assert not g.is_box and g.path.startswith("meshes/")
        back = trimesh.load(tmp_path / g.path.split("/")[-1])
        assert np.isclose(back.volume, piece.volume, rtol=1e-5) and back.is_watertight


def test_exported_urdf_collisions_are_the_asset_pieces(exported):
    """Every object URDF holds one <collision> per convex piece, boxes as <box>."""
    bundle, d, _ = exported["living_room"]
    kinds = {"box": 0, "mesh": 0}
    for obj in bundle.objects:
        root = ET.parse(d / "urdf" / f"{obj.name}.urdf").getroot()
        cols = root.findall(".//collision/geometry/*")
        assert len(cols) == len(bundle.assets[obj.name].collision), obj.name
        for c in cols:
            kinds[c.tag] += 1
    assert kinds["box"] > 0 and kinds["mesh"] > 0
