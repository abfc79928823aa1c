"""MJCF stability per scene: export furnished rooms (and a home), simulate 2 s in MuJoCo, and
print each scene's share of free bodies that moved < 2 cm and the largest drift.

    python benchmarks/stability.py [--seeds 2] [--rooms living_room,dining_room] [--homes 1]

Target (issue 5): >= 99 % of free bodies under 2 cm and none over 10 cm, every scene.
"""
from __future__ import annotations

import argparse
import tempfile
from pathlib import Path

from indoorgen import GenerateConfig, HomeConfig, generate, generate_home
from indoorgen.export import write_formats
from indoorgen.export.bundle import bundle_from_generated
from indoorgen.export.stability import simulate, stability


def report(label: str, gen) -> bool:
    with tempfile.TemporaryDirectory() as tmp:
        write_formats(bundle_from_generated(gen), Path(tmp), "mjcf", texture_resolution=64)
        st = stability(simulate(Path(tmp) / "scene.xml"))
    worst = ", ".join(f"{n} {d * 100:.1f} cm" for n, d in st.worst)
    print(f"{label:28s} {st.free:5d} free  {100 * st.under_2cm:6.1f}% < 2 cm  "
          f"max {st.max_m * 100:6.2f} cm  {'ok  ' if st.passes else 'MISS'}  ({worst})")
    return st.passes


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", type=int, default=2)
    ap.add_argument("--rooms", default="living_room,dining_room")
    ap.add_argument("--homes", type=int, default=1, help="whole one-storey homes (seeds 0..N-1)")
    args = ap.parse_args()
    ok = []
    for room in args.rooms.split(","):
        for seed in range(args.seeds):
            ok.append(report(f"{room} seed {seed}", generate(seed, GenerateConfig(room_type=room))))
    for seed in range(args.homes):
        ok.append(report(f"home seed {seed}", generate_home(seed, HomeConfig())))
    print(f"{sum(ok)}/{len(ok)} scenes meet the target")


if __name__ == "__main__":
    main()
