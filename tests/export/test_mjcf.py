"""MJCF export loaded and simulated by MuJoCo: the stability test of issue 5.

From the exported poses, 2 s under gravity: at least 99 % of the free bodies move less than
2 cm and none more than 10 cm. A failure is a placement bug (solver or asset), reported, never
fixed by pinning objects."""
from __future__ import annotations

import logging

import mujoco
import numpy as np
import pytest

from indoorgen.architecture.solidify import solidify
from indoorgen.export import write_formats
from indoorgen.export.bundle import ExportBundle, elements_from_architecture, make_bundle
from indoorgen.export.convex import MIN_THICKNESS
from indoorgen.export.stability import simulate, stability
from indoorgen.floorplan.generate import FloorplanConfig, generate_floorplan
from indoorgen.floorplan.solve import FloorplanAnnealConfig
from indoorgen.model.scene import Scene

log = logging.getLogger(__name__)


@pytest.mark.slow
@pytest.mark.parametrize("room", ["living_room", "dining_room"])
def test_stability_under_gravity(exported, room, record_property):
    bundle, d, _ = exported[room]
    moved = simulate(d / "scene.xml")
    # every object a free body but those fixed to a wall or to another's link (hung clothes)
    assert len(moved) == sum(1 for o in bundle.objects
                             if not bundle.is_fixed(o) and bundle.attachment(o) is None)
    st = stability(moved)
    record_property("stability", st.__dict__)
    log.warning("%s: %d free bodies, %.1f%% moved < 2 cm, max %.3f m (%s)", room, st.free,
                100 * st.under_2cm, st.max_m, st.worst)
    assert st.passes, st


def test_articulated_objects_load_stay_put_and_shut(articulated):
    bundle, d = articulated
    m = mujoco.MjModel.from_xml_path(str(d / "scene.xml"))
    moving = (int(mujoco.mjtJoint.mjJNT_HINGE), int(mujoco.mjtJoint.mjJNT_SLIDE))
    hinges = [j for j in range(m.njnt) if int(m.jnt_type[j]) in moving]
    assert len(hinges) == sum(len(bundle.assets[o.name].joints) for o in bundle.objects)
    for j in hinges:
        assert m.jnt_limited[j] and m.dof_damping[m.jnt_dofadr[j]] > 0
    # visual geoms never collide; collision geoms are the convex pieces
    vis = (m.geom_contype == 0) & (m.geom_conaffinity == 0)
    assert vis.any() and (~vis).any()
    d_ = mujoco.MjData(m)
    mujoco.mj_forward(m, d_)
    q0 = d_.qpos[[m.jnt_qposadr[j] for j in hinges]].copy()
    st = stability(simulate(d / "scene.xml"))
    assert st.passes, st
    # doors, flaps and drawers stay (nearly) shut under gravity
    for _ in range(1000):
        mujoco.mj_step(m, d_)
    q1 = d_.qpos[[m.jnt_qposadr[j] for j in hinges]]
    assert np.abs(q1 - q0).max() < 0.05


def test_fixed_objects_are_welded(exported):
    bundle, d, _ = exported["living_room"]
    m = mujoco.MjModel.from_xml_path(str(d / "scene.xml"))
    for o in bundle.objects:
        b = m.body(o.name)
        has_free = any(m.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE
                       for j in range(m.body_jntadr[b.id], m.body_jntadr[b.id] + m.body_jntnum[b.id]))
        assert has_free == (not bundle.is_fixed(o) and bundle.attachment(o) is None), o.name


def test_hung_garments_are_welded_in_their_wardrobe_and_its_fronts_open_clear_of_them(articulated):
    """A garment on the wardrobe's rail is a body inside the wardrobe's, with no joint: it stays
    on its hanger under gravity, and every door and drawer of the wardrobe opened to its limit
    touches none (the contacts the export excludes counted too)."""
    bundle, d = articulated
    m = mujoco.MjModel.from_xml_path(str(d / "scene.xml"))
    garments = [o.name for o in bundle.objects if o.generator == "hung_garment"]
    assert garments
    wardrobe = m.body("wardrobe_0").id
    for g in garments:
        b = m.body(g)
        assert m.body_parentid[b.id] == wardrobe and m.body_jntnum[b.id] == 0
    data = mujoco.MjData(m)
    mujoco.mj_forward(m, data)
    start = {g: data.xpos[m.body(g).id].copy() for g in garments}
    for _ in range(500):
        mujoco.mj_step(m, data)
    for g in garments:
        assert np.linalg.norm(data.xpos[m.body(g).id] - start[g]) < 0.01
    mujoco.mj_resetData(m, data)
    for j in range(m.njnt):
        if m.body_parentid[m.jnt_bodyid[j]] == wardrobe and m.jnt_limited[j]:
            data.qpos[m.jnt_qposadr[j]] = m.jnt_range[j][1]
    mujoco.mj_forward(m, data)
    ids = {m.body(g).id for g in garments}
    fronts = {b for b in range(m.nbody) if m.body_parentid[b] == wardrobe} - ids
    solid = (m.geom_contype != 0) | (m.geom_conaffinity != 0)
    hung = [k for k in range(m.ngeom) if solid[k] and m.geom_bodyid[k] in ids]
    moving = [k for k in range(m.ngeom) if solid[k] and m.geom_bodyid[k] in fronts]
    assert hung and moving
    for a in hung:  # measured apart from contacts: the export excludes these pairs
        for b in moving:
            assert mujoco.mj_geomDistance(m, data, a, b, 0.05, None) > -1e-3, (a, b)


def test_what_lies_in_a_drawer_is_welded_in_it_and_comes_out_with_it(articulated):
    bundle, d = articulated
    m = mujoco.MjModel.from_xml_path(str(d / "scene.xml"))
    drawer = m.body("dresser_0__drawer_0").id
    clothes = m.body("folded_clothes_0").id
    assert m.body_parentid[clothes] == drawer and m.body_jntnum[clothes] == 0
    data = mujoco.MjData(m)
    mujoco.mj_forward(m, data)
    start = data.xpos[[drawer, clothes]].copy()
    j = m.body_jntadr[drawer]
    data.qpos[m.jnt_qposadr[j]] = m.jnt_range[j][1]
    mujoco.mj_forward(m, data)
    moved = data.xpos[[drawer, clothes]] - start
    assert np.linalg.norm(moved[0]) > 0.1
    np.testing.assert_allclose(moved[1], moved[0], atol=1e-9)


def test_rugs_lie_fixed_and_furniture_stands_through_them(exported):
    """A rug is welded to the world with no collision geom: the sofa's and the dining chairs'
    legs standing on it stand on the floor through its pile."""
    rugs = 0
    for room in ("living_room", "dining_room"):
        bundle, d, _ = exported[room]
        m = mujoco.MjModel.from_xml_path(str(d / "scene.xml"))
        for o in bundle.objects:
            if not bundle.lies_under(o):
                continue
            rugs += 1
            b = m.body(o.name).id
            geoms = [g for g in range(m.ngeom) if m.geom_bodyid[g] == b]
            assert geoms and all(m.geom_contype[g] == 0 and m.geom_conaffinity[g] == 0 for g in geoms)
            assert m.body_jntnum[b] == 0
    assert rugs >= 1


def _architecture_only(seed: int, floors: int, out) -> ExportBundle:
    """Export the bare architecture (parametric doors and stairs, no furniture) of a cheaply
    annealed floorplan of `seed` as MJCF into `out`: floors, ceilings and walls are where
    degenerate collision pieces come from (L-shaped rooms, stairwells)."""
    plan = generate_floorplan(seed, FloorplanConfig(
        floors=floors, anneal=FloorplanAnnealConfig(steps_per_storey=20)))
    scene = Scene(seed=seed)
    bundle = make_bundle(scene, {}, elements_from_architecture(scene, solidify(plan)))
    write_formats(bundle, out, "mjcf", texture_resolution=16)
    return bundle


#: (storeys, seed) of cheap floorplans whose architecture MuJoCo must compile: 1-, 2- and
#: 3-storey plans over many seeds (about a second each), 2-storey 6, 8 and 11 among them, which
#: MuJoCo refused before collision pieces were made sound (0.1 um slivers of floors and
#: ceilings: "coplanar vertices")
ARCHITECTURE_PLANS = ([(1, s) for s in range(6)] + [(2, s) for s in range(12)] + [(3, 0)])


@pytest.mark.parametrize(("floors", "seed"), ARCHITECTURE_PLANS)
def test_mujoco_compiles_every_architecture(floors, seed, tmp_path):
    bundle = _architecture_only(seed, floors, tmp_path)
    # the pieces fill the solid, no more: a hull over a ring of walls would swallow the room
    for el in bundle.static_elements:
        if el.kind in ("floor", "ceiling", "wall"):
            solid = sum(part.mesh.volume for part in el.parts)
            pieces = sum(p.volume for p in bundle.element_pieces(el))
            assert np.isclose(pieces, solid, rtol=2e-3, atol=1e-6), el.path
    m = mujoco.MjModel.from_xml_path(str(tmp_path / "scene.xml"))
    collision = (m.geom_contype != 0) | (m.geom_conaffinity != 0)
    assert collision.sum() > 20
    # no collision piece thinner than the exporter's floor
    sizes = m.geom_size[collision & (m.geom_type == mujoco.mjtGeom.mjGEOM_BOX)]
    assert (sizes.min(axis=1) >= MIN_THICKNESS / 2 - 1e-9).all()


@pytest.mark.slow
@pytest.mark.xdist_group("export_homes")
@pytest.mark.parametrize("home", ["home1", "home2"])
def test_homes_compile_and_stay_still(exported_homes, home):
    bundle, d = exported_homes[home]
    moved = simulate(d / "scene.xml")
    # every object a free body but those fixed to a wall or to another's link (hung clothes)
    assert len(moved) == sum(1 for o in bundle.objects
                             if not bundle.is_fixed(o) and bundle.attachment(o) is None)
    st = stability(moved)
    log.warning("%s: %d free bodies, %.1f%% moved < 2 cm, max %.3f m (%s)", home, st.free,
                100 * st.under_2cm, st.max_m, st.worst)
    assert st.passes, st
