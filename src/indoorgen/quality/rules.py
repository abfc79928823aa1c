"""Layout rules about what a room holds and at what height: lights, their headroom and their
place off the walls, the kitchen sink, the work triangle, continuous counter runs, wall cabinets
and hoods, bathroom accessories, and everyday objects within reach.

Each rule is a function `Context -> list[Check]` registered with `context.rule`; its constants
name their source.
"""
from __future__ import annotations

import itertools

import numpy as np
import shapely.geometry as sg
from shapely.ops import polylabel

from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart
from indoorgen.programs.contents import EVERYDAY, REACH_HEIGHT
from indoorgen.programs.relations import LIGHT_FROM_WALLS, LIGHT_HEADROOM
from indoorgen.programs.rooms.kitchen import IN_RUN, TRIANGLE_LEG
from indoorgen.quality.context import Check, Context, Placed, is_wall_hung, on_floor, rule

#: room types that need no light of their own: a balcony is open to the sky and lit through the
#: home's windows and doors (closets, hallways and garages are dark without one, so they do)
UNLIT_ROOM_TYPES = frozenset({"balcony"})
#: NKBA Kitchen Planning Guideline 4 (work triangle): legs TRIANGLE_LEG (the kitchen program's),
#: sum <= 26 ft
TRIANGLE_SUM = 7.9
#: NKBA: wall cabinets 15-18 in above a 36 in counter, i.e. bottoms at 1.35-1.5 m
WALL_CABINET_BOTTOM = (1.35, 1.5)
#: range hood (HVI / manufacturers' installation guides): centred on the range, its bottom
#: 24-36 in (0.6-0.9 m) above the cooking surface
HOOD_OFFSET = 0.15
HOOD_HEIGHT = (0.6, 0.9)
#: NKBA Bathroom Planning Guideline 19 / ADA: toilet-paper holder 15-26 in; we use the common
#: 0.6-0.75 m (24-30 in) to its centre; towel bars at 1.0-1.2 m (40-48 in)
ROLL_HOLDER_HEIGHT = (0.6, 0.75)
TOWEL_BAR_HEIGHT = (1.0, 1.2)
#: light sources: anything tagged lighting (ceiling lights, pendants, lamps, sconces)
LIGHTS = (S.Lighting, S.CeilingLight, S.PendantLight, S.FloorLamp, S.TableLamp, S.DeskLamp,
          S.WallSconce)
SINKS = (S.KitchenSink, S.BathroomSink)
#: a hanging light's bottom over a table: this far over its top at least (lighting guidance
#: hangs a pendant 30-36 in over a dining table; 0.7 m allows 28 in); over open floor, the
#: programs' `relations.LIGHT_HEADROOM`
OVER_TABLE = 0.7
#: what a light may hang low over
TABLES = (S.Table, S.KitchenIsland, S.Desk)
COOKING = (S.Range, S.Cooktop)


@rule("room_has_light", hard=True)
def room_has_light(ctx: Context) -> list[Check]:
    """Every room (but a balcony) holds a light source; value: how many."""
    out = []
    for rn in sorted(ctx.scene.rooms):
        if ctx.room_type(rn) in UNLIT_ROOM_TYPES:
            continue
        lights = ctx.in_room(rn, *LIGHTS)
        out.append(Check(rn, tuple(p.name for p in lights[:3]), float(len(lights)), ">= 1",
                         bool(lights)))
    return out


@rule("light_headroom")
def light_headroom(ctx: Context) -> list[Check]:
    """A light hanging from the ceiling leaves headroom: its bottom LIGHT_HEADROOM above the
    floor, or, over a table (its plan centre within the table's footprint), OVER_TABLE above the
    tabletop; value: its bottom's height above the floor."""
    out = []
    for p in ctx.with_tags(S.CeilingMounted):
        if not p.has(S.Lighting):
            continue
        centre = sg.Point(p.xy)
        under = [t for t in ctx.in_room(p.obj.room, *TABLES) if t.footprint.contains(centre)]
        least = max([t.top - t.floor + OVER_TABLE for t in under], default=LIGHT_HEADROOM)
        least = min(least, LIGHT_HEADROOM)
        bottom = p.bottom - p.floor
        out.append(Check(p.obj.room, (p.name, *(t.name for t in under)), bottom, least,
                         bottom >= least - 1e-6))
    return out


#: in a room narrower than twice LIGHT_FROM_WALLS, a ceiling light this share of the way from
#: the walls to the room's middle (its pole of inaccessibility) at least
TOWARDS_MIDDLE = 0.8


@rule("light_off_the_walls")
def light_off_the_walls(ctx: Context) -> list[Check]:
    """A ceiling light hangs over the room, not by a wall: its centre LIGHT_FROM_WALLS or more
    from the walls, or, in a narrower room, TOWARDS_MIDDLE of the way to the room's middle;
    value: its centre's distance to the walls (m)."""
    out = []
    for p in ctx.with_tags(S.CeilingMounted):
        if not p.has(S.Lighting):
            continue
        walls = sg.Polygon(ctx.scene.rooms[p.obj.room].polygon)
        middle = polylabel(walls, tolerance=0.01).distance(walls.exterior)
        least = min(LIGHT_FROM_WALLS, TOWARDS_MIDDLE * middle)
        away = sg.Point(p.xy).distance(walls.exterior)
        out.append(Check(p.obj.room, (p.name,), round(away, 4), least, away >= least - 1e-6))
    return out


@rule("kitchen_has_sink", hard=True)
def kitchen_has_sink(ctx: Context) -> list[Check]:
    """Every kitchen holds a sink; value: how many."""
    out = []
    for rn in sorted(ctx.scene.rooms):
        if ctx.room_type(rn) == "kitchen":
            sinks = ctx.in_room(rn, *SINKS)
            out.append(Check(rn, tuple(p.name for p in sinks), float(len(sinks)), ">= 1",
                             bool(sinks)))
    return out


def _front_centre(p: Placed) -> np.ndarray:
    """World plan point at the middle of the object's front face (where one stands to use it)."""
    return p.world_point((p.hi[0], (p.lo[1] + p.hi[1]) / 2))


@rule("kitchen_work_triangle")
def kitchen_work_triangle(ctx: Context) -> list[Check]:
    """Sink, range and fridge front centres form legs of 1.2-2.7 m summing to <= 7.9 m (the
    tightest such triple of a kitchen); value: the sum, detail: the legs. Kitchens missing one
    of the three are skipped (the sink rule already fails)."""
    out = []
    for rn in sorted(ctx.scene.rooms):
        if ctx.room_type(rn) != "kitchen":
            continue
        groups = [ctx.in_room(rn, *SINKS), ctx.in_room(rn, *COOKING), ctx.in_room(rn, S.Fridge)]
        if not all(groups):
            continue
        best = None
        for triple in itertools.product(*groups):
            pts = [_front_centre(p) for p in triple]
            legs = [float(np.linalg.norm(pts[i] - pts[(i + 1) % 3])) for i in range(3)]
            key = (sum(legs), [p.name for p in triple])
            if best is None or key < best[0]:
                best = (key, triple, legs)
        assert best is not None
        (total, _), triple, legs = best
        ok = total <= TRIANGLE_SUM and all(TRIANGLE_LEG[0] <= g <= TRIANGLE_LEG[1] for g in legs)
        out.append(Check(rn, tuple(p.name for p in triple), total,
                         {"leg": list(TRIANGLE_LEG), "sum_max": TRIANGLE_SUM}, ok,
                         {"sink_range": legs[0], "range_fridge": legs[1], "fridge_sink": legs[2]}))
    return out


#: what a kitchen's counter runs are made of: base units and the appliances set into them
RUN_MEMBERS = (S.KitchenCabinet, S.KitchenSink, S.Range, S.Dishwasher)


@rule("counter_runs")
def counter_runs(ctx: Context) -> list[Check]:
    """In a kitchen, every base unit, sink, range, dishwasher and fridge standing on the floor
    joins a continuous counter run: within 5 cm (the program's IN_RUN) of another base unit or
    appliance of the run (the fridge closing its end); value: that gap (m)."""
    out = []
    for rn in sorted(ctx.scene.rooms):
        if ctx.room_type(rn) != "kitchen":
            continue
        standing = [p for p in ctx.in_room(rn, *RUN_MEMBERS, S.Fridge)
                    if on_floor(p.obj) and not p.has(S.KitchenIsland, S.WallCabinet)]
        run = [p for p in standing if not p.has(S.Fridge)]
        for p in standing:
            gap = min((float(p.footprint.distance(q.footprint)) for q in run if q is not p),
                      default=None)
            out.append(Check(rn, (p.name,), gap, IN_RUN, gap is not None and gap <= IN_RUN))
    return out


def _in_range(v: float, lim: tuple[float, float]) -> bool:
    return lim[0] - 1e-6 <= v <= lim[1] + 1e-6


@rule("wall_cabinet_height")
def wall_cabinet_height(ctx: Context) -> list[Check]:
    """Kitchen wall cabinets hang with their bottoms 1.35-1.5 m above the floor; value: bottom."""
    return [Check(p.obj.room, (p.name,), p.bottom - p.floor, list(WALL_CABINET_BOTTOM),
                  _in_range(p.bottom - p.floor, WALL_CABINET_BOTTOM))
            for p in ctx.with_tags(S.WallCabinet) if ctx.room_type(p.obj.room) == "kitchen"]


def cooking_height(p: Placed) -> float:
    """World z of a range's or cooktop's cooking surface (its highest support surface, else its
    top)."""
    z = p.surface_height(Subpart.SupportSurface, "cooktop")
    return p.top if z is None else z


@rule("hood_over_range")
def hood_over_range(ctx: Context) -> list[Check]:
    """A hood is centred over a range (its centre within 0.15 m of the range's axis, measured along
    the range's width: a wall hood is shallower than the range, so front-to-back offset says
    nothing) with its bottom 0.6-0.9 m above the cooking surface; value: the offset, detail: the
    height. A hood with no range fails."""
    out = []
    for h in ctx.with_tags(S.RangeHood):
        ranges = ctx.in_room(h.obj.room, *COOKING)
        hc = np.asarray(h.footprint.centroid.coords[0])
        r = min(ranges, key=lambda q: (float(np.linalg.norm(
            np.asarray(q.footprint.centroid.coords[0]) - hc)), q.name), default=None)
        if r is None:
            out.append(Check(h.obj.room, (h.name,), None, "a range below", False))
            continue
        offset = float(abs(r.local_point(hc)[1] - (r.lo[1] + r.hi[1]) / 2))
        height = h.bottom - cooking_height(r)
        out.append(Check(h.obj.room, (h.name, r.name), offset,
                         {"offset_max": HOOD_OFFSET, "height": list(HOOD_HEIGHT)},
                         offset <= HOOD_OFFSET and _in_range(height, HOOD_HEIGHT),
                         {"height": height}))
    return out


@rule("accessory_heights")
def accessory_heights(ctx: Context) -> list[Check]:
    """Toilet-roll holders' centres at 0.6-0.75 m, towel bars' at 1.0-1.2 m above the floor, and
    wall mirrors in a room with a sink hung above a sink (centred within its width, bottom above
    its top); value: the centre height, or for a mirror its plan offset from the sink's axis."""
    out = []
    for tag, lim in ((S.ToiletRollHolder, ROLL_HOLDER_HEIGHT), (S.TowelBar, TOWEL_BAR_HEIGHT)):
        for p in ctx.with_tags(tag):
            h = (p.bottom + p.top) / 2 - p.floor
            out.append(Check(p.obj.room, (p.name,), h, list(lim), _in_range(h, lim)))
    for m in ctx.with_tags(S.Mirror):
        sinks = ctx.in_room(m.obj.room, *SINKS)
        if not sinks or not is_wall_hung(m.obj):
            continue
        best = None
        for s in sinks:
            local = s.local_point(np.asarray(m.footprint.centroid.coords[0]))
            lateral = abs(local[1] - (s.lo[1] + s.hi[1]) / 2)
            ok = lateral <= (s.hi[1] - s.lo[1]) / 2 and m.bottom >= s.top - 0.01
            key = (not ok, lateral, s.name)
            if best is None or key < best[0]:
                best = (key, s, lateral, ok)
        assert best is not None
        _, s, lateral, ok = best
        out.append(Check(m.obj.room, (m.name, s.name), lateral, "within the sink's width, above it",
                         ok, {"bottom_above_sink": m.bottom - s.top}))
    return out


@rule("reach")
def reach(ctx: Context) -> list[Check]:
    """Everyday small objects (laptops, remotes, tableware, books, kitchenware, food) rest on a
    surface no higher than 1.6 m above the floor; value: that surface's height."""
    out = []
    for p in ctx.with_tags(*EVERYDAY):
        if not p.has(S.SmallObject) or not p.obj.relations:
            continue
        h = p.bottom - p.floor
        out.append(Check(p.obj.room, (p.name, p.obj.parent), h, REACH_HEIGHT,
                         h <= REACH_HEIGHT + 1e-6))
    return out

