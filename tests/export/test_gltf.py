"""The glTF export (`scene.glb`) loaded back by trimesh."""
from __future__ import annotations

import trimesh


def test_glb_loads_with_nodes_textures_and_extras(exported):
    bundle, d, _ = exported["dining_room"]
    scene = trimesh.load(d / "scene.glb")
    assert isinstance(scene, trimesh.Scene)
    nodes = set(scene.graph.nodes)
    n_links = sum(len(bundle.assets[o.name].links) for o in bundle.objects)
    # world, architecture, objects + an element node per element + object and link nodes
    assert len(nodes) >= 3 + len(bundle.elements) + len(bundle.objects) + n_links
    for o in bundle.objects:
        assert f"objects/{o.name}" in nodes
    textured = [g for g in scene.geometry.values()
                if getattr(g.visual, "material", None) is not None
                and g.visual.material.baseColorTexture is not None]
    assert len(textured) == len(scene.geometry)
    assert any(g.visual.material.normalTexture is not None for g in textured)
    extras = [scene.graph.transforms.edge_data[e].get("metadata") or {}
              for e in scene.graph.transforms.edge_data]
    labelled = {x["name"]: x for x in extras if "semantics" in x}
    for o in bundle.objects:
        assert labelled[o.name]["semantics"] == sorted(o.tags)
        assert labelled[o.name]["generator"] == o.generator
