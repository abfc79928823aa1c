"""Suite-wide settings and fixtures: hypothesis profiles (`ci`, the default, gives the fuzz suite a
fixed example budget; `long`, `pytest --hypothesis-profile long tests/fuzz`, runs it far longer),
and the two furnished homes the export, door and navigation tests open (built once per worker)."""
from __future__ import annotations

import pytest
from hypothesis import HealthCheck, settings

from indoorgen.pipeline import HomeConfig, generate_home
from support.exports import export_each

#: every example a fuzzed reader may take (ms) before hypothesis calls it a failure
FUZZ_DEADLINE_MS = 5000

settings.register_profile("ci", max_examples=40, deadline=FUZZ_DEADLINE_MS,
                          suppress_health_check=[HealthCheck.too_slow,
                                                 HealthCheck.data_too_large])
settings.register_profile("long", max_examples=2000, deadline=FUZZ_DEADLINE_MS,
                          suppress_health_check=[HealthCheck.too_slow,
                                                 HealthCheck.data_too_large])
settings.load_profile("ci")

#: whole homes the tests open in the real consumers: name -> (seed, storeys), fast preset
HOMES = {"home1": (0, 1), "home2": (0, 2)}
#: the formats and texture size the homes are exported in (small textures: baking is not what
#: the tests check)
HOME_FORMATS = "usd,urdf,mjcf,glb,obj"
HOME_TEX = 128


@pytest.fixture(scope="session")
def generated_homes():
    """'home1' / 'home2' -> Generated (a 1- and a 2-storey home, fast preset, doors open). Tests
    using it carry `@pytest.mark.xdist_group("export_homes")` so one worker builds them once."""
    return {k: generate_home(seed, HomeConfig(floors=floors, preset="fast"))
            for k, (seed, floors) in HOMES.items()}


@pytest.fixture(scope="session")
def exported_homes(generated_homes, tmp_path_factory):
    """'home1' / 'home2' -> (bundle, directory with every format)."""
    return {k: (bundle, d) for k, (bundle, d, _) in
            export_each(generated_homes, tmp_path_factory, HOME_FORMATS, HOME_TEX).items()}
