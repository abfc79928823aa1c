"""Seeded random streams.

Every stage, room and object draws from its own child of the user's `SeedSequence`, addressed by
a path of names (e.g. ``("room", "living_room_0", "solver")``). Because a stream is found by its
path rather than by the order streams were spawned in, adding a room or an object never
reshuffles the randomness of another.
"""
from __future__ import annotations

import zlib

import numpy as np

from indoorgen.errors import ConfigError

#: the largest seed: scene.json records seeds as signed 64-bit integers
MAX_SEED = 2**63 - 1


def _key(part: str | int) -> int:
    if isinstance(part, (int, np.integer)):
        return int(part) & 0xFFFFFFFF
    return zlib.crc32(str(part).encode("utf-8"))


def seed_sequence(seed: int, *path: str | int) -> np.random.SeedSequence:
    """The child `SeedSequence` of `seed` at `path` (the same spawn-key mechanism `spawn` uses)."""
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or \
            not 0 <= seed <= MAX_SEED:
        raise ConfigError(f"seed must be an integer from 0 to {MAX_SEED}, got {seed!r}")
    return np.random.SeedSequence(int(seed), spawn_key=tuple(_key(p) for p in path))


def stream(seed: int, *path: str | int) -> np.random.Generator:
    """A `numpy.random.Generator` for the child stream at `path`."""
    return np.random.default_rng(seed_sequence(seed, *path))


def child_seed(rng: np.random.Generator) -> int:
    """Draw a 31-bit seed from `rng`, for giving an object its own reproducible stream."""
    return int(rng.integers(0, 2**31 - 1))
