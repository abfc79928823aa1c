"""A rail's surface and a hanger's hook around the rail."""
from __future__ import annotations

import numpy as np
import pytest

from indoorgen.assets.shapes.hanging import RAIL_HALF_WIDTH, RAIL_RADIUS, hook, rail_surface
from indoorgen.assets.shapes.primitives import rod
from indoorgen.constraints.relations import CONTACT_GAP
from indoorgen.model.tags import Subpart


def test_rail_surface_lies_along_the_rails_top_facing_up():
    s = rail_surface("rail_0", 0.1, -0.4, 0.6, 1.7)
    assert s.subpart == Subpart.Rail
    np.testing.assert_allclose(s.normal, [0, 0, 1])
    np.testing.assert_allclose(s.u, [0, 1, 0])  # what hangs from it faces along it
    np.testing.assert_allclose(s.origin, [0.1, 0.1, 1.7 + RAIL_RADIUS])
    assert s.polygon.bounds == pytest.approx((-0.5, -RAIL_HALF_WIDTH, 0.5, RAIL_HALF_WIDTH))


@pytest.mark.parametrize("across", [-RAIL_HALF_WIDTH, 0.0, RAIL_HALF_WIDTH])
def test_a_hook_hung_anywhere_on_the_rail_clears_it(across):
    """Hung as the solver hangs it (its z = 0 the contact gap over the rail's top, its centre
    anywhere across the rail's surface), the hook's arc passes over the rail without touching
    it (the wardrobe's 16-sided rail), and nearly rests on it."""
    h = hook(0.0025, -0.05).translate((0.0, across, CONTACT_GAP))
    rail = rod((-0.1, 0.0, -RAIL_RADIUS), (0.1, 0.0, -RAIL_RADIUS), RAIL_RADIUS, 16)
    assert (h ^ rail).is_empty()
    assert (h ^ rail.translate((0.0, 0.0, 0.005))).volume() > 0  # within 5 mm above it
