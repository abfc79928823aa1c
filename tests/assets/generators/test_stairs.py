"""Staircases and stair railings (generators/stairs.py): uniform risers, goings, landings, the
handrail's height and the railing's dimensions (the generic asset contract runs on them in
test_generators.py)."""
from __future__ import annotations

import math

import numpy as np
import pytest

from indoorgen.assets.catalogue import get_factory
from indoorgen.assets.generators.stairs import RISER_MAX, RISER_MIN, riser_count
from indoorgen.model.tags import Semantics, Subpart
from support.assetcheck import build, make

SEEDS = range(8)
TOL = 1e-3


def test_tags():
    for name in ("staircase", "stair_railing"):
        f = get_factory(name)
        assert {Semantics.Object, Semantics.Architecture} <= f.tags and f.size_class == "large"
    assert Semantics.Staircase in get_factory("staircase").tags
    assert Semantics.Railing in get_factory("stair_railing").tags


def _levels(a) -> np.ndarray:
    return np.array(sorted(s.origin[2] for s in a.surfaces
                           if s.name.startswith(("tread_", "landing_"))))


def test_riser_count_keeps_risers_in_range():
    for rise in np.linspace(2.4, 3.6, 25):
        for target in (0.16, 0.175, 0.19):
            r = rise / riser_count(rise, target)
            assert RISER_MIN - 1e-9 <= r <= RISER_MAX + 1e-9


@pytest.mark.parametrize("seed", SEEDS)
@pytest.mark.parametrize("style", ["straight", "l_shaped", "u_shaped", "spiral"])
def test_staircase_risers_uniform(style, seed):
    """Treads and landings rise by one uniform riser of 0.15-0.20 m from the floor, the last
    one a riser below the total rise; landings take the place of a tread."""
    _, p, a = make("staircase", seed, style=style)
    z = _levels(a)
    steps = np.diff(np.r_[0.0, z, p["total_rise"]])
    r = steps[0]
    assert RISER_MIN - 1e-9 <= r <= RISER_MAX + 1e-9
    assert np.allclose(steps, r, atol=1e-9)
    treads = [s for s in a.surfaces if s.name.startswith("tread_")]
    landings = [s for s in a.surfaces if s.name.startswith("landing_")]
    assert len(landings) == (1 if style in ("l_shaped", "u_shaped") else 0)
    assert all(s.subpart == Subpart.SupportSurface for s in treads + landings)
    assert [s.name for s in treads] == [f"tread_{i}" for i in range(len(treads))]


@pytest.mark.parametrize("seed", SEEDS)
@pytest.mark.parametrize("style", ["straight", "l_shaped", "u_shaped", "spiral"])
def test_staircase_going(style, seed):
    """Consecutive treads of a flight are one going (0.22-0.32 m) apart: along +X for the
    first flight, +-Y after an L landing, -X after a U landing; round the column (at the
    walking line) for a spiral."""
    f, p, a = make("staircase", seed, style=style)
    go = p["going"]
    assert 0.22 <= go <= 0.32
    treads = sorted((s for s in a.surfaces if s.name.startswith("tread_")), key=lambda s: s.origin[2])
    if style == "spiral":
        q = f._spiral_g(f._g(f.resolve(p)))
        angles = np.unwrap([math.atan2(s.u[1], s.u[0]) for s in treads])
        assert np.allclose(np.abs(np.diff(angles)) * q["rw"], go)
        return
    c = np.array([s.origin for s in treads])
    d = np.diff(c[:, :2], axis=0)
    step = np.linalg.norm(d, axis=1)
    flights = [0] + [i + 1 for i in np.nonzero(np.abs(step - go) > 1e-6)[0]] + [len(c)]
    assert len(flights) - 1 == (1 if style == "straight" else 2)
    first = d[:flights[1] - 1]
    assert np.allclose(first, (go, 0.0))  # climbing toward +X
    if style != "straight":
        second = d[flights[1]:]
        expect = {"l_shaped": (0.0, go if p["turn"] == "left" else -go), "u_shaped": (-go, 0.0)}[style]
        assert len(second) and np.allclose(second, expect)


@pytest.mark.parametrize("seed", SEEDS)
def test_straight_stair_starts_at_the_minus_x_end(seed):
    _, p, a = make("staircase", seed, style="straight")
    t0 = a.surface("tread_0")
    lo, hi = a.mesh.bounds
    assert t0.origin[0] < lo[0] + 0.25 * (hi[0] - lo[0])
    last = max((s for s in a.surfaces if s.name.startswith("tread_")), key=lambda s: s.origin[2])
    assert last.origin[0] > hi[0] - 0.25 * (hi[0] - lo[0])


@pytest.mark.parametrize("seed", SEEDS)
def test_handrail_height_above_the_nosings(seed):
    """Where a balustrade runs, the top of the stair near the middle of a flight is the
    handrail (plus newel caps at its ends), about `handrail_height` above the treads."""
    _, p, a = make("staircase", seed, style="straight", railing_side="both", baluster_style="round")
    t = a.surface("tread_3")
    cut = a.mesh.section(plane_normal=[1.0, 0.0, 0.0], plane_origin=t.origin)
    top = cut.vertices[:, 2].max() - t.origin[2]
    assert p["handrail_height"] - 0.01 < top < p["handrail_height"] + p["riser_target"] + 0.06


# --------------------------------------------------------------------------------- railing
@pytest.mark.parametrize("seed", SEEDS)
def test_stair_railing_dimensions(seed):
    f, p, _, a = build("stair_railing", seed)
    d, w, h = a.extents
    assert abs(w - p["length"]) < TOL and abs(h - (p["height"] + 0.06)) < TOL
    assert d < 0.15
    low = a.mesh.vertices[a.mesh.vertices[:, 2] < 1e-6]
    assert low[:, 1].min() < -p["length"] / 2 + p["post_size"] + 0.02  # posts stand at both ends
    assert low[:, 1].max() > p["length"] / 2 - p["post_size"] - 0.02
    gaps = np.diff(f._posts(f.resolve(p)))
    assert gaps.max() <= p["post_spacing"] + 1e-9
