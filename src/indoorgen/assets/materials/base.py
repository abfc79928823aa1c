"""The material protocol: `MaterialMaps`, `MaterialGenerator`, the registry, `bake` and
`save_maps`.

A material generator is a `MaterialGenerator` subclass registered by `name`. Like an asset
generator it documents every parameter as a `Param`, so sampling and validation come for free.
Subclasses implement `build(p, res, rng) -> Layers` (colour, roughness, a height field, optional
metallic); `generate` validates the params, seeds the rng, and turns the height field into a
tangent-space normal map with periodic finite differences.
"""
from __future__ import annotations

import logging
import zlib
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path
from typing import Any, ClassVar

import numpy as np

from indoorgen.assets.protocol import Param
from indoorgen.errors import ParameterError, UnknownGeneratorError

log = logging.getLogger(__name__)

F32 = np.float32

#: The families a material may belong to (exporters may key shading presets on them).
FAMILIES = ("wood", "metal", "ceramic", "glass", "plastic", "fabric", "leather", "stone", "tile",
            "plaster", "brick", "wallpaper", "carpet", "paper", "rubber", "cork")


@dataclass
class MaterialMaps:
    """Baked PBR maps of one material, plus scalar fallbacks for exporters without textures.

    base_color: float32 (H, W, 3) sRGB-encoded in [0, 1]; roughness: float32 (H, W);
    normal: float32 (H, W, 3) tangent-space, OpenGL convention (+Y up), encoded n * 0.5 + 0.5;
    metallic: float32 (H, W) or None for non-metals. mean_color is sRGB-encoded (averaged in
    linear light); opacity < 1 marks transparent materials (glass), ior their refractive index.
    tile_size_m is the real-world width one repeat of the maps covers, so that metre-based UVs
    (assets' `corner_uv`) map at true scale with uv / tile_size_m.
    """

    name: str
    base_color: np.ndarray
    roughness: np.ndarray
    normal: np.ndarray
    metallic: np.ndarray | None
    mean_color: tuple[float, float, float]
    mean_roughness: float
    metallic_value: float
    opacity: float = 1.0
    ior: float = 1.5
    family: str = ""
    tile_size_m: float = 1.0
    params: dict[str, Any] = field(default_factory=dict)

    @property
    def resolution(self) -> int:
        """The maps' size in pixels (they are square)."""
        return int(self.base_color.shape[0])


@dataclass
class Layers:
    """What a generator's `build` returns: raw maps before normal derivation and clamping.

    height is in arbitrary units (about 0..1 for the main relief); `bump` scales its slopes.
    """

    base_color: np.ndarray
    roughness: np.ndarray
    height: np.ndarray
    bump: float = 1.0
    metallic: np.ndarray | None = None
    opacity: float = 1.0
    ior: float = 1.5


def srgb_to_linear(c: np.ndarray) -> np.ndarray:
    """sRGB-encoded colour values (0..1) to linear light, for averaging colours."""
    c = np.asarray(c, np.float64)
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


def linear_to_srgb(c: np.ndarray) -> np.ndarray:
    """Linear-light values to sRGB encoding (clamped to 0..1)."""
    c = np.clip(np.asarray(c, np.float64), 0.0, 1.0)
    return np.where(c <= 0.0031308, c * 12.92, 1.055 * c ** (1 / 2.4) - 0.055)


def normal_from_height(height: np.ndarray, strength: float) -> np.ndarray:
    """Tangent-space normal map (encoded in [0, 1], OpenGL +Y up) from a height field, by
    central differences that wrap around, so the normal map tiles whenever the height does.

    Slopes are measured per texture unit and divided by 256, so a height step of 1 spread over
    1/256 of the texture tilts the normal by 45 degrees at strength 1, at any resolution.
    """
    h = np.ascontiguousarray(height, dtype=F32)
    res = h.shape[0]
    scale = F32(strength * res / 256.0 * 0.5)
    gx = np.empty_like(h)
    gx[:, 1:-1] = h[:, 2:] - h[:, :-2]
    gx[:, 0] = h[:, 1] - h[:, -1]
    gx[:, -1] = h[:, 0] - h[:, -2]
    gy = np.empty_like(h)
    gy[1:-1] = h[2:] - h[:-2]
    gy[0] = h[1] - h[-1]
    gy[-1] = h[0] - h[-2]
    gx *= scale
    gy *= scale
    # +Y is up (towards row 0): dh/dy = -dh/drow, and n = (-dh/dx, -dh/dy, 1) normalised.
    inv = F32(1.0) / np.sqrt(gx * gx + gy * gy + F32(1.0))
    out = np.empty(h.shape + (3,), F32)
    out[..., 0] = F32(0.5) - F32(0.5) * gx * inv
    out[..., 1] = F32(0.5) + F32(0.5) * gy * inv
    out[..., 2] = F32(0.5) + F32(0.5) * inv
    return out


class MaterialGenerator:
    """Base class of every material. Subclasses set `name`, `family`, `density` (kg/m^3) and
    `params`, and implement `build`; `generate` does validation and finishing."""

    name: ClassVar[str] = ""
    family: ClassVar[str] = ""
    density: ClassVar[float] = 1000.0
    params: ClassVar[dict[str, Param]] = {}
    #: metres one texture repeat spans (see `tile_size_m`, which may depend on params)
    tile_size: ClassVar[float] = 0.5
    #: or (param name, metres per unit of it) when the repeat scales with a count parameter
    tile_param: ClassVar[tuple[str, float] | None] = None

    def tile_size_m(self, p: dict[str, Any]) -> float:
        """Real-world width of one repeat of the maps for params `p`, in metres."""
        if self.tile_param is not None:
            key, per = self.tile_param
            return float(p[key]) * per
        return float(self.tile_size)

    def sample_params(self, rng: np.random.Generator) -> dict[str, Any]:
        """Draw every documented parameter from its range (in sorted-name order, for stability)."""
        return {k: self.params[k].sample(rng) for k in sorted(self.params)}

    def validate_params(self, params: dict[str, Any]) -> dict[str, Any]:
        """Check params against the documented ones; ParameterError on unknown names or values."""
        out = {}
        for k, v in params.items():
            if k not in self.params:
                raise ParameterError(f"material {self.name} has no parameter {k!r}; valid: "
                                     + ", ".join(sorted(self.params)))
            out[k] = self.params[k].check(k, v)
        return out

    def generate(self, params: dict[str, Any], resolution: int, seed: int) -> MaterialMaps:
        """Bake the maps at `resolution` x `resolution`. Params missing from `params` are drawn
        from `np.random.default_rng(seed)` exactly as `bake` would; the noise is seeded by
        (seed, name), so the result is a pure function of the arguments."""
        try:
            res = int(resolution)
        except (TypeError, ValueError):
            res = -1
        if res < 16 or res > 8192:
            raise ParameterError(f"resolution {resolution!r} is invalid; valid: int in [16, 8192]")
        p = self.validate_params(params or {})
        if len(p) < len(self.params):
            p = {**self.sample_params(np.random.default_rng(_seed_word(seed))), **p}
        rng = np.random.default_rng([_seed_word(seed), zlib.crc32(self.name.encode())])
        layers = self.build(p, res, rng)
        return self._finish(layers, p, res)

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """The raw layers for resolved params `p` at `res` pixels, drawing from `rng`."""
        raise NotImplementedError

    def _finish(self, layers: Layers, p: dict[str, Any], res: int) -> MaterialMaps:
        color = np.clip(np.broadcast_to(layers.base_color, (res, res, 3)), 0.0, 1.0).astype(F32)
        rough = np.clip(np.broadcast_to(layers.roughness, (res, res)), 0.0, 1.0).astype(F32)
        height = np.broadcast_to(layers.height, (res, res)).astype(F32)
        normal = normal_from_height(height, layers.bump)
        metal = None
        if layers.metallic is not None:
            metal = np.clip(np.broadcast_to(layers.metallic, (res, res)), 0.0, 1.0).astype(F32)
        step = max(1, res // 64)  # a 64 x 64 subsample is plenty for the mean
        lin = srgb_to_linear(color[::step, ::step].reshape(-1, 3)).mean(axis=0)
        r, g, b = (float(x) for x in linear_to_srgb(lin))
        mean_color = (r, g, b)
        return MaterialMaps(
            name=self.name, base_color=color, roughness=rough, normal=normal, metallic=metal,
            mean_color=mean_color, mean_roughness=float(rough.mean()),
            metallic_value=float(metal.mean()) if metal is not None else 0.0,
            opacity=float(layers.opacity), ior=float(layers.ior), family=self.family,
            tile_size_m=float(self.tile_size_m(p)),
            params=dict(p))


def _seed_word(seed: int) -> int:
    """A non-negative int for numpy's seeding (negative seeds wrap)."""
    return int(seed) % (1 << 63)


_REGISTRY: dict[str, type[MaterialGenerator]] = {}


def register(cls: type[MaterialGenerator]) -> type[MaterialGenerator]:
    """Class decorator: make a material available by its `name`."""
    if not cls.name:
        raise ValueError(f"{cls.__name__} has no name")
    if cls.family not in FAMILIES:
        raise ValueError(f"{cls.__name__}: family {cls.family!r} not one of {FAMILIES}")
    if cls.name in _REGISTRY and _REGISTRY[cls.name] is not cls:
        raise ValueError(f"duplicate material name {cls.name!r}")
    for k, prm in cls.params.items():
        if not prm.doc:
            raise ValueError(f"{cls.__name__}: parameter {k!r} has no doc")
    _REGISTRY[cls.name] = cls
    return cls


def get_material(name: str) -> MaterialGenerator:
    """The material generator registered as `name`, or UnknownGeneratorError naming the valid
    ones."""
    try:
        return _REGISTRY[name]()
    except (KeyError, TypeError):
        raise UnknownGeneratorError(
            f"unknown material {name!r}; valid: {', '.join(sorted(_REGISTRY))}") from None


def material_names() -> list[str]:
    """Every registered material name, sorted."""
    return sorted(_REGISTRY)


def materials_in_family(family: str) -> list[str]:
    """Names of the materials of one family (sorted); empty for an unknown family."""
    return sorted(n for n, c in _REGISTRY.items() if c.family == family)


def _freeze(maps: MaterialMaps) -> MaterialMaps:
    for arr in (maps.base_color, maps.roughness, maps.normal, maps.metallic):
        if arr is not None:
            arr.setflags(write=False)
    return maps


@lru_cache(maxsize=48)
def _bake_cached(name: str, seed: int, resolution: int,
                 params: tuple[tuple[str, Any], ...] | None) -> MaterialMaps:
    gen = get_material(name)
    p = dict(params) if params is not None else gen.sample_params(
        np.random.default_rng(_seed_word(seed)))
    return _freeze(gen.generate(p, resolution, seed))


def bake(name: str, seed: int, resolution: int = 512,
         params: dict[str, Any] | None = None) -> MaterialMaps:
    """Maps of material `name`: params sampled from `np.random.default_rng(seed)` unless given
    (missing keys are sampled too), then generated. Deterministic and memoised (a bounded LRU
    cache); the returned arrays are read-only because they may be shared between callers."""
    get_material(name)  # raise UnknownGeneratorError before touching the cache
    key = None
    if params is not None:
        try:
            key = tuple(sorted(params.items()))
            hash(key)
        except TypeError:
            return _freeze(get_material(name).generate(params, resolution, seed))
    return _bake_cached(name, int(seed), int(resolution), key)


def _to_u8(x: np.ndarray) -> np.ndarray:
    return (np.clip(x, 0.0, 1.0) * 255.0 + 0.5).astype(np.uint8)


def save_maps(maps: MaterialMaps, directory: Path | str, stem: str) -> dict[str, Path]:
    """Write 8-bit PNGs `{stem}_basecolor.png`, `_roughness.png`, `_normal.png` (and
    `_metallic.png` for metals) into `directory` (created if missing). Returns the paths keyed by
    map kind: "base_color", "roughness", "normal", "metallic"."""
    from PIL import Image

    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    out: dict[str, Path] = {}
    items = [("base_color", "basecolor", maps.base_color),
             ("roughness", "roughness", maps.roughness),
             ("normal", "normal", maps.normal)]
    if maps.metallic is not None:
        items.append(("metallic", "metallic", maps.metallic))
    for kind, suffix, arr in items:
        path = directory / f"{stem}_{suffix}.png"
        Image.fromarray(_to_u8(arr)).save(path)  # uint8 HxW -> "L", HxWx3 -> "RGB"
        out[kind] = path
    log.debug("wrote %d maps for %s to %s", len(out), maps.name, directory)
    return out
