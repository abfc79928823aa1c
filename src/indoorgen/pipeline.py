"""`generate(seed, config) -> Generated`: the only place that orders the stages.

room architecture -> constraint program -> staged solve -> full-mesh check -> Scene, and
`write_scene_dir` for the files (written to a temporary directory, then renamed into place).
"""
from __future__ import annotations

import functools
import json
import logging
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from indoorgen.architecture.doors import check_door_mode
from indoorgen.architecture.room import RoomGeometry, build_room, place_door, rectangle
from indoorgen.architecture.solidify import room_geometries, solidify
from indoorgen.assets import Asset
from indoorgen.assets.cache import AssetCache
from indoorgen.assets.materials import check_style, draw_style
from indoorgen.constraints.evaluator import Result
from indoorgen.constraints.problem import Problem
from indoorgen.constraints.sets import scene as scene_set
from indoorgen.errors import ConfigError, IndoorGenError, InvalidGeometryError, UnknownPresetError
from indoorgen.export import write_formats
from indoorgen.export.bundle import bundle_from_generated
from indoorgen.floorplan.generate import WALL_RANGE, FloorplanConfig, generate_floorplan
from indoorgen.model.floorplan import Floorplan
from indoorgen.model.floorplan_io import check_predefined, from_json
from indoorgen.model.floorplan_io import to_json as floorplan_json
from indoorgen.model.polygons import validate_polygon
from indoorgen.model.room_types import ROOM_TYPES, RoomTypeSpec
from indoorgen.model.scene import Pose, RelationInstance, Room, Scene, SceneObject
from indoorgen.model.schemas import MAX_ROOM_SIDE, MIN_ROOM_SIDE, RoomPolygon, parse
from indoorgen.model.tags import Semantics
from indoorgen.outputs import atomic_dir
from indoorgen.programs import ROOM_PROGRAMS, get_program
from indoorgen.quality.layout import quality_report
from indoorgen.quality.navigation import navigation_report, write_nav_images
from indoorgen.quality.verdict import scene_status
from indoorgen.render.plan import draw_plan
from indoorgen.rng import stream
from indoorgen.solver.anneal import AnnealConfig
from indoorgen.solver.circulation import circulation_report
from indoorgen.solver.full_mesh import full_mesh_check
from indoorgen.solver.placement import planar
from indoorgen.solver.stages import (
    STAGES,
    RoomUnmet,
    evaluators_for,
    first_unmet,
    merge,
    solve,
)
from indoorgen.solver.state import State
from indoorgen.solver.workers import solve_rooms

log = logging.getLogger(__name__)

#: the most generated floorplans a home tries: a plan whose furnished home fails a hard
#: requirement gives way to the seed's next plan (a 1.3 m-wide bathroom with no room for a
#: shower, a kitchen whose doors leave no wall for the fridge's run), as rejection sampling does
HOME_PLANS = 3


@dataclass(frozen=True)
class Preset:
    """Time traded for density: annealing steps per stage and the range each scene's fullness
    (how much its furniture holds, `programs.contents`) is drawn from."""

    steps: dict[str, int]
    fullness: tuple[float, float]


#: the presets of `--preset`; "default" is what `indoorgen generate --seed N` gives
PRESETS: dict[str, Preset] = {
    "fast": Preset({"large": 250, "medium": 200, "small": 300}, (0.3, 0.7)),
    "default": Preset({"large": 600, "medium": 300, "small": 700}, (0.6, 1.4)),
    "dense": Preset({"large": 800, "medium": 400, "small": 1400}, (1.1, 1.6)),
}


def get_preset(name: str) -> Preset:
    """The preset called `name`, or UnknownPresetError naming the valid ones."""
    try:
        return PRESETS[name]
    except KeyError:
        raise UnknownPresetError(f"unknown preset {name!r}; valid: "
                                 + ", ".join(PRESETS)) from None


#: the most annealing steps a stage may be given (the dense preset's largest is 1,400)
MAX_STEPS = 100_000


def stage_steps(preset: Preset, steps: dict[str, int] | None) -> dict[str, int]:
    """The preset's annealing steps per stage, with the caller's `steps` over them; ConfigError
    names an unknown stage or a count outside 0..MAX_STEPS."""
    for stage, n in (steps or {}).items():
        if stage not in STAGES:
            raise ConfigError(f"steps for unknown stage {stage!r}; valid: {', '.join(STAGES)}")
        if isinstance(n, bool) or not isinstance(n, int) or not 0 <= n <= MAX_STEPS:
            raise ConfigError(f"steps[{stage!r}] = {n!r} is out of range; give an integer from 0 "
                              f"to {MAX_STEPS}")
    return {**preset.steps, **(steps or {})}


def home_style(seed: int, style: str | None) -> str:
    """The home style the scene's furniture materials are drawn from: `style` if given (checked),
    else drawn once per scene from the seed's own stream (`assets.materials.styles`)."""
    return check_style(style) if style is not None else draw_style(stream(seed, "style"))


def scene_fullness(seed: int, preset: Preset) -> float:
    """How full this scene's furniture is: drawn once per scene from the seed's own stream
    within the preset's range (some homes sparse, some cluttered)."""
    lo, hi = preset.fullness
    return round(float(stream(seed, "fullness").uniform(lo, hi)), 3)


@dataclass
class GenerateConfig:
    """What to generate. `program` overrides the room type's built-in constraint program."""

    room_type: str = "living_room"
    size: tuple[float, float] | None = None
    polygon: list[tuple[float, float]] | None = None
    height: float | None = None  # None: the room type's usual height
    wall_thickness: float = 0.12
    steps: dict[str, int] | None = None
    check: bool = False
    program: Callable[..., Problem] | None = None
    preset: str = "default"
    #: the home style (`assets.materials.STYLES`); None: drawn from the seed
    style: str | None = None

    def to_json(self) -> dict:
        """The settings as recorded in scene.json (the program by name; `generate` adds the
        style, given or drawn)."""
        return {"room_type": self.room_type,
                "size": list(self.size) if self.size else None,
                "polygon": [list(p) for p in self.polygon] if self.polygon else None,
                "height": self.height, "wall_thickness": self.wall_thickness,
                "steps": self.steps, "preset": self.preset,
                "program": getattr(self.program, "__name__", None)}


@dataclass
class Generated:
    """A solved scene plus what export and reporting need (rooms, solver state, cache)."""

    scene: Scene
    rooms: dict[str, RoomGeometry]
    state: State
    cache: AssetCache
    results: dict[str, Result]
    report: dict[str, Any] = field(default_factory=dict)
    #: the solidified home (architecture.solidify.Architecture) when this is a whole home
    architecture: Any = None

    def full_assets(self) -> dict[str, Asset]:
        """Every object's full (detailed) asset, built once per (generator, params)."""
        return {n: self.cache.full(o.generator, o.params) for n, o in self.scene.objects.items()}

    def footprints(self) -> dict:
        """Every object's footprint polygon on the floor plane, for plan drawings."""
        return {n: self.state.footprint(n) for n in self.scene.objects}


def _make_room(seed: int, cfg: GenerateConfig) -> Room:
    if cfg.program is None and cfg.room_type not in ROOM_PROGRAMS:
        get_program(cfg.room_type)  # raises UnknownRoomTypeError
    rng = stream(seed, "room", "architecture")
    # sizes and height when the user gives none: the table's, or its defaults for a custom type
    spec = ROOM_TYPES.get(cfg.room_type) or RoomTypeSpec(cfg.room_type)
    if cfg.polygon is not None:  # the ranges of --size hold for a polygon too
        poly = list(parse(RoomPolygon, {"polygon": cfg.polygon}, "room polygon").polygon)
    else:
        if cfg.size is not None:
            w, d = cfg.size
            if not (w > 0 and d > 0):
                raise InvalidGeometryError(f"room size {w} x {d} must be positive")
            if not all(MIN_ROOM_SIDE <= v <= MAX_ROOM_SIDE for v in (w, d)):
                raise InvalidGeometryError(f"room size {w} x {d} m is out of range; each side "
                                           f"must be between {MIN_ROOM_SIDE:g} and "
                                           f"{MAX_ROOM_SIDE:g} m")
        else:
            (w0, w1), (d0, d1) = spec.width, spec.depth
            w, d = round(float(rng.uniform(w0, w1)), 2), round(float(rng.uniform(d0, d1)), 2)
        poly = rectangle(w, d)
    lo, hi = WALL_RANGE
    if not (isinstance(cfg.wall_thickness, (int, float)) and lo <= cfg.wall_thickness <= hi):
        raise ConfigError(f"wall thickness {cfg.wall_thickness!r} m is out of range [{lo:g}, {hi:g}]")
    height = cfg.height if cfg.height is not None else spec.height
    if not (1.8 <= height <= 12.0):
        raise InvalidGeometryError(f"wall height {height} m is out of range [1.8, 12.0]")
    shape = validate_polygon(poly)
    coords = [(float(x), float(y)) for x, y in list(shape.exterior.coords)[:-1]]
    room = Room(cfg.room_type + "_0", cfg.room_type, coords, height, cfg.wall_thickness)
    room.doors.append(place_door(room, rng))
    return room


def _room_set(name: str):
    return scene_set()[Semantics.Room].named(name)


def generate(seed: int = 0, config: GenerateConfig | None = None, *, progress: bool = False
             ) -> Generated:
    """Generate one furnished room from `seed`. Same seed + config + version => same scene."""
    cfg = config or GenerateConfig()
    preset = get_preset(cfg.preset)
    t0 = time.perf_counter()
    room = _make_room(seed, cfg)
    geometry = {room.name: build_room(room)}
    fullness = scene_fullness(seed, preset)
    program = cfg.program or get_program(cfg.room_type, fullness)
    problems = {room.name: _problem(program, room.name)}
    timings = {"architecture": time.perf_counter() - t0}
    recorded = {**cfg.to_json(), "style": home_style(seed, cfg.style)}
    try:
        gen = _furnish(seed, geometry, problems, recorded, timings,
                       steps=stage_steps(preset, cfg.steps), check=cfg.check,
                       progress=progress)
    except IndoorGenError as e:  # a custom program's fault is named with the program
        if cfg.program is None:
            raise
        raise type(e)(f"program {getattr(cfg.program, '__name__', cfg.program)!r} failed while "
                      f"solving: {e}") from e
    gen.report["fullness"] = fullness
    _assess(gen)
    gen.report["timings_s"]["total"] = round(time.perf_counter() - t0, 4)
    return gen


@dataclass
class HomeConfig:
    """A whole home: the floorplan stage's settings (storeys, room counts, area or contour, or
    a predefined `floorplan` JSON dict), then every room furnished by its room type's program.
    Rooms whose type has no program (none today) stay empty."""

    floors: int = 1
    rooms: dict[str, int] | str | None = None
    area: float | None = None
    contour: list | None = None
    floorplan: dict | None = None
    steps: dict[str, int] | None = None
    check: bool = False
    #: how the room doors stand: "open", "closed" or "random" (architecture.doors.DOOR_MODES)
    doors: str = "open"
    preset: str = "default"
    #: processes solving rooms in parallel (1: in this process). Not recorded in scene.json:
    #: any number gives the same scene, byte for byte.
    workers: int = 1
    #: the home style (`assets.materials.STYLES`) every room's furniture draws its materials
    #: from; None: drawn from the seed
    style: str | None = None

    def to_json(self) -> dict:
        """The settings as recorded in scene.json (a predefined floorplan as a flag; not the
        number of workers, which changes nothing in the scene)."""
        return {"home": True, "floors": self.floors, "doors": self.doors,
                "rooms": self.rooms if isinstance(self.rooms, (str, type(None))) else dict(self.rooms),
                "area": self.area, "contour": self.contour,
                "predefined_floorplan": self.floorplan is not None, "steps": self.steps,
                "preset": self.preset}


def generate_home(seed: int = 0, config: HomeConfig | None = None, *, progress: bool = False
                  ) -> Generated:
    """Generate a furnished home from `seed`: floorplan, solid architecture, then each room
    furnished by its program. A generated floorplan whose furnished home fails a hard
    requirement is replaced by the seed's next plan, up to HOME_PLANS plans; the home is
    reported failed only if every one fails (report.json's `replanned` lists the plans given up
    and why). Same seed + config + version => same scene."""
    cfg = config or HomeConfig()
    check_door_mode(cfg.doors)
    style = home_style(seed, cfg.style)
    if isinstance(cfg.workers, bool) or not isinstance(cfg.workers, int) or cfg.workers < 1:
        raise ConfigError(f"workers must be a positive integer, got {cfg.workers!r}")
    preset = get_preset(cfg.preset)
    t0 = time.perf_counter()
    replanned: list[dict] = []
    gen: Generated | None = None
    if cfg.floorplan is not None:  # the user's own plan: furnished as it is
        plan = from_json(cfg.floorplan)
        check_predefined(plan)
        gen = _furnished_home(seed, cfg, plan, preset, style, progress)
    else:
        plan_cfg = FloorplanConfig(floors=cfg.floors, rooms=cfg.rooms, area=cfg.area,
                                   contour=cfg.contour)
        plan = generate_floorplan(seed, plan_cfg)
        for attempt in range(1, HOME_PLANS + 1):
            # a room left unmet dooms the plan: the rooms after it are not solved, unless this
            # is the last plan, whose failed home is reported whole
            try:
                gen = _furnished_home(seed, cfg, plan, preset, style, progress,
                                      give_up=attempt < HOME_PLANS)
                if not gen.report["status"]["failed"] or attempt == HOME_PLANS:
                    break
                reasons = gen.report["status"]["reasons"]
            except RoomUnmet as e:
                gen, reasons = None, e.reasons()
            try:
                nxt = generate_floorplan(seed, plan_cfg, first_redraw=plan.info["redraws"] + 1)
            except InvalidGeometryError:  # the seed has no further plan: report this one whole
                if gen is None:
                    gen = _furnished_home(seed, cfg, plan, preset, style, progress)
                break
            log.info("home %d: plan %d failed (%s); furnishing plan %d", seed,
                     plan.info["redraws"], reasons[0], nxt.info["redraws"])
            replanned.append({"plan": plan.info["redraws"], "reasons": reasons})
            plan = nxt
    assert gen is not None
    gen.report["replanned"] = replanned
    gen.report["timings_s"]["total"] = round(time.perf_counter() - t0, 4)
    return gen


def _furnished_home(seed: int, cfg: HomeConfig, plan: Floorplan, preset: Preset, style: str,
                    progress: bool, *, give_up: bool = False) -> Generated:
    """`plan` built, every room furnished by its program, and the home assessed; with
    `give_up`, RoomUnmet as soon as a room is left with a hard constraint unmet."""
    t1 = time.perf_counter()
    # seeded: doors, windows and stairs from the catalogue, door leaves as cfg.doors says
    arch = solidify(plan, seed=seed, doors=cfg.doors)
    geometry = room_geometries(arch)
    fullness = scene_fullness(seed, preset)
    problems = {name: _home_problem(g.room.room_type, fullness, name)
                for name, g in geometry.items() if g.room.room_type in ROOM_PROGRAMS}
    timings = {"floorplan": plan.info.get("timings_s", {}).get("total", 0.0),
               "architecture": time.perf_counter() - t1}
    gen = _furnish(seed, geometry, problems, {**cfg.to_json(), "style": style}, timings,
                   steps=stage_steps(preset, cfg.steps), check=cfg.check,
                   progress=progress, workers=cfg.workers,
                   make_problem=functools.partial(_room_problem, _room_types(geometry),
                                                  fullness), give_up=give_up)
    gen.report["fullness"] = fullness
    gen.scene.floorplan = floorplan_json(plan)
    gen.scene.doors = arch.door_states
    gen.architecture = arch
    _assess(gen)
    gen.report["floorplan"] = {k: v for k, v in plan.info.items() if k in ("anneal", "timings_s")}
    return gen


def _assess(gen: Generated) -> None:
    """Measure the finished scene (it changes nothing): the layout-quality rules and community
    measures go into report.json's `quality` section, walkability for a robot into `navigation`,
    and whether the scene failed (any hard requirement unmet) and why into `status`."""
    t = time.perf_counter()
    gen.report["quality"] = quality_report(gen.scene, gen.rooms, gen.cache, gen.architecture)
    gen.report["navigation"] = navigation_report(gen.scene, gen.rooms, gen.cache,
                                                 gen.architecture)
    gen.report["timings_s"]["quality"] = round(time.perf_counter() - t, 4)
    gen.report["status"] = scene_status(gen.report)


def _home_problem(room_type: str, fullness: float, room: str) -> Problem:
    """The built-in program of `room_type` at `fullness`, for the room called `room`."""
    return _problem(get_program(room_type, fullness), room)


def _room_types(geometry: dict[str, RoomGeometry]) -> dict[str, str]:
    """Each room's type, by room name."""
    return {name: g.room.room_type for name, g in geometry.items()}


def _room_problem(room_types: dict[str, str], fullness: float, room: str) -> Problem:
    """A home room's problem, built from picklable facts (what a worker process is sent)."""
    return _home_problem(room_types[room], fullness, room)


def _problem(program: Callable[..., Problem], room: str) -> Problem:
    problem = program(_room_set(room))
    if not isinstance(problem, Problem):
        raise ConfigError(f"program {getattr(program, '__name__', program)!r} must return a "
                          f"Problem, got {type(problem).__name__}")
    return problem


def _furnish(seed: int, geometry: dict[str, RoomGeometry], problems: dict[str, Problem],
             config: dict, timings: dict[str, float], *, steps, check: bool, progress: bool,
             workers: int = 1, make_problem: Callable[[str], Problem] | None = None,
             give_up: bool = False) -> Generated:
    """Solve every room's problem (in `workers` processes if `make_problem` rebuilds each
    room's problem there), re-check with full meshes and package the Scene. With `give_up`,
    RoomUnmet for the first room (in name order) left with a hard constraint unmet, however
    many workers solve them."""
    cache = AssetCache()
    state = State(geometry, cache)
    t1 = time.perf_counter()
    anneal = AnnealConfig(check=check)
    if workers > 1 and make_problem is not None and len(problems) > 1:
        solutions, full = solve_rooms(geometry, make_problem, sorted(problems), seed,
                                      workers=min(workers, len(problems)), config=anneal,
                                      steps=steps, progress=progress)
        unmet = first_unmet(solutions)
        if give_up and unmet is not None:
            raise RoomUnmet(unmet)
        for generator, params, asset in full:
            cache.adopt_full(generator, params, asset)
        stats = merge(state, solutions)
        evaluators = evaluators_for(state, problems, check=check)
    else:
        stats, evaluators = solve(state, problems, seed, config=anneal, steps=steps,
                                  progress=progress, give_up=give_up)
    timings["solve"] = time.perf_counter() - t1

    t2 = time.perf_counter()
    removed = full_mesh_check(state)
    for ev in evaluators.values():
        ev.set_active(None)
        ev.notify(removed=removed)
    results = {r: ev.evaluate() for r, ev in evaluators.items()}
    timings["full_meshes"] = time.perf_counter() - t2

    sc = Scene(seed=seed, config=config)
    for name, g in geometry.items():
        sc.rooms[name] = g.room
    for name, ob in state.objects.items():
        sc.add_object(SceneObject(
            name=name, generator=ob.generator, params=ob.params, seed=ob.seed,
            pose=Pose((float(ob.position[0]), float(ob.position[1]), float(ob.position[2])),
                      float(ob.yaw)),
            tags=sorted(getattr(t, "value", str(t)) for t in ob.tags), room=ob.room,
            relations=[RelationInstance(repr(p.relation), p.parent, p.child_surface,
                                        p.parent_surface, planar(p.relation).margin)
                       for p in ob.placements],
            stage=ob.stage))
    report = {
        "seed": seed,
        "timings_s": {k: round(v, 4) for k, v in timings.items()},
        "stages": [s.to_json() for s in stats],
        "objects": len(sc.objects),
        "objects_per_stage": {s: sum(1 for o in sc.objects.values() if o.stage == s)
                              for s in ("large", "medium", "small")},
        "removed_by_full_mesh_check": removed,
        "rooms": {r: {"violations": res.violations, "n_violated": res.n_violated,
                      "scores": res.scores, "loss": res.loss,
                      "circulation": circulation_report(evaluators[r].problem, state, r)}
                  for r, res in results.items()},
    }
    return Generated(sc, geometry, state, cache, results, report)


def write_scene_dir(gen: Generated, out: Path, *, usd_ext: str = "usdc",
                    formats=None, nav_images: bool = False, overwrite: bool = False) -> Path:
    """Write scene.json, plan.png, report.json and the export `formats` (default usd, urdf,
    mjcf; see `export.formats`) to `out`, atomically: everything goes to a temporary sibling
    directory that is renamed into place when complete. `nav_images` adds a `nav_<storey>.png`
    per storey: the free floor a robot reaches from the entrance, and what it cannot.
    `overwrite` lets it write beside the files of a non-empty directory indoorgen did not write
    (`outputs.atomic_dir`)."""
    out = Path(out)
    with atomic_dir(out, overwrite=overwrite) as tmp:
        t0 = time.perf_counter()
        (tmp / "scene.json").write_text(gen.scene.dumps())
        write_formats(bundle_from_generated(gen), tmp, formats, usd_ext=usd_ext)
        zones = {r: g.door_zones for r, g in gen.rooms.items()}
        draw_plan(gen.scene, gen.footprints(), tmp / "plan.png", door_zones=zones,
                  title=_plan_title(gen.scene))
        if nav_images:
            write_nav_images(gen.scene, gen.rooms, gen.cache, gen.architecture, tmp)
        gen.report.setdefault("timings_s", {})["export"] = round(time.perf_counter() - t0, 4)
        (tmp / "report.json").write_text(json.dumps(gen.report, indent=1, sort_keys=True,
                                                    default=_json_default) + "\n")
    return out


def _plan_title(scene: Scene) -> str:
    if len(scene.rooms) == 1:
        return f"{next(iter(scene.rooms.values())).room_type}  seed {scene.seed}"
    return f"home, seed {scene.seed}: {len(scene.rooms)} rooms, {len(scene.objects)} objects"


def _json_default(o):
    if isinstance(o, (np.floating, np.integer)):
        return o.item()
    return str(o)
