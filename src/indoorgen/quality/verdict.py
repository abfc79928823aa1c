"""Whether a generated scene failed, and why: report.json's `status`.

A scene (a room or a home) is failed when any hard requirement is unmet:

- a room's program has a violated hard constraint (the circulation constraint among them: a
  door, stair landing or large object's front the agent cannot reach within the room);
- a hard layout-quality rule fails (`quality` section);
- the navigation measure finds a room the agent cannot reach from the entrance, or a door it
  cannot pass (`navigation` section).

It reads the report's sections only; it measures nothing itself.
"""
from __future__ import annotations

from collections.abc import Mapping
from typing import Any

#: A constraint's violation above this counts (as the evaluator counts `n_violated`).
VIOLATION_EPS = 1e-9


def failure_reasons(report: Mapping[str, Any]) -> list[str]:
    """Every unmet hard requirement of a scene's `report` (its `rooms`, `quality` and
    `navigation` sections; a missing section adds nothing), one line each."""
    out = []
    for room in sorted(report.get("rooms") or {}):
        violations = report["rooms"][room].get("violations") or {}
        out += [f"room {room}: hard constraint {name} violated ({value:.3g})"
                for name, value in sorted(violations.items()) if value > VIOLATION_EPS]
    quality = report.get("quality") or {}
    out += [f"layout rule {line}" for line in quality.get("failures", [])]
    nav = report.get("navigation") or {}
    out += list(nav.get("failures", []))
    return out


def scene_status(report: Mapping[str, Any]) -> dict[str, Any]:
    """report.json's `status`: {"failed": bool, "reasons": [...]} (see `failure_reasons`)."""
    reasons = failure_reasons(report)
    return {"failed": bool(reasons), "reasons": reasons}
