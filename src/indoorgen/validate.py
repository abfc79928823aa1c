"""An independent check of a generated scene, sharing none of the solver's bookkeeping.

It rebuilds every object's *full* mesh from (generator, params) and the room from its polygon,
then checks with manifold3d booleans and plain geometry:

- no two meshes (objects, walls, floor, ceiling) interpenetrate by more than 1 mm (furniture
  stands on the floor through a rug: a floor covering meets only the architecture and other
  floor coverings);
- every object rests on or hangs from its declared parent surface within 5 mm;
- every door's clearance zone is free of objects (but rugs, which a door swings over);
- dining chairs face the table they are pulled up to;
- the room's constraint program, evaluated from scratch, has no hard violation (its circulation
  constraint included, as the solver adds it: `solver.circulation`).

`ok` is that physical and program validity. The layout-quality rules (`quality.layout`) are
reported beside it as `quality` and `quality_passed`: a scene can be physically valid and still
fail a design rule (a kitchen with no sink), and the report says so.
"""
from __future__ import annotations

from pathlib import Path
from typing import Any

import manifold3d
import numpy as np
import shapely
import shapely.geometry as sg
import trimesh

from indoorgen.architecture.rebuild import scene_architecture
from indoorgen.assets import get_factory
from indoorgen.assets.cache import AssetCache
from indoorgen.assets.protocol import Asset, Surface
from indoorgen.constraints.evaluator import Evaluator
from indoorgen.constraints.relations import CONTACT_GAP, CoPlanar, StableAgainst, parse_relation
from indoorgen.constraints.sets import scene as scene_set
from indoorgen.errors import ConfigError
from indoorgen.export.scene_files import read_scene
from indoorgen.model.boxes import overlapping_pairs
from indoorgen.model.scene import Scene, SceneObject
from indoorgen.model.tags import Semantics
from indoorgen.model.walkable import band_outlines
from indoorgen.programs import ROOM_PROGRAMS
from indoorgen.quality.layout import quality_report
from indoorgen.quality.navigation import navigation_report
from indoorgen.solver.circulation import with_circulation
from indoorgen.solver.state import state_from_scene

PENETRATION_TOL = 0.001
SUPPORT_TOL = 0.005
#: how far in front of a dining chair its table must begin (m)
FACING_REACH = 1.0
#: door clearance zones are kept free up to this height (m)
DOOR_ZONE_TOP = 2.0


def _manifold(mesh: trimesh.Trimesh) -> manifold3d.Manifold:
    return manifold3d.Manifold(manifold3d.Mesh(
        vert_properties=np.asarray(mesh.vertices, np.float32),
        tri_verts=np.asarray(mesh.faces, np.uint32)))


def _penetration(a: manifold3d.Manifold, b: manifold3d.Manifold) -> float:
    """Smallest extent of the intersection volume's bounding box (0 if they don't overlap)."""
    inter = a ^ b
    if inter.is_empty() or inter.volume() < 1e-12:
        return 0.0
    lo, hi = np.array(inter.bounding_box()[:3]), np.array(inter.bounding_box()[3:])
    return float(np.min(hi - lo))


def _world(scene_obj, mesh: trimesh.Trimesh) -> trimesh.Trimesh:
    m = mesh.copy()
    m.apply_transform(scene_obj.pose.matrix())
    return m


def validate_scene(scene: Scene, *, program_check: bool = True) -> dict[str, Any]:
    """Check `scene`; return a report with `ok` and the list of problems found per check."""
    rooms, architecture = scene_architecture(scene)
    meshes, assets = {}, {}
    for n, o in scene.objects.items():
        asset = get_factory(o.generator).create(o.params)
        assets[n] = asset
        meshes[n] = _world(o, asset.mesh)
    solids: dict[str, trimesh.Trimesh] = dict(meshes)
    for rn, g in rooms.items():
        for i, w in enumerate(g.walls):
            solids[f"{rn}/wall_{i}"] = w
        solids[f"{rn}/floor"] = g.floor
        solids[f"{rn}/ceiling"] = g.ceiling

    # 1. interpenetration (AABB prefilter, then exact manifold intersection)
    under = {n for n, o in scene.objects.items() if Semantics.FloorCovering.value in o.tags}
    names = sorted(solids)
    bounds = np.array([solids[n].bounds for n in names])
    man: dict[str, manifold3d.Manifold] = {}
    penetrating = []
    for i, j in overlapping_pairs(bounds, PENETRATION_TOL):
        a, b = names[i], names[j]
        if a not in meshes and b not in meshes:
            continue  # architecture against architecture
        if a in meshes and b in meshes and (a in under) != (b in under):
            continue  # a rug and what stands on it
        ma = man.setdefault(a, _manifold(solids[a]))
        mb = man.setdefault(b, _manifold(solids[b]))
        d = _penetration(ma, mb)
        if d > PENETRATION_TOL:
            penetrating.append({"a": a, "b": b, "depth_m": round(d, 4)})

    # 2. support: each declared relation's surfaces are parallel, facing (or, CoPlanar, facing the
    # same way), at the margin
    unsupported = []
    for n, o in scene.objects.items():
        for r in o.relations:
            rel = parse_relation(r.relation)
            if not isinstance(rel, (StableAgainst, CoPlanar)):
                raise ConfigError(f"{n}: relation {r.relation!r} pins no surface to its parent")
            child = _surface(assets[n].surfaces, r.child_surface, n).transformed(
                o.pose.rotation(), np.array(o.pose.position))
            if r.parent in rooms:
                parent = _surface(rooms[r.parent].surfaces, r.parent_surface, r.parent)
            else:
                po = scene.objects[r.parent]
                parent = _surface(assets[r.parent].surfaces, r.parent_surface, r.parent).transformed(
                    po.pose.rotation(), np.array(po.pose.position))
            gaps = (child.corners() - parent.origin) @ parent.normal - rel.margin
            facing = float(np.dot(child.normal, parent.normal))
            # StableAgainst surfaces face each other; CoPlanar ones face the same way
            want = 1.0 if isinstance(rel, CoPlanar) else -1.0
            if facing * want < 0.999 or np.abs(gaps).max() > SUPPORT_TOL:
                unsupported.append({"object": n, "relation": r.relation, "parent": r.parent,
                                    "gap_m": round(float(np.abs(gaps).max()), 4),
                                    "facing": round(facing, 4)})

    # 3. door clearance zones: nothing below 2 m may stand in them. Footprints are the union of
    # the plan views of the object's convex pieces (an L-shaped sofa's notch is empty floor).
    blocked = []
    for rn, g in rooms.items():
        floor_z = float(getattr(g, "elevation", 0.0))
        footprints = {n: _footprint_below(scene.objects[n], assets[n], floor_z) for n in meshes
                      if n not in under}  # a door swings over a rug
        for k, zone in enumerate(g.door_zones):
            for n, fp in footprints.items():
                if fp is not None and fp.intersection(zone).area > 1e-6:
                    blocked.append({"room": rn, "door": k, "object": n})

    # 4. dining chairs face their table: a ray from the chair's seat along its front meets the
    # table's footprint within 1 m (for a long table, the chair faces its edge, not its centre)
    misfacing = []
    for n, o in scene.objects.items():
        if Semantics.DiningChair.value not in o.tags:
            continue
        for r in o.relations:
            if r.parent in scene.objects and Semantics.DiningTable.value in scene.objects[r.parent].tags:
                table = sg.MultiPoint(meshes[r.parent].vertices[:, :2]).convex_hull
                seat = np.asarray(o.pose.position[:2])
                ray = sg.LineString([seat, seat + o.pose.front()[:2] * FACING_REACH])
                if not ray.intersects(table):
                    misfacing.append({"chair": n, "table": r.parent})

    # 5. the program's hard constraints, evaluated from scratch
    violations: dict[str, dict[str, float]] = {}
    if program_check:
        violations = program_violations(scene, rooms)
    n_violated = sum(1 for v in violations.values() for x in v.values() if x > 1e-9)
    ok = not (penetrating or unsupported or blocked or misfacing or n_violated)
    cache = AssetCache()
    quality = quality_report(scene, rooms, cache, architecture)
    navigation = navigation_report(scene, rooms, cache, architecture)
    return {"ok": ok, "objects": len(scene.objects), "interpenetrating": penetrating,
            "unsupported": unsupported, "door_zone_blocked": blocked,
            "chairs_not_facing_table": misfacing, "hard_violations": violations,
            "n_hard_violated": n_violated, "contact_gap_m": CONTACT_GAP,
            "quality_passed": quality["passed"], "quality": quality, "navigation": navigation}


def _surface(surfaces: list[Surface], name: str, owner: str) -> Surface:
    """The surface `name` of `owner` (an object or a room); ConfigError naming those it has."""
    for s in surfaces:
        if s.name == name:
            return s
    raise ConfigError(f"scene.json: {owner!r} has no surface {name!r}; it has "
                      f"{', '.join(sorted(s.name for s in surfaces))}")


def _footprint_below(obj: SceneObject, asset: Asset, floor_z: float) -> Any:
    """Plan-view footprint (world) of the parts of `asset` up to `DOOR_ZONE_TOP` above a floor at
    `floor_z`: the union of its convex pieces cut to that band; None if none reach it."""
    outlines = band_outlines([m for _, m in asset.collision], obj.pose.matrix(), floor_z,
                             (-0.05, DOOR_ZONE_TOP))
    # on a 1 micron grid: a cupboard's collision pieces meet along its shelves in slivers,
    # whose floating-point union GEOS may refuse ("Ring edge missing")
    return shapely.union_all(outlines, grid_size=1e-6) if outlines else None


def program_violations(scene: Scene, rooms) -> dict[str, dict[str, float]]:
    """Each room's built-in program, with its circulation constraint, evaluated fully (a fresh
    evaluator) on the saved scene."""
    state = state_from_scene(scene, rooms, AssetCache())
    out = {}
    for rn, room in scene.rooms.items():
        prog = ROOM_PROGRAMS.get(room.room_type)
        if prog is None:
            continue
        problem = with_circulation(prog(scene_set()[Semantics.Room].named(rn)), rn)
        res = Evaluator(problem, state).evaluate()
        out[rn] = {k: v for k, v in res.violations.items() if v > 1e-9}
    return out


def validate_scene_dir(path: Path) -> dict[str, Any]:
    """`validate_scene` of the scene.json in directory `path` (SceneFileError, a ConfigError, if
    it is missing or breaks the scene schema)."""
    scene, _ = read_scene(Path(path))
    return validate_scene(scene)
