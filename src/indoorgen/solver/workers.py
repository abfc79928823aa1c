"""A home's rooms solved in parallel processes (`--workers`).

Once the floorplan is fixed the rooms are independent (`solver.stages`: each room has its own
random streams and namer and is solved in a state holding no other room's objects), so a pool
of worker processes solves them in any order and `stages.merge` gives the same scene as solving
them one after the other. Each worker also builds the detailed assets of its room's objects (the
full-mesh check and the exports need them), so that work runs in parallel too.

The pool is created once per home from a "forkserver" context (forking a process that has
started threads is unsafe); the server imports indoorgen once, so workers start without
re-importing it. A task carries only what its room needs: the rooms' geometry (walls of every
room: the solver's static pieces), a picklable function building the room's problem, the seed
and the settings.
"""
from __future__ import annotations

import logging
import multiprocessing as mp
import os
from collections.abc import Callable, Mapping
from concurrent.futures import ProcessPoolExecutor, as_completed
from typing import Any

import shapely.geometry as sg
from threadpoolctl import threadpool_limits
from tqdm import tqdm

from indoorgen.assets import Asset
from indoorgen.assets.cache import AssetCache, params_key
from indoorgen.constraints.problem import Problem
from indoorgen.solver.anneal import AnnealConfig
from indoorgen.solver.stages import RoomSolution, solve_room
from indoorgen.solver.state import RoomShape, State

log = logging.getLogger(__name__)

#: what a worker imports before it forks (so each worker starts with indoorgen loaded)
PRELOAD = ["indoorgen.pipeline"]

#: a room's detailed assets as (generator, params, asset), one per distinct design
FullAssets = list[tuple[str, dict[str, Any], Asset]]


def usable_cores() -> int:
    """How many cores this process may run on (its CPU affinity where the platform tells it,
    else the machine's count): the default number of parallel processes."""
    affinity = getattr(os, "sched_getaffinity", None)
    return len(affinity(0)) if affinity is not None else (os.cpu_count() or 1)


def solve_rooms(geometry: Mapping[str, RoomShape], make_problem: Callable[[str], Problem],
                rooms: list[str], seed: int, *, workers: int,
                config: AnnealConfig | None = None, steps: dict[str, int] | None = None,
                progress: bool = False) -> tuple[list[RoomSolution], FullAssets]:
    """Solve `rooms` (each room's problem from `make_problem(room)`, which must pickle: a
    module-level function or a `functools.partial` of one) in `workers` processes. Returns the
    rooms' solutions and the detailed assets of their objects."""
    config = config or AnnealConfig()
    # the biggest rooms first, so no worker is left with a long room at the end
    order = sorted(rooms, key=lambda r: (-sg.Polygon(geometry[r].room.polygon).area, r))
    ctx = mp.get_context("forkserver")
    ctx.set_forkserver_preload(PRELOAD)
    solutions: list[RoomSolution] = []
    full: FullAssets = []
    # the pool's parallelism is its processes: one BLAS thread each, not one spinning on the
    # other worker's core (as `batch.runner` runs its scenes)
    with ProcessPoolExecutor(max_workers=workers, mp_context=ctx, initializer=threadpool_limits,
                             initargs=(1,)) as pool:
        futures = [pool.submit(solve_one, dict(geometry), make_problem, room, seed, config, steps)
                   for room in order]
        for fut in tqdm(as_completed(futures), total=len(futures), desc="solving", unit="room",
                        disable=not progress, leave=False):
            sol, assets = fut.result()
            solutions.append(sol)
            full.extend(assets)
    return solutions, full


def solve_one(geometry: dict[str, RoomShape], make_problem: Callable[[str], Problem], room: str,
              seed: int, config: AnnealConfig, steps: dict[str, int] | None
              ) -> tuple[RoomSolution, FullAssets]:
    """One worker task: solve `room` in a fresh state of the home's architecture and build its
    objects' detailed assets."""
    cache = AssetCache()
    sol = solve_room(State(geometry, cache), room, make_problem(room), seed, config=config,
                     steps=steps)
    full: dict[tuple, tuple[str, dict[str, Any], Asset]] = {}
    for ob in sol.objects:
        key = params_key(ob.generator, ob.params)
        if key not in full:
            full[key] = (ob.generator, ob.params, cache.full(ob.generator, ob.params))
    return sol, list(full.values())
