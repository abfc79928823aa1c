"""The stability summary of simulated drifts (the simulation itself is checked by test_mjcf)."""
from __future__ import annotations

from indoorgen.export.stability import stability


def test_stability_summary_and_bar():
    assert stability({}).passes and stability({}).free == 0
    still = stability({f"o{i}": 0.001 for i in range(100)})
    assert still.passes and still.under_2cm == 1.0 and still.max_m == 0.001
    one_slides = stability({**{f"o{i}": 0.001 for i in range(99)}, "vase": 0.05})
    assert one_slides.passes and one_slides.worst[0] == ("vase", 0.05)
    one_falls = stability({**{f"o{i}": 0.001 for i in range(99)}, "vase": 0.5})
    assert not one_falls.passes
    many_drift = stability({f"o{i}": 0.03 if i < 5 else 0.0 for i in range(100)})
    assert many_drift.under_2cm == 0.95 and not many_drift.passes
