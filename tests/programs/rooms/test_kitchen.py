"""The kitchen program (`programs.rooms.kitchen`): base units are set into the run beside the
appliances, across a filler strip that clears the doors' sweeps and stays inside the run."""
from __future__ import annotations

import math

import numpy as np
import pytest

from indoorgen.assets import get_factory
from indoorgen.constraints import scene
from indoorgen.constraints.bounds import find_bounds
from indoorgen.constraints.evaluator import Evaluator
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart
from indoorgen.programs.relations import against_wall, hung_above, on_floor, on_wall
from indoorgen.programs.rooms.kitchen import (
    HOOD_GAP,
    IN_RUN,
    RUN_FILLER,
    TRIANGLE_HARD_CAP,
    TRIANGLE_LEG,
    in_run,
    kitchen,
    work_triangle,
)
from indoorgen.solver.keep_free import sweep_volumes
from support.dsl import value
from support.fakeview import FakeView

#: how far before the fronts a neighbour's handles and worktop edge stand (m)
FRONT_BAND = 0.06


def test_base_units_are_offered_a_place_beside_the_sink():
    view = FakeView()
    view.add_room("r", [(0, 0), (4, 0), (4, 3), (0, 3)])
    view.add("kitchen_sink_0", {S.Object, S.KitchenSink, S.Countertop}, center=(0.3, 1.5, 0.45),
             extents=(0.6, 0.8, 0.9), relations=[(on_floor, "r"), (against_wall, "r")],
             generator="kitchen_sink", params={})
    problem = kitchen(scene()[S.Room].named("r"))
    bounds = {b.name: b for b in find_bounds(problem, Evaluator(problem, view))}
    runs = bounds["cabinet runs"]
    assert runs.can_add
    beside = [names for rel, names in runs.parents if rel == in_run]
    assert beside and "kitchen_sink_0" in beside[0]


@pytest.mark.parametrize("generator", ["kitchen_base_cabinet", "countertop_run", "kitchen_sink",
                                       "range", "dishwasher", "fridge"])
def test_the_filler_clears_the_sweeps_before_the_fronts_and_stays_in_the_run(generator):
    assert RUN_FILLER <= IN_RUN
    factory = get_factory(generator)
    for seed in range(6):
        params = factory.sample_params(np.random.default_rng(seed))
        asset = factory.placeholder(params)
        sweeps = sweep_volumes(asset.joints, factory.link_boxes(params))
        if not sweeps:
            continue
        lo, hi = asset.mesh.bounds
        pts = np.vstack(sweeps)
        near = pts[pts[:, 0] <= hi[0] + FRONT_BAND]
        if len(near):
            past_side = max(near[:, 1].max() - hi[1], lo[1] - near[:, 1].min())
            assert past_side <= RUN_FILLER, (generator, seed, past_side)


def test_the_runs_are_built_in_one_stage_with_the_fridge_at_an_end():
    """Units, the dishwasher and the fridge are set in beside the appliances while the large
    stage stands them (they are no afterthought of the medium stage); no unit is set beside the
    fridge, which closes a run's end."""
    view = FakeView()
    view.add_room("r", [(0, 0), (4, 0), (4, 3), (0, 3)])
    view.add("kitchen_sink_0", {S.Object, S.KitchenSink, S.Countertop}, center=(0.3, 1.5, 0.45),
             extents=(0.6, 0.8, 0.9), relations=[(on_floor, "r"), (against_wall, "r")],
             generator="kitchen_sink", params={})
    view.add("fridge_0", {S.Object, S.Fridge, S.Appliance}, center=(0.35, 0.5, 0.9),
             extents=(0.7, 0.8, 1.8), relations=[(on_floor, "r"), (against_wall, "r")],
             generator="fridge", params={})
    problem = kitchen(scene()[S.Room].named("r"))
    bounds = {b.name: b for b in find_bounds(problem, Evaluator(problem, view))}
    for name in ("cabinet runs", "a fridge", "a dishwasher at most"):
        assert bounds[name].stage(frozenset({"r"})) == "large", name
    assert "kitchen_sink_0" not in dict(bounds["a fridge"].parents).get(in_run, ())
    assert "fridge_0" not in dict(bounds["cabinet runs"].parents)[in_run]


@pytest.mark.parametrize("cooker_y,fridge_y,outside", [
    (2.9, 0.5, 0.2),    # legs 1.4, 1.0, 2.4: sink-fridge 0.2 short
    (3.0, -0.3, 0.6),   # legs 1.5, 1.8, 3.3: cooker-fridge 0.6 long
])
def test_the_work_triangle_measures_its_legs_between_the_fronts(cooker_y, fridge_y, outside):
    """`work_triangle`: how far the legs, front centre to front centre, fall outside the
    guideline's 1.2-2.7 m; zero when every leg is inside."""
    term = work_triangle(scene()[S.KitchenSink], scene()[S.Range], scene()[S.Fridge], TRIANGLE_LEG)
    view = FakeView()
    for name, tag, y in (("sink", S.KitchenSink, 1.5), ("range", S.Range, cooker_y),
                         ("fridge", S.Fridge, fridge_y)):
        view.add(name, {tag}, center=(0.3, y, 0.45), extents=(0.6, 0.6, 0.9))
    assert value(view, term) == pytest.approx(outside)
    # the fridge turned onto the next wall of the corner, an L: every leg 1.4-2.5 m
    view.move("fridge", center=(1.9, 0.6, 0.45), yaw=math.pi / 2)
    assert value(view, term) == pytest.approx(0.0)


def test_the_everyday_kit_stands_on_the_run_one_of_each():
    """A kettle, a toaster, a knife block and a utensil crock are offered a place on the run's
    units (after the furniture, with the small things), one of each at most."""
    view = FakeView()
    view.add_room("r", [(0, 0), (4, 0), (4, 3), (0, 3)])
    view.add("kitchen_sink_0", {S.Object, S.KitchenSink, S.Countertop}, center=(0.3, 1.5, 0.45),
             extents=(0.6, 0.8, 0.9), relations=[(on_floor, "r"), (against_wall, "r")],
             generator="kitchen_sink", params={})
    view.add("unit_0", {S.Object, S.KitchenCabinet, S.Countertop}, center=(0.3, 2.35, 0.45),
             extents=(0.6, 0.8, 0.9), generator="kitchen_base_cabinet", params={},
             relations=[(on_floor, "r"), (against_wall, "r"), (in_run, "kitchen_sink_0")])
    problem = kitchen(scene()[S.Room].named("r"))
    bounds = {b.name: b for b in find_bounds(problem, Evaluator(problem, view))}
    for kind in ("kettle", "toaster", "knife block", "utensil crock"):
        b = bounds[f"a {kind} at most"]
        assert b.stage(frozenset({"r"})) == "small", kind
        assert b.can_add and any("unit_0" in names for _, names in b.parents), kind


@pytest.mark.parametrize("room_y,required", [(3.0, True), (2.4, False), (6.0, True),
                                             (9.5, False)])
def test_the_triangle_is_required_where_the_floor_allows_it(room_y, required):
    """A work triangle whose legs fall short violates the program in a kitchen 2.8-9 m each
    way (where an L or two facing runs fit it), by less than a missing appliance (so none is
    dropped to spare a leg); in a narrower (a galley) or a longer one it stays a score."""
    view = FakeView()
    view.add_room("r", [(0, 0), (4, 0), (4, room_y), (0, room_y)])
    for name, tag, y in (("sink", S.KitchenSink, 0.5), ("range", S.Range, 1.3)):
        view.add(name, {S.Object, tag}, center=(0.35, y, 0.45), extents=(0.6, 0.7, 0.9),
                 relations=[(on_floor, "r"), (against_wall, "r")], generator=name, params={})
    # the cooker 0.8 m from the sink: 0.4 m short of the shortest leg
    result = Evaluator(kitchen(scene()[S.Room].named("r")), view).evaluate()
    violation = result.violations["the work triangle where it fits"]
    assert (violation > 0) == required
    assert violation <= TRIANGLE_HARD_CAP < 1.0


@pytest.mark.parametrize("hood_at,hood_yaw,ok", [
    ((0.25, 1.5, 1.6), 0.0, True),                # behind the cooker, on its wall
    ((0.3, 1.56, 1.6), 0.0, True),                # on its wall, 0.06 m to a side
    ((0.55, 0.25, 1.6), math.pi / 2, False),      # on the next wall of the corner
])
def test_a_hood_hangs_on_the_cookers_wall(hood_at, hood_yaw, ok):
    """A hood hangs behind the cooker on the cooker's own wall, not beside it on the next wall
    of a corner (where its centre can still be over the cooker's top)."""
    view = FakeView()
    view.add_room("r", [(0, 0), (4, 0), (4, 3), (0, 3)])
    view.add("range", {S.Object, S.Range}, center=(0.4, 1.5, 0.45), extents=(0.7, 0.76, 0.9),
             relations=[(on_floor, "r"), (against_wall, "r")], generator="range", params={})
    view.add("hood", {S.Object, S.RangeHood}, center=hood_at, yaw=hood_yaw,
             extents=(0.5, 0.7, 0.5), generator="range_hood", params={},
             relations=[(on_wall, "r"), (hung_above(HOOD_GAP, Subpart.Top), "range")])
    result = Evaluator(kitchen(scene()[S.Room].named("r")), view).evaluate()
    assert (result.violations["a hood behind the cooker"] == 0) == ok
