"""The asset catalogue: every generator, looked up by name or by semantic tags.

Importing this module imports every generator module (`assets.generators` walks its package),
which registers them; lookups then read the registry.
"""
from __future__ import annotations

from collections.abc import Iterable

import indoorgen.assets.generators  # noqa: F401  (importing it registers every generator)
from indoorgen.assets.protocol import AssetFactory
from indoorgen.assets.registry import REGISTRY
from indoorgen.errors import UnknownGeneratorError
from indoorgen.model.tags import Semantics


def get_factory(name: str) -> AssetFactory:
    """The generator registered as `name`, or UnknownGeneratorError listing the valid names."""
    try:
        return REGISTRY[name]()
    except KeyError:
        raise UnknownGeneratorError(
            f"unknown generator {name!r}; valid: {', '.join(sorted(REGISTRY))}") from None


def factory_names() -> list[str]:
    """Every registered generator's name, sorted."""
    return sorted(REGISTRY)


def factories_with(tags: Iterable[Semantics | str], without: Iterable[Semantics | str] = ()
                   ) -> list[str]:
    """Names of generators whose tags include all of `tags` and none of `without`."""
    need, avoid = set(tags), set(without)
    return sorted(n for n, c in REGISTRY.items() if need <= c.tags and not (avoid & c.tags))
