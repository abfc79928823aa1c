"""Window dressings: curtains hung at a room's windows once its furniture stands, sized to each
window (a rod above the opening, panels reaching past the frame on both sides, hanging to just
over the floor, or to below the sill where furniture stands under the window).

The constraint language knows no windows, so a program asks for its dressing by name
(`Problem.window_dressing`) and the solver hangs one on each window of the room (a home's rooms
know their windows' boxes, `RoomShape.windows`; a single room has none). A curtain goes up in
the first of a few sizes that meets nothing (walls, furniture, door zones: `State.collides`) and
cuts no walkway the furniture left (`solver.circulation`: a floor-length curtain beside a sofa
had closed the one way to its front), or not at all; it hangs on the wall (`on_wall`), so it is
exported fixed, without a free body.
"""
from __future__ import annotations

import logging
import math
from collections.abc import Callable

import numpy as np
import shapely.geometry as sg

from indoorgen.assets.catalogue import get_factory
from indoorgen.assets.protocol import Surface
from indoorgen.constraints import StableAgainst
from indoorgen.model.tags import Subpart
from indoorgen.rng import child_seed
from indoorgen.solver.circulation import room_cache, walkway
from indoorgen.solver.placement import placements_hold, solve_pose
from indoorgen.solver.state import ObjState, Placement, State

log = logging.getLogger(__name__)

#: hanging flat on a wall by its back (the board behind the rod's brackets); programs'
#: `relations.on_wall` (the solver may not import programs)
ON_WALL = StableAgainst(Subpart.Back, Subpart.Wall)
#: the rod's axis this far above the window's frame (m): 10-15 cm above the casing is the
#: usual advice, so the heading hides the frame's top
ROD_ABOVE = (0.1, 0.15)
#: how far the fabric reaches past the frame on each side (m): 10-25 cm, so the panels drawn
#: open stack beside the glass, not over it; narrower where a neighbour stands close
OVERLAPS = ((0.1, 0.25), (0.04, 0.08))
#: a floor-length hem's gap over the floor (m: 1-2 cm, "just kissing the floor" clear of rugs)
HEM_FLOOR = 0.02
#: a sill-length hem this far below the window's frame (m), or, over furniture reaching higher,
#: just under the frame (to the sill)
HEM_SILL = 0.1
HEM_AT_SILL = 0.01
#: the fabric stays this far in front of the frame's face (m)
FRAME_CLEAR = 0.015
#: window walls are found within this distance of the window's box (m)
WALL_TOL = 0.6


def dress_windows(state: State, room: str, generator: str, rng: np.random.Generator,
                  namer: Callable[[str], str], stage: str = "medium") -> list[str]:
    """Hang one `generator` object (a curtain) at each window of `room`, sized to it: the names
    of those hung, in window order. Windows whose every size meets something stay bare."""
    shape = state.rooms[room]
    floor = float(getattr(shape, "elevation", 0.0))
    walls = [s for s in shape.surfaces if s.subpart == Subpart.Wall]
    fac = get_factory(generator)
    out: list[str] = []
    windows = getattr(shape, "windows", ())
    if not len(windows):
        return out
    # what the furniture left unreached: a curtain may not add to it (one cache: each size
    # tried rasterises only itself)
    cache = room_cache(shape)
    allowed = walkway(state, room, cache=cache).violation
    for bounds in windows:
        bounds = np.asarray(bounds, float)
        wall = _window_wall(walls, bounds)
        seed = child_seed(rng)
        if wall is None:
            continue
        base = fac.sample_params(np.random.default_rng(seed))
        # a window whose frame reaches further into the room than the rod may stand off the
        # wall (its box taken along a slanted or curved wall) is left bare
        sizes = [(p, h) for p, h in _sizes(base, bounds, wall, floor, rng)
                 if p["standoff"] <= fac.params["standoff"].high]
        for params, hem in sizes:
            name = _hang(state, room, generator, fac.tags, params, seed, wall, bounds, hem,
                         namer, stage, lambda: walkway(state, room, cache=cache).violation
                         <= allowed)
            if name is not None:
                out.append(name)
                break
        else:
            log.info("%s: no curtain fits the window at %s", room, bounds.mean(axis=0).round(2))
    return out


def _window_wall(walls: list[Surface], bounds: np.ndarray) -> Surface | None:
    """The room wall the window sits in: the nearest wall plane whose outline holds the window's
    centre along the wall."""
    c = bounds.mean(axis=0)
    best, best_d = None, WALL_TOL
    for w in walls:
        d = abs(float(np.dot(c - w.origin, w.normal)))
        along = (float(np.dot(c - w.origin, w.u)), float(np.dot(c - w.origin, w.v)))
        if d < best_d and w.polygon.buffer(0.05).covers(sg.Point(along[0], along[1])):
            best, best_d = w, d
    return best


def _sizes(base: dict, bounds: np.ndarray, wall: Surface, floor: float,
           rng: np.random.Generator) -> list[tuple[dict, float]]:
    """The sizes to try, largest first: (params, hem height over the floor) for a floor-length
    curtain, one below the sill and one to the sill, each with a wide and then a narrow overlap
    past the frame."""
    corners = np.array([[x, y, z] for x in bounds[:, 0] for y in bounds[:, 1] for z in bounds[:, 2]])
    depth = float(np.max((corners - wall.origin) @ wall.normal))  # the frame's reach into the room
    width = float(np.ptp((corners - wall.origin) @ wall.u))
    z0, z1 = float(bounds[0, 2]) - floor, float(bounds[1, 2]) - floor
    rod = z1 + float(rng.uniform(*ROD_ABOVE))
    overlap = [float(rng.uniform(*o)) for o in OVERLAPS]
    out = []
    for hem in (HEM_FLOOR, max(HEM_FLOOR, z0 - HEM_SILL), max(HEM_FLOOR, z0 - HEM_AT_SILL)):
        for o in overlap:
            p = dict(base, n_panels=2, width=min(3.0, max(1.0, width + 2 * o)),
                     drop=min(2.6, max(1.0, rod - hem)))
            # the fabric's folds clear the frame: the rod's standoff is the frame's depth plus
            # the folds' half depth and a margin
            amp = p["fold_depth"] / 2
            p["standoff"] = max(p["standoff"], depth + amp + FRAME_CLEAR + 0.005)
            p["coverage"] = min(p["coverage"], 0.7)  # drawn open: the glass shows between
            out.append((p, rod - p["drop"]))
    return out


def _hang(state: State, room: str, generator: str, tags: frozenset, params: dict, seed: int,
          wall: Surface, bounds: np.ndarray, hem: float, namer: Callable[[str], str],
          stage: str, walkway_kept: Callable[[], bool]) -> str | None:
    """Add the curtain centred on the window with its hem `hem` over the floor; its name, or
    None (and nothing added) if it meets anything or `walkway_kept` says it closes a way."""
    asset = state.cache.placeholder(generator, params)
    placement = Placement(ON_WALL, room, "back", wall.name)
    centre = bounds.mean(axis=0)
    floor = float(getattr(state.rooms[room], "elevation", 0.0))
    guess = np.array([centre[0], centre[1], floor + hem])
    posed = solve_pose(state, asset, [placement], guess, math.atan2(wall.normal[1], wall.normal[0]))
    if posed is None:
        return None
    position, yaw, _ = posed
    position = np.array([position[0], position[1], floor + hem])
    # centred on the window along the wall (the curtain's local y axis lies along it)
    side = np.array([-math.sin(yaw), math.cos(yaw), 0.0])
    position = position + side * float(np.dot(centre - position, side))
    # tried under a name of its own, so a curtain that does not fit takes no name from the room
    ob = ObjState(f"{generator}_trial", generator, params, seed, frozenset(tags), room, stage,
                  asset, [placement], position, yaw)
    state.add(ob)
    fits = (not state.collides(ob.name) and placements_hold(state, ob.name)
            and walkway_kept())
    state.remove(ob.name)
    if not fits:
        return None
    ob.name = namer(generator)
    state.add(ob)
    return ob.name
