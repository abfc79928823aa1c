"""Swap placeholders for full meshes and re-check collisions with them.

Placeholders are built to contain their full meshes, so this rarely finds anything; when it
does, the later-placed object of a colliding pair (and anything resting on it) is removed rather
than left interpenetrating. The architecture's keep-out volumes count as the solver counts
them: a window's zone only for what must keep out of it (`State.window_bound`), so a pendant
light by a window or a candle on a desk under it stays. A floor covering is checked against the
solid architecture and other floor coverings only: furniture stands on the floor through a
rug, and a door swings over it.
"""
from __future__ import annotations

import logging

import fcl

from indoorgen.assets.cache import mesh_bvh
from indoorgen.constraints.bounds import STAGE_ORDER
from indoorgen.model.frames import yaw_matrix
from indoorgen.model.tags import Semantics
from indoorgen.solver.broadphase import DOOR_ZONE, SCREEN_ZONE, WINDOW_ZONE
from indoorgen.solver.state import State

log = logging.getLogger(__name__)


def _hits(manager: fcl.DynamicAABBTreeCollisionManager, co: fcl.CollisionObject) -> bool:
    data = fcl.CollisionData(request=fcl.CollisionRequest())
    manager.collide(co, data, fcl.defaultCollisionCallback)
    return bool(data.result.is_collision)


def full_mesh_check(state: State) -> list[str]:
    """Remove objects whose full mesh collides; return the removed names."""
    # what stands on the floor, and what lies under it (each also meets the architecture)
    managers = {False: fcl.DynamicAABBTreeCollisionManager(),
                True: fcl.DynamicAABBTreeCollisionManager()}
    windows = fcl.DynamicAABBTreeCollisionManager()
    for co, kind in zip(state.static, state.static_kinds, strict=True):
        if kind == WINDOW_ZONE:
            windows.registerObject(co)
        elif kind != SCREEN_ZONE:  # where screens' stands keep out is a rule, not a solid
            for under, m in managers.items():
                if not (under and kind == DOOR_ZONE):  # a rug may lie where a door swings
                    m.registerObject(co)
    for m in (*managers.values(), windows):
        m.setup()
    last = len(STAGE_ORDER)  # an object of no known stage is checked after all the others
    names = sorted(state.objects, key=lambda n: (STAGE_ORDER.get(state.objects[n].stage, last), n))
    kept: set[str] = set()
    removed: list[str] = []
    for n in names:
        ob = state.objects[n]
        if any(p.parent in removed for p in ob.placements):
            removed.append(n)
            continue
        full = state.cache.full(ob.generator, ob.params)
        co = fcl.CollisionObject(mesh_bvh(full.mesh), fcl.Transform(yaw_matrix(ob.yaw), ob.position))
        manager = managers[Semantics.FloorCovering in ob.tags]
        if _hits(manager, co) or (state.window_bound(n) and _hits(windows, co)):
            log.warning("full mesh of %s collides; removing it", n)
            removed.append(n)
            continue
        manager.registerObject(co)
        kept.add(n)
    for n in removed:
        state.remove(n)
    return removed
