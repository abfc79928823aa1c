"""Mass properties for simulators: the vectorised moments against trimesh's per-mesh ones."""
from __future__ import annotations

import numpy as np
import trimesh

from indoorgen.assets import get_factory
from indoorgen.export.bundle import object_materials
from indoorgen.export.physics import density_of, link_inertials, piece_slots, volume_integrals
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
    density, and the centre of mass is the density-weighted mean of the pieces' centres."""
    f = get_factory("dresser")
    params = f.sample_params(np.random.default_rng(3))
    asset = f.create(params)
    obj = SceneObject("dresser_0", "dresser", params, 3, Pose(), [], "room")
    mats = {slot: ref.name for slot, ref in object_materials(obj, asset).items()}
    got = link_inertials(asset, mats)
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
        assert np.isclose(got[link].mass, volume * density, rtol=1e-6)
        w = np.linalg.eigvalsh(got[link].inertia)
        assert np.all(w > 0)
