"""Solver benchmark: end-to-end room generation times, and annealing step cost versus scene size.

    python benchmarks/solve_room.py [--seeds 5] [--room living_room] [--steps 1500] [--repeats 5]
                                    [--no-steps]

Prints, per seed, seconds per stage, total, steps/s and objects placed, then the median and p90
of the totals; then (unless --no-steps)
the cost of one annealing step in a large synthetic hall holding ~30 and ~300 objects.
"""
from __future__ import annotations

import argparse
import math
import statistics
import time

import numpy as np

from indoorgen import GenerateConfig, generate
from indoorgen.architecture.room import build_room, rectangle
from indoorgen.assets import get_factory
from indoorgen.assets.cache import AssetCache
from indoorgen.constraints import Problem, rotational_asymmetry, scene
from indoorgen.constraints.evaluator import Evaluator
from indoorgen.model.scene import Room
from indoorgen.model.tags import Semantics as S
from indoorgen.programs.relations import at_table, on_floor
from indoorgen.solver.anneal import AnnealConfig, Annealer
from indoorgen.solver.placement import solve_pose
from indoorgen.solver.stages import make_namer
from indoorgen.solver.state import ObjState, Placement, State


def end_to_end(seeds: int, room: str) -> None:
    print(f"== {room}: end to end, {seeds} seeds ==")
    print(f"{'seed':>4} {'large':>7} {'medium':>7} {'small':>7} {'total':>7} {'steps/s':>8} "
          f"{'objects':>7} {'violated':>8}")
    totals = []
    for seed in range(seeds):
        t0 = time.perf_counter()
        g = generate(seed, GenerateConfig(room_type=room))
        total = time.perf_counter() - t0
        totals.append(total)
        st = {s["stage"]: s for s in g.report["stages"]}
        steps = sum(s["steps"] for s in st.values())
        solve_s = sum(s["seconds"] for s in st.values())
        viol = sum(r["n_violated"] for r in g.report["rooms"].values())
        print(f"{seed:>4} {st['large']['seconds']:>7.2f} {st['medium']['seconds']:>7.2f} "
              f"{st['small']['seconds']:>7.2f} {total:>7.2f} {steps / solve_s:>8.0f} "
              f"{g.report['objects']:>7d} {viol:>8d}")
    print(f"total: median {statistics.median(totals):.2f} s, "
          f"p90 {float(np.percentile(totals, 90)):.2f} s")


def hall_program(room):
    floor = scene().related_to(room, on_floor)
    tables, chairs = floor[S.DiningTable], floor[S.DiningChair]
    return Problem(
        constraints={"chairs at tables": tables.all(
            lambda t: chairs.related_to(t, at_table).count().in_range(4, 4))},
        score_terms={"even": tables.mean(
            lambda t: rotational_asymmetry(chairs.related_to(t, at_table))).minimize(1),
            "near": tables.mean(lambda t: t.distance(room).hinge(0.5, 99)).minimize(1)})


def hall_state(n_tables: int) -> tuple[State, str]:
    """A square hall with `n_tables` tables on a 3 m grid, four chairs at each (5 objects per
    table), built directly rather than solved so both sizes start from the same kind of layout."""
    side = 3.0 * math.ceil(math.sqrt(n_tables)) + 1.0
    room = Room("hall_0", "dining_room", rectangle(side, side), 3.0, 0.12)
    rooms = {room.name: build_room(room)}
    state = State(rooms, AssetCache())
    rng = np.random.default_rng(0)
    namer = make_namer()
    tfac, cfac = get_factory("dining_table_rect"), get_factory("dining_chair")
    k = int(math.ceil(math.sqrt(n_tables)))
    tparams = tfac.sample_params(rng)
    tparams.update({k2: v for k2, v in tparams.items()})
    for i in range(n_tables):
        x, y = 2.0 + 3.0 * (i % k), 2.0 + 3.0 * (i // k)
        tname = namer("dining_table_rect")
        asset = state.cache.placeholder("dining_table_rect", tparams)
        pl = [Placement(on_floor, room.name, "bottom", "floor")]
        ob = ObjState(tname, "dining_table_rect", tparams, 0, frozenset(tfac.tags), room.name,
                      "large", asset, pl, np.zeros(3), 0.0)
        state.add(ob)
        pos, yaw, _ = solve_pose(state, asset, pl, np.array([x, y, 0.0]), 0.0)
        state.set_pose(tname, pos, yaw)
        sides = [s.name for s in asset.surfaces if s.subpart.value == "side"][:4]
        cparams = cfac.sample_params(rng)
        for s in sides:
            casset = state.cache.placeholder("dining_chair", cparams)
            cpl = [Placement(on_floor, room.name, "bottom", "floor"),
                   Placement(at_table, tname, "front", s)]
            cname = namer("dining_chair")
            sw = state.surface_world(tname, s)
            c = ObjState(cname, "dining_chair", cparams, 0, frozenset(cfac.tags), room.name,
                         "medium", casset, cpl, np.zeros(3), 0.0)
            state.add(c)
            pos, yaw, _ = solve_pose(state, casset, cpl, sw.origin, 0.0)
            state.set_pose(cname, pos, yaw)
    return state, room.name


def step_cost(n_tables: int, steps: int) -> tuple[int, float, float]:
    state, room = hall_state(n_tables)
    prob = hall_program(scene()[S.Room].named(room))
    ev = Evaluator(prob, state)
    cfg = AnnealConfig(moves={"translate": 3.0, "rotate": 1.0, "reinit": 0.5, "delete": 0.2,
                              "add": 0.2}, patience=10.0)  # no early stop: every step counts
    ann = Annealer(state, prob, ev, room, "medium", np.random.default_rng(1), cfg, make_namer())
    t0 = time.perf_counter()
    st = ann.run(steps)
    dt = time.perf_counter() - t0
    return len(state.objects), dt / st.steps * 1e3, ev.recomputed / st.steps


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--seeds", type=int, default=5)
    ap.add_argument("--room", default="living_room")
    ap.add_argument("--steps", type=int, default=1500)
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--no-steps", action="store_true", help="skip the step-cost measurement")
    a = ap.parse_args()
    end_to_end(a.seeds, a.room)
    if a.no_steps:
        return
    print("== step cost versus objects (synthetic hall, medium stage, continuous + discrete moves) ==")
    print(f"   ({a.repeats} interleaved runs per size; the median run is reported, since a single "
          "run on this shared machine varies by +-30%)")
    runs: dict[int, list] = {6: [], 60: []}
    for _ in range(a.repeats):
        for n in runs:
            runs[n].append(step_cost(n, a.steps))
    rows = [sorted(r, key=lambda x: x[1])[len(r) // 2] for r in runs.values()]
    for (n, ms, rec), r in zip(rows, runs.values(), strict=True):
        spread = ", ".join(f"{x[1]:.2f}" for x in r)
        print(f"{n:>4} objects: {ms:.3f} ms/step ({spread}), {rec:.1f} nodes re-evaluated/step")
    print(f"ratio 300 vs 30: {rows[1][1] / rows[0][1]:.2f}x")


if __name__ == "__main__":
    main()
