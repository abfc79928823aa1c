"""Layout rules about free space: in front of storage and appliances, around a toilet, in the
sweep of every furniture door, drawer and lid at its open limit, and before windows.
"""
from __future__ import annotations

import fcl
import numpy as np
import shapely.geometry as sg
import trimesh

from indoorgen.architecture.solidify import element_bounds
from indoorgen.assets.cache import convex_shape
from indoorgen.assets.catalogue import get_factory
from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Asset, Joint
from indoorgen.model.tags import Semantics as S
from indoorgen.quality.context import (
    BAND_MARGIN,
    Check,
    Context,
    Placed,
    free_depth,
    is_wall_hung,
    on_floor,
    rule,
)
from indoorgen.solver.keep_free import (
    ACCESSORIES,
    FRONT_CLEAR,
    FRONT_CLEAR_WIDE,
    TOILET_FRONT,
    TOILET_SIDE,
    WIDE_FRONTS,
    WINDOW_DRESSINGS,
    WINDOW_SCREENS,
    WINDOW_TALL,
    open_limit,
    spins_in_place,
    window_zone,
)

#: an opened moving part may touch (not enter) a wall or object by this much (m)
SWEEP_TOL = 0.005


@rule("front_clearance")
def front_clearance(ctx: Context) -> list[Check]:
    """Floor-standing storage and appliances keep 0.6 m free before their fronts (0.9 m for a
    fridge, range or dishwasher), over their width, to the first wall or object (as the solver
    keeps them: a seat pulled up to it aside, one moves it to open the doors, and a towel rail or
    hook on the wall beside it, `ACCESSORIES`); value: the free depth."""
    out = []
    for p in ctx.with_tags(S.Storage, S.Appliance):
        if not on_floor(p.obj) or p.has(S.Box):
            continue
        need = FRONT_CLEAR_WIDE if p.has(*WIDE_FRONTS) else FRONT_CLEAR
        beside = {q.name for q in ctx.in_room(p.obj.room, *ACCESSORIES)}
        d = free_depth(ctx, p, exclude=ctx.pulled_up(p.name) | beside)
        out.append(Check(p.obj.room, (p.name,), d, need, d >= need - 1e-6))
    return out


def _side_clearance(ctx: Context, t: Placed) -> float:
    """Plan distance from a toilet's centreline (over its depth) to the nearest wall or obstacle
    beside it."""
    cy = (t.lo[1] + t.hi[1]) / 2
    x0, x1 = t.lo[0] + BAND_MARGIN, t.hi[0] - BAND_MARGIN  # the wall behind is not beside
    line = sg.LineString([(x0, cy), (x1, cy)])
    band = sg.box(x0, cy - 2.0, x1, cy + 2.0)
    skip = {t.name} | ctx.descendants(t.name) | {
        q.name for q in ctx.in_room(t.obj.room, *ACCESSORIES)}
    blockers = [ctx.walls_outside(t.obj.room)] + [
        q.footprint for q in ctx.obstacles(t.obj.room, skip)]
    d = 2.0
    for g in blockers:
        hit = t.to_local(g).intersection(band)
        if not hit.is_empty and hit.area > 1e-8:
            d = min(d, float(hit.distance(line)))
    return d


@rule("toilet_clearance")
def toilet_clearance(ctx: Context) -> list[Check]:
    """A toilet's centreline keeps 0.38 m from side walls and obstacles, with 0.53 m free in
    front; value: the side clearance, detail: the front depth."""
    out = []
    for t in ctx.with_tags(S.Toilet):
        side = _side_clearance(ctx, t)
        skip = {q.name for q in ctx.in_room(t.obj.room, *ACCESSORIES)}
        front = free_depth(ctx, t, exclude=skip)
        out.append(Check(t.obj.room, (t.name,), side,
                         {"side": TOILET_SIDE, "front": TOILET_FRONT},
                         side >= TOILET_SIDE - 1e-6 and front >= TOILET_FRONT - 1e-6,
                         {"front": front}))
    return out


def _world_pieces(ctx: Context, q: Placed) -> list[fcl.CollisionObject]:
    """`q`'s placeholder convex pieces as fcl objects at its pose."""
    tf = fcl.Transform(q.obj.pose.rotation(), np.asarray(q.obj.pose.position, float))
    return [fcl.CollisionObject(g, tf)
            for g in ctx.cache.placeholder_convex(q.obj.generator, q.obj.params)]


def _depth(a: fcl.CollisionObject, b: fcl.CollisionObject) -> float:
    """Penetration depth of two fcl solids (0 if apart)."""
    res = fcl.CollisionResult()
    if not fcl.collide(a, b, fcl.CollisionRequest(num_max_contacts=1, enable_contact=True), res):
        return 0.0
    return max((float(c.penetration_depth) for c in res.contacts), default=0.0)


def _open_link(asset: Asset, j: Joint, p: Placed) -> np.ndarray:
    """World vertices of a joint's moving link at its open limit (the end of larger travel)."""
    posed = asset.posed({j.name: open_limit(j)})
    idx = np.unique(asset.mesh.faces[asset.link_faces(j.child)])
    return p.obj.pose.apply(posed.vertices[idx])


@rule("joint_sweep")
def joint_sweep(ctx: Context) -> list[Check]:
    """Every furniture door, drawer and lid opened to its limit stays clear of the walls (its
    plan outline inside the room) and of the room's other objects (placeholder pieces, fcl);
    value: the deepest intrusion (m), detail: into the walls and into objects. Things resting
    on it or pulled up to it (a desk's chair) are not in its way, as in the solver. A part that
    spins in place (a chair's swivel) has no open limit and is not checked."""
    out = []
    for p in ctx.placed.values():
        fac = get_factory(p.obj.generator)
        if not isinstance(fac, PartsFactory) or not fac.joints(fac.resolve(p.obj.params)):
            continue  # only PartsFactory generators articulate; asking is cheaper than building
        asset = ctx.cache.full(p.obj.generator, p.obj.params)
        # what rests on it, and what is pulled up to it (a chair at a desk stands before its
        # drawers; one pushes it back to open them), as the solver's keep-free space allows
        skip = {p.name} | ctx.descendants(p.name)
        others = [q for q in ctx.in_room(p.obj.room) if q.name not in skip
                  and not q.has(S.FloorCovering)
                  and not any(r.parent == p.name for r in q.obj.relations)]
        outline = ctx.outlines[p.obj.room]
        for j in asset.joints:
            idx = np.unique(asset.mesh.faces[asset.link_faces(j.child)])
            if spins_in_place(j, asset.mesh.vertices[idx]):
                continue  # a swivel has no open pose: any turn of it is as good as its rest
            pts = _open_link(asset, j, p)
            wall = max((outline.exterior.distance(sg.Point(x, y)) for x, y in pts[:, :2]
                        if not outline.contains(sg.Point(x, y))), default=0.0)
            hull = trimesh.convex.convex_hull(pts)
            lo, hi = pts.min(axis=0), pts.max(axis=0)
            moved = fcl.CollisionObject(convex_shape(hull), fcl.Transform())
            worst, hit = 0.0, ""
            for q in others:
                qb = q.footprint.bounds
                if (qb[0] > hi[0] or qb[2] < lo[0] or qb[1] > hi[1] or qb[3] < lo[1]
                        or q.bottom > hi[2] or q.top < lo[2]):
                    continue
                d = max((_depth(moved, piece) for piece in _world_pieces(ctx, q)), default=0.0)
                if d > worst:
                    worst, hit = d, q.name
            value = max(wall, worst)
            names = (p.name, j.name) + ((hit,) if worst > SWEEP_TOL else ())
            out.append(Check(p.obj.room, names, value, SWEEP_TOL, value <= SWEEP_TOL,
                             {"into_wall": wall, "into_object": worst}))
    return out


@rule("windows_keep_out")
def windows_keep_out(ctx: Context) -> list[Check]:
    """No floor object taller than 1.0 m and nothing hung on the wall (window dressings aside:
    curtains hang there on purpose, `WINDOW_DRESSINGS`), and no screen wherever it stands
    (`WINDOW_SCREENS`: glare), is before a window opening, at its height: the solid of such an
    object between the opening's bottom and top, not its whole footprint (a sink's basin below
    the sill is not before the window, its tap beside it neither); value: the longest overlap
    along the window (m). Only for a home (windows come from its architecture)."""
    if ctx.architecture is None:
        return []
    out = []
    for e in sorted(ctx.architecture.elements, key=lambda e: e.name):
        if e.kind != "window" or e.room not in ctx.scene.rooms:
            continue
        bounds = element_bounds(e)
        zone, axis = window_zone(bounds)
        z0, z1 = bounds[0][2], bounds[1][2]
        hits: list[tuple[str, float]] = []
        for q in ctx.in_room(e.room):
            tall = on_floor(q.obj) and q.top - q.floor > WINDOW_TALL
            hung = is_wall_hung(q.obj) and not q.has(*WINDOW_DRESSINGS)
            if not (tall or hung or q.has(*WINDOW_SCREENS)) or q.top <= z0 or q.bottom >= z1:
                continue
            if not q.footprint.intersects(zone):
                continue
            inter = q.footprint_between(z0, z1).intersection(zone)
            if not inter.is_empty and inter.area > 1e-4:
                b = inter.bounds
                hits.append((q.name, b[2 + axis] - b[axis]))
        value = max((h for _, h in hits), default=0.0)
        out.append(Check(e.room, (e.name, *sorted(n for n, _ in hits)), value, 0.0, not hits))
    return out
