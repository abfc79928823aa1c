"""The layout-quality report of a generated scene: every layout rule evaluated per instance, with
object names and measured values, plus the community's published measures.

A scene passes when no instance of a hard rule fails (a person would call it broken); soft rules
are reported with their pass rates. The result is JSON-ready and deterministic.
"""
from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from indoorgen.architecture.room import RoomGeometry
from indoorgen.architecture.solidify import Architecture
from indoorgen.assets.cache import AssetCache
from indoorgen.model.scene import Scene
from indoorgen.quality import arrangement, clearance, rules
from indoorgen.quality.context import RULES, Check, build_context
from indoorgen.quality.measures import community_measures
from indoorgen.quality.navigation import navigability

#: the modules whose rules the report runs (importing them registers their rules)
RULE_MODULES = (rules, arrangement, clearance)
#: instances listed per rule (failed first), so report.json stays small
MAX_INSTANCES = 50


def _failure_line(name: str, c: Check) -> str:
    value = "none" if c.value is None else f"{c.value:.3f}"
    return f"{name}: {c.room}: {', '.join(c.objects) or '-'}: value {value}, limit {c.limit}"


def rule_summary(checks: list[Check], hard: bool) -> dict[str, Any]:
    """One rule's record: hard, counts, pass rate, and its instances (failed first, capped)."""
    passed = sum(1 for c in checks if c.ok)
    listed = sorted(checks, key=lambda c: (c.ok, c.room, c.objects))[:MAX_INSTANCES]
    return {"hard": hard, "checked": len(checks), "passed": passed,
            "rate": round(passed / len(checks), 4) if checks else 1.0,
            "instances": [c.to_json() for c in listed]}


def quality_report(scene: Scene, rooms: Mapping[str, RoomGeometry], cache: AssetCache,
                   architecture: Architecture | None = None) -> dict[str, Any]:
    """The `quality` section of report.json: {"passed", "failures", "rules", "measures"}."""
    ctx = build_context(scene, rooms, cache, architecture)
    out_rules: dict[str, Any] = {}
    failures: list[str] = []
    for name in sorted(RULES):
        fn, hard = RULES[name]
        checks = fn(ctx)
        out_rules[name] = rule_summary(checks, hard)
        if hard:
            failures += [_failure_line(name, c) for c in checks if not c.ok]
    measures = community_measures(ctx)
    measures["navigability"] = round(navigability(scene, rooms, cache, architecture), 4)
    return {"passed": not failures, "failures": failures, "rules": out_rules,
            "measures": measures}
