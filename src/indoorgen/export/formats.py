"""`write_formats`: every requested export format of one bundle into one directory.

Formats (comma-separated on the command line):

| name | files |
|---|---|
| usd  | `scene.usdc` (or `scene.usda` with usd_ext="usda") + `textures/` |
| usda, usdc | the stage in that encoding |
| usdz | `scene.usdz`, stage and textures in one package |
| urdf | `scene.urdf`, `urdf/<object>.urdf`, `urdf/architecture.urdf`, `meshes/`, `textures/` |
| mjcf | `scene.xml`, `meshes/`, `textures/` |
| glb  | `scene.glb` (alias gltf), textures embedded |
| obj  | `scene.obj` + `scene.mtl`, `obj/<object>.obj` + .mtl, `textures/` |

Textures and mesh files are shared by the formats of one call, so asking for several costs
little more than the slowest one.
"""
from __future__ import annotations

import logging
import time
from collections.abc import Iterable
from pathlib import Path

from indoorgen.errors import ConfigError
from indoorgen.export.bundle import ExportBundle
from indoorgen.export.gltf import write_glb
from indoorgen.export.mjcf import write_mjcf
from indoorgen.export.obj import MeshFiles, write_obj_format
from indoorgen.export.textures import TextureStore
from indoorgen.export.urdf import write_urdf

log = logging.getLogger(__name__)

FORMATS = ("usd", "usda", "usdc", "usdz", "urdf", "mjcf", "glb", "obj")
ALIASES = {"gltf": "glb", "xml": "mjcf", "mujoco": "mjcf"}
DEFAULT_FORMATS = ("usd", "urdf", "mjcf")
#: texture size (px) written by default
DEFAULT_TEXTURE_RESOLUTION = 512


class UnknownFormatError(ConfigError):
    """An export format name that is not one of FORMATS."""


def parse_formats(spec: str | Iterable[str] | None) -> list[str]:
    """`"usd,urdf"` (or a list) -> validated, deduplicated format names; None -> defaults.
    Raises UnknownFormatError naming the bad value and the valid ones."""
    if spec is None:
        return list(DEFAULT_FORMATS)
    items = spec.split(",") if isinstance(spec, str) else list(spec)
    out = []
    for raw in items:
        f = str(raw).strip().lower()
        if not f:
            continue
        f = ALIASES.get(f, f)
        if f not in FORMATS:
            raise UnknownFormatError(f"unknown export format {str(raw).strip()!r}; valid: "
                                     + ", ".join(FORMATS))
        if f not in out:
            out.append(f)
    if not out:
        raise UnknownFormatError("no export format given; valid: " + ", ".join(FORMATS))
    return out


def write_formats(bundle: ExportBundle, out_dir: Path, formats: str | Iterable[str] | None = None,
                  *, usd_ext: str = "usdc", texture_resolution: int = DEFAULT_TEXTURE_RESOLUTION,
                  instancing: bool = True, timings: dict | None = None) -> dict[str, list[Path]]:
    """Write `formats` of `bundle` into the existing directory `out_dir` (the caller makes it
    atomic, e.g. with `outputs.atomic_dir`). Returns the main files per format; seconds per
    format go into `timings` when given."""
    # import time: USD (pxr) adds ~0.28 s to the ~0.73 s of `import indoorgen.export`; only
    # calls that write a USD format pay it (measured with python -X importtime)
    from indoorgen.export.usd.scene import write_usd_bundle

    fmts = parse_formats(formats)
    out_dir = Path(out_dir)
    timings = {} if timings is None else timings
    textures = TextureStore(out_dir, texture_resolution)
    t = time.perf_counter()
    textures.ensure(bundle.all_matrefs())
    timings["textures"] = time.perf_counter() - t
    files = MeshFiles(bundle, out_dir, textures)
    written: dict[str, list[Path]] = {}
    for f in fmts:
        t = time.perf_counter()
        if f in ("usd", "usda", "usdc", "usdz"):
            ext = usd_ext if f == "usd" else f
            written[f] = [write_usd_bundle(bundle, out_dir / f"scene.{ext}", textures,
                                           instancing=instancing)]
        elif f == "urdf":
            written[f] = write_urdf(bundle, out_dir, files)
        elif f == "mjcf":
            written[f] = [write_mjcf(bundle, out_dir, files)]
        elif f == "glb":
            written[f] = [write_glb(bundle, out_dir / "scene.glb", textures)]
        elif f == "obj":
            written[f] = write_obj_format(bundle, out_dir, textures)
        timings[f] = time.perf_counter() - t
        log.info("export %s: %.2f s", f, timings[f])
    return written
