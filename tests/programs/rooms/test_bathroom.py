"""The bathroom program: a compact shower where a small bathroom has no corner for more."""
from __future__ import annotations

import numpy as np
import pytest

from indoorgen.assets import get_factory
from indoorgen.constraints import scene
from indoorgen.constraints.bounds import find_bounds
from indoorgen.constraints.evaluator import Evaluator
from indoorgen.model.tags import Semantics as S
from indoorgen.programs.rooms.bathroom import (
    BARE_BAR_BOTTOM,
    COMPACT_SHOWER,
    DRAPED_BAR_BOTTOM,
    bathroom,
)
from indoorgen.quality.rules import TOWEL_BAR_HEIGHT
from indoorgen.solver.keep_free import sweep_volumes
from support.fakeview import FakeView


@pytest.mark.parametrize("seed", range(4))
def test_a_compact_shower_is_a_0_8_m_square_whose_door_sweeps_nothing_before_it(seed):
    factory = get_factory("shower_enclosure")
    params = {**factory.sample_params(np.random.default_rng(seed)), **COMPACT_SHOWER}
    asset = factory.placeholder(params)
    lo, hi = asset.mesh.bounds
    assert (hi - lo)[:2] == pytest.approx([0.8, 0.8], abs=0.05)
    for pts in sweep_volumes(asset.joints, factory.link_boxes(params)):
        assert pts[:, 0].max() <= hi[0] + 0.02  # a sliding door stays in the front's plane


@pytest.mark.parametrize("size, offered", [((1.8, 2.4), True), ((3.0, 3.4), False)])
def test_a_compact_shower_is_offered_in_a_small_bathroom_only(size, offered):
    """A 1.8 x 2.4 m bathroom may take the compact shower for its bath or shower; a 10 m^2 one
    takes a full-size enclosure or a bath."""
    w, d = size
    view = FakeView()
    view.add_room("r", [(0, 0), (w, 0), (w, d), (0, d)])
    problem = bathroom(scene()[S.Room].named("r"))
    bounds = [b for b in find_bounds(problem, Evaluator(problem, view))
              if b.context.generator == "shower_enclosure"
              and dict(b.context.params).get("door") == "sliding"]
    assert bounds
    most = min(b.hi for b in bounds)  # the compact shower's allowance, the tighter bound
    assert (most >= 1) == offered


@pytest.mark.parametrize("towel", [False, True])
def test_towel_bars_centre_at_nkba_heights_with_or_without_a_towel(towel):
    """Each kind of towel bar the program offers, hung at its own mounting height, centres at
    1.0-1.2 m whatever its towel's drop (300 sampled bars of each kind)."""
    view = FakeView()
    view.add_room("r", [(0, 0), (3.0, 0), (3.0, 3.4), (0, 3.4)])
    problem = bathroom(scene()[S.Room].named("r"))
    offered = {dict(b.context.params).get("towel") for b in find_bounds(problem, Evaluator(problem, view))
               if b.context.generator == "towel_bar"}
    assert offered == {False, True}
    factory = get_factory("towel_bar")
    bottom = DRAPED_BAR_BOTTOM if towel else BARE_BAR_BOTTOM
    rng = np.random.default_rng(7)
    centres = []
    for _ in range(300):
        params = {**factory.sample_params(rng), "towel": towel}
        height = factory.placeholder(params).extents[2]
        centres.append(bottom + height / 2)
    lo, hi = TOWEL_BAR_HEIGHT
    assert lo <= min(centres) and max(centres) <= hi
