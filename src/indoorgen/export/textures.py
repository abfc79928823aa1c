"""Baked material textures, written once per export next to the files that use them.

`TextureStore` bakes each (material, seed) pair once (`materials.bake`), writes its maps as
8-bit PNGs into `<root>/textures/<material>_<seed>_{basecolor,roughness,normal,metallic}.png`
and hands out paths relative to whichever file references them. Baking dominates export time,
so pairs are baked in a small thread pool and kept in an on-disk cache keyed by the material
library's source fingerprint and the resolution (`INDOORGEN_TEXTURE_CACHE` names the cache
directory; set it to an empty string to disable the cache).
"""
from __future__ import annotations

import hashlib
import json
import logging
import os
import shutil
from collections.abc import Iterable
from concurrent.futures import ThreadPoolExecutor
from dataclasses import asdict, dataclass
from pathlib import Path

import numpy as np
from PIL import Image

from indoorgen.assets import materials
from indoorgen.assets.materials import bake, get_material
from indoorgen.export.bundle import MatRef

log = logging.getLogger(__name__)

#: map kind -> file suffix
MAP_SUFFIX = {"base_color": "basecolor", "roughness": "roughness", "normal": "normal",
              "metallic": "metallic"}
TEXTURE_DIR = "textures"


@dataclass(frozen=True)
class MaterialInfo:
    """Scalar description of a baked material (for formats or consumers without textures)."""

    name: str
    family: str
    mean_color: tuple[float, ...]
    mean_roughness: float
    metallic_value: float
    opacity: float
    ior: float
    tile_size_m: float
    has_metallic: bool
    density: float


def default_cache_dir() -> Path | None:
    """The texture cache directory: $INDOORGEN_TEXTURE_CACHE, else ~/.cache/indoorgen/textures;
    None when the variable is set but empty (no caching)."""
    env = os.environ.get("INDOORGEN_TEXTURE_CACHE")
    if env is not None:
        return Path(env) if env.strip() else None
    base = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
    return Path(base) / "indoorgen" / "textures"


def _library_fingerprint() -> str:
    """Hash of the material library's sources, so a changed material never reuses a stale
    cached texture."""
    h = hashlib.sha1()
    for p in sorted(Path(materials.__file__).parent.glob("*.py")):
        h.update(p.read_bytes())
    return h.hexdigest()[:12]


def _u8(x: np.ndarray) -> np.ndarray:
    return (np.clip(x, 0.0, 1.0) * 255.0 + 0.5).astype(np.uint8)


class TextureStore:
    """Textures of one export (state: which pairs are already written). `resolution` 0 means
    no texture files at all: exporters then fall back to each material's scalar values."""

    def __init__(self, root: Path, resolution: int = 512, cache_dir: Path | None | bool = True,
                 workers: int | None = None) -> None:
        self.root = Path(root)
        self.dir = self.root / TEXTURE_DIR
        self.resolution = int(resolution)
        self._paths: dict[MatRef, dict[str, Path]] = {}
        self._info: dict[MatRef, MaterialInfo] = {}
        if cache_dir is True:
            cache_dir = default_cache_dir()
        self._cache: Path | None = None
        if cache_dir and self.resolution > 0:
            self._cache = Path(cache_dir) / f"{_library_fingerprint()}_{self.resolution}"
        self.workers = workers or min(4, os.cpu_count() or 1)

    @property
    def enabled(self) -> bool:
        """Whether texture files are written (resolution > 0)."""
        return self.resolution > 0

    # ---------------------------------------------------------------------------------------
    def ensure(self, refs: Iterable[MatRef]) -> None:
        """Bake and write every pair in `refs` not written yet (in parallel)."""
        todo = [r for r in dict.fromkeys(refs) if r not in self._info]
        if not todo:
            return
        if self.enabled:
            self.dir.mkdir(parents=True, exist_ok=True)
        if len(todo) == 1 or self.workers <= 1:
            for r in todo:
                self._make(r)
            return
        with ThreadPoolExecutor(self.workers) as pool:
            for r, (paths, info) in zip(todo, pool.map(self._build, todo), strict=True):
                self._paths[r], self._info[r] = paths, info

    def _make(self, ref: MatRef) -> None:
        self._paths[ref], self._info[ref] = self._build(ref)

    def _build(self, ref: MatRef) -> tuple[dict[str, Path], MaterialInfo]:
        if self._cache is not None:
            hit = self._from_cache(self._cache, ref)
            if hit is not None:
                return hit
        res = self.resolution if self.enabled else 16
        maps = bake(ref.name, ref.seed, res)
        info = MaterialInfo(ref.name, maps.family, tuple(float(c) for c in maps.mean_color),
                            float(maps.mean_roughness), float(maps.metallic_value),
                            float(maps.opacity), float(maps.ior), float(maps.tile_size_m),
                            maps.metallic is not None, float(get_material(ref.name).density))
        paths: dict[str, Path] = {}
        if self.enabled:
            self.dir.mkdir(parents=True, exist_ok=True)
            for kind, suffix in MAP_SUFFIX.items():
                arr = getattr(maps, kind)
                if arr is None:
                    continue
                p = self.dir / f"{ref.key}_{suffix}.png"
                Image.fromarray(_u8(arr)).save(p, compress_level=3)
                paths[kind] = p
            if self._cache is not None:
                self._to_cache(self._cache, ref, paths, info)
        return paths, info

    def _from_cache(self, cache: Path, ref: MatRef) -> tuple[dict[str, Path], MaterialInfo] | None:
        meta = cache / f"{ref.key}.json"
        try:
            self.dir.mkdir(parents=True, exist_ok=True)
            d = json.loads(meta.read_text())
            info = MaterialInfo(**{**d, "mean_color": tuple(d["mean_color"])})
            paths = {}
            for kind, suffix in MAP_SUFFIX.items():
                src = cache / f"{ref.key}_{suffix}.png"
                if kind == "metallic" and not info.has_metallic:
                    continue
                dst = self.dir / src.name
                shutil.copyfile(src, dst)
                paths[kind] = dst
            return paths, info
        except (OSError, ValueError, TypeError, KeyError):
            return None

    def _to_cache(self, cache: Path, ref: MatRef, paths: dict[str, Path], info: MaterialInfo) -> None:
        try:
            cache.mkdir(parents=True, exist_ok=True)
            for p in paths.values():
                tmp = cache / f".{p.name}.{os.getpid()}"
                shutil.copyfile(p, tmp)
                os.replace(tmp, cache / p.name)
            tmp = cache / f".{ref.key}.json.{os.getpid()}"
            tmp.write_text(json.dumps(asdict(info)))
            os.replace(tmp, cache / f"{ref.key}.json")
        except OSError as e:  # a read-only or full cache never fails an export
            log.debug("texture cache not written: %s", e)

    # ---------------------------------------------------------------------------------------
    def info(self, ref: MatRef) -> MaterialInfo:
        """Scalar values of `ref` (baking it if needed)."""
        if ref not in self._info:
            self._make(ref)
        return self._info[ref]

    def paths(self, ref: MatRef) -> dict[str, Path]:
        """Absolute paths of `ref`'s maps by kind (empty when textures are disabled)."""
        if ref not in self._info:
            self._make(ref)
        return self._paths[ref]

    def relpath(self, ref: MatRef, kind: str, start: Path) -> str | None:
        """Path of one map relative to directory `start` (posix separators), or None."""
        p = self.paths(ref).get(kind)
        if p is None:
            return None
        return Path(os.path.relpath(p, start)).as_posix()

    def uv_scale(self, ref: MatRef) -> float:
        """Multiply metre UVs by this to get texture repeats."""
        return 1.0 / max(self.info(ref).tile_size_m, 1e-6)
