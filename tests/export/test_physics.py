"""Mass properties for simulators: the vectorised moments against trimesh's per-mesh ones."""
from __future__ import annotations

import numpy as np
import trimesh

from indoorgen.assets import get_factory
from indoorgen.export.bundle import object_materials
from indoorgen.export.physics import (
    density_of,
    link_inertials,
    piece_slots,
    volume_integrals,
    wall_masses,
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


def test_link_inertials_sum_their_pieces():
    """A dresser's links: mass is the shell volume (capped by the pieces') at the pieces' mean
    density, capped by the link's mass as a hollow wall, and the centre of mass is the
    density-weighted mean of the pieces' centres."""
    f = get_factory("dresser")
    params = f.sample_params(np.random.default_rng(3))
    asset = f.create(params)
    obj = SceneObject("dresser_0", "dresser", params, 3, Pose(), [], "room")
    mats = {slot: ref.name for slot, ref in object_materials(obj, asset).items()}
    got = link_inertials(asset, mats)
    walls = wall_masses(asset, mats)
    slots = piece_slots(asset)
    assert set(got) == set(asset.links) and len(asset.links) > 1
    for link in asset.links:
        pieces = [(p, asset.slots[s] if s < len(asset.slots) else "body")
                  for (lk, p), s in zip(asset.collision, slots, strict=True) if lk == link]
        rho = np.array([density_of(mats[s]) if s in mats else 1000.0 for _, s in pieces])
        vols = np.array([p.volume for p, _ in pieces])
        coms = np.array([p.center_mass for p, _ in pieces])
        assert np.allclose(got[link].com, (rho * vols) @ coms / (rho * vols).sum(), atol=1e-9)
        shell = asset.link_mesh(link)
        volume = min(shell.volume, vols.sum()) if shell.is_volume else vols.sum()
        density = (rho * vols).sum() / vols.sum()
        assert np.isclose(got[link].mass, min(volume * density, walls[link]), rtol=1e-6)
        w = np.linalg.eigvalsh(got[link].inertia)
        assert np.all(w > 0)


#: household objects' real masses (kg): (generator, lightest, heaviest), from retailers' sheets
REAL_MASSES = [("sofa", 25.0, 110.0), ("dining_chair", 3.0, 12.0), ("glass_tumbler", 0.1, 0.5),
               ("wineglass", 0.08, 0.4), ("book", 0.1, 2.5), ("fridge", 40.0, 160.0),
               ("toilet", 15.0, 50.0), ("tv", 4.0, 35.0), ("can", 0.05, 1.0)]


def test_masses_are_real_objects_masses():
    """Hollow things weigh their walls: a sofa is tens of kg, not half a tonne (issue 12)."""
    for gen, lo, hi in REAL_MASSES:
        f = get_factory(gen)
        for seed in range(3):
            params = f.sample_params(np.random.default_rng(seed))
            asset = f.create(params)
            obj = SceneObject(f"{gen}_0", gen, params, seed, Pose(), [], "room")
            mats = {slot: ref.name for slot, ref in object_materials(obj, asset).items()}
            mass = sum(i.mass for i in link_inertials(asset, mats).values())
            assert lo <= mass <= hi, (gen, seed, mass)
