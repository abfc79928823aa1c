"""What a dataset user checks before training on a batch's scenes: room types, objects per room
and per category, diversity (distinct generators and parameter values), the quality and
navigation figures, and disk use per scene; as numbers (`dataset_stats`, `stats_lines`) and as a
picture (`plot_stats`, stats.png)."""
from __future__ import annotations

import json
import statistics
from collections import Counter, defaultdict
from collections.abc import Iterable, Mapping
from pathlib import Path
from typing import Any

from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from indoorgen.batch.manifest import latest, read_manifest, scenes_dir
from indoorgen.errors import BatchConfigError

#: the categories and generators a plot and the printed lines show at most
TOP = 15


def dataset_stats(directory: Path) -> dict[str, Any]:
    """The statistics of the scenes a batch made in `directory` (each seed's last ok record and
    its scene.json)."""
    directory = Path(directory)
    records = latest(read_manifest(directory))
    if not records:
        raise BatchConfigError(f"{directory} holds no manifest.jsonl records: is it a directory "
                               "written by `indoorgen batch`?")
    ok = {s: r for s, r in records.items() if r["status"] == "ok"}
    room_types: Counter[str] = Counter()
    per_room: dict[str, list[int]] = defaultdict(list)
    categories: Counter[str] = Counter()
    generators: Counter[str] = Counter()
    values: dict[tuple[str, str], set[str]] = defaultdict(set)
    designs: set[str] = set()
    disk: list[int] = []
    for seed in sorted(ok):
        scene_path = scenes_dir(directory) / str(seed)
        try:
            scene = json.loads((scene_path / "scene.json").read_text())
        except (OSError, ValueError):
            continue
        disk.append(_disk_use(scene_path))
        counts = Counter(o["room"] for o in scene["objects"])
        for room in scene["rooms"]:
            room_types[room["type"]] += 1
            per_room[room["type"]].append(counts.get(room["name"], 0))
        for obj in scene["objects"]:
            generators[obj["generator"]] += 1
            categories[obj["tags"][0] if obj.get("tags") else obj["generator"]] += 1
            params = obj.get("params", {})
            designs.add(json.dumps([obj["generator"], params], sort_keys=True))
            for name, value in params.items():
                values[(obj["generator"], name)].add(json.dumps(value))
    figures = list(ok.values())
    return {
        "scenes": len(ok),
        "attempts": {status: sum(r["status"] == status for r in records.values())
                     for status in ("ok", "failed", "timeout")},
        "room_types": dict(room_types.most_common()),
        "objects_per_room": {t: _describe(v) for t, v in sorted(per_room.items())},
        "objects_per_scene": _describe(r.get("objects") for r in figures),
        "categories": dict(categories.most_common()),
        "diversity": {"generators": len(generators), "designs": len(designs),
                      "parameters": len(values),
                      "median_values_per_parameter": _median(len(v) for v in values.values()),
                      "generators_used": dict(generators.most_common())},
        "quality": {"passed": _share(r["quality"].get("passed") for r in figures),
                    "rule_share": _describe(r["quality"].get("share") for r in figures),
                    "collision_rate": _describe(r["quality"].get("collision_rate")
                                                for r in figures)},
        "navigation": {"passed": _share(r["navigation"].get("passed") for r in figures),
                       "reachable_share": _describe(r["navigation"].get("reachable_share")
                                                    for r in figures)},
        "seconds_per_scene": _describe(r["seconds"].get("wall") for r in figures),
        "disk_mb_per_scene": _describe(round(b / 1e6, 3) for b in disk),
        "series": {"objects_per_room": dict(sorted(per_room.items())),
                   "rule_share": [r["quality"].get("share") for r in figures],
                   "reachable_share": [r["navigation"].get("reachable_share") for r in figures],
                   "disk_mb": [round(b / 1e6, 3) for b in disk]},
    }


def stats_lines(stats: Mapping[str, Any]) -> list[str]:
    """The statistics as the lines `indoorgen dataset-stats` prints."""
    d = stats["diversity"]
    a = stats["attempts"]
    lines = [f"scenes: {stats['scenes']} ok ({a['failed']} failed, {a['timeout']} timed out)",
             "room types: " + ", ".join(f"{t} {n}" for t, n in stats["room_types"].items()),
             "objects per room (median, min-max): " + "; ".join(
                 f"{t} {s['median']} ({s['min']}-{s['max']})"
                 for t, s in stats["objects_per_room"].items()),
             f"objects per scene: {_fmt(stats['objects_per_scene'])}",
             "categories: " + ", ".join(f"{c} {n}" for c, n in
                                        list(stats["categories"].items())[:TOP]),
             f"diversity: {d['generators']} generators, {d['designs']} distinct designs, "
             f"{d['parameters']} parameters with a median of {d['median_values_per_parameter']} "
             "distinct values each",
             f"quality: {_pct(stats['quality']['passed'])} of scenes pass; rule checks held "
             f"{_fmt(stats['quality']['rule_share'])}; collision rate "
             f"{_fmt(stats['quality']['collision_rate'])}",
             f"navigation: {_pct(stats['navigation']['passed'])} of scenes pass; reachable share "
             f"{_fmt(stats['navigation']['reachable_share'])}",
             f"seconds per scene: {_fmt(stats['seconds_per_scene'])}",
             f"disk per scene (MB): {_fmt(stats['disk_mb_per_scene'])}"]
    return lines


def plot_stats(stats: Mapping[str, Any], path: Path) -> Path:
    """Draw the statistics in six panels into `path` (a PNG)."""
    fig = Figure(figsize=(15, 8.5), dpi=100)
    FigureCanvasAgg(fig)  # headless: drawn straight to a file
    ax = fig.subplots(2, 3).ravel()
    _bars(ax[0], stats["room_types"], "rooms by type")
    per_room = stats["series"]["objects_per_room"]
    ax[1].boxplot(list(per_room.values()))
    ax[1].set_xticks(range(1, len(per_room) + 1), list(per_room), fontsize=8, rotation=30)
    ax[1].set_title("objects per room, by room type")
    _bars(ax[2], dict(list(stats["categories"].items())[:TOP]), f"objects by category (top {TOP})")
    ax[3].hist([v for v in stats["series"]["rule_share"] if v is not None], bins=20,
               range=(0, 1), color="#55a868")
    ax[3].set_title(f"layout rule checks held per scene (passed: {_pct(stats['quality']['passed'])})")
    ax[4].hist([v for v in stats["series"]["reachable_share"] if v is not None], bins=20,
               range=(0, 1), color="#c44e52")
    ax[4].set_title("reachable share of the free floor per scene")
    ax[5].hist(stats["series"]["disk_mb"], bins=20, color="#8172b2")
    ax[5].set_title("disk use per scene (MB)")
    d = stats["diversity"]
    fig.suptitle(f"{stats['scenes']} scenes; {d['generators']} generators, {d['designs']} "
                 f"distinct designs, median {d['median_values_per_parameter']} values per parameter")
    fig.tight_layout()
    fig.savefig(path)
    return Path(path)


def _bars(ax: Any, counts: Mapping[str, int], title: str) -> None:
    """A horizontal bar chart of `counts`, largest on top."""
    names = list(counts)[::-1]
    ax.barh(names, [counts[n] for n in names], color="#4c72b0")
    ax.set_title(title)
    ax.tick_params(axis="y", labelsize=8)


def _disk_use(path: Path) -> int:
    """Bytes of every file under `path`."""
    return sum(p.stat().st_size for p in path.rglob("*") if p.is_file())


def _describe(values: Iterable[Any]) -> dict[str, float | None]:
    """Median, minimum and maximum of the values given (None skipped)."""
    vals = [float(v) for v in values if v is not None]
    if not vals:
        return {"median": None, "min": None, "max": None}
    return {"median": round(statistics.median(vals), 4), "min": min(vals), "max": max(vals)}


def _median(values: Iterable[int]) -> float | None:
    """The median of `values`, None if empty."""
    vals = list(values)
    return statistics.median(vals) if vals else None


def _share(flags: Iterable[Any]) -> float | None:
    """The share of true flags (None skipped)."""
    vals = [bool(f) for f in flags if f is not None]
    return round(sum(vals) / len(vals), 4) if vals else None


def _fmt(d: Mapping[str, Any]) -> str:
    """`median (min-max)`."""
    return f"median {d['median']} ({d['min']}-{d['max']})"


def _pct(share: float | None) -> str:
    """A share as a percentage."""
    return "n/a" if share is None else f"{share:.0%}"
