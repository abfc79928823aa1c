"""OBJ/MTL files: the `obj` format loaded back, and collision pieces written as box primitives
where they are boxes, as STL files otherwise."""
from __future__ import annotations

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
    for g, piece in zip(geoms[1:], (cyl, turned), strict=True):  # not axis-aligned boxes: STL files
        assert not g.is_box and g.path.startswith("meshes/")
        back = trimesh.load(tmp_path / g.path.split("/")[-1])
        assert np.isclose(back.volume, piece.volume, rtol=1e-5) and back.is_watertight


def test_obj_scene_and_objects_load(exported):
    bundle, d, _ = exported["dining_room"]
    whole = trimesh.load(d / "scene.obj", force="scene")
    assert len(whole.geometry) > 0
    for o in bundle.objects[:5]:
        m = trimesh.load(d / "obj" / f"{o.name}.obj", force="scene")
        assert len(m.geometry) >= 1
        g = next(iter(m.geometry.values()))
        assert g.visual.kind == "texture"
    mtl = (d / "scene.mtl").read_text()
    assert "map_Kd textures/" in mtl
