"""Mass properties for simulators: the vectorised moments against trimesh's per-mesh ones."""
from __future__ import annotations

import numpy as np
import trimesh

from indoorgen.assets import get_factory
from indoorgen.assets.protocol import Asset
from indoorgen.export.bundle import object_materials
from indoorgen.export.physics import (
    AXES_SNAP,
    Inertial,
    density_of,
    link_inertials,
    object_inertials,
    piece_slots,
    slot_wall_masses,
    volume_integrals,
)
from indoorgen.model.scene import Pose, SceneObject


def _props(mesh: trimesh.Trimesh) -> tuple[float, np.ndarray, np.ndarray]:
    m = volume_integrals(np.asarray(mesh.triangles)).sum(axis=0)
    vol, com = m[0], m[1:4] / m[0]
    xx, yy, zz = m[4:7] - vol * com ** 2
    xy, yz, zx = m[7:10] - vol * com * np.roll(com, -1)
    inertia = np.array([[yy + zz, -xy, -zx], [-xy, xx + zz, -yz], [-zx, -yz, xx + yy]])
    return vol, com, inertia


def test_volume_integrals_match_trimesh_on_posed_solids():
    rot = trimesh.transformations.euler_matrix(0.3, -0.7, 1.1)
    rot[:3, 3] = [0.4, -1.2, 2.0]
    for mesh in (trimesh.creation.box([0.3, 0.5, 1.1]),
                 trimesh.creation.cylinder(0.2, 0.6, sections=24),
                 trimesh.creation.icosphere(2, 0.35)):
        mesh.apply_transform(rot)
        vol, com, inertia = _props(mesh)
        ref = mesh.mass_properties
        assert np.isclose(vol, ref.volume, rtol=1e-9)
        assert np.allclose(com, ref.center_mass, atol=1e-9)
        assert np.allclose(inertia, ref.inertia, atol=1e-9)


def _dresser() -> tuple:
    f = get_factory("dresser")
    params = f.sample_params(np.random.default_rng(3))
    asset = f.create(params)
    obj = SceneObject("dresser_0", "dresser", params, 3, Pose(), [], "room")
    return asset, {slot: ref.name for slot, ref in object_materials(obj, asset).items()}


def test_link_inertials_sum_their_pieces():
    """A dresser's links: mass is the shell volume (capped by the pieces') at the pieces' mean
    density, capped per material by its pieces' mass as a hollow wall; the centre of mass is
    the closed render shell's, and the inertia the pieces' moved there (parallel axes)."""
    asset, mats = _dresser()
    got = link_inertials(asset, mats)
    walls = slot_wall_masses(asset, mats)
    slots = piece_slots(asset)
    assert set(got) == set(asset.links) and len(asset.links) > 1
    for link in asset.links:
        pieces = [(p, s) for (lk, p), s in zip(asset.collision, slots, strict=True) if lk == link]
        rho = np.array([density_of(mats[asset.slots[s]]) for _, s in pieces])
        vols = np.array([p.volume for p, _ in pieces])
        shell = asset.link_mesh(link)
        assert shell.is_volume
        lo, hi = shell.bounds
        assert np.all((got[link].com >= lo) & (got[link].com <= hi))
        volume = min(shell.volume, vols.sum())
        density = (rho * vols).sum() / vols.sum()
        solid = np.bincount([s for _, s in pieces], weights=rho * vols,
                            minlength=len(asset.slots))
        owned = np.isin(np.arange(len(asset.slots)), [s for _, s in pieces])
        hollow = np.where(owned, np.minimum(solid, walls[link]), walls[link]).sum()
        assert np.isclose(got[link].mass, min(volume * density, hollow), rtol=1e-6)
        # the pieces' inertia about the pieces' centre, moved to the shell's
        piece_com = (rho * vols) @ np.array([p.center_mass for p, _ in pieces]) / (rho * vols).sum()
        about = [trimesh.Trimesh(p.vertices - piece_com, p.faces) for p, _ in pieces]
        moved = sum(r * (m.moment_inertia + m.volume * (
            (m.center_mass @ m.center_mass) * np.eye(3) - np.outer(m.center_mass, m.center_mass)))
            for m, r in zip(about, rho, strict=True))
        d = got[link].com - piece_com
        want = moved * got[link].mass / (rho * vols).sum() + got[link].mass * (
            (d @ d) * np.eye(3) - np.outer(d, d))
        assert np.allclose(got[link].inertia, want, atol=1e-6)


def test_centre_of_mass_is_the_shells_not_the_hulls():
    """A lamp: a 2 cm foot under a shade whose convex piece is a solid drum. The centre of mass
    is the render shell's centroid, low in the foot; the pieces' would sit in the drum."""
    foot = trimesh.creation.box([0.2, 0.2, 0.02])
    foot.apply_translation([0, 0, 0.01])
    outer = trimesh.creation.cylinder(0.15, 0.2, sections=32)
    inner = trimesh.creation.cylinder(0.148, 0.2, sections=32)
    inner.invert()
    shade = trimesh.util.concatenate([outer, inner])
    shade.apply_translation([0, 0, 0.4])
    mesh = trimesh.util.concatenate([foot, shade])
    slots = np.repeat([0, 1], [len(foot.faces), len(shade.faces)])
    asset = Asset(mesh, [], face_slots=slots, slots=["metal", "shade"],
                  collision=[("base", foot), ("base", outer.copy().apply_translation([0, 0, 0.4]))])
    mats = {"metal": "brushed_steel", "shade": "paper"}
    got = link_inertials(asset, mats)["base"]
    m_foot, m_shade = foot.volume, shade.volume
    want = (m_foot * 0.01 + m_shade * 0.4) / (m_foot + m_shade)
    assert np.allclose(got.com, [0, 0, want], atol=1e-6)
    assert got.com[2] < 0.2  # the pieces' centre: 0.38 m
    assert _triangle_inequality(got.inertia)


def _triangle_inequality(inertia: np.ndarray) -> bool:
    a, b, c = np.sort(np.linalg.eigvalsh(inertia))
    return bool(a > 0 and a + b >= c * (1 - 1e-9))


def test_inertias_are_physical_and_lamps_stand_on_their_feet():
    """Every link's inertia is a physical tensor (MuJoCo checks A + B >= C), and a lamp's
    centre of mass lies low over its weighted foot, not in its shade's hull (issue 12: lamps
    tipped in Newton)."""
    for gen in ("table_lamp", "floor_lamp", "desk_lamp", "shower_enclosure", "table_clock",
                "dresser", "sofa"):
        f = get_factory(gen)
        for seed in range(4):
            params = f.sample_params(np.random.default_rng(seed))
            asset = f.create(params)
            obj = SceneObject(f"{gen}_0", gen, params, seed, Pose(), [], "room")
            mats = {slot: ref.name for slot, ref in object_materials(obj, asset).items()}
            for link, inertial in object_inertials(asset, mats, f.tags).items():
                assert _triangle_inequality(inertial.inertia), (gen, seed, link)
            if gen in ("table_lamp", "floor_lamp"):
                # the weight low in the foot (the pieces' centre: above half the height), and
                # the foot wide enough to tip only past 14 degrees
                base = object_inertials(asset, mats, f.tags)["base"]
                foot = np.sqrt(asset.surface("bottom").polygon.area / np.pi)
                assert base.com[2] < 0.35 * float(asset.extents[2]), (seed, base.com)
                assert foot > 0.25 * base.com[2], (gen, seed, foot, base.com)


#: household objects' real masses (kg): (generator, lightest, heaviest), from retailers' sheets
REAL_MASSES = [("sofa", 25.0, 110.0), ("dining_chair", 3.0, 12.0), ("glass_tumbler", 0.1, 0.5),
               ("wineglass", 0.08, 0.4), ("book", 0.1, 2.5), ("fridge", 40.0, 160.0),
               ("toilet", 15.0, 50.0), ("tv", 4.0, 35.0), ("can", 0.05, 1.0),
               ("shower_enclosure", 40.0, 200.0), ("table_lamp", 1.5, 7.0),
               ("desk_lamp", 1.0, 4.0), ("floor_lamp", 3.5, 10.0), ("bed", 40.0, 140.0),
               ("bathtub_alcove", 25.0, 70.0), ("bathtub_corner", 25.0, 70.0),
               ("food_box", 0.1, 1.0)]


def test_masses_are_real_objects_masses():
    """Hollow things weigh their walls: a sofa is tens of kg, not half a tonne (issue 12)."""
    for gen, lo, hi in REAL_MASSES:
        f = get_factory(gen)
        for seed in range(3):
            params = f.sample_params(np.random.default_rng(seed))
            asset = f.create(params)
            obj = SceneObject(f"{gen}_0", gen, params, seed, Pose(), [], "room")
            mats = {slot: ref.name for slot, ref in object_materials(obj, asset).items()}
            mass = sum(i.mass for i in object_inertials(asset, mats, f.tags).values())
            assert lo <= mass <= hi, (gen, seed, mass)


def test_principal_axes_are_the_bodys_own_unless_products_matter():
    # a round pot: two nearly equal moments and near-zero products, which left the eigen-solver
    # a general rotation that Newton rebuilt asymmetric in float32
    pot = np.array([[1.0996, 2e-4, 0.0], [2e-4, 1.09995, 0.0], [0.0, 0.0, 0.5036]])
    moments, axes = Inertial(28.0, np.zeros(3), pot).diagonalised()
    assert (axes == np.eye(3)).all() and np.allclose(moments, np.diag(pot))
    # a tensor with real products: the eigen-axes, a proper rotation diagonalising it
    turned = trimesh.transformations.rotation_matrix(0.4, [0, 0, 1])[:3, :3]
    tensor = turned @ np.diag([0.2, 0.5, 0.6]) @ turned.T
    assert np.abs(tensor - np.diag(np.diag(tensor))).max() > AXES_SNAP * 0.6
    moments, axes = Inertial(5.0, np.zeros(3), tensor).diagonalised()
    assert np.isclose(np.linalg.det(axes), 1.0)
    assert np.allclose(axes @ np.diag(moments) @ axes.T, tensor)
