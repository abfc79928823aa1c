"""Suite-wide settings: hypothesis profiles. `ci` (the default) gives the fuzz suite a fixed
example budget; `long` (`pytest --hypothesis-profile long tests/fuzz`) runs it far longer."""
from __future__ import annotations

from hypothesis import HealthCheck, settings

#: every example a fuzzed reader may take (ms) before hypothesis calls it a failure
FUZZ_DEADLINE_MS = 5000

settings.register_profile("ci", max_examples=40, deadline=FUZZ_DEADLINE_MS,
                          suppress_health_check=[HealthCheck.too_slow,
                                                 HealthCheck.data_too_large])
settings.register_profile("long", max_examples=2000, deadline=FUZZ_DEADLINE_MS,
                          suppress_health_check=[HealthCheck.too_slow,
                                                 HealthCheck.data_too_large])
settings.load_profile("ci")
