"""Export benchmark: seconds per format and file sizes for a furnished room and a whole home.

    python benchmarks/export.py [--seed 0] [--room living_room] [--floors 2] [--res 512]
                                [--formats usd,urdf,mjcf,glb,obj] [--cold]

Room: `indoorgen.generate` (default config), then every format. Home: `indoorgen.generate_home`
with `--floors` storeys, every room furnished, then USD, URDF and MJCF. Generation is not
counted, only export.
`--cold` bakes textures from scratch (an empty texture cache); otherwise the texture cache is
warm after the first run. Targets (issue 5): home USD+URDF+MJCF <= 10 s, scene.usdc <= 100 MB
with 512 px textures.
"""
from __future__ import annotations

import argparse
import os
import tempfile
import time
from pathlib import Path

from indoorgen import GenerateConfig, HomeConfig, generate, generate_home
from indoorgen.export import parse_formats, write_formats
from indoorgen.export.bundle import bundle_from_generated


def _size(p: Path) -> int:
    if p.is_file():
        return p.stat().st_size
    return sum(f.stat().st_size for f in p.rglob("*") if f.is_file())


def _mb(n: int) -> str:
    return f"{n / 1e6:8.2f} MB"


def run_formats(label: str, bundle, formats: str, res: int) -> None:
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp)
        timings: dict[str, float] = {}
        t = time.perf_counter()
        write_formats(bundle, out, formats, texture_resolution=res, timings=timings)
        total = time.perf_counter() - t
        print(f"\n== {label}: {len(bundle.objects)} objects, {len(bundle.elements)} elements, "
              f"{len(bundle.all_matrefs())} materials, textures {res} px")
        for k, v in timings.items():
            print(f"  {k:10s} {v:7.2f} s")
        core = sum(timings.get(k, 0.0) for k in ("textures", "usd", "urdf", "mjcf"))
        print(f"  {'total':10s} {total:7.2f} s   (textures+usd+urdf+mjcf: {core:.2f} s)")
        names = {"usd": "scene.usdc", "urdf": "scene.urdf", "mjcf": "scene.xml",
                 "glb": "scene.glb", "obj": "scene.obj"}
        for f in parse_formats(formats):
            if f in names and (out / names[f]).exists():
                print(f"  {names[f]:12s} {_mb(_size(out / names[f]))}")
        for d in ("textures", "meshes", "urdf", "obj"):
            if (out / d).exists():
                print(f"  {d + '/':12s} {_mb(_size(out / d))}")
        print(f"  {'directory':12s} {_mb(_size(out))}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--room", default="living_room")
    ap.add_argument("--floors", type=int, default=2)
    ap.add_argument("--res", type=int, default=512)
    ap.add_argument("--formats", default="usd,urdf,mjcf,glb,obj")
    ap.add_argument("--home-formats", default="usd,urdf,mjcf")
    ap.add_argument("--cold", action="store_true", help="empty texture cache")
    ap.add_argument("--no-home", action="store_true")
    args = ap.parse_args()
    if args.cold:
        os.environ["INDOORGEN_TEXTURE_CACHE"] = tempfile.mkdtemp(prefix="texcache-")

    t = time.perf_counter()
    gen = generate(args.seed, GenerateConfig(room_type=args.room))
    print(f"generated {args.room} seed {args.seed} in {time.perf_counter() - t:.1f} s "
          "(not counted)")
    t = time.perf_counter()
    bundle = bundle_from_generated(gen)
    print(f"bundle (full assets, materials): {time.perf_counter() - t:.2f} s")
    run_formats(f"furnished {args.room}", bundle, args.formats, args.res)
    if not args.no_home:
        t = time.perf_counter()
        home_gen = generate_home(args.seed, HomeConfig(floors=args.floors))
        print(f"\ngenerated a {args.floors}-storey home, seed {args.seed}: "
              f"{len(home_gen.scene.rooms)} rooms, {len(home_gen.scene.objects)} objects in "
              f"{time.perf_counter() - t:.1f} s (not counted)")
        t = time.perf_counter()
        home = bundle_from_generated(home_gen)
        print(f"home bundle (full assets, materials): {time.perf_counter() - t:.2f} s")
        run_formats(f"whole home ({args.floors} storeys)", home, args.home_formats, args.res)


if __name__ == "__main__":
    main()
