"""Layout rules about how furniture is arranged and grouped: the TV facing the seats at a viewing
distance, the coffee table before the sofa, nightstands at the bed's head, the bed's head to a
wall, dining chairs facing their table, matching sets (chairs at one table, nightstands at one
bed), and rugs under the group they belong to.
"""
from __future__ import annotations

import json
import math
from collections.abc import Iterator

import numpy as np
import shapely.geometry as sg

from indoorgen.assets.catalogue import get_factory
from indoorgen.assets.materials.slots import choose_materials
from indoorgen.model.tags import Semantics as S
from indoorgen.programs.rooms.living_room import VIEWING
from indoorgen.quality.context import Check, Context, Placed, angle_deg, rule

#: a TV and its seating face each other within 30 deg (viewing-angle guidance: THX / SMPTE
#: recommend seats within ~30-40 deg of the screen axis)
TV_ANGLE = 30.0
#: coffee table 0.3-0.6 m (12-18 in, up to 24 in) from the sofa front, square to it within 15 deg
#: (common furniture-layout guidance, e.g. Neufert / "Human Dimension & Interior Space")
COFFEE_GAP = (0.3, 0.6)
COFFEE_YAW = 15.0
#: nightstands within 0.15 m of the bed, beside its head (its first 0.7 m from the head)
NIGHTSTAND_GAP = 0.15
HEAD_ZONE = 0.7
#: a bed's head within 0.1 m of a wall
BED_WALL_GAP = 0.1
#: how far in from a seat's front its front legs stand, and in from a bed's sides and foot the
#: points a rug under it must reach (m)
LEG_INSET = 0.1
#: a bed's rug reaches under its lower two-thirds: the share of its length from the head where
#: the rug must begin at the latest (less a margin for a bed longer than the rug is sized for)
BED_RUG_FROM_HEAD = 0.4
#: the share of a group's anchor points (the coffee table's corners and the sofa's front legs;
#: the dining table's corners and its chairs' seats; a bed's lower part) that must lie on its
#: rug: layout guidance puts every one on it; a quarter may miss (a chair at a long table's end
#: pulled out past a round rug, a sofa leg at a short rug's edge)
RUG_SHARE = 0.75
#: a point this close (m) to a rug's outline counts as on it (placeholder hulls are polygons)
RUG_TOL = 0.02
#: a dining chair's front ray meets its table within 1 m (validate.py's FACING_REACH)
CHAIR_REACH = 1.0


def _centre(p: Placed) -> np.ndarray:
    return np.asarray(p.footprint.centroid.coords[0])


def _seats(ctx: Context, room: str) -> list[Placed]:
    """The room's sofas, else its armchairs (what a TV or coffee table is arranged around)."""
    return ctx.in_room(room, S.Sofa) or ctx.in_room(room, S.Armchair)


def _tv_seats(ctx: Context) -> Iterator[tuple[Placed, Placed, np.ndarray]]:
    """Each TV in a room with a sofa (else armchairs), the nearest of those seats, and the plan
    vector from the TV's centre to the seat's."""
    for tv in ctx.with_tags(S.TV):
        seats = _seats(ctx, tv.obj.room)
        if seats:
            c = _centre(tv)
            seat = min(seats, key=lambda q: (float(np.linalg.norm(_centre(q) - c)), q.name))
            yield tv, seat, _centre(seat) - c


@rule("tv_faces_seating")
def tv_faces_seating(ctx: Context) -> list[Check]:
    """Each TV in a room with a sofa (else armchairs) faces the nearest one within 30 deg, and
    that seat faces the TV within 30 deg; value: the larger of the two angles (deg)."""
    out = []
    for tv, seat, to_seat in _tv_seats(ctx):
        a_tv, a_seat = angle_deg(tv.front, to_seat), angle_deg(seat.front, -to_seat)
        out.append(Check(tv.obj.room, (tv.name, seat.name), max(a_tv, a_seat), TV_ANGLE,
                         max(a_tv, a_seat) <= TV_ANGLE, {"tv_angle": a_tv, "seat_angle": a_seat}))
    return out


def _yaw_misalignment(a: Placed, b: Placed) -> float:
    """Angle (deg) between the two objects' axes, modulo 90 deg for a near-square or round `b`
    and 180 deg otherwise (a rectangle turned half a turn is still aligned)."""
    d = math.degrees(abs(b.obj.pose.yaw - a.obj.pose.yaw))
    size = b.hi[:2] - b.lo[:2]
    period = 90.0 if min(size) > 0.87 * max(size) else 180.0
    d = d % period
    return min(d, period - d)


def _coffee_fit(sofa: Placed, table: Placed) -> tuple[bool, float, float, float]:
    """(ok, gap to the sofa front, lateral offset of the table centre from the sofa's axis, yaw
    misalignment) of `table` before `sofa`."""
    local = sofa.to_local(table.footprint)
    gap = local.bounds[0] - sofa.hi[0]
    cy = sofa.local_point(_centre(table))[1] - (sofa.lo[1] + sofa.hi[1]) / 2
    yaw = _yaw_misalignment(sofa, table)
    ok = (COFFEE_GAP[0] - 1e-6 <= gap <= COFFEE_GAP[1] + 1e-6
          and abs(cy) <= (sofa.hi[1] - sofa.lo[1]) / 2 and yaw <= COFFEE_YAW)
    return ok, gap, cy, yaw


@rule("coffee_table_in_front_of_sofa")
def coffee_table_in_front_of_sofa(ctx: Context) -> list[Check]:
    """Each coffee table lies before a sofa (else armchair): its centre within the sofa's width,
    its near edge 0.3-0.6 m from the sofa front, square to it within 15 deg; value: the gap to
    the best-fitting seat (negative: beside or behind its front)."""
    out = []
    for t in ctx.with_tags(S.CoffeeTable):
        seats = _seats(ctx, t.obj.room)
        if not seats:
            out.append(Check(t.obj.room, (t.name,), None, "a sofa", False))
            continue
        fits = sorted((not f[0], abs(f[1] - sum(COFFEE_GAP) / 2) + abs(f[2]), s.name, f, s)
                      for s in seats for f in [_coffee_fit(s, t)])
        *_, (ok, gap, lateral, yaw), seat = fits[0]
        out.append(Check(t.obj.room, (t.name, seat.name), gap,
                         {"gap": list(COFFEE_GAP), "yaw_max": COFFEE_YAW}, ok,
                         {"lateral": lateral, "yaw": yaw}))
    return out


def _beside_head(bed: Placed, stand: Placed) -> tuple[bool, float, float]:
    """(ok, footprint distance, centre's distance from the head) of `stand` beside `bed`'s head:
    within 0.15 m, its centre in the bed's first 0.7 m from the head and outside its width."""
    gap = float(bed.footprint.distance(stand.footprint))
    u, v = bed.local_point(_centre(stand))
    ok = (gap <= NIGHTSTAND_GAP and -0.1 <= u - bed.lo[0] <= HEAD_ZONE
          and abs(v - (bed.lo[1] + bed.hi[1]) / 2) >= (bed.hi[1] - bed.lo[1]) / 2 - 0.05)
    return ok, gap, float(u - bed.lo[0])


def _bed_of(ctx: Context, stand: Placed) -> tuple[Placed, bool, float, float] | None:
    """The bed `stand` belongs to (the best-fitting of its room's beds), with (ok, gap, distance
    from the head)."""
    fits = sorted((not ok, gap, b.name, b, ok, u) for b in ctx.in_room(stand.obj.room, S.Bed)
                  for ok, gap, u in [_beside_head(b, stand)])
    if not fits:
        return None
    _, gap, _, bed, ok, u = fits[0]
    return bed, ok, gap, u


@rule("nightstand_by_bed")
def nightstand_by_bed(ctx: Context) -> list[Check]:
    """Each nightstand in a room with a bed stands within 0.15 m of the bed, beside its head;
    value: the gap between their footprints."""
    out = []
    for n in ctx.with_tags(S.Nightstand):
        fit = _bed_of(ctx, n)
        if fit is not None:
            bed, ok, gap, from_head = fit
            out.append(Check(n.obj.room, (n.name, bed.name), gap,
                             {"gap_max": NIGHTSTAND_GAP, "from_head": [-0.1, HEAD_ZONE]}, ok,
                             {"from_head": from_head}))
    return out


@rule("bed_head_to_wall")
def bed_head_to_wall(ctx: Context) -> list[Check]:
    """Each bed's head (back face) lies within 0.1 m of a wall along its whole width; value: the
    larger distance of its two back corners from the room outline."""
    out = []
    for b in ctx.with_tags(S.Bed):
        ring = ctx.outlines[b.obj.room].exterior
        corners = [b.world_point((b.lo[0], y)) for y in (b.lo[1], b.hi[1])]
        d = max(float(ring.distance(sg.Point(c))) for c in corners)
        out.append(Check(b.obj.room, (b.name,), d, BED_WALL_GAP, d <= BED_WALL_GAP))
    return out


def _table_of(ctx: Context, chair: Placed) -> Placed | None:
    """The dining table `chair` is pulled up to (its relation's parent), if any."""
    for r in chair.obj.relations:
        t = ctx.placed.get(r.parent)
        if t is not None and t.has(S.DiningTable):
            return t
    return None


@rule("dining_chairs_face_table")
def dining_chairs_face_table(ctx: Context) -> list[Check]:
    """Each chair pulled up to a dining table faces it: a ray from the seat along its front meets
    the table's footprint within 1 m; value: the distance to the table along that ray."""
    out = []
    for c in ctx.with_tags(S.Chair):
        t = _table_of(ctx, c)
        if t is None:
            continue
        ray = sg.LineString([c.xy, c.xy + c.front * CHAIR_REACH])
        hit = ray.intersection(t.footprint)
        d = None if hit.is_empty else float(sg.Point(c.xy).distance(hit))
        out.append(Check(c.obj.room, (c.name, t.name), d, CHAIR_REACH, d is not None))
    return out


def design(p: Placed, style: str | None = None) -> str:
    """An object's design: its generator, params and the materials its seed draws in the home's
    `style` (what makes two objects look identical)."""
    fac = get_factory(p.obj.generator)
    mats = choose_materials(list(p.asset.slots), np.random.default_rng(p.obj.seed),
                            fac.material_choices, style)
    return json.dumps([p.obj.generator, p.obj.params, mats], sort_keys=True, default=str)


@rule("matching_sets")
def matching_sets(ctx: Context) -> list[Check]:
    """The chairs pulled up to one dining table, and the nightstands beside one bed, share one
    design (generator, params and materials); value: how many distinct designs the set has."""
    groups: dict[tuple[str, str], list[Placed]] = {}
    for c in ctx.with_tags(S.Chair):
        t = _table_of(ctx, c)
        if t is not None:
            groups.setdefault((c.obj.room, t.name), []).append(c)
    for n in ctx.with_tags(S.Nightstand):
        fit = _bed_of(ctx, n)
        if fit is not None and fit[2] <= 1.0:
            groups.setdefault((n.obj.room, fit[0].name), []).append(n)
    out = []
    for (room, anchor), members in sorted(groups.items()):
        if len(members) < 2:
            continue
        k = len({design(m, ctx.scene.style) for m in members})
        out.append(Check(room, (anchor, *sorted(m.name for m in members)), float(k), 1, k == 1))
    return out


@rule("viewing_distance")
def viewing_distance(ctx: Context) -> list[Check]:
    """Each TV in a room with a sofa (else armchairs) is 1.8-3.5 m from the nearest, centre to
    centre in plan (1.5-2.5 times a living room's screen diagonal); value: that distance (m)."""
    out = []
    for tv, seat, to_seat in _tv_seats(ctx):
        d = float(np.linalg.norm(to_seat))
        out.append(Check(tv.obj.room, (tv.name, seat.name), d, list(VIEWING),
                         VIEWING[0] <= d <= VIEWING[1]))
    return out


def _local_points(p: Placed, pts: list[tuple[float, float]]) -> list[np.ndarray]:
    """Local plan points of `p` in world coordinates."""
    return [p.world_point(q) for q in pts]


def _corners(p: Placed, inset: float = 0.0) -> list[np.ndarray]:
    """The corners of `p`'s local bounding box in plan, `inset` in from its edges, in world."""
    return _local_points(p, [(x, y) for x in (p.lo[0] + inset, p.hi[0] - inset)
                             for y in (p.lo[1] + inset, p.hi[1] - inset)])


def _group_anchors(ctx: Context, rug: Placed) -> tuple[Placed, list[np.ndarray]] | None:
    """The group `rug` lies under (the room's sofa, dining table or bed it overlaps most) and
    that group's anchor points: what should stand on the rug."""
    room = rug.obj.room
    owners = [q for q in ctx.in_room(room, S.Sofa, S.DiningTable, S.Bed)
              if q.footprint.intersects(rug.footprint)]
    if not owners:
        return None
    owner = max(owners, key=lambda q: (q.footprint.intersection(rug.footprint).area, q.name))
    if owner.has(S.Sofa):
        front = [(float(owner.hi[0] - LEG_INSET), float(y)) for y in (owner.lo[1] + LEG_INSET,
                                                         owner.hi[1] - LEG_INSET)]
        tables = [t for t in ctx.in_room(room, S.CoffeeTable)
                  if _coffee_fit(owner, t)[0]]
        pts = _local_points(owner, front) + [c for t in tables for c in _corners(t)]
        return owner, pts
    if owner.has(S.DiningTable):
        chairs = [c for c in ctx.with_tags(S.Chair) if _table_of(ctx, c) is owner]
        return owner, _corners(owner) + [_centre(c) for c in chairs]
    head = owner.lo[0] + BED_RUG_FROM_HEAD * (owner.hi[0] - owner.lo[0])
    lower = [(float(x), float(y)) for x in (head, owner.hi[0] - LEG_INSET)
             for y in (owner.lo[1] + LEG_INSET, owner.hi[1] - LEG_INSET)]
    return owner, _local_points(owner, lower)


@rule("rug_under_group")
def rug_under_group(ctx: Context) -> list[Check]:
    """Each rug lies under a group, not alone: under the sofa's front legs and the coffee table,
    under a dining table and its chairs, or under a bed's lower two-thirds; value: the share of
    the group's anchor points on the rug (0: under no group)."""
    out = []
    for rug in ctx.with_tags(S.Rug):
        found = _group_anchors(ctx, rug)
        if found is None:
            out.append(Check(rug.obj.room, (rug.name,), 0.0, RUG_SHARE, False))
            continue
        owner, pts = found
        area = rug.footprint.buffer(RUG_TOL)
        share = float(np.mean([area.contains(sg.Point(q)) for q in pts]))
        out.append(Check(rug.obj.room, (rug.name, owner.name), share, RUG_SHARE,
                         share >= RUG_SHARE, {"anchors": float(len(pts))}))
    return out
