"""Saved scenes read back and re-exported without solving: rooms rebuilt from scene.json's Room
data, assets from their generators, written atomically."""
from __future__ import annotations

import json
import time
from pathlib import Path

from indoorgen.architecture.doors import check_door_mode
from indoorgen.errors import ConfigError
from indoorgen.export.bundle import bundle_from_scene
from indoorgen.export.formats import parse_formats, write_formats
from indoorgen.model.scene import Scene
from indoorgen.outputs import atomic_dir, check_writable


class SceneFileError(ConfigError):
    """A scene.json that is missing, unreadable or not a scene."""


def read_scene(path: Path):
    """The `Scene` stored in `path` (a scene.json or a directory holding one); SceneFileError
    if it is missing or corrupt."""
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
                 usd_ext: str = "usdc", texture_resolution: int = 512,
                 doors: str | None = None) -> tuple[Path, dict]:
    """Re-export a saved scene into `out` (default: its own directory), atomically, beside
    what is already there (other formats, the user's files). scene.json is copied along, and
    plan.png / report.json too when they sit beside it. `doors` (open, closed or random)
    re-stands a home's door leaves: scene.json is written with the new states and report.json,
    whose navigation depended on the old ones, is left out (and dropped from `out`). Returns
    the directory and the seconds per stage."""
    fmts = parse_formats(formats)
    if doors is not None:
        check_door_mode(doors)
    scene, src = read_scene(scene_path)
    if doors is not None and scene.floorplan is None:
        raise ConfigError(f"--doors {doors} re-stands a home's doors; {str(src)!r} is a single "
                          "room, whose door has no leaf")
    out = Path(out) if out else src.parent
    check_writable(out, replacing=False)
    if texture_resolution < 0 or texture_resolution > 8192:
        raise ConfigError(f"--texture-resolution {texture_resolution} is invalid; valid: 0 "
                          "(no textures) or 16..8192")
    timings: dict[str, float] = {}
    t = time.perf_counter()
    bundle = bundle_from_scene(scene, doors=doors)
    timings["assets"] = time.perf_counter() - t
    keep = {}
    if out.resolve() != src.parent.resolve():  # a new place: the scene's own files go along
        for name in ("scene.json", "plan.png", "report.json"):
            if (src.parent / name).is_file():
                keep[name] = (src.parent / name).read_bytes()
        keep["scene.json"] = src.read_bytes()
    stale: set[str] = set()
    if doors is not None:
        scene.doors = {e.parent: round(e.joint_value, 6) for e in bundle.moving_elements}
        scene.config["doors"] = doors
        keep["scene.json"] = scene.dumps().encode()
        keep.pop("report.json", None)
        stale.add("report.json")
    with atomic_dir(out, merge=True, drop=stale) as tmp:  # other formats already there stay
        for name, data in keep.items():
            (tmp / name).write_bytes(data)
        write_formats(bundle, tmp, fmts, usd_ext=usd_ext, texture_resolution=texture_resolution,
                      timings=timings)
    return out, timings
