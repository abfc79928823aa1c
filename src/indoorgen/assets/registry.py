"""The generator registry: every generator module decorates its classes with `register`.

Only `assets.catalogue` reads it, after importing every generator module.
"""
from __future__ import annotations

from indoorgen.assets.protocol import AssetFactory

#: generator name -> class; filled as generator modules are imported (read through `catalogue`)
REGISTRY: dict[str, type[AssetFactory]] = {}


def register(cls: type[AssetFactory]) -> type[AssetFactory]:
    """Class decorator: make a generator available by its `name`."""
    if not cls.name:
        raise ValueError(f"{cls.__name__} has no name")
    if cls.name in REGISTRY and REGISTRY[cls.name] is not cls:
        raise ValueError(f"duplicate generator name {cls.name!r}")
    REGISTRY[cls.name] = cls
    return cls
