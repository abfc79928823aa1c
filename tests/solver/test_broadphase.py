"""The solver's broadphase answers exactly what brute-force fcl does."""
from __future__ import annotations

import fcl
import numpy as np
import trimesh
from hypothesis import given, settings
from hypothesis import strategies as st

from indoorgen.assets.cache import convex_shape, mesh_bvh
from indoorgen.model.frames import yaw_matrix as rotation
from indoorgen.solver.broadphase import Broadphase, world_boxes


def _pieces(rng: np.random.Generator) -> list[trimesh.Trimesh]:
    """One to three convex pieces of an object (boxes and a cylinder), in its local frame."""
    out = []
    for _ in range(int(rng.integers(1, 4))):
        if rng.random() < 0.7:
            m = trimesh.creation.box(rng.uniform(0.1, 0.8, 3))
        else:
            m = trimesh.creation.cylinder(rng.uniform(0.05, 0.3), rng.uniform(0.1, 0.8), sections=12)
        m.apply_translation(rng.uniform(-0.3, 0.3, 3))
        out.append(m)
    return out


def _brute(objs: dict, static: list, name: str) -> bool:
    request = fcl.CollisionRequest()
    mine = objs[name][0]
    others = [c for n, (cs, _) in objs.items() if n != name for c in cs] + static
    return any(fcl.collide(a, b, request, fcl.CollisionResult()) > 0 for a in mine for b in others)


@settings(max_examples=25, deadline=None)
@given(st.integers(0, 10_000))
def test_random_adds_moves_and_removals_match_brute_force(seed):
    rng = np.random.default_rng(seed)
    wall = trimesh.creation.box([0.2, 4.0, 2.5])
    wall.apply_translation([2.0, 0.0, 1.25])
    static = [fcl.CollisionObject(mesh_bvh(wall), fcl.Transform())]
    bp = Broadphase(static, np.asarray(wall.bounds).reshape(1, 6))
    objs: dict[str, tuple[list, np.ndarray]] = {}
    local: dict[str, tuple[list, np.ndarray]] = {}

    def pose(name):
        r, t = rotation(rng.uniform(-np.pi, np.pi)), rng.uniform([-2, -2, 0], [2.5, 2, 1])
        _, boxes = local[name]
        for c in objs[name][0]:
            c.setTransform(fcl.Transform(r, t))
        return world_boxes(boxes, r, t)

    for step in range(30):
        action = rng.random()
        if action < 0.4 or len(objs) < 2:
            name = f"o{step}"
            meshes = _pieces(rng)
            local[name] = ([convex_shape(m) for m in meshes],
                           np.array([m.bounds for m in meshes]))
            objs[name] = ([fcl.CollisionObject(s, fcl.Transform()) for s in local[name][0]], None)
            boxes = pose(name)
            objs[name] = (objs[name][0], boxes)
            bp.add(name, objs[name][0], boxes)
        elif action < 0.8:
            name = sorted(objs)[int(rng.integers(len(objs)))]
            boxes = pose(name)
            objs[name] = (objs[name][0], boxes)
            bp.move(name, boxes)
        else:
            name = sorted(objs)[int(rng.integers(len(objs)))]
            bp.remove(name)
            del objs[name]
        for n in objs:
            assert bp.collides(n) == _brute(objs, static, n), (seed, step, n)


def test_world_boxes_contain_the_posed_pieces():
    rng = np.random.default_rng(4)
    for _ in range(20):
        meshes = _pieces(rng)
        r, t = rotation(rng.uniform(-np.pi, np.pi)), rng.uniform(-3, 3, 3)
        boxes = world_boxes(np.array([m.bounds for m in meshes]), r, t)
        for m, b in zip(meshes, boxes, strict=True):
            v = m.vertices @ r.T + t
            assert np.all(v >= b[:3] - 1e-9) and np.all(v <= b[3:] + 1e-9)
