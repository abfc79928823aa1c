"""Home benchmark: seconds per furnished home, how walkable it is and how often it fails.

    python benchmarks/home.py [--homes1 30] [--homes2 10] [--seed0 0] [--preset default]
                              [--workers 1]

Generates 1-storey homes for seeds seed0..seed0+homes1-1 and 2-storey homes for
seed0..seed0+homes2-1 (`pipeline.generate_home`) and prints, per storey count: the failure rate
(homes whose report.json `status` is failed, any hard requirement unmet, or that raised; the
commonest reasons are listed below the table, then each failed room's type, area and size), the
homes furnished on a later floorplan after their first failed (and why each plan was given up),
the layout rules' instances held (each rule held under 100% listed with its failed instances),
seconds per home (median, p90), rooms and objects
per home, the navigation figures of `quality.navigation` for a 0.25 m agent from the entrance
(reachable share of walkable floor, and of all free floor: median and minimum, per storey too;
homes with every room reachable; doors passable of all doors; unreachable rooms per home; large
objects whose front cannot be reached per home), the community navigability (0.2 m robot) and the seconds
`navigation_report` takes per storey (median, max).
"""
from __future__ import annotations

import argparse
import statistics
import time
from collections import Counter

import numpy as np
import shapely.geometry as sg

from indoorgen.pipeline import HomeConfig, generate_home
from indoorgen.quality.navigation import navigability, navigation_report


def one(seed: int, floors: int, preset: str, workers: int = 1) -> dict:
    """Generate and measure one home; an exception is recorded as the home's failure."""
    t0 = time.perf_counter()
    try:
        gen = generate_home(seed, HomeConfig(floors=floors, preset=preset, workers=workers))
    except Exception as e:  # reported, not fatal: the benchmark counts failures
        return {"seed": seed, "error": f"{type(e).__name__}: {e}"}
    t1 = time.perf_counter()
    rep = navigation_report(gen.scene, gen.rooms, gen.cache, gen.architecture)
    t2 = time.perf_counter()
    nav = navigability(gen.scene, gen.rooms, gen.cache, gen.architecture)
    return {"seed": seed, "seconds": t1 - t0, "rooms": len(gen.scene.rooms),
            "objects": len(gen.scene.objects), "report": rep, "navigability": nav,
            "reasons": gen.report["status"]["reasons"],
            "rules": {name: (r["checked"], r["passed"], [c for c in r["instances"] if not c["ok"]])
                      for name, r in gen.report["quality"]["rules"].items()},
            "replanned": gen.report.get("replanned", []),
            "failed_rooms": _failed_rooms(gen.report["status"]["reasons"], gen.scene.rooms),
            "nav_s_per_storey": (t2 - t1) / len(rep["storeys"])}


def _failed_rooms(reasons: list[str], rooms: dict) -> list[str]:
    """Each room a hard constraint failed in, as `constraint @ type (area m^2, w x l m)`: the
    room's size and its minimum rotated rectangle, to tell a room too small for its program
    from a search that missed a layout."""
    out = []
    for reason in reasons:
        if not (reason.startswith("room ") and ": hard constraint " in reason):
            continue
        name = reason[len("room "):].split(":", 1)[0]
        room = rooms.get(name)
        if room is None:
            continue
        poly = sg.Polygon(room.polygon)
        xy = np.asarray(poly.minimum_rotated_rectangle.exterior.coords)
        sides = sorted(float(np.hypot(*(xy[i + 1] - xy[i]))) for i in range(2))
        shape = "" if len(room.polygon) == 4 else f", {len(room.polygon)} corners"
        out.append(f"{_reason_kind(reason)} @ {room.room_type} ({poly.area:.1f} m^2, "
                   f"{sides[0]:.1f} x {sides[1]:.1f} m{shape})")
    return out


def _progress(floors: int, r: dict) -> str:
    """One line as each home finishes (a long run shows how it goes), a failed home's rooms
    and reasons on it (a run stopped early still tells why)."""
    if "error" in r:
        return f"  {floors}-storey seed {r['seed']}: raised {r['error']}"
    rep = r["report"]
    return (f"  {floors}-storey seed {r['seed']}: {r['seconds']:.1f} s, {r['objects']} objects, "
            f"reachable {rep['reachable_share']:.3f} ({rep['reachable_share_of_free']:.3f} of "
            f"free floor), {len(rep['unreachable_rooms'])} rooms and "
            f"{len(rep['unreachable_doors'])} doors cut off, "
            f"{len(r['replanned'])} plans given up, "
            f"{'failed: ' + '; '.join(r['failed_rooms'] or r['reasons']) if r['reasons'] else 'ok'}")


def _held(ok: list[dict]) -> str:
    """The layout rules' instances held over the homes, of all checked."""
    checked = sum(c for r in ok for c, _, _ in r["rules"].values())
    held = sum(h for r in ok for _, h, _ in r["rules"].values())
    return f"{held} / {checked} ({held / max(checked, 1):.2%})"


def _p90(xs: list[float]) -> float:
    return float(np.percentile(xs, 90))


def _reason_kind(reason: str) -> str:
    """A failure reason without the names of rooms, doors and objects: what kind of fault."""
    if reason.startswith("room ") and ": hard constraint " in reason:
        name = reason.split(": hard constraint ", 1)[1].rsplit(" violated (", 1)[0]
        return f"hard constraint {name!r}"
    if reason.startswith("layout rule "):
        return reason.split(":", 1)[0]
    for kind in ("is not reachable from the entrance", "cannot be passed from the entrance"):
        if kind in reason:
            return f"{reason.split(' ', 1)[0]} {kind}"
    return reason


def failure_kinds(runs: list[dict]) -> Counter[str]:
    """How many homes failed for each kind of reason (a raised error counts as its type)."""
    kinds: Counter[str] = Counter()
    for r in runs:
        if "error" in r:
            kinds["raised " + r["error"].split(":", 1)[0]] += 1
        else:
            kinds.update({_reason_kind(x) for x in r["reasons"]})
    return kinds


def rule_misses(floors: int, runs: list[dict]) -> list[str]:
    """The layout rules' instances held over the homes, per rule held under 100%, with each
    failed instance (home, room, objects, value)."""
    ok = [r for r in runs if "error" not in r]
    out = []
    for name in sorted({n for r in ok for n in r["rules"]}):
        checked = sum(r["rules"].get(name, (0, 0, []))[0] for r in ok)
        held = sum(r["rules"].get(name, (0, 0, []))[1] for r in ok)
        if held < checked:
            out.append(f"  {floors}-storey rule {name}: {held} of {checked} held "
                       f"({held / checked:.1%})")
            out += [f"    seed {r['seed']}: {c['room']}: {', '.join(c['objects'])}: value "
                    f"{c['value']}, limit {c['limit']}" for r in ok
                    for c in r["rules"].get(name, (0, 0, []))[2]]
    return out


def summary(floors: int, runs: list[dict]) -> list[tuple[str, str]]:
    """The table's rows for the homes of one storey count."""
    ok = [r for r in runs if "error" not in r]
    failed = sum(1 for r in runs if "error" in r or r["reasons"])
    rows = [("homes (raised)", f"{len(runs)} ({len(runs) - len(ok)})"),
            ("failure rate", f"{failed / len(runs):.1%} ({failed})" if runs else "")]
    if not ok:
        return rows
    secs = [r["seconds"] for r in ok]
    share = [r["report"]["reachable_share"] for r in ok]
    of_free = [r["report"]["reachable_share_of_free"] for r in ok]
    nav_s = [r["nav_s_per_storey"] for r in ok]
    rows += [
        ("homes on a later plan (plans given up)",
         f"{sum(1 for r in ok if r['replanned'])} ({sum(len(r['replanned']) for r in ok)})"),
        ("layout rule instances held", _held(ok)),
        ("seconds per home: median / p90", f"{statistics.median(secs):.1f} / {_p90(secs):.1f}"),
        ("rooms per home: median", f"{statistics.median(r['rooms'] for r in ok):g}"),
        ("objects per home: median", f"{statistics.median(r['objects'] for r in ok):g}"),
        ("reachable share: median / min", f"{statistics.median(share):.3f} / {min(share):.3f}"),
        ("of all free floor: median / min", f"{statistics.median(of_free):.3f} / "
                                            f"{min(of_free):.3f}"),
        ("homes with every room reachable",
         f"{sum(r['report']['passed'] for r in ok)} / {len(ok)}"),
        ("unreachable rooms per home: mean",
         f"{statistics.mean(len(r['report']['unreachable_rooms']) for r in ok):.2f}"),
        ("doors passable",
         f"{sum(r['report']['doors'] - len(r['report']['unreachable_doors']) for r in ok)} / "
         f"{sum(r['report']['doors'] for r in ok)}"),
        ("large objects unreachable per home: mean",
         f"{statistics.mean(len(r['report']['large_objects_unreachable']) for r in ok):.2f}"),
        ("navigability (0.2 m robot): median / min",
         f"{statistics.median(r['navigability'] for r in ok):.3f} / "
         f"{min(r['navigability'] for r in ok):.3f}"),
        ("navigation_report s per storey: median / max",
         f"{statistics.median(nav_s):.3f} / {max(nav_s):.3f}"),
    ]
    for lv in range(1, floors):
        up = [r["report"]["storeys"].get(str(lv), {}).get("reachable_share", 0.0) for r in ok]
        rows.append((f"storey {lv} reachable share: median / min",
                     f"{statistics.median(up):.3f} / {min(up):.3f}"))
    return rows


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--homes1", type=int, default=30, help="1-storey homes")
    ap.add_argument("--homes2", type=int, default=10, help="2-storey homes")
    ap.add_argument("--seed0", type=int, default=0, help="first seed")
    ap.add_argument("--preset", default="default", help="fast, default or dense")
    ap.add_argument("--workers", type=int, default=1, help="processes solving rooms")
    args = ap.parse_args()
    columns = {}
    for floors, n in ((1, args.homes1), (2, args.homes2)):
        if n > 0:
            runs = []
            for s in range(args.seed0, args.seed0 + n):
                runs.append(one(s, floors, args.preset, args.workers))
                print(_progress(floors, runs[-1]), flush=True)
            columns[floors] = summary(floors, runs)
            for r in runs:
                if "error" in r:
                    print(f"  {floors}-storey seed {r['seed']} raised: {r['error']}")
                elif r["reasons"]:
                    print(f"  {floors}-storey seed {r['seed']} failed: "
                          + "; ".join(r["reasons"][:4])
                          + (f" (+{len(r['reasons']) - 4})" if len(r["reasons"]) > 4 else ""))
            for r in runs:
                for given_up in r.get("replanned", []):
                    print(f"  {floors}-storey seed {r['seed']}: plan {given_up['plan']} given up: "
                          + "; ".join(given_up["reasons"][:3]))
            for line in rule_misses(floors, runs):
                print(line)
            for kind, count in failure_kinds(runs).most_common():
                print(f"  {floors}-storey homes failed by {kind}: {count}")
            for r in runs:
                for line in r.get("failed_rooms", []):
                    print(f"  {floors}-storey seed {r['seed']}: {line}")
    labels = list(dict.fromkeys(k for rows in columns.values() for k, _ in rows))
    table = [["", *(f"{f}-storey" for f in columns)]]
    table += [[label, *(dict(rows).get(label, "") for rows in columns.values())]
              for label in labels]
    widths = [max(len(row[i]) for row in table) for i in range(len(table[0]))]
    for k, row in enumerate(table):
        print("| " + " | ".join(c.ljust(w) if i == 0 else c.rjust(w)
                                for i, (c, w) in enumerate(zip(row, widths, strict=True))) + " |")
        if k == 0:
            print("|" + "|".join("-" * (w + 2) for w in widths) + "|")

if __name__ == "__main__":
    main()
