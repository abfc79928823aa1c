"""The `indoorgen export` and `indoorgen asset` commands.

    indoorgen export SCENE.json [--formats usd,urdf,mjcf,glb,obj] [--out DIR]
    indoorgen asset NAME [--seed S] --out FILE.glb|.obj|.usd|.usda|.usdc|.usdz [--param k=v ...]

`export` re-exports a saved scene without solving: rooms are rebuilt from scene.json's Room data
and assets from their generators. `asset` writes one textured asset. Bad input (unknown format,
generator or parameter, a missing or corrupt scene.json, an unwritable output) raises an
`IndoorGenError` subclass: one line on stderr, exit status 2.
"""
from __future__ import annotations

import json
import logging
import os
import shutil
import tempfile
import time
from pathlib import Path
from typing import Any

from indoorgen.errors import ConfigError, OutputError, ParameterError
from indoorgen.export.formats import DEFAULT_FORMATS, FORMATS, parse_formats

log = logging.getLogger(__name__)

ASSET_EXTENSIONS = (".glb", ".obj", ".usd", ".usda", ".usdc", ".usdz")


class SceneFileError(ConfigError):
    """A scene.json that is missing, unreadable or not a scene."""


def add_export_parsers(subparsers) -> None:
    """Register the `export` and `asset` sub-commands on an argparse subparsers object."""
    e = subparsers.add_parser("export", help="re-export a saved scene.json to other formats")
    e.add_argument("scene", help="a scene.json (or the directory holding it)")
    e.add_argument("--formats", default=",".join(DEFAULT_FORMATS),
                   help=f"comma-separated, from {', '.join(FORMATS)} "
                        f"(default {','.join(DEFAULT_FORMATS)})")
    e.add_argument("--out", help="output directory (default: the scene's own directory)")
    e.add_argument("--usd-format", choices=["usdc", "usda"], default="usdc")
    e.add_argument("--texture-resolution", type=int, default=512,
                   help="texture size in pixels (0: no textures)")
    e.set_defaults(func=run_export)

    a = subparsers.add_parser("asset", help="write one textured asset to a file")
    a.add_argument("name", help="generator name (see `indoorgen assets list`)")
    a.add_argument("--seed", type=int, default=0)
    a.add_argument("--out", required=True, help="FILE" + "|".join(ASSET_EXTENSIONS))
    a.add_argument("--param", action="append", default=[], metavar="K=V",
                   help="override one parameter (repeatable)")
    a.add_argument("--texture-resolution", type=int, default=512)
    a.set_defaults(func=run_asset)


# --------------------------------------------------------------------------------------------
# export


def read_scene(path: Path):
    """The `Scene` stored in `path` (a scene.json or a directory holding one); SceneFileError
    if it is missing or corrupt."""
    from indoorgen.model.scene import Scene
    path = Path(path)
    if path.is_dir():
        path = path / "scene.json"
    if not path.is_file():
        raise SceneFileError(f"scene file {str(path)!r} does not exist; give a scene.json "
                             "written by `indoorgen generate`")
    try:
        data = json.loads(path.read_text())
        scene = Scene.from_json(data)
    except (OSError, UnicodeDecodeError, ValueError, KeyError, TypeError, AttributeError) as e:
        raise SceneFileError(f"scene file {str(path)!r} is corrupt ({type(e).__name__}: {e}); "
                             "expected the scene.json written by `indoorgen generate`") from None
    return scene, path


def export_scene(scene_path: Path, out: Path | None, formats: str | None, *,
                 usd_ext: str = "usdc", texture_resolution: int = 512) -> tuple[Path, dict]:
    """Re-export a saved scene into `out` (default: its own directory), atomically. scene.json
    is copied along, and plan.png / report.json too when they sit beside it. Returns the
    directory and the seconds per stage."""
    from indoorgen.export.bundle import bundle_from_scene
    from indoorgen.export.formats import write_formats
    from indoorgen.outputs import atomic_dir, check_writable
    fmts = parse_formats(formats)
    scene, src = read_scene(scene_path)
    out = Path(out) if out else src.parent
    check_writable(out)
    if texture_resolution < 0 or texture_resolution > 8192:
        raise ConfigError(f"--texture-resolution {texture_resolution} is invalid; valid: 0 "
                          "(no textures) or 16..8192")
    timings: dict[str, float] = {}
    t = time.perf_counter()
    bundle = bundle_from_scene(scene)
    timings["assets"] = time.perf_counter() - t
    keep = {}
    for name in ("scene.json", "plan.png", "report.json"):
        if (src.parent / name).is_file():
            keep[name] = (src.parent / name).read_bytes()
    keep["scene.json"] = src.read_bytes()
    with atomic_dir(out) as tmp:
        for name, data in keep.items():
            (tmp / name).write_bytes(data)
        write_formats(bundle, tmp, fmts, usd_ext=usd_ext, texture_resolution=texture_resolution,
                      timings=timings)
    return out, timings


def run_export(args) -> int:
    """`indoorgen export`."""
    out, timings = export_scene(Path(args.scene), Path(args.out) if args.out else None,
                                args.formats, usd_ext=args.usd_format,
                                texture_resolution=args.texture_resolution)
    print(f"{out}: " + ", ".join(f"{k} {v:.2f} s" for k, v in timings.items()))
    return 0


# --------------------------------------------------------------------------------------------
# asset


def parse_param(text: str) -> tuple[str, Any]:
    """`k=v` -> (k, v) with v read as JSON when it parses (numbers, true/false), else a string."""
    key, sep, value = text.partition("=")
    if not sep or not key.strip():
        raise ParameterError(f"--param {text!r} is invalid; expected NAME=VALUE")
    try:
        v = json.loads(value)
    except ValueError:
        v = value
    return key.strip(), v


def write_asset(name: str, seed: int, out: Path, overrides: dict[str, Any] | None = None, *,
                texture_resolution: int = 512) -> Path:
    """Write generator `name` (params sampled from `seed`, then `overrides`) to `out`; its
    textures go to `textures/` beside it (.glb embeds them, .usdz packages them)."""
    import numpy as np

    from indoorgen.assets import get_factory
    from indoorgen.export.bundle import make_bundle
    from indoorgen.export.textures import TextureStore
    from indoorgen.model.scene import Pose, Scene, SceneObject
    from indoorgen.outputs import atomic_file, check_writable

    out = Path(out)
    ext = out.suffix.lower()
    if ext not in ASSET_EXTENSIONS:
        raise OutputError(f"cannot write an asset to {str(out)!r}: the file name must end in "
                          + ", ".join(ASSET_EXTENSIONS))
    if seed < 0:
        raise ConfigError(f"--seed must be a non-negative integer, got {seed}")
    check_writable(out, directory=False)
    factory = get_factory(name)
    params = factory.sample_params(np.random.default_rng(seed))
    params.update(factory.validate_params(dict(overrides or {})))
    asset = factory.create(params)
    obj = SceneObject(name, name, params, int(seed), Pose(), sorted(t.value for t in factory.tags),
                      "")
    scene = Scene(seed=int(seed))
    scene.add_object(obj)
    bundle = make_bundle(scene, {name: asset}, [])
    out.resolve().parent.mkdir(parents=True, exist_ok=True)
    tmp_root = Path(tempfile.mkdtemp(prefix=f".{out.stem}.tex-", dir=out.resolve().parent))
    try:
        textures = TextureStore(tmp_root, texture_resolution)
        with atomic_file(out) as tmp:
            staged = tmp_root / f"{out.stem}{ext}"
            if ext in (".usd", ".usda", ".usdc", ".usdz"):
                from indoorgen.export.usd import write_usd_bundle
                write_usd_bundle(bundle, staged, textures)
            elif ext == ".glb":
                from indoorgen.export.gltf import write_glb
                write_glb(bundle, staged, textures)
            else:
                from indoorgen.export.obj import write_obj_format
                write_obj_format(bundle, tmp_root, textures)
                staged = tmp_root / "obj" / f"{name}.obj"
                text = staged.read_text().replace(f"mtllib {name}.mtl", f"mtllib {out.stem}.mtl")
                mtl = (tmp_root / "obj" / f"{name}.mtl").read_text().replace("../textures/",
                                                                             "textures/")
                staged.write_text(text)
                (tmp_root / "obj" / f"{name}.mtl").write_text(mtl)
            _move_textures(tmp_root, out.resolve().parent, ext)
            if ext == ".obj":
                os.replace(tmp_root / "obj" / f"{name}.mtl", out.with_suffix(".mtl"))
            shutil.copyfile(staged, tmp)
    finally:
        shutil.rmtree(tmp_root, ignore_errors=True)
    return out


def _move_textures(src_root: Path, dst_root: Path, ext: str) -> None:
    """Move baked textures into `dst_root/textures/` (not needed for self-contained files)."""
    if ext in (".glb", ".usdz"):
        return
    src = src_root / "textures"
    if not src.is_dir():
        return
    dst = dst_root / "textures"
    dst.mkdir(exist_ok=True)
    for p in src.iterdir():
        os.replace(p, dst / p.name)


def run_asset(args) -> int:
    """`indoorgen asset`."""
    overrides = dict(parse_param(p) for p in args.param)
    out = write_asset(args.name, args.seed, Path(args.out), overrides,
                      texture_resolution=args.texture_resolution)
    print(f"{out}: {args.name} seed {args.seed}")
    return 0
