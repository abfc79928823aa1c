"""The glTF export (`scene.glb`) as its users open it: the Khronos glTF-Validator finds nothing
wrong, trimesh loads each object once, upright (glTF is Y-up), under its own name, and the
lamps' lights stand where their bulbs are."""
from __future__ import annotations

import numpy as np
import pytest
import trimesh
from tests.support.gltf import glb_json, validate, validator, world_matrices

from indoorgen.export.gltf import glb_bytes, y_up
from indoorgen.export.lights import emitters
from indoorgen.export.textures import TextureStore

#: float32 positions and welded corners: how closely loaded geometry matches the bundle (m)
TOL = 2e-3


def _object_nodes(scene: trimesh.Scene, name: str) -> list[str]:
    """The geometry nodes trimesh made for object `name` (its links' primitives)."""
    return [n for n in scene.graph.nodes_geometry if n.startswith(f"{name}/")]


def check_validator_clean(path):
    cmd, why = validator()
    if cmd is None:
        pytest.skip(why)
    report = validate(cmd, path)
    issues = report["issues"]
    assert issues["numErrors"] == 0 and issues["numWarnings"] == 0, [
        m for m in issues["messages"] if m["severity"] <= 1][:10]
    assert "KHR_lights_punctual" in report["info"]["extensionsUsed"]


def check_each_object_once_upright(bundle, path):
    scene = trimesh.load(path)
    assert isinstance(scene, trimesh.Scene)
    tree = glb_json(path)
    roots = tree["scenes"][0]["nodes"]
    assert [tree["nodes"][i]["name"] for i in roots] == ["world"]
    assert "mesh" not in tree["nodes"][roots[0]]
    names = [n["name"] for n in tree["nodes"]]
    assert len(names) == len(set(names))
    for o in bundle.objects:
        asset = bundle.assets[o.name]
        assert o.name in scene.graph.nodes
        parts = _object_nodes(scene, o.name)
        faces = sum(len(scene.geometry[scene.graph[n][1]].faces) for n in parts)
        assert 0.99 * len(asset.mesh.faces) <= faces <= len(asset.mesh.faces), o.name
        # where the object stands in indoorgen's Z-up world, turned into glTF's Y-up frame:
        # its height along +Y, its floor-plan position in X and -Z
        want = y_up(o.pose.apply(asset.mesh.vertices))
        got = np.concatenate([trimesh.transform_points(scene.geometry[g].vertices, m)
                              for m, g in (scene.graph[n] for n in parts)])
        assert np.allclose(got.min(0), want.min(0), atol=TOL), o.name
        assert np.allclose(got.max(0), want.max(0), atol=TOL), o.name
    floors = [e for e in bundle.elements if e.kind == "floor"]
    lowest = min(float(p.mesh.bounds[0, 2]) for e in floors for p in e.parts)
    assert scene.bounds[0, 1] == pytest.approx(lowest, abs=TOL)


def check_lights_at_bulbs(bundle, path):
    tree = glb_json(path)
    lights = tree["extensions"]["KHR_lights_punctual"]["lights"]
    world = world_matrices(tree)
    placed = {n["name"]: (world[i][:3, 3], lights[n["extensions"]["KHR_lights_punctual"]["light"]])
              for i, n in enumerate(tree["nodes"]) if "extensions" in n}
    want = {f"{o.name}/light_{e.index}": (o.pose.apply(e.centre[None])[0], e.candela)
            for o in bundle.objects for e in emitters(bundle.assets[o.name], o.generator)}
    assert want and set(placed) == set(want)
    for name, (pos, light) in placed.items():
        assert light["type"] == "point"
        assert light["intensity"] == pytest.approx(want[name][1])
        assert np.allclose(pos, y_up(want[name][0][None])[0], atol=TOL)


def test_living_room_glb_is_valid_upright_and_lit(exported):
    bundle, d, _ = exported["living_room"]
    check_validator_clean(d / "scene.glb")
    check_each_object_once_upright(bundle, d / "scene.glb")
    check_lights_at_bulbs(bundle, d / "scene.glb")


@pytest.mark.slow
@pytest.mark.xdist_group("export_homes")
@pytest.mark.parametrize("home", ["home1", "home2"])
def test_home_glb_is_valid_upright_and_lit(exported_homes, home):
    bundle, d = exported_homes[home]
    check_validator_clean(d / "scene.glb")
    check_each_object_once_upright(bundle, d / "scene.glb")
    check_lights_at_bulbs(bundle, d / "scene.glb")


def test_glb_nests_objects_in_rooms_with_textures_and_extras(exported):
    bundle, d, _ = exported["dining_room"]
    scene = trimesh.load(d / "scene.glb")
    assert isinstance(scene, trimesh.Scene)
    room = next(iter(bundle.scene.rooms))
    for o in bundle.objects:
        assert scene.graph.transforms.parents[o.name] == room
        for link in bundle.assets[o.name].links:
            assert f"{o.name}/{link}" in scene.graph.nodes
    for e in bundle.elements:
        assert f"{e.room}/{e.name}" in scene.graph.nodes
    textured = [g for g in scene.geometry.values()
                if getattr(g.visual, "material", None) is not None
                and g.visual.material.baseColorTexture is not None]
    assert len(textured) == len(scene.geometry)
    assert any(g.visual.material.normalTexture is not None for g in textured)
    assert any(g.visual.material.metallicRoughnessTexture is not None for g in textured)
    extras = [data.get("metadata") or {} for data in scene.graph.transforms.edge_data.values()]
    labelled = {x["name"]: x for x in extras if "semantics" in x}
    for o in bundle.objects:
        assert labelled[o.name]["semantics"] == sorted(o.tags)
        assert labelled[o.name]["generator"] == o.generator


def test_glb_bytes_are_deterministic(exported, tmp_path):
    bundle, _, _ = exported["dining_room"]
    textures = TextureStore(tmp_path, 16)
    assert glb_bytes(bundle, textures) == glb_bytes(bundle, textures)
