"""The community's published scene measures, so results compare with papers:

- `collision_rate`: the share of objects that interpenetrate at least one other object by more
  than 1 mm ("object collision rate", Col_obj of PhyScene, Yang et al., CVPR 2024; SceneEval's
  object-collision metric, Tam et al., 2025);
- `out_of_bounds_rate`: the share of objects whose footprint leaves their room's outline by more
  than 1 cm, i.e. into or through a wall, or whose top passes the ceiling (R_out of PhyScene;
  SceneEval's "object out of bounds").

Both use the solver's placeholder convex pieces (which enclose the detailed meshes within 2 cm),
so they are cheap for a whole home.
"""
from __future__ import annotations

from typing import Any

import fcl
import numpy as np
import shapely.geometry as sg

from indoorgen.model.boxes import overlapping_pairs
from indoorgen.model.tags import Semantics as S
from indoorgen.quality.context import Context, Placed

#: interpenetration deeper than this counts as a collision (m)
PENETRATION_TOL = 0.001
#: leaving the room's outline (or passing its ceiling) by more than this is out of bounds (m)
BOUNDS_TOL = 0.01


def _pieces(ctx: Context, p: Placed) -> list[tuple[fcl.CollisionObject, np.ndarray]]:
    """`p`'s placeholder convex pieces as fcl objects at its pose, with their world boxes."""
    tf = fcl.Transform(p.obj.pose.rotation(), np.asarray(p.obj.pose.position, float))
    geoms = ctx.cache.placeholder_convex(p.obj.generator, p.obj.params)
    boxes = ctx.cache.placeholder_boxes(p.obj.generator, p.obj.params)
    out = []
    for g, b in zip(geoms, boxes, strict=True):
        corners = np.array([[x, y, z] for x in b[:, 0] for y in b[:, 1] for z in b[:, 2]])
        w = p.obj.pose.apply(corners)
        out.append((fcl.CollisionObject(g, tf), np.array([w.min(axis=0), w.max(axis=0)])))
    return out


def colliding_objects(ctx: Context) -> dict[str, tuple[str, float]]:
    """Each object that interpenetrates another by more than `PENETRATION_TOL`: (the other,
    depth). Rugs lie under furniture by design and are left out."""
    names = sorted(n for n, p in ctx.placed.items() if not p.has(S.FloorCovering))
    pieces = {n: _pieces(ctx, ctx.placed[n]) for n in names}
    boxes = np.array([[np.min([b[0] for _, b in pieces[n]], axis=0) if pieces[n] else np.zeros(3),
                       np.max([b[1] for _, b in pieces[n]], axis=0) if pieces[n] else np.zeros(3)]
                      for n in names]).reshape(-1, 2, 3)
    request = fcl.CollisionRequest(num_max_contacts=1, enable_contact=True)
    hits: dict[str, tuple[str, float]] = {}
    for i, j in overlapping_pairs(boxes, PENETRATION_TOL):
        a, b = names[i], names[j]
        depth = 0.0
        for oa, ba in pieces[a]:
            for ob, bb in pieces[b]:
                if np.any(ba[0] >= bb[1] - PENETRATION_TOL) or np.any(bb[0] >= ba[1] - PENETRATION_TOL):
                    continue
                res = fcl.CollisionResult()
                if fcl.collide(oa, ob, request, res):
                    depth = max([depth, *(float(c.penetration_depth) for c in res.contacts)])
        if depth > PENETRATION_TOL:
            for x, y in ((a, b), (b, a)):
                if depth > hits.get(x, ("", 0.0))[1]:
                    hits[x] = (y, depth)
    return hits


def out_of_bounds_objects(ctx: Context) -> dict[str, float]:
    """Each object whose footprint leaves its room's outline, or whose top passes its ceiling, by
    more than `BOUNDS_TOL`: how far (m)."""
    out: dict[str, float] = {}
    for n, p in sorted(ctx.placed.items()):
        room = ctx.scene.rooms.get(p.obj.room)
        if room is None:
            continue
        outline = ctx.outlines[p.obj.room]
        far = max((outline.exterior.distance(sg.Point(x, y))
                   for x, y in np.asarray(p.footprint.exterior.coords)
                   if not outline.contains(sg.Point(x, y))), default=0.0)
        far = max(far, p.top - (room.elevation + room.height))
        if far > BOUNDS_TOL:
            out[n] = float(far)
    return out


def community_measures(ctx: Context) -> dict[str, Any]:
    """collision_rate and out_of_bounds_rate over all objects, with the object count."""
    n = len(ctx.placed)
    hits, oob = colliding_objects(ctx), out_of_bounds_objects(ctx)
    return {"objects": n,
            "collision_rate": round(len(hits) / n, 4) if n else 0.0,
            "colliding": sorted(hits)[:50],
            "out_of_bounds_rate": round(len(oob) / n, 4) if n else 0.0,
            "out_of_bounds": sorted(oob)[:50]}
