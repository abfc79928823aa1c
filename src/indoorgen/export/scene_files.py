"""Saved scenes read back and re-exported without solving: rooms rebuilt from scene.json's Room
data, assets from their generators, written atomically."""
from __future__ import annotations

import math
import time
from pathlib import Path

from indoorgen.architecture.doors import check_door_mode
from indoorgen.assets import factory_names, get_factory
from indoorgen.constraints.relations import parse_relation
from indoorgen.errors import ConfigError, IndoorGenError
from indoorgen.export.bundle import bundle_from_scene
from indoorgen.export.formats import parse_formats, write_formats
from indoorgen.model.scene import Scene
from indoorgen.model.schemas import SchemaError, read_json_file
from indoorgen.outputs import atomic_dir, check_writable

#: the largest relation margin (m) a scene may declare
MAX_MARGIN = 10.0


#: texture sizes (pixels) an export may ask for, besides 0 (no textures)
MIN_TEXTURE, MAX_TEXTURE = 16, 8192


def check_texture_resolution(value: int) -> None:
    """Raise ConfigError unless `value` is 0 (no textures) or MIN_TEXTURE..MAX_TEXTURE."""
    if value != 0 and not MIN_TEXTURE <= value <= MAX_TEXTURE:
        raise ConfigError(f"--texture-resolution {value} is invalid; valid: 0 (no textures) or "
                          f"{MIN_TEXTURE}..{MAX_TEXTURE}")


class SceneFileError(ConfigError):
    """A scene.json that is missing, unreadable or not a scene."""


def read_scene(path: Path) -> tuple[Scene, Path]:
    """The `Scene` stored in `path` (a scene.json or a directory holding one) and the file's
    path; SceneFileError if it is missing, too big, not JSON, breaks `schemas.SceneFile`, or
    names a generator, parameter or relation that does not exist."""
    path = Path(path)
    if path.is_dir():
        path = path / "scene.json"
    if not path.is_file():
        raise SceneFileError(f"scene file {str(path)!r} does not exist; give a scene.json "
                             "written by `indoorgen generate`")
    what = f"scene file {str(path)!r}"
    try:
        scene = Scene.from_json(read_json_file(path, what, "scene"))
    except SchemaError as e:
        raise SceneFileError(str(e).replace("scene.json: ", f"{what}: ", 1)) from None
    check_scene_names(scene, what)
    return scene, path


def check_scene_names(scene: Scene, what: str = "scene.json") -> None:
    """Raise SceneFileError unless every object's generator and parameters exist and every
    relation is one the constraint language reads, with a finite margin in range."""
    known = set(factory_names())
    for o in scene.objects.values():
        if o.generator not in known:
            raise SceneFileError(f"{what}: object {o.name!r} names generator {o.generator!r}, "
                                 "which does not exist; see `indoorgen assets list`")
        try:
            get_factory(o.generator).validate_params(o.params)
        except IndoorGenError as e:
            raise SceneFileError(f"{what}: object {o.name!r}: {e}") from None
        for r in o.relations:
            try:
                rel = parse_relation(r.relation)
            except (IndoorGenError, ValueError, IndexError):
                raise SceneFileError(f"{what}: object {o.name!r} has relation {r.relation!r}, "
                                     "which is not a relation; valid: StableAgainst(child, "
                                     "parent, margin), SupportedBy(...), CoPlanar(...), "
                                     "Touching(...)") from None
            margin = getattr(rel, "margin", 0.0)
            if not (math.isfinite(margin) and abs(margin) <= MAX_MARGIN):
                raise SceneFileError(f"{what}: object {o.name!r} has relation {r.relation!r} "
                                     f"with margin {margin}; valid: -{MAX_MARGIN:g} to "
                                     f"{MAX_MARGIN:g} m")


def export_scene(scene_path: Path, out: Path | None, formats: str | None, *,
                 usd_ext: str = "usdc", texture_resolution: int = 512,
                 doors: str | None = None, overwrite: bool = False) -> tuple[Path, dict]:
    """Re-export a saved scene into `out` (default: its own directory), atomically, beside
    what is already there (other formats, the user's files). scene.json is copied along, and
    plan.png / report.json too when they sit beside it. `doors` (open, closed or random)
    re-stands a home's door leaves: scene.json is written with the new states and report.json,
    whose navigation depended on the old ones, is left out (and dropped from `out`). Returns
    the directory and the seconds per stage. `overwrite` lets it write into a non-empty
    directory indoorgen did not write (beside the files there, never replacing them)."""
    fmts = parse_formats(formats)
    check_texture_resolution(texture_resolution)
    if doors is not None:
        check_door_mode(doors)
    scene, src = read_scene(scene_path)  # cheap: the file's checks come first
    if doors is not None and scene.floorplan is None:
        raise ConfigError(f"--doors {doors} re-stands a home's doors; {str(src)!r} is a single "
                          "room, whose door has no leaf")
    out = Path(out) if out else src.parent
    check_writable(out, replacing=False, overwrite=overwrite)  # before any work
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
    # other formats already there stay
    with atomic_dir(out, merge=True, drop=stale, overwrite=overwrite) as tmp:
        for name, data in keep.items():
            (tmp / name).write_bytes(data)
        write_formats(bundle, tmp, fmts, usd_ext=usd_ext, texture_resolution=texture_resolution,
                      timings=timings)
    return out, timings
