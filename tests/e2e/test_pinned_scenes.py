"""scene.json digests pinned for fixed seeds: a refactor must not change what is generated.

A change that means to alter the output regenerates the digests with
`python tests/e2e/test_pinned_scenes.py` and says so in its commit.
"""
from __future__ import annotations

import hashlib
import json
import sys
from pathlib import Path

import pytest

from indoorgen import GenerateConfig, HomeConfig, generate, generate_home

DIGESTS = Path(__file__).resolve().parents[1] / "data" / "scene_digests.json"
ROOM_TYPES = ("living_room", "kitchen", "bedroom")
SEEDS = range(4)


def scene_digest(key: str) -> str:
    """sha256 of the scene.json generated for a key such as 'kitchen/3' or 'home2/0'."""
    kind, seed = key.split("/")
    if kind.startswith("home"):
        gen = generate_home(int(seed), HomeConfig(floors=int(kind[-1]), preset=HOME_PRESETS[kind]))
    else:
        gen = generate(int(seed), GenerateConfig(room_type=kind))
    return digest(gen.scene)


def digest(scene) -> str:
    """sha256 of a scene's scene.json text."""
    return hashlib.sha256(scene.dumps().encode()).hexdigest()


#: the preset each pinned home is solved on: the 1-storey home as `indoorgen generate --seed 0`
#: makes it, the 2-storey one on the fast preset (CI's 15 minutes)
HOME_PRESETS = {"home1": "default", "home2": "fast"}
ROOM_KEYS = [f"{t}/{s}" for t in ROOM_TYPES for s in SEEDS]
#: fewer homes than rooms: a home takes 30-90 s of CI's 15 minutes (benchmarks/home.py runs many)
HOME_KEYS = ["home2/0"]
#: what `indoorgen generate --seed 0` writes; tests/e2e/test_cli.py checks it against this digest
CLI_HOME_KEY = "home1/0"


def pinned(key: str) -> str:
    """The digest stored for a key."""
    return json.loads(DIGESTS.read_text())[key]


@pytest.mark.parametrize("key", ROOM_KEYS)
def test_room_scene_json_is_pinned(key):
    assert scene_digest(key) == pinned(key)


@pytest.mark.slow
@pytest.mark.xdist_group("export_homes")
@pytest.mark.parametrize("key", HOME_KEYS)
def test_home_scene_json_is_pinned(key, generated_homes):
    # the suite's shared homes are these keys' homes (tests/conftest.py): not generated again
    kind, seed = key.split("/")
    gen = generated_homes[kind]
    assert (gen.scene.seed, gen.scene.config["floors"], gen.scene.config["preset"]) == \
        (int(seed), int(kind[-1]), HOME_PRESETS[kind])
    assert digest(gen.scene) == pinned(key)


if __name__ == "__main__":
    digests = {k: scene_digest(k) for k in ROOM_KEYS + HOME_KEYS + [CLI_HOME_KEY]}
    DIGESTS.write_text(json.dumps(digests, indent=1, sort_keys=True) + "\n")
    sys.exit(0)
