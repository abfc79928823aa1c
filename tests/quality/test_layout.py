"""The quality report as a whole: its shape, counts, determinism and hard failures, on a
generated living room and on hand-built rooms."""
from __future__ import annotations

import json

import pytest

from indoorgen.pipeline import GenerateConfig, generate
from indoorgen.quality.context import RULES, Check
from indoorgen.quality.layout import MAX_INSTANCES, quality_report, rule_summary
from support.qualityscene import new_scene, put, report


@pytest.fixture(scope="module")
def living():
    """A generated living room and its report."""
    g = generate(0, GenerateConfig(room_type="living_room"))
    return g, quality_report(g.scene, g.rooms, g.cache)


def test_generated_room_report_round_trips_and_counts_add_up(living):
    g, rep = living
    assert json.loads(json.dumps(rep, sort_keys=True)) == rep
    assert set(rep) == {"passed", "failures", "rules", "measures"}
    assert set(rep["rules"]) == set(RULES)
    for r in rep["rules"].values():
        assert 0 <= r["passed"] <= r["checked"]
        assert len(r["instances"]) == min(r["checked"], MAX_INSTANCES)
        assert sum(i["ok"] for i in r["instances"]) <= r["passed"]
        assert r["rate"] == (round(r["passed"] / r["checked"], 4) if r["checked"] else 1.0)
    hard_failed = sum(r["checked"] - r["passed"] for r in rep["rules"].values() if r["hard"])
    assert len(rep["failures"]) == hard_failed and rep["passed"] == (hard_failed == 0)
    assert rep["measures"]["objects"] == len(g.scene.objects)


def test_report_is_deterministic(living):
    g, rep = living
    again = quality_report(g.scene, g.rooms, g.cache)
    assert json.dumps(again, sort_keys=True) == json.dumps(rep, sort_keys=True)


def test_a_soft_failure_keeps_the_scene_passed():
    sc = new_scene()
    put(sc, "ceiling_light", 3.0, 2.5, z=2.5)
    put(sc, "sofa", 3.0, 0.6, 1.57)
    put(sc, "tv", 3.0, 4.6, 1.57)  # turned away
    rep = report(sc)
    assert rep["passed"] is True and rep["failures"] == []
    assert rep["rules"]["tv_faces_seating"]["passed"] == 0


def test_instances_list_failures_first_and_are_capped():
    checks = [Check("r", (f"o{i}",), float(i), 1.0, i % 2 == 0) for i in range(2 * MAX_INSTANCES)]
    s = rule_summary(checks, hard=False)
    assert s["checked"] == 2 * MAX_INSTANCES and s["passed"] == MAX_INSTANCES
    assert len(s["instances"]) == MAX_INSTANCES and not any(i["ok"] for i in s["instances"])
