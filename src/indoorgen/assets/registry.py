"""The generator registry: `register` fills it, `get_factory` / `factory_names` / `factories_with` read it.

Generators register themselves when their module is imported; the readers import the whole
`assets.generators` package first, so callers never need to.
"""
from __future__ import annotations

from collections.abc import Iterable

from indoorgen.assets.protocol import AssetFactory
from indoorgen.errors import UnknownGeneratorError
from indoorgen.model.tags import Semantics

_REGISTRY: dict[str, type[AssetFactory]] = {}


def register(cls: type[AssetFactory]) -> type[AssetFactory]:
    """Class decorator: make a generator available by its `name`."""
    if not cls.name:
        raise ValueError(f"{cls.__name__} has no name")
    if cls.name in _REGISTRY and _REGISTRY[cls.name] is not cls:
        raise ValueError(f"duplicate generator name {cls.name!r}")
    _REGISTRY[cls.name] = cls
    return cls


def _ensure_loaded() -> None:
    # Imported here, not at the top: every generator module imports `register` from this
    # module (a cycle), and loading every generator module costs ~0.16 s that
    # `import indoorgen.assets` (e.g. for `Surface` alone) should not pay.
    from indoorgen.assets import generators  # noqa: F401  (importing registers every generator)


def get_factory(name: str) -> AssetFactory:
    """The generator registered as `name`, or UnknownGeneratorError listing the valid names."""
    _ensure_loaded()
    try:
        return _REGISTRY[name]()
    except KeyError:
        raise UnknownGeneratorError(
            f"unknown generator {name!r}; valid: {', '.join(sorted(_REGISTRY))}") from None


def factory_names() -> list[str]:
    """Every registered generator's name, sorted."""
    _ensure_loaded()
    return sorted(_REGISTRY)


def factories_with(tags: Iterable[Semantics], without: Iterable[Semantics] = ()) -> list[str]:
    """Names of generators whose tags include all of `tags` and none of `without`."""
    _ensure_loaded()
    need, avoid = set(tags), set(without)
    return sorted(n for n, c in _REGISTRY.items() if need <= c.tags and not (avoid & c.tags))
