"""The lights every exporter shares: one sphere emitter per lamp link with emissive faces."""
from __future__ import annotations

import math

import numpy as np
from tests.support.assetcheck import build

from indoorgen.export.bundle import EMISSIVE_SLOTS
from indoorgen.export.lights import FIXTURE_LUMENS, MAX_RADIUS, MIN_RADIUS, emitters
from indoorgen.export.meshes import face_slot_names


def test_a_table_lamp_glows_at_its_bulb_with_a_reading_lamp_s_flux():
    asset = build("table_lamp", 0)[3]
    found = emitters(asset, "table_lamp")
    assert found
    lit = np.isin(face_slot_names(asset), [i for i, s in enumerate(asset.slots)
                                           if s in EMISSIVE_SLOTS])
    assert math.isclose(sum(e.area for e in found), float(asset.mesh.area_faces[lit].sum()))
    lo, hi = asset.mesh.bounds
    for e in found:
        assert np.all(e.centre >= lo) and np.all(e.centre <= hi)
        assert e.centre[2] > 0.5 * hi[2]  # the bulb sits in the shade, high up
        assert MIN_RADIUS <= e.radius <= MAX_RADIUS
        # an isotropic point of flux F: I = F / 4 pi (cd)
        assert math.isclose(4 * math.pi * e.candela, e.lumens)
    assert math.isclose(sum(e.lumens for e in found), FIXTURE_LUMENS["table_lamp"])


def test_furniture_without_emissive_faces_has_no_lights():
    assert emitters(build("sofa", 0)[3]) == []
