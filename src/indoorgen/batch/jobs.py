"""What one scene task of a batch does and returns: run the `generate` command's own function for
one seed into `DIR/scenes/<seed>/`, and turn its report.json into one manifest record.

The function that generates is handed in (`Entry`: `indoorgen.cli.generate.run_generate`, which
`indoorgen batch` passes), so a scene made in a batch is made by exactly what `indoorgen generate`
runs, with the same options, and the same seed gives the same scene.json either way.
"""
from __future__ import annotations

import argparse
import json
import resource
import sys
import time
from collections.abc import Callable, Mapping
from pathlib import Path
from typing import Any

from indoorgen import __version__

#: the function that writes one scene from the `generate` command's parsed options
Entry = Callable[[argparse.Namespace], int]
#: the manifest's statuses: a scene written, an error, a scene killed at its time limit
STATUSES = ("ok", "failed", "timeout")
#: the version of the manifest's record layout
RECORD_VERSION = 1


def scene_dir(scenes: Path, seed: int) -> Path:
    """Where seed `seed`'s scene lives in a batch's `scenes` directory."""
    return Path(scenes) / str(seed)


def run_scene(entry: Entry, options: Mapping[str, Any], seed: int, scenes: Path) -> dict[str, Any]:
    """Generate seed `seed` with the `generate` options `options` into `scenes/<seed>/` (written
    atomically by the entry) and return its manifest record (with the scene's CPU seconds and
    the process's peak memory); an error becomes a `failed` record with the error's first line
    as the reason."""
    t0 = time.perf_counter()
    usage = resource.getrusage(resource.RUSAGE_SELF)
    cpu0 = usage.ru_utime + usage.ru_stime
    out = scene_dir(scenes, seed)
    # a batch's parallelism is across scenes: each scene solves its rooms in its own process
    args = argparse.Namespace(**{**options, "seed": seed, "out": str(out), "quiet": True,
                                 "overwrite": False, "workers": 1})
    try:
        entry(args)
        report = json.loads((out / "report.json").read_text())
    except Exception as e:  # any error of one scene is that scene's alone
        return record(seed, "failed", f"{type(e).__name__}: {first_line(e)}",
                      wall=time.perf_counter() - t0)
    rec = record(seed, "ok", "", report=report, wall=time.perf_counter() - t0)
    usage = resource.getrusage(resource.RUSAGE_SELF)
    rec["seconds"]["cpu"] = round(usage.ru_utime + usage.ru_stime - cpu0, 3)
    rec["peak_rss_mb"] = peak_rss_mb()
    return rec


def peak_rss_mb() -> float:
    """This process's peak resident memory so far, in MiB (a batch runs a scene per process, so
    it is the scene's)."""
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    return round(peak / (2**20 if sys.platform == "darwin" else 2**10), 1)  # bytes on macOS


def record(seed: int, status: str, reason: str, *, report: Mapping[str, Any] | None = None,
           wall: float | None = None) -> dict[str, Any]:
    """One manifest line: seed, status, reason, seconds per stage (report.json's timings and the
    attempt's wall time), objects, the quality and navigation figures, and indoorgen's version
    (`run_scene` adds the scene process's peak memory)."""
    rec: dict[str, Any] = {"seed": int(seed), "status": status, "reason": reason,
                           "version": __version__, "record": RECORD_VERSION}
    seconds = dict(report.get("timings_s", {})) if report else {}
    if wall is not None:
        seconds["wall"] = round(wall, 3)
    rec["seconds"] = seconds
    if report:
        rec["objects"] = report.get("objects")
        rec["rooms"] = len(report.get("rooms", {}))
        rec["quality"] = quality_figures(report.get("quality", {}))
        rec["navigation"] = navigation_figures(report.get("navigation", {}))
    return rec


def quality_figures(quality: Mapping[str, Any]) -> dict[str, Any]:
    """The layout-quality figures a dataset user compares: passed, rule checks held of checked,
    hard failures, collision and out-of-bounds rates."""
    rules = quality.get("rules", {}).values()
    checked = sum(r.get("checked", 0) for r in rules)
    held = sum(r.get("passed", 0) for r in rules)
    measures = quality.get("measures", {})
    return {"passed": quality.get("passed"), "checked": checked, "held": held,
            "share": round(held / checked, 4) if checked else None,
            "failures": len(quality.get("failures", [])),
            "collision_rate": measures.get("collision_rate"),
            "out_of_bounds_rate": measures.get("out_of_bounds_rate")}


def navigation_figures(nav: Mapping[str, Any]) -> dict[str, Any]:
    """The navigation figures: passed, the reachable share of the free floor, unreachable rooms."""
    return {"passed": nav.get("passed"), "reachable_share": nav.get("reachable_share"),
            "unreachable_rooms": len(nav.get("unreachable_rooms", []))}


def first_line(e: BaseException) -> str:
    """An exception's message on one line (a manifest reason never spans lines)."""
    text = str(e).strip()
    return text.splitlines()[0] if text else type(e).__name__
