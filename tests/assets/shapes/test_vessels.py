"""shapes/vessels: hollow solids of revolution keep their wall and floor thickness and open at
the rim; bowls built from their params stand on their base and hold their floor."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from indoorgen.assets.shapes.vessels import (
    SECTIONS,
    bowl_base_radius,
    bowl_foot_height,
    bowl_outer,
    bowl_params,
    bowl_vessel,
    cheap_cylinder,
    interior_floor,
    mirrored_section,
    revolve_vessel,
    round_bottom,
    solid_revolve,
)
from indoorgen.model.tags import Subpart

#: area of a regular n-gon inscribed in the unit circle: what a revolved section's radius^2 gets
NGON = SECTIONS / 2 * math.sin(2 * math.pi / SECTIONS)


@given(st.floats(0.02, 0.2), st.floats(0.02, 0.3), st.floats(0.001, 0.01), st.floats(0.002, 0.02))
def test_a_cylindrical_vessel_keeps_its_wall_and_floor(r, h, wall, floor):
    """A straight-walled cup: the shell is the outer cylinder less a cavity `wall` in from the
    side and `floor` above the underside, open at the rim; the flat floor reaches the wall
    (`revolve_vessel` wants the floor at least a wall above the underside)."""
    assume(wall <= 0.3 * r and wall <= floor <= 0.5 * h)
    v = revolve_vessel([(0.0, 0.0), (r, 0.0), (r, h)], wall, floor)
    assert v.floor_z == floor and v.floor_r == pytest.approx(r - wall, abs=1e-6)
    expect = NGON * (r * r * h - (r - wall) ** 2 * (h - floor))
    assert v.shell.volume() == pytest.approx(expect, rel=1e-4)
    lo, hi = np.split(np.asarray(v.cavity.bounding_box()), 2)
    assert lo[2] == pytest.approx(floor, abs=1e-6) and hi[2] > h  # the cavity opens above the rim


@settings(max_examples=25)
@given(st.integers(0, 10_000))
def test_bowls_from_their_params(seed):
    """Any bowl its params allow: the profile climbs from the axis to the rim, the vessel's
    floor lies its base thickness above the foot, inside the rim, and the shell is hollow
    (less than half of the solid of the same outline)."""
    rng = np.random.default_rng(seed)
    p = {k: prm.sample(rng) for k, prm in bowl_params(0.06, 0.16, 0.04, 0.1).items()}
    outer = bowl_outer(p)
    rs, zs = np.array(outer).T
    assert rs[0] == 0.0 and zs[-1] == pytest.approx(p["height"])
    assert rs.max() == pytest.approx(p["radius"] + (p["rim_flare"] if p["rim_flare"] > 5e-4 else 0.0))
    foot = bowl_foot_height(p)
    assert (foot == 0.0) == (not p["foot_ring"]) and foot <= 0.01
    v = bowl_vessel(p)
    assert v.floor_z == pytest.approx(foot + p["base_thickness"])
    assert 0.0 < v.floor_r < p["radius"]
    assert 0.0 < bowl_base_radius(p) <= p["radius"] * p["foot_frac"]
    assert v.shell.volume() < 0.5 * solid_revolve(outer).volume()


def test_mirrored_section_is_symmetric_about_the_axis():
    half = [(0.0, 0.0), (0.05, 0.0), (0.06, 0.1), (0.0, 0.1)]
    cs = mirrored_section(half)
    assert cs.area() == pytest.approx(2 * 0.1 * 0.055)
    x0, y0, x1, y1 = cs.bounds()
    assert x0 == pytest.approx(-x1) and x1 == pytest.approx(0.06) and (y0, y1) == pytest.approx((0.0, 0.1))


@pytest.mark.parametrize("sections", [12, SECTIONS])
def test_round_surfaces_lie_inside_the_mesh_disc(sections):
    """`bottom` faces down under a disc of the given radius, `interior` up on a vessel's floor;
    both stay inside the n-gon the mesh has there."""
    r = 0.04
    inscribed = r * math.cos(math.pi / sections)
    bottom = round_bottom("bottom", r, sections)
    assert bottom.subpart == Subpart.Bottom and np.allclose(bottom.normal, (0, 0, -1))
    assert np.linalg.norm(bottom.corners()[:, :2], axis=1).max() <= r
    assert bottom.polygon.area < math.pi * inscribed ** 2
    inner = interior_floor("interior", 0.01, r, sections)
    assert inner.subpart == Subpart.Interior and inner.origin[2] == 0.01
    assert np.linalg.norm(np.asarray(inner.polygon.exterior.coords), axis=1).max() <= 0.9 * r + 1e-12


def test_cheap_cylinder_contains_the_round_shape():
    """The placeholder's 16-gon circumscribes the circle: its bounding box is the circle's."""
    part = cheap_cylinder(0.05, 0.01, 0.2, "ceramic")
    bb = part.solid.bounding_box()
    assert bb == pytest.approx((-0.05, -0.05, 0.01, 0.05, 0.05, 0.2))
    assert part.solid.volume() > math.pi * 0.05 ** 2 * 0.19
