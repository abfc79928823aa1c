"""Can a robot walk from the entrance to every room, door and large object? The `navigation`
section of report.json, the community's navigability figure and `nav_<storey>.png`.

Method (issue 11): each storey's free floor on a 5 cm grid (`quality.occupancy`: rooms and the
passages of doors standing open (a door scene.json records as shut blocks its passage), less
stairs, stairwells and everything 0.02-1.8 m above the floor), eroded by the agent's radius (the
cells its centre may occupy), split into 4-connected components, and flooded from the components
just inside the entrance door (a single room: its door). A stair joins the components at its
foot (lower storey) to those at its head (upper storey). The floor *reached* is what the agent's
body sweeps from every reachable centre; the *walkable* floor is what it sweeps from every centre
it could occupy, reachable or not. The reachable share is reached over walkable floor: free floor
no agent of this radius could ever touch, wherever it stood (a right-angled corner loses
(1 - pi/4) r^2, a slot between furniture or behind it narrower than the agent, the gaps between
dining chairs pushed in round their table), is no walking agent's to reach, so it is left out of
the share rather than counted as cut off; the floor an agent could stand on and cannot get to
(a pocket sealed by furniture, a room behind a blocked door, an unreachable storey) is what the
share misses. The share of all free floor is reported beside it (`reachable_share_of_free`).

- a room is reachable when a reachable centre lies on its floor;
- a door when reachable centres lie in front of it on each side it opens into (`APPROACH` beyond
  the agent's radius) and, between two rooms, in its passage through the wall;
- a large object whose front matters (`model.walkable.FRONT_TAGS`) when a reachable centre lies within
  `FRONT_TOLERANCE` of its front point, `agent_radius + FRONT_GAP` in front of its front face;
  a bed (`BED_TAGS`) when one of its two side points is (a bed against a wall is reached from
  its other side).
"""
from __future__ import annotations

from collections import deque
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import shapely.geometry as sg
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.patches import Patch
from scipy import ndimage

from indoorgen.architecture.doors import SHUT
from indoorgen.architecture.room import RoomGeometry
from indoorgen.architecture.solidify import Architecture
from indoorgen.assets.cache import AssetCache
from indoorgen.model.floorplan import Floorplan, StairSpec
from indoorgen.model.floorplan_io import from_json
from indoorgen.model.scene import Room, Scene, SceneObject
from indoorgen.model.walkable import (
    AGENT_RADIUS,
    APPROACH,
    CELL,
    FRONT_TOLERANCE,
    band_outlines,
    cover,
    erode,
)
from indoorgen.model.walkable import access_points as local_access_points
from indoorgen.quality.occupancy import DoorSite, StoreyOccupancy, storey_occupancy

#: Robot radius of the community navigability figure (m).
ROBOT_RADIUS = 0.2

_COLOURS = {"outside": (1.0, 1.0, 1.0), "obstacle": (0.33, 0.33, 0.33),
            "untouchable": (0.97, 0.80, 0.55), "unreached": (0.88, 0.34, 0.35),
            "reached": (0.69, 0.86, 0.63),
            "centres": (0.35, 0.63, 0.31)}
_LEGEND = {"obstacle": "obstacle (0.02-1.8 m)",
           "untouchable": "free, but no agent fits there", "unreached": "walkable, not reached",
           "reached": "reached by the agent's body", "centres": "agent centre can reach"}


@dataclass
class StoreyReach:
    """One storey's occupancy with the centres an agent can occupy, those it can reach, the
    floor the reachable ones sweep (`swept`) and the floor all of them sweep (`walkable`)."""

    occ: StoreyOccupancy
    centres: np.ndarray
    labels: np.ndarray
    reached: np.ndarray
    swept: np.ndarray
    walkable: np.ndarray

    def hits(self, geom: sg.base.BaseGeometry) -> bool:
        """Whether a reachable centre lies in `geom`."""
        return bool((self.occ.grid.rasterise([geom]) & self.reached).any())


@dataclass
class Reach:
    """Every storey's reach for an agent of `radius`, and where the flood started."""

    radius: float
    cell: float
    storeys: dict[int, StoreyReach]
    start: tuple[int, str, str] | None  # (level, door name, room) the flood starts from


def _floorplan(scene: Scene, architecture: Architecture | None) -> Floorplan | None:
    if architecture is not None:
        return architecture.floorplan
    return from_json(scene.floorplan) if scene.floorplan else None


def _room_map(scene: Scene, rooms: Mapping[str, RoomGeometry]) -> dict[str, Room]:
    return {n: g.room for n, g in rooms.items()} if rooms else dict(scene.rooms)


def _railings(architecture: Architecture | None, level: int, elevation: float
              ) -> list[sg.Polygon]:
    """Outlines in the band of the railings standing on storey `level`."""
    if architecture is None:
        return []
    out = []
    for el in architecture.elements:
        if el.kind == "railing" and el.storey == level:
            pieces = el.collision or list(el.meshes.values())
            out += band_outlines(pieces, np.eye(4), elevation)
    return out


def shut_doors(scene: Scene) -> list[str]:
    """The doors scene.json records as shut, by name."""
    return sorted(n for n, v in (scene.doors or {}).items() if v <= SHUT)


def occupancies(scene: Scene, rooms: Mapping[str, RoomGeometry], cache: AssetCache,
                architecture: Architecture | None = None, *, cell: float = CELL
                ) -> dict[int, StoreyOccupancy]:
    """Every storey's occupancy grid, by level."""
    room_map = _room_map(scene, rooms)
    fp = _floorplan(scene, architecture)
    levels = sorted({r.storey for r in room_map.values()})
    shut = shut_doors(scene)
    out = {}
    for lv in levels:
        elevation = next(r.elevation for r in room_map.values() if r.storey == lv)
        out[lv] = storey_occupancy(scene, cache, lv, rooms=room_map, floorplan=fp,
                                   extra_obstacles=_railings(architecture, lv, elevation),
                                   shut=shut, cell=cell)
    return out


def _start(occ: dict[int, StoreyOccupancy]) -> tuple[int, str, str] | None:
    """The entrance door (level, name, room): the door called "entrance", else the lowest
    storey's first door by name (a single room's only door)."""
    for lv, o in occ.items():
        site = o.doors.get("entrance")
        if site is not None:
            return lv, "entrance", next(iter(site.sides))
    low = min(occ)
    for name in sorted(occ[low].doors):
        site = occ[low].doors[name]
        return low, name, next(iter(site.sides))
    return None


def _landing(st: StairSpec, head: bool, depth: float) -> sg.Polygon:
    """The strip `depth` deep beyond a flight's foot (or head)."""
    p = np.asarray(st.polygon, float)
    up = (p[3] - p[0]) / np.linalg.norm(p[3] - p[0])
    if head:
        return sg.Polygon([p[3], p[2], p[2] + depth * up, p[3] + depth * up])
    return sg.Polygon([p[0] - depth * up, p[1] - depth * up, p[1], p[0]])


def _labels_in(o: StoreyOccupancy, labels: np.ndarray, geom: sg.Polygon) -> set[int]:
    found = labels[o.grid.rasterise([geom])]
    return {int(v) for v in np.unique(found) if v}


def reach(scene: Scene, rooms: Mapping[str, RoomGeometry], cache: AssetCache,
          architecture: Architecture | None = None, *, agent_radius: float = AGENT_RADIUS,
          cell: float = CELL) -> Reach:
    """Flood every storey from the entrance for an agent of `agent_radius`, through stairs."""
    occ = occupancies(scene, rooms, cache, architecture, cell=cell)
    centres = {lv: erode(o.free, agent_radius, cell) for lv, o in occ.items()}
    labels = {lv: ndimage.label(c)[0] for lv, c in centres.items()}
    links: dict[tuple[int, int], set[tuple[int, int]]] = {}
    fp = _floorplan(scene, architecture)
    for st in (fp.stairs if fp else []):
        if st.from_level not in occ or st.to_level not in occ:
            continue
        depth = agent_radius + APPROACH
        foot = _labels_in(occ[st.from_level], labels[st.from_level], _landing(st, False, depth))
        head = _labels_in(occ[st.to_level], labels[st.to_level], _landing(st, True, depth))
        for a in foot:
            for b in head:
                links.setdefault((st.from_level, a), set()).add((st.to_level, b))
                links.setdefault((st.to_level, b), set()).add((st.from_level, a))
    start = _start(occ)
    seen: set[tuple[int, int]] = set()
    if start is not None:
        lv, door, room = start
        site = occ[lv].doors[door]
        region = site.approach(room, agent_radius + APPROACH).union(site.passage)
        queue = deque((lv, lab) for lab in sorted(_labels_in(occ[lv], labels[lv], region)))
        seen.update(queue)
        while queue:
            for nxt in sorted(links.get(queue.popleft(), ())):
                if nxt not in seen:
                    seen.add(nxt)
                    queue.append(nxt)
    storeys = {}
    for lv, o in occ.items():
        got = sorted(lab for level, lab in seen if level == lv)
        reached = np.isin(labels[lv], got) & centres[lv]
        storeys[lv] = StoreyReach(o, centres[lv], labels[lv], reached,
                                  cover(reached, o.free, agent_radius, cell),
                                  cover(centres[lv], o.free, agent_radius, cell))
    return Reach(agent_radius, cell, storeys, start)


def _door_ok(sr: StoreyReach, site: DoorSite, radius: float) -> bool:
    if not all(sr.hits(site.approach(r, radius + APPROACH)) for r in site.sides):
        return False
    return len(site.sides) < 2 or sr.hits(site.passage)


def access_points(ob: SceneObject, cache: AssetCache, radius: float) -> list[np.ndarray]:
    """World XY points an agent of `radius` must reach to use `ob` (any one of them suffices):
    the front point, or for a bed its two side points; [] when its front does not matter (or it
    is not a large object)."""
    if ob.stage != "large":
        return []
    local = local_access_points(ob.tags, cache.placeholder(ob.generator, ob.params).mesh.bounds,
                                radius)
    if not local:
        return []
    world = ob.pose.apply(np.array([[x, y, 0.0] for x, y in local]))
    return [w[:2] for w in world]


def _pulled_up(scene: Scene, name: str) -> list[SceneObject]:
    """The floor-standing objects pulled up to object `name` (a chair at its desk)."""
    return [o for o in scene.objects.values() if o.relations and o.relations[0].parent == o.room
            and any(r.parent == name for r in o.relations[1:])]


def _plan_box(ob: SceneObject, cache: AssetCache) -> sg.Polygon:
    """The plan outline of `ob`'s placeholder box where it stands."""
    (x0, y0, _), (x1, y1, _) = cache.placeholder(ob.generator, ob.params).mesh.bounds
    corners = ob.pose.apply(np.array([[x0, y0, 0.0], [x1, y0, 0.0], [x1, y1, 0.0], [x0, y1, 0.0]]))
    return sg.Polygon(corners[:, :2])


def _r4(x: float) -> float:
    return round(float(x), 4)


def _share(part: float, whole: float) -> float:
    return _r4(part / whole if whole else 0.0)


def navigation_report(scene: Scene, rooms: Mapping[str, RoomGeometry], cache: AssetCache,
                      architecture: Architecture | None = None, *, agent_radius: float = AGENT_RADIUS,
                      cell: float = CELL) -> dict[str, Any]:
    """The `navigation` section of report.json: per storey and overall, the share of walkable
    floor (and of all free floor) an agent of `agent_radius` reaches from the entrance; rooms,
    doors and large objects it cannot reach; `passed` when every room is reachable and every
    door standing open can be passed (`failures` says what is not: a shut door is the user's
    choice, not a fault)."""
    rc = reach(scene, rooms, cache, architecture, agent_radius=agent_radius, cell=cell)
    shut = set(shut_doors(scene))
    storeys, free_all, walk_all, got_all = {}, 0.0, 0.0, 0.0
    bad_rooms, bad_doors, n_doors = [], [], 0
    for lv, sr in rc.storeys.items():
        g = sr.occ.grid
        free, walk, got = g.area(sr.occ.free), g.area(sr.walkable), g.area(sr.swept)
        free_all, walk_all, got_all = free_all + free, walk_all + walk, got_all + got
        storeys[str(lv)] = {"free_m2": _r4(free), "walkable_m2": _r4(walk),
                            "reachable_m2": _r4(got), "reachable_share": _share(got, walk),
                            "reachable_share_of_free": _share(got, free)}
        bad_rooms += [n for n, poly in sr.occ.rooms.items() if not sr.hits(poly)]
        n_doors += len(sr.occ.doors)
        bad_doors += [n for n, site in sr.occ.doors.items()
                      if not _door_ok(sr, site, agent_radius)]
    bad_objects = []
    for name in sorted(scene.objects):
        ob = scene.objects[name]
        pts = access_points(ob, cache, agent_radius)
        room = scene.rooms.get(ob.room)
        if not pts or room is None or room.storey not in rc.storeys:
            continue
        sr = rc.storeys[room.storey]
        # a chair pulled up to a desk stands where its user does: reaching it will do (as the
        # solver's circulation has it)
        near = [sg.Point(p).buffer(FRONT_TOLERANCE) for p in pts] + [
            _plan_box(seat, cache).buffer(agent_radius + FRONT_TOLERANCE)
            for seat in _pulled_up(scene, name)]
        if not any(sr.hits(zone) for zone in near):
            bad_objects.append({"object": name, "room": ob.room})
    failures = [] if rc.start is not None else ["no entrance door to start from"]
    failures += [f"room {n} is not reachable from the entrance" for n in sorted(bad_rooms)]
    failures += [f"door {n} cannot be passed from the entrance" for n in sorted(set(bad_doors))
                 if n not in shut]
    return {"agent_radius": _r4(agent_radius), "cell": _r4(cell), "storeys": storeys,
            "reachable_share": _share(got_all, walk_all),
            "reachable_share_of_free": _share(got_all, free_all),
            "rooms": sum(len(sr.occ.rooms) for sr in rc.storeys.values()), "doors": n_doors,
            "unreachable_rooms": sorted(bad_rooms), "unreachable_doors": sorted(set(bad_doors)),
            "large_objects_unreachable": bad_objects, "passed": not failures,
            "failures": failures}


def navigability(scene: Scene, rooms: Mapping[str, RoomGeometry], cache: AssetCache,
                 architecture: Architecture | None = None, *, robot_radius: float = ROBOT_RADIUS
                 ) -> float:
    """The community's navigability: the area of the largest connected region of the free floor
    eroded by `robot_radius` over the area of the whole eroded free floor.

    This is PhyScene's walkable rate (Yang et al., CVPR 2024; `cal_walkable_metric` in its
    scripts/eval/walkable_metric.py, when no door is given: floor eroded and objects grown by
    the robot's size, then largest component / all walkable pixels), which SceneEval (Tam et
    al., 2025) reuses as its navigability metric. Here obstacles are everything in the band
    (not only boxes below 1.5 m), doors are open, and a home's storeys are measured apart
    (stairs do not join them) and area-weighted."""
    occ = occupancies(scene, rooms, cache, architecture)
    largest = total = 0
    for o in occ.values():
        c = erode(o.free, robot_radius, o.grid.cell)
        labels, n = ndimage.label(c)
        total += int(c.sum())
        if n:
            largest += int(np.bincount(labels.ravel())[1:].max())
    return round(largest / total, 4) if total else 0.0


def _picture(sr: StoreyReach) -> np.ndarray:
    o = sr.occ
    img = np.empty((*o.grid.shape, 3))
    img[:] = _COLOURS["outside"]
    img[o.floor & o.obstacles] = _COLOURS["obstacle"]
    img[o.free] = _COLOURS["untouchable"]
    img[sr.walkable] = _COLOURS["unreached"]
    img[sr.swept] = _COLOURS["reached"]
    img[sr.reached] = _COLOURS["centres"]
    return img


def write_nav_images(scene: Scene, rooms: Mapping[str, RoomGeometry], cache: AssetCache,
                     architecture: Architecture | None, out_dir: Path, *,
                     agent_radius: float = AGENT_RADIUS) -> list[Path]:
    """Write `nav_<storey>.png` per storey into `out_dir` (free floor reached or not, agent
    centres, obstacles, the entrance marked) and return their paths."""
    rc = reach(scene, rooms, cache, architecture, agent_radius=agent_radius)
    out_dir = Path(out_dir)
    paths = []
    for lv, sr in rc.storeys.items():
        fig = Figure(dpi=100)
        FigureCanvasAgg(fig)
        ny, nx = sr.occ.grid.shape
        fig.set_size_inches(10, max(3.0, 10 * ny / nx + 1.0))
        ax = fig.add_subplot()
        ax.imshow(_picture(sr), origin="lower", extent=sr.occ.grid.extent,
                  interpolation="nearest")
        for name, poly in sr.occ.rooms.items():
            c = poly.representative_point()
            ax.text(c.x, c.y, name, ha="center", va="center", fontsize=7)
        if rc.start is not None and rc.start[0] == lv:
            c = sr.occ.doors[rc.start[1]].centre
            ax.plot([c[0]], [c[1]], marker="*", markersize=16, color="#1f77b4",
                    markeredgecolor="black", label="entrance")
        walk = sr.occ.grid.area(sr.walkable)
        share = sr.occ.grid.area(sr.swept) / walk if walk else 0.0
        ax.set_title(f"storey {lv}: {share:.1%} of walkable floor reached "
                     f"(agent radius {agent_radius} m)")
        ax.set_aspect("equal")
        handles = [Patch(color=_COLOURS[k], label=v) for k, v in _LEGEND.items()]
        ax.legend(handles=handles + ax.get_legend_handles_labels()[0], loc="upper left",
                  bbox_to_anchor=(1.01, 1.0), fontsize=8)
        path = out_dir / f"nav_{lv}.png"
        fig.savefig(path, dpi=100, bbox_inches="tight", facecolor="white")
        paths.append(path)
    return paths
