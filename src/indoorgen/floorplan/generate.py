"""The floorplan stage end to end: seed (+ config) -> `Floorplan`.

room graph -> outlines and staircase placeholder -> per storey: Mondrian subdivision, merging
and room assignment, retried until the hard rules hold -> annealing under the floorplan program
-> doors, open connections, front door, windows and stairs.

All randomness comes from child streams of the seed (`rng.stream(seed, "floorplan", ...)`),
addressed by purpose and attempt number, so the result is a pure function of seed and config.
"""
from __future__ import annotations

import dataclasses
import logging
import math
import time
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
import shapely.geometry as sg

from indoorgen.constraints.problem import Problem
from indoorgen.errors import ConfigError, InvalidGeometryError
from indoorgen.floorplan.assign import assign, relabel
from indoorgen.floorplan.check import home_problems
from indoorgen.floorplan.contour import make_contour, upper_contour, user_contour
from indoorgen.floorplan.graph import MIN_AREA_SHARE, HomeGraph, graph_from_spec, sample_home_graph
from indoorgen.floorplan.grid import OUTSIDE, make_grid
from indoorgen.floorplan.openings import (
    place_doors,
    place_entrance,
    place_stairs,
    place_vehicle_doors,
    place_windows,
)
from indoorgen.floorplan.rooms import parse_room_counts, room_type_of
from indoorgen.floorplan.rules import room_problems
from indoorgen.floorplan.solve import FloorplanAnnealConfig, anneal
from indoorgen.floorplan.subdivide import MIN_SIDE, grow_hub, merge, mondrian
from indoorgen.floorplan.view import GridPlan
from indoorgen.model.floorplan import Floorplan, RoomSpec, Storey
from indoorgen.model.room_types import ROOM_TYPES
from indoorgen.model.schemas import MAX_HOME_AREA, MAX_STOREYS, HomeContour, parse
from indoorgen.programs.floorplan import floorplan as default_program
from indoorgen.rng import stream

log = logging.getLogger(__name__)

#: The staircase placeholder: two 1 m lanes, 6 m long (a 3.8 m flight plus 1.1 m landings at
#: both ends, `openings.LANDING`), in cells.
STAIR_CELLS = (4, 12)
#: Attempts at subdividing and assigning one storey, and at the whole home.
STOREY_ATTEMPTS = 80
HOME_ATTEMPTS = 20
#: The first attempts of each round make rooms `rooms.planned_width` wide; the rest, for crowded
#: homes those do not fit, only `rooms.min_width` (a narrow room rather than no home).
PLANNED_WIDTH_ATTEMPTS = 16
#: Finished plans drawn at most before giving up on `check.home_problems`.
REDRAWS = 4


@dataclass
class FloorplanConfig:
    """What to generate.

    `floors`: storeys (1-3). `rooms`: fixed counts of room types for the whole home, as a dict or
    ``"bedroom=2,bathroom=1"``. `area`: ground-floor area in m^2 (default: the rooms' typical
    areas). `contour`: the ground-floor outline as [[x, y], ...] instead. `graph`: a fixed room
    graph (`HomeGraph` or its JSON form). `program`: a floorplan constraint program (a callable
    returning a `Problem`; default `programs.floorplan.floorplan`).
    """

    floors: int = 1
    rooms: dict[str, int] | str | None = None
    area: float | None = None
    contour: list | None = None
    graph: HomeGraph | dict | None = None
    height: float = 2.8
    slab: float = 0.1
    interior_wall: float = 0.12
    exterior_wall: float = 0.24
    open_prob: float = 0.5
    program: Callable[[], Problem] | None = None
    anneal: FloorplanAnnealConfig = field(default_factory=FloorplanAnnealConfig)

    def to_json(self) -> dict:
        """The settings as plain JSON (room counts parsed), recorded with the plan."""
        return {"floors": self.floors, "rooms": parse_room_counts(self.rooms),
                "area": self.area, "contour": self.contour, "height": self.height,
                "slab": self.slab, "interior_wall": self.interior_wall,
                "exterior_wall": self.exterior_wall, "open_prob": self.open_prob,
                "program": getattr(self.program, "__name__", None),
                "steps_per_storey": self.anneal.steps_per_storey}


def storey_pitch(cfg: FloorplanConfig) -> float:
    """Floor-to-floor distance: ceiling slab + floor slab between storeys."""
    return cfg.height + 2 * cfg.slab


def _needed_area(names: list[str]) -> float:
    return math.fsum(ROOM_TYPES[room_type_of(n)].min_area for n in names)


def _typical(names: list[str]) -> float:
    return math.fsum(ROOM_TYPES[room_type_of(n)].typical_area for n in names)


def _place_stair(rng: np.random.Generator, grid) -> tuple[int, int, int, int] | None:
    """A random placeholder rectangle of full cells, each side either on the outline's bounding
    box or at least MIN_SIDE cells (a room's width) clear of it, with a cell of full cells
    around it inside the outline."""
    full = grid.full
    ny, nx = full.shape
    shapes = [STAIR_CELLS, STAIR_CELLS[::-1]]
    if rng.random() < 0.5:
        shapes.reverse()
    for h, w in shapes:
        cands = []
        for y in range(0, ny - h + 1):
            for x in range(0, nx - w + 1):
                gaps = (y, x, ny - y - h, nx - x - w)
                if any(0 < g < MIN_SIDE for g in gaps):
                    continue
                if full[max(0, y - 1):y + h + 1, max(0, x - 1):x + w + 1].all():
                    cands.append((y, x, y + h, x + w))
        if cands:
            return cands[int(rng.integers(len(cands)))]
    return None


class _Failed(Exception):
    """One home attempt did not work out (the next attempt draws new randomness)."""


def _init_storey(seed: int, attempt: int, plan: GridPlan, k: int, *tail: str) -> bool:
    """Subdivide storey k and assign its rooms until the hard rules hold (`tail` names a
    second try's random streams)."""
    grid = plan.grids[k]
    names = plan.names[k]
    g = plan.graph.storeys[k]
    entry = plan.graph.storey_entry(k)
    stair = plan.stair_mask()
    ideal = {n: plan.ideal_area(n) for n in names}
    need_ext = {plan.graph.entrance} if k == 0 else set()
    for t in range(STOREY_ATTEMPTS):
        rng = stream(seed, "floorplan", "init", attempt, k, t, *tail)
        spaces = mondrian(rng, grid, int(math.ceil(1.5 * len(names))), fixed=plan.stair_rect)
        if spaces.max() + 1 < len(names):
            continue
        if rng.random() < 0.6:
            spaces = grow_hub(rng, spaces, max(d for _, d in g.degree), len(names),
                              keep_apart=stair)
        spaces = merge(rng, spaces, len(names))
        if spaces.max() + 1 < len(names):
            continue
        mapping = assign(rng, g, entry, grid, spaces, stair, ideal, need_ext)
        if mapping is None:
            continue
        labels = relabel(spaces, mapping, names)
        if stair is not None:
            labels[stair & (labels != OUTSIDE)] = names.index(plan.graph.stairs[k])
        plan.labels[k] = labels
        plan.invalidate(names)
        problems = [p for n in names for p in room_problems(plan, n)]
        if not problems:
            log.debug("storey %d initialised after %d attempt(s)", k, t + 1)
            return True
        log.debug("storey %d attempt %d: %s", k, t, problems[:3])
    return False


def _contours(seed: int, attempt: int, cfg: FloorplanConfig, hg: HomeGraph):
    """Ground outline, staircase placeholder and upper outlines for one attempt."""
    rng = stream(seed, "floorplan", "contour", attempt)
    names = [hg.rooms(k) for k in range(hg.n_storeys)]
    need = max(_needed_area(n) for n in names)
    if cfg.contour is not None:
        ground = user_contour(cfg.contour)
    else:
        area = cfg.area if cfg.area is not None else \
            max(_typical(n) for n in names) * float(rng.uniform(1.0, 1.15))
        ground = make_contour(rng, float(area))
    if ground.area < need / MIN_AREA_SHARE:
        where = f"--contour ({ground.area:.0f} m^2)" if cfg.contour is not None else \
            f"--area {cfg.area:g} m^2"
        raise InvalidGeometryError(
            f"{where} is too small for the rooms "
            f"({', '.join(sorted(set(room_type_of(r) for r in sum(names, []))))}): they need "
            f"at least {need / MIN_AREA_SHARE:.0f} m^2 on one storey; give a larger area or fewer rooms")
    grid0 = make_grid(ground)
    rect, stair_poly = None, None
    if hg.n_storeys > 1:
        rect = _place_stair(rng, grid0)
        if rect is None:
            raise InvalidGeometryError(
                "the outline has no room for a 2 x 6 m staircase; give a larger area or contour")
        iy0, ix0, iy1, ix1 = rect
        (x0, y0), (x1, y1) = grid0.to_world(ix0, iy0), grid0.to_world(ix1, iy1)
        stair_poly = sg.box(x0, y0, x1, y1)
    contours = [ground]
    for k in range(1, hg.n_storeys):
        min_area = max(_needed_area(names[k]) * 1.4, _typical(names[k]) * 0.85)
        target = _typical(names[k]) * float(rng.uniform(1.1, 1.3))
        contours.append(upper_contour(rng, contours[-1], stair_poly, min_area, target))
    frame = (grid0.origin, grid0.shape)
    grids = [grid0] + [make_grid(c, frame) for c in contours[1:]]
    return grids, rect


def _attempt(seed: int, attempt: int, cfg: FloorplanConfig, counts: dict[str, int]) -> GridPlan:
    if cfg.graph is not None:
        hg = cfg.graph if isinstance(cfg.graph, HomeGraph) else graph_from_spec(cfg.graph)
    else:
        max_area = None
        if cfg.contour is not None:
            max_area = user_contour(cfg.contour).area
        elif cfg.area is not None:
            max_area = float(cfg.area)
        hg = sample_home_graph(lambda a: stream(seed, "floorplan", "graph", attempt, a),
                               cfg.floors, counts, max_area=max_area)
    grids, rect = _contours(seed, attempt, cfg, hg)
    planned = attempt % HOME_ATTEMPTS < PLANNED_WIDTH_ATTEMPTS
    plan = _grid_plan(hg, grids, [np.full(g.shape, OUTSIDE, np.int64) for g in grids], rect,
                      planned)
    for k in range(hg.n_storeys):
        if _init_storey(seed, attempt, plan, k):
            continue
        if k and grids[k].contour.area < grids[k - 1].contour.area - 1e-6:
            # an upper outline cut towards its rooms' area: try the storey below's whole outline
            grids[k] = make_grid(grids[k - 1].contour, (grids[0].origin, grids[0].shape))
            plan.labels[k] = np.full(grids[k].shape, OUTSIDE, np.int64)
            plan = _grid_plan(hg, grids, plan.labels, rect, planned)
            if _init_storey(seed, attempt, plan, k, "uncut"):
                continue
        raise _Failed(f"storey {k}: no subdivision satisfies the room graph "
                      f"({len(plan.names[k])} rooms in {grids[k].contour.area:.0f} m^2)")
    return plan


def _grid_plan(hg: HomeGraph, grids, labels: list[np.ndarray], rect, planned: bool) -> GridPlan:
    """A plan on `grids` with `labels`, its rooms `planned_width` wide if `planned`."""
    plan = GridPlan(hg, grids, labels, rect)
    plan.planned_widths = planned
    return plan


#: thickness ranges (m) of the slabs and walls a FloorplanConfig may ask for
SLAB_RANGE, WALL_RANGE = (0.05, 0.5), (0.05, 0.6)
#: the most annealing steps per storey a floorplan may be given (the default is 250)
MAX_PLAN_STEPS = 100_000


def check_config(cfg: FloorplanConfig) -> None:
    """ConfigError naming the first setting of `cfg` outside what a home may have (the ranges
    the command line allows), before any work: the Python API is held to the same bounds."""
    if isinstance(cfg.floors, bool) or not isinstance(cfg.floors, (int, np.integer)) or \
            not 1 <= cfg.floors <= MAX_STOREYS:
        raise ConfigError(f"--floors {cfg.floors} is out of range; a home has 1 to {MAX_STOREYS} "
                          "storeys")
    if cfg.area is not None and not (isinstance(cfg.area, (int, float)) and
                                     0 < cfg.area <= MAX_HOME_AREA):
        raise ConfigError(f"--area {cfg.area} is out of range; a home's ground floor is over 0 "
                          f"and at most {MAX_HOME_AREA:g} m^2")
    if cfg.contour is not None:
        parse(HomeContour, {"contour": cfg.contour}, "--contour")
    ranges = {"storey height": (cfg.height, (2.2, 5.0)), "slab": (cfg.slab, SLAB_RANGE),
              "interior wall": (cfg.interior_wall, WALL_RANGE),
              "exterior wall": (cfg.exterior_wall, WALL_RANGE),
              "open_prob": (cfg.open_prob, (0.0, 1.0)),
              "annealing steps per storey": (cfg.anneal.steps_per_storey, (0, MAX_PLAN_STEPS))}
    for what, (value, (lo, hi)) in ranges.items():
        if not (isinstance(value, (int, float)) and lo <= value <= hi):
            raise ConfigError(f"{what} {value} is out of range [{lo:g}, {hi:g}]")


def build_plan(seed: int, cfg: FloorplanConfig, redraw: int = 0) -> GridPlan:
    """An initial plan satisfying the hard rules (before annealing); `redraw` > 0 draws it
    afresh (other attempt streams) after a finished plan failed `check.home_problems`."""
    check_config(cfg)
    counts = parse_room_counts(cfg.rooms)
    user_fixed = bool(counts) or cfg.area is not None or cfg.contour is not None or \
        cfg.graph is not None
    reason = ""
    for attempt in range(redraw * HOME_ATTEMPTS, (redraw + 1) * HOME_ATTEMPTS):
        try:
            return _attempt(seed, attempt, cfg, counts)
        except _Failed as e:
            reason = str(e)
            log.debug("home attempt %d failed: %s", attempt, e)
    what = "the given rooms, area or contour" if user_fixed else "this seed"
    raise InvalidGeometryError(f"cannot lay out {what}: {reason}; try a larger --area or "
                               "fewer rooms")


def generate_floorplan(seed: int, config: FloorplanConfig | None = None, *,
                       first_redraw: int = 0) -> Floorplan:
    """Generate a home's floorplan from `seed`: the first of its plans (drawn in a fixed order,
    `redraw` 0, 1, ...) from `first_redraw` on that passes `check.home_problems` within
    REDRAWS draws. Same seed + config + version => same plan."""
    cfg = config or FloorplanConfig()
    t0 = time.perf_counter()
    program = cfg.program or default_program
    problem = program()
    if not isinstance(problem, Problem):
        raise ConfigError(f"floorplan program {getattr(program, '__name__', program)!r} must "
                          f"return a Problem, got {type(problem).__name__}")
    acfg = cfg.anneal
    if cfg.program is None:  # the default program's constraints are the solver's own rules
        acfg = dataclasses.replace(acfg, constraints_at_ends_only=True)
    problems: list[str] = []
    for redraw in range(first_redraw, first_redraw + REDRAWS):
        tail = (redraw,) if redraw else ()
        plan = build_plan(seed, cfg, redraw)
        t1 = time.perf_counter()
        stats = anneal(plan, problem, stream(seed, "floorplan", "anneal", *tail), acfg)
        t2 = time.perf_counter()
        fp = to_floorplan(plan, cfg, stream(seed, "floorplan", "openings", *tail))
        problems = home_problems(fp, cfg.exterior_wall / 2)
        if not problems:
            break
        log.debug("plan %d re-drawn: %s", redraw, problems[:3])
    else:
        raise InvalidGeometryError(f"cannot lay out this seed's home after {REDRAWS} plans: "
                                   f"{'; '.join(problems[:3])}")
    fp.info.update({"redraws": redraw, "planned_widths": plan.planned_widths, "seed": seed,
                    "config": cfg.to_json(),
                    "graph": plan.graph.to_json(),
                    "contours": [g.contour for g in plan.grids],
                    "anneal": stats.to_json(), "stats": stats,
                    "timings_s": {"init": round(t1 - t0, 4), "anneal": round(t2 - t1, 4),
                                  "openings": round(time.perf_counter() - t2, 4),
                                  "total": round(time.perf_counter() - t0, 4)}})
    return fp


def to_floorplan(plan: GridPlan, cfg: FloorplanConfig, rng: np.random.Generator) -> Floorplan:
    """The solved plan as data: room polygons, doors, openings, windows, stairs, entrance."""
    pitch = storey_pitch(cfg)
    stairs = place_stairs(plan)
    doors, openings = place_doors(plan, rng, cfg.interior_wall, cfg.open_prob, cfg.height,
                                  stairs, cfg.exterior_wall / 2)
    entrance = place_entrance(plan)
    vehicle_doors = place_vehicle_doors(plan)
    windows = place_windows(plan, rng, cfg.exterior_wall, entrance, plan.stair_polygon(),
                            vehicle_doors)
    storeys = []
    for k, names in enumerate(plan.names):
        rooms = []
        for n in names:
            poly = plan.polygon(n)
            assert poly is not None  # annealing keeps every room one simple polygon
            pts = np.asarray(poly.exterior.coords)[:-1]
            rooms.append(RoomSpec(n, room_type_of(n),
                                  [(round(float(x), 6), round(float(y), 6)) for x, y in pts]))
        storeys.append(Storey(k, round(k * pitch, 6), cfg.height, rooms, doors[k], windows[k],
                              openings[k]))
    return Floorplan(storeys, stairs, entrance, vehicle_doors=vehicle_doors)


__all__ = ["FloorplanConfig", "generate_floorplan", "build_plan", "to_floorplan", "storey_pitch"]
