"""A scene's status: failed with every unmet hard requirement as a reason, else ok."""
from __future__ import annotations

from indoorgen.quality.verdict import failure_reasons, scene_status


def _report(violations=None, quality_failures=(), nav_failures=()):
    return {"rooms": {"kitchen_0": {"violations": violations or {}, "n_violated": 0}},
            "quality": {"passed": not quality_failures, "failures": list(quality_failures)},
            "navigation": {"passed": not nav_failures, "failures": list(nav_failures)}}


def test_a_scene_meeting_every_hard_requirement_is_ok():
    assert scene_status(_report({"circulation": 0.0, "count_fridge": 1e-12})) == {
        "failed": False, "reasons": []}


def test_every_unmet_requirement_is_a_reason():
    rep = _report({"circulation": 2.0, "count_sink": 0.0},
                  ["toilet_clearance: bathroom_0: toilet_0: value 0.300, limit 0.38"],
                  ["room bedroom_1 is not reachable from the entrance",
                   "door door_3 cannot be passed from the entrance"])
    reasons = failure_reasons(rep)
    assert reasons == ["room kitchen_0: hard constraint circulation violated (2)",
                       "layout rule toilet_clearance: bathroom_0: toilet_0: value 0.300, "
                       "limit 0.38",
                       "room bedroom_1 is not reachable from the entrance",
                       "door door_3 cannot be passed from the entrance"]
    assert scene_status(rep) == {"failed": True, "reasons": reasons}


def test_missing_sections_add_nothing():
    assert failure_reasons({}) == []
