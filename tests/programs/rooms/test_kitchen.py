"""The kitchen program (`programs.rooms.kitchen`): base units are set into the run beside the
appliances, across a filler strip that clears the doors' sweeps and stays inside the run."""
from __future__ import annotations

import numpy as np
import pytest

from indoorgen.assets import get_factory
from indoorgen.constraints import scene
from indoorgen.constraints.bounds import find_bounds
from indoorgen.constraints.evaluator import Evaluator
from indoorgen.model.tags import Semantics as S
from indoorgen.programs.relations import against_wall, on_floor
from indoorgen.programs.rooms.kitchen import IN_RUN, RUN_FILLER, in_run, kitchen
from indoorgen.solver.keep_free import sweep_volumes
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
