"""Solid architecture of a whole home, room by room, in world coordinates (Z up).

For each room this builds a `HomeRoomGeometry`, which is a `architecture.room.RoomGeometry` (same
attributes and methods), so the object solver and the validator furnish a room of a home exactly
as they furnish a single room:

- `room`: a `scene.Room` whose polygon is the room's free floor (inside the wall faces), with
  its doors and open connections as `scene.Door`s on that polygon's edges, `storey` and
  `elevation` set;
- `floor`/`ceiling`: slabs under and over the room's share of the storey (the staircase opening
  cut where a flight passes);
- `walls`: the room's share of the storey's walls (its half of each interior wall, the inner
  half of each exterior wall plus the outer half beside it), with door, opening, window and
  front-door holes cut by manifold3d booleans;
- `surfaces`: "floor", "ceiling" and "wall_<i>" (one per edge of the free polygon), normals into
  the room, as `build_room` makes them;
- `door_zones`: keep-out regions: each door's swing and clearance (deeper on the side it opens
  into), a strip in front of open connections, and the stairs with their landings and a lane
  beside them (`stair_circulation`).

Doors, windows and stairs are separate `Element`s (a simple parametric door leaf with casing, a
window frame with glass, straight stair flights with guard rails round the floor opening where
no wall guards it, `rail_sides`). A catalogue door's leaf is its own part ("leaf", with its convex
pieces in `leaf_collision`) on a `joint` (world coordinates, 0 = shut), standing at `state`
(`architecture.doors`: open, closed, random, or the values a saved scene recorded);
`Architecture.door_states` collects them. Garages' vehicle doors are cut in their exterior walls
and closed by a sectional door (`_vehicle_door_element`).
"""
from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping
from dataclasses import dataclass, field

import manifold3d
import numpy as np
import shapely.geometry as sg
import trimesh

from indoorgen.architecture import fixtures
from indoorgen.architecture.doors import check_door_mode, door_value, posed
from indoorgen.architecture.room import (
    SLAB_THICKNESS,
    RoomGeometry,
    ceiling_surface,
    floor_surface,
    wall_surfaces,
)
from indoorgen.architecture.solids import checked_mesh, extrude_region, subtract, to_trimesh
from indoorgen.architecture.walls import (
    WallFrame,
    WallThickness,
    door_frame,
    entrance_frame,
    exterior_frame,
    free_polygon,
    outer_outline,
    room_region,
    wall_footprint,
    window_frame,
)
from indoorgen.assets.protocol import Joint, Surface
from indoorgen.model.floorplan import DoorSpec, Floorplan, StairSpec, Storey, VehicleDoor
from indoorgen.model.polygons import cross_2d, largest_polygon
from indoorgen.model.scene import Door, Room

#: Depth of the keep-out zone on the side a door swings into, and on the other side (m).
SWING_DEPTH = 1.0
PASS_DEPTH = 0.6
#: Clear floor kept at the foot and the head of a flight (m; the plan leaves
#: `floorplan.stairs.LANDING`, 1.1 m, between a flight's end and the staircase room's wall).
STAIR_LANDING = 1.0
#: Guard rail height and thickness (m).
RAIL_HEIGHT = 1.0
RAIL_THICKNESS = 0.05
#: Door leaf thickness and casing profile (m).
LEAF = 0.04
CASING = 0.06
#: A sectional garage door's panel thickness (m).
VEHICLE_PANEL = 0.04


@dataclass
class Element:
    """An architectural element for export: `meshes` by part name, in world coordinates."""

    name: str
    kind: str          # "door" | "window" | "stair" | "railing"
    room: str
    storey: int
    meshes: dict[str, trimesh.Trimesh]
    semantics: list[str] = field(default_factory=list)
    generator: str = ""  # the catalogue generator that made it ("" for the simple solids)
    params: dict = field(default_factory=dict)
    #: convex collision pieces in world coordinates (a catalogue asset's own); empty: exporters
    #: decompose `meshes` themselves
    collision: list[trimesh.Trimesh] = field(default_factory=list)
    #: a door's leaf joint (world coordinates, 0 = shut) and the value the "leaf" part and
    #: `leaf_collision` stand at
    joint: Joint | None = None
    state: float = 0.0
    leaf_collision: list[trimesh.Trimesh] = field(default_factory=list)

    @classmethod
    def of(cls, fx, name: str, kind: str, room: str, storey: int, semantics: list[str],
           state: float = 0.0) -> Element:
        """An element holding a catalogue fixture's mesh (and a door's leaf at `state`)."""
        el = cls(name, kind, room, storey, {kind: fx.mesh}, semantics, fx.generator,
                 dict(fx.params), list(fx.collision))
        if fx.joint is not None and fx.leaf is not None:
            el.joint, el.state = fx.joint, float(state)
            el.meshes["leaf"] = posed(fx.leaf, fx.joint, el.state)
            el.leaf_collision = [posed(p, fx.joint, el.state) for p in fx.leaf_collision]
        return el


@dataclass
class HomeRoomGeometry(RoomGeometry):
    """`RoomGeometry` of one room of a home, plus where it is: `storey`, `elevation` (its floor's
    z) and `plan_polygon` (the partition polygon walls are centred on)."""

    storey: int = 0
    elevation: float = 0.0
    plan_polygon: sg.Polygon | None = None
    #: each window's world box (2, 3: min, max corners): the solver keeps a zone before it free
    windows: list[np.ndarray] = field(default_factory=list)
    #: the collision pieces of the door leaves that stand in this room at their state (an open
    #: leaf against the wall beside its opening): solids nothing may overlap, like the walls
    leaves: list[trimesh.Trimesh] = field(default_factory=list)

    def collision_meshes(self) -> list[trimesh.Trimesh]:
        """Every solid the solver must not penetrate: walls, floor and ceiling slabs, and the
        door leaves standing in the room."""
        return [*super().collision_meshes(), *self.leaves]

    def door_zone_meshes(self, height: float = 2.0) -> list[trimesh.Trimesh]:
        """Keep-out zones extruded from the room's floor to `height` above it."""
        return [to_trimesh(extrude_region(z, self.elevation, self.elevation + height))
                for z in self.door_zones if not z.is_empty]


@dataclass
class Architecture:
    """A solidified home: per-room geometry plus doors, windows, stairs."""

    floorplan: Floorplan
    rooms: dict[str, HomeRoomGeometry]
    elements: list[Element]
    walls: WallThickness

    @property
    def door_states(self) -> dict[str, float]:
        """Each articulated door's joint value by door name (what scene.json records)."""
        return {e.name: round(e.state, 6) for e in self.elements if e.joint is not None}


# --------------------------------------------------------------------------------------------
# elements


def _box(frame: WallFrame, width: float, depth: float, z0: float, z1: float) -> manifold3d.Manifold:
    """A box `width` along the wall and `depth` across it, centred on the frame, z0..z1."""
    rect = frame.rect(width, -depth / 2, depth / 2)
    return extrude_region(rect, z0, z1)


def _door_element(d: DoorSpec, frame: WallFrame, storey: Storey) -> Element:
    """A door leaf (closed, in the wall's centre plane) and its casing."""
    e = storey.elevation
    leaf = _box(frame, d.width - 0.02, LEAF, e + 0.01, e + d.height - 0.005)
    outer = _box(frame, d.width + 2 * CASING, frame.thickness + 0.02, e, e + d.height + CASING)
    inner = _box(frame, d.width, frame.thickness + 0.2, e - 0.01, e + d.height)
    casing = subtract(outer, [inner])
    return Element(d.name, "door", d.rooms[0], storey.level,
                   {"leaf": checked_mesh(leaf, d.name), "casing": checked_mesh(casing, d.name)},
                   ["door", "architecture"])


def _window_element(name: str, room: str, frame: WallFrame, storey: Storey, width: float,
                    height: float, sill: float) -> Element:
    e = storey.elevation
    outer = _box(frame, width, frame.thickness + 0.02, e + sill, e + sill + height)
    inner = _box(frame, width - 0.1, frame.thickness + 0.2, e + sill + 0.05,
                 e + sill + height - 0.05)
    glass = _box(frame, width - 0.1, 0.01, e + sill + 0.05, e + sill + height - 0.05)
    return Element(name, "window", room, storey.level,
                   {"frame": checked_mesh(subtract(outer, [inner]), name),
                    "glass": checked_mesh(glass, name)}, ["window", "architecture"])


def _vehicle_door_element(name: str, v: VehicleDoor, frame: WallFrame, storey: Storey
                          ) -> Element:
    """A garage's sectional door, closed: horizontal panels in the wall's outer half (as a
    sectional door runs behind the opening), and a frame round the opening."""
    e = storey.elevation
    outer_face = frame.thickness / 2 - VEHICLE_PANEL
    n_panels = 4
    rise = v.height / n_panels
    panels = [extrude_region(frame.rect(v.width - 0.01, outer_face - VEHICLE_PANEL, outer_face),
                             e + 0.01 + i * rise, e + (i + 1) * rise - 0.005)
              for i in range(n_panels)]
    panel = manifold3d.Manifold.batch_boolean(panels, manifold3d.OpType.Add)
    outer = _box(frame, v.width + 2 * CASING, frame.thickness + 0.02, e, e + v.height + CASING)
    inner = _box(frame, v.width, frame.thickness + 0.2, e - 0.01, e + v.height)
    return Element(name, "vehicle_door", v.room, storey.level,
                   {"panel": checked_mesh(panel, name),
                    "casing": checked_mesh(subtract(outer, [inner]), name)},
                   ["door", "garage_door", "architecture"])


def stair_profile(rise: float, run: float, max_riser: float = 0.19,
                  thickness: float = 0.3) -> tuple[np.ndarray, int]:
    """Side profile (s along the flight, z up) of a straight flight climbing `rise` over `run`:
    a sawtooth of risers and treads over a sloped underside; returns (points, risers)."""
    n = max(2, int(math.ceil(rise / max_riser - 1e-9)))
    hr, td = rise / n, run / n  # the top tread lies flush with the upper floor
    pts = [(0.0, 0.0)]
    for i in range(n):
        pts += [(i * td, (i + 1) * hr), ((i + 1) * td, (i + 1) * hr)]
    pts += [(run, rise - thickness), (min(0.5, run / 4), 0.0)]
    return np.asarray(pts[::-1]), n  # counter-clockwise


def _stair_element(st: StairSpec, fp: Floorplan, pitch: float) -> Element:
    """A straight flight on its footprint, climbing from its storey's floor to the next."""
    lower = next(s for s in fp.storeys if s.level == st.from_level)
    p0, up, right, run, width = st.frame()
    prof, _ = stair_profile(pitch, run)
    cs = manifold3d.CrossSection([np.ascontiguousarray(prof)], manifold3d.FillRule.Positive)
    solid = manifold3d.Manifold.extrude(cs, width)      # (s, z, w)
    mesh = checked_mesh(solid, f"stair {st.from_level}->{st.to_level}")
    m = np.eye(4)
    m[:3, 0] = [up[0], up[1], 0.0]
    m[:3, 1] = [0.0, 0.0, 1.0]
    m[:3, 2] = [right[0], right[1], 0.0]
    m[:3, 3] = [p0[0], p0[1], lower.elevation]
    mesh.apply_transform(m)
    if np.linalg.det(m[:3, :3]) < 0:
        mesh.invert()
    a, _ = fp.stair_rooms(st)
    return Element(f"stair_{st.from_level}_{st.to_level}", "stair", a or "", st.from_level,
                   {"flight": mesh}, ["stairs", "architecture"])


def stair_circulation(st: StairSpec) -> sg.Polygon:
    """The floor kept free round a flight on both its storeys: the flight (or its stairwell),
    STAIR_LANDING at its foot and its head, and a lane as wide as the flight on either side,
    where one walks between the landings and the staircase room's doors."""
    p0, up, right, run, width = st.frame()
    a0, a1, b0, b1 = -STAIR_LANDING, run + STAIR_LANDING, -width, 2 * width
    return sg.Polygon([p0 + a * up + b * right for a, b in ((a0, b0), (a1, b0), (a1, b1),
                                                             (a0, b1))])


def rail_sides(st: StairSpec, fp: Floorplan, walls: WallThickness | None = None
               ) -> list[tuple[np.ndarray, np.ndarray]]:
    """The sides of a flight's stairwell on its upper storey that need a guard rail: all but
    the head (where one steps off) and those lying on the staircase room's outline, where its
    wall already guards the drop; a side running up to a wall ends at the wall's face (the
    thicker, outside one of `walls`)."""
    p = np.asarray(st.polygon, float)  # bl, br, tr, tl
    sides = [(p[0], p[1]), (p[1], p[2]), (p[3], p[0])]
    upper = next((s for s in fp.storeys if s.level == st.to_level), None)
    _, b = fp.stair_rooms(st)
    if upper is None or b is None:
        return sides
    shape = upper.room(b).shape()
    inner = shape.buffer(-(walls or WallThickness()).exterior / 2, join_style="mitre")
    out = []
    for a, c in sides:
        if shape.exterior.distance(sg.Point((a + c) / 2)) <= 1e-3:
            continue
        kept = sg.LineString([a, c]).intersection(inner)
        if isinstance(kept, sg.LineString) and kept.length > RAIL_THICKNESS:
            u, v = np.asarray(kept.coords, float)[[0, -1]]
            out.append((u, v))
    return out


def _rail_element(st: StairSpec, fp: Floorplan, walls: WallThickness) -> Element | None:
    """Guard rails round the floor opening of a flight on the upper storey (`rail_sides`)."""
    upper = next((s for s in fp.storeys if s.level == st.to_level), None)
    sides = rail_sides(st, fp, walls)
    if upper is None or not sides:
        return None
    e = upper.elevation
    rails = []
    for u, v in sides:
        line = sg.LineString([u, v])
        rails.append(extrude_region(line.buffer(RAIL_THICKNESS / 2, cap_style="flat"),
                                   e, e + RAIL_HEIGHT))
    solid = manifold3d.Manifold.batch_boolean(rails, manifold3d.OpType.Add)
    _, head_room = fp.stair_rooms(st)
    return Element(f"rail_{st.from_level}_{st.to_level}", "railing", head_room or "", st.to_level,
                   {"rail": checked_mesh(solid, "stair rail")}, ["railing", "architecture"])


# --------------------------------------------------------------------------------------------
# rooms


def _door_on_free_edge(free: sg.Polygon, frame: WallFrame, into: np.ndarray, width: float
                       ) -> tuple[int, float] | None:
    """The edge of the free polygon on which an opening of `frame` lies (seen from the room
    on side `into`), and the opening centre's offset along it."""
    face = frame.center + into * frame.thickness / 2
    pts = np.asarray(free.exterior.coords)[:-1]
    q = np.roll(pts, -1, axis=0)
    d = q - pts
    length = np.linalg.norm(d, axis=1)
    best = None
    for i in range(len(pts)):
        if length[i] < 1e-9 or abs(cross_2d(d[i] / length[i], frame.u)) > 1e-3:
            continue
        s = float(np.dot(face - pts[i], d[i]) / length[i])
        dist = abs(cross_2d(d[i] / length[i], face - pts[i]))
        if (-width / 2 <= s <= length[i] + width / 2 and dist < frame.thickness / 2 + 0.05
                and (best is None or dist < best[2])):
            off = float(np.clip(s, min(width / 2, length[i] / 2),
                                max(length[i] - width / 2, length[i] / 2)))
            best = (i, off, dist)
    return None if best is None else best[:2]


def solidify(fp: Floorplan, walls: WallThickness | None = None, pitch: float | None = None,
             seed: int | None = None, doors: str | Mapping[str, float] = "open"
             ) -> Architecture:
    """Build every room's geometry and the doors, windows and stairs of `fp`.

    `pitch` is the floor-to-floor distance (default: the difference of the first two storeys'
    elevations, or height + 2 slab thicknesses). With a `seed`, doors, windows, stairs and
    railings come from the asset catalogue (each from its own child stream of the seed); without
    one, or where a generator is missing, they are simple parametric solids. `doors` sets how
    far each catalogue door's leaf stands open: a mode of `architecture.doors.DOOR_MODES` or
    recorded joint values by door name. Raises InvalidGeometryError when a door or window does
    not sit on a suitable wall, ConfigError for an unknown door mode."""
    if isinstance(doors, str):
        check_door_mode(doors)
    t = walls or WallThickness()
    if pitch is None:
        pitch = (fp.storeys[1].elevation - fp.storeys[0].elevation) if len(fp.storeys) > 1 \
            else fp.storeys[0].height + 2 * SLAB_THICKNESS
    depth = fp.room_depths()
    rooms: dict[str, HomeRoomGeometry] = {}
    elements: list[Element] = []
    for st in fp.stairs:
        elements += _stair_elements(st, fp, pitch, seed, t)
    for storey in fp.storeys:
        rooms.update(_solidify_storey(fp, storey, t, depth, elements, seed, doors))
    return Architecture(fp, rooms, elements, t)


def _stair_elements(st: StairSpec, fp: Floorplan, pitch: float, seed: int | None,
                    walls: WallThickness) -> list[Element]:
    """The flight (catalogue staircase or a simple solid) and the rails round its opening,
    ending at the faces of `walls`."""
    lower = next(s for s in fp.storeys if s.level == st.from_level)
    upper = next((s for s in fp.storeys if s.level == st.to_level), None)
    a, b = fp.stair_rooms(st)
    name = f"stair_{st.from_level}_{st.to_level}"
    fx = None if seed is None else fixtures.stair(seed, name, st.polygon, pitch, lower.elevation)
    out = [Element.of(fx, name, "stair", a or "", st.from_level, ["stairs", "architecture"])
           if fx is not None else _stair_element(st, fp, pitch)]
    if upper is None:
        return out
    sides = rail_sides(st, fp, walls)
    rails = [] if seed is None else [
        fixtures.railing(seed, f"rail_{st.from_level}_{st.to_level}_{i}", u, v,
                         upper.elevation) for i, (u, v) in enumerate(sides)]
    if rails and all(r is not None for r in rails):
        out += [Element.of(r, f"rail_{st.from_level}_{st.to_level}_{i}", "railing", b or "",
                           st.to_level, ["railing", "architecture"])
                for i, r in enumerate(rails)]
    else:
        rail = _rail_element(st, fp, walls)
        if rail is not None:
            out.append(rail)
    return out


def _door_state(fx: fixtures.Fixture | None, doors: str | Mapping[str, float],
                seed: int | None, name: str) -> float:
    """The joint value door `name`'s leaf stands at (0 without a jointed leaf)."""
    if fx is None or fx.joint is None:
        return 0.0
    return door_value(doors, seed, name, fx.joint)


def _solidify_storey(fp: Floorplan, storey: Storey, t: WallThickness, depth: dict[str, int],
                     elements: list[Element], seed: int | None,
                     doors_state: str | Mapping[str, float]) -> dict[str, HomeRoomGeometry]:
    e, h = storey.elevation, storey.height
    wall_fp = wall_footprint(storey, t)
    outline = storey.contour()
    outer = outer_outline(storey, t)
    # openings of this storey: (rooms they belong to, frame, cutter, zones per room)
    cut: dict[str, list[manifold3d.Manifold]] = {r.name: [] for r in storey.rooms}
    zones: dict[str, list[sg.Polygon]] = {r.name: [] for r in storey.rooms}
    doors: dict[str, list[Door]] = {r.name: [] for r in storey.rooms}
    windows: dict[str, list[np.ndarray]] = {r.name: [] for r in storey.rooms}
    frees = {r.name: free_polygon(r.shape(), wall_fp) for r in storey.rooms}

    def add_door(room: str, name: str, frame: WallFrame, side: np.ndarray, width: float,
                 height: float, zone_depth: float, zone_width: float) -> None:
        free = frees[room]
        where = _door_on_free_edge(free, frame, side, width)
        if where is not None:
            doors[room].append(Door(name, where[0], round(where[1], 6), width, height,
                                    zone_depth))
        rect = WallFrame(frame.center, frame.u, side, frame.thickness).rect(
            zone_width, 0.0, frame.thickness / 2 + zone_depth)
        z = rect.intersection(free)
        if not z.is_empty:
            zones[room].append(largest_polygon(z))

    for d in storey.doors:
        f = door_frame(storey, d, t)
        a, b = d.rooms
        swing_into = b if depth.get(b, 0) >= depth.get(a, 0) else a
        fx = None if seed is None else fixtures.door(
            seed, d.name, False, f.center, f.n if swing_into == b else -f.n, d.width,
            d.height, f.thickness, e)
        ow, oh = _opening(fx, d.width, d.height)
        cutter = _box(f, ow, 3 * t.exterior, e - 0.01, e + oh)
        for rn in d.rooms:
            cut[rn].append(cutter)
        for rn, side in ((a, -f.n), (b, f.n)):
            dep = SWING_DEPTH if rn == swing_into else PASS_DEPTH
            add_door(rn, d.name, f, side, d.width, d.height, dep, d.width + 0.2)
        elements.append(Element.of(fx, d.name, "door", swing_into, storey.level,
                                   ["door", "architecture"],
                                   _door_state(fx, doors_state, seed, d.name)) if fx is not None
                        else _door_element(d, f, storey))
    for o in storey.openings:
        f = door_frame(storey, o, t)
        cutter = _box(f, o.width, 3 * t.exterior, e - 0.01, e + h + 0.01)
        for rn, side in ((o.rooms[0], -f.n), (o.rooms[1], f.n)):
            cut[rn].append(cutter)
            add_door(rn, o.name, f, side, o.width, min(o.height, h), PASS_DEPTH, o.width)
    for w in storey.windows:
        f = window_frame(storey, w, t)
        fx = None if seed is None else fixtures.window(
            seed, w.name, f.center, -f.n, w.width, w.height, w.sill, f.thickness, e)
        ww, wh = _opening(fx, w.width, w.height)
        cut[w.room].append(_box(f, ww, 3 * t.exterior, e + w.sill, e + w.sill + wh))
        elements.append(Element.of(fx, w.name, "window", w.room, storey.level,
                                   ["window", "architecture"]) if fx is not None
                        else _window_element(w.name, w.room, f, storey, w.width, w.height,
                                             w.sill))
        windows[w.room].append(element_bounds(elements[-1]))
    if fp.entrance is not None and storey.level == 0:
        en = fp.entrance
        f = entrance_frame(storey, en, t)
        fx = None if seed is None else fixtures.door(
            seed, "entrance", True, f.center, -f.n, en.width, en.height, f.thickness, e)
        ow, oh = _opening(fx, en.width, en.height)
        cut[en.room].append(_box(f, ow, 3 * t.exterior, e - 0.01, e + oh))
        add_door(en.room, "entrance", f, -f.n, en.width, en.height, SWING_DEPTH, en.width + 0.2)
        elements.append(Element.of(fx, "entrance", "door", en.room, 0,
                                   ["door", "entrance", "architecture"],
                                   _door_state(fx, doors_state, seed, "entrance"))
                        if fx is not None else _door_element(
            DoorSpec("entrance", (en.room, en.room), en.center, en.width, en.height), f,
            storey))
    for v in fp.vehicle_doors if storey.level == 0 else []:
        f = exterior_frame(storey, v.room, v.center, t, f"the vehicle door of {v.room!r}")
        name = f"vehicle_door_{v.room}"
        cut[v.room].append(_box(f, v.width, 3 * t.exterior, e - 0.01, e + v.height))
        add_door(v.room, name, f, -f.n, v.width, v.height, SWING_DEPTH, v.width)
        elements.append(_vehicle_door_element(name, v, f, storey))
    # stairs: flights leave this storey (cut the ceiling) or arrive (cut the floor)
    floor_holes: list[sg.Polygon] = []
    ceil_holes: list[sg.Polygon] = []
    for st in fp.stairs:
        if storey.level not in (st.from_level, st.to_level):
            continue
        (ceil_holes if st.from_level == storey.level else floor_holes).append(st.shape())
        walk = stair_circulation(st)
        for r in storey.rooms:
            z = walk.intersection(frees[r.name])
            if z.area > 1e-6:
                zones[r.name].append(largest_polygon(z))
    out = {}
    for r in storey.rooms:
        poly = r.shape()
        region = room_region(poly, outline, t)
        region = region.intersection(outer)
        piece = wall_fp.intersection(region)
        wall = subtract(extrude_region(piece, e, e + h), cut[r.name])
        floor_region = region
        for hole in floor_holes:
            floor_region = floor_region.difference(hole)
        ceil_region = region
        for hole in ceil_holes:
            ceil_region = ceil_region.difference(hole)
        floor = extrude_region(floor_region, e - SLAB_THICKNESS, e)
        ceiling = extrude_region(ceil_region, e + h, e + h + SLAB_THICKNESS)
        free = frees[r.name]
        room = Room(r.name, r.type, [(float(x), float(y)) for x, y in
                                     np.asarray(free.exterior.coords)[:-1]],
                    height=h, wall_thickness=t.interior / 2, storey=storey.level,
                    doors=doors[r.name], elevation=e)
        lift = np.array([0.0, 0.0, e])
        surfaces = [_shift(floor_surface(free), lift), ceiling_surface(free, e + h),
                    *[_shift(s, lift) for s in wall_surfaces(room)]]
        out[r.name] = HomeRoomGeometry(
            room, checked_mesh(floor, f"{r.name} floor"), checked_mesh(ceiling, f"{r.name} ceiling"),
            [checked_mesh(wall, f"{r.name} walls")], surfaces, zones[r.name],
            storey=storey.level, elevation=e, plan_polygon=poly, windows=windows[r.name])
    return out


def element_bounds(e: Element) -> np.ndarray:
    """The world box (2, 3: min, max corners) round all of an element's meshes."""
    return np.array([np.min([m.bounds[0] for m in e.meshes.values()], axis=0),
                     np.max([m.bounds[1] for m in e.meshes.values()], axis=0)])


def _opening(fx: fixtures.Fixture | None, width: float, height: float) -> tuple[float, float]:
    """The rough opening (width, height) a catalogue door or window needs, or the plan's own
    for the simple solids."""
    if fx is None:
        return width, height
    assert fx.opening is not None  # doors and windows always state theirs
    return fx.opening


def _shift(s: Surface, lift: np.ndarray) -> Surface:
    return Surface(s.name, s.subpart, s.origin + lift, s.normal, s.u, s.polygon)


def room_geometries(arch: Architecture) -> dict[str, RoomGeometry]:
    """Per-room `RoomGeometry` objects of a home, keyed by room name (what `solver.State` and
    the validator take), each with the door leaves that stand in it."""
    leaves: dict[str, list[trimesh.Trimesh]] = {}
    for el in arch.elements:
        if el.kind == "door" and el.leaf_collision:
            leaves.setdefault(el.room, []).extend(el.leaf_collision)
    return {n: dataclasses.replace(g, leaves=leaves.get(n, [])) for n, g in arch.rooms.items()}

