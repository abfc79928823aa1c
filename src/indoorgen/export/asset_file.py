"""One textured asset written to a file (.glb, .obj, .usd, .usda, .usdc, .usdz), textures beside it."""
from __future__ import annotations

import os
import shutil
import tempfile
from pathlib import Path
from typing import Any

import numpy as np

from indoorgen.assets import get_factory
from indoorgen.errors import ConfigError, OutputError
from indoorgen.export.bundle import make_bundle
from indoorgen.export.gltf import write_glb
from indoorgen.export.obj import write_obj_format
from indoorgen.export.textures import TextureStore
from indoorgen.export.usd.scene import write_usd_bundle
from indoorgen.model.scene import Pose, Scene, SceneObject
from indoorgen.outputs import atomic_file, check_writable
from indoorgen.rng import MAX_SEED

ASSET_EXTENSIONS = (".glb", ".obj", ".usd", ".usda", ".usdc", ".usdz")


def write_asset(name: str, seed: int, out: Path, overrides: dict[str, Any] | None = None, *,
                texture_resolution: int = 512) -> Path:
    """Write generator `name` (params sampled from `seed`, then `overrides`) to `out`; its
    textures go to `textures/` beside it (.glb embeds them, .usdz packages them)."""
    out = Path(out)
    ext = out.suffix.lower()
    if ext not in ASSET_EXTENSIONS:
        raise OutputError(f"cannot write an asset to {str(out)!r}: the file name must end in "
                          + ", ".join(ASSET_EXTENSIONS))
    if not 0 <= seed <= MAX_SEED:
        raise ConfigError(f"--seed must be an integer from 0 to {MAX_SEED}, got {seed}")
    check_writable(out, directory=False)
    factory = get_factory(name)
    params = factory.sample_params(np.random.default_rng(seed))
    params.update(factory.validate_params(dict(overrides or {})))
    asset = factory.create(params)
    obj = SceneObject(name, name, params, int(seed), Pose(), sorted(t.value for t in factory.tags),
                      "")
    scene = Scene(seed=int(seed))
    scene.add_object(obj)
    bundle = make_bundle(scene, {name: asset}, [])
    out.resolve().parent.mkdir(parents=True, exist_ok=True)
    tmp_root = Path(tempfile.mkdtemp(prefix=f".{out.stem}.tex-", dir=out.resolve().parent))
    try:
        textures = TextureStore(tmp_root, texture_resolution)
        with atomic_file(out) as tmp:
            staged = tmp_root / f"{out.stem}{ext}"
            if ext in (".usd", ".usda", ".usdc", ".usdz"):
                write_usd_bundle(bundle, staged, textures)
            elif ext == ".glb":
                write_glb(bundle, staged, textures)
            else:
                write_obj_format(bundle, tmp_root, textures)
                staged = tmp_root / "obj" / f"{name}.obj"
                text = staged.read_text().replace(f"mtllib {name}.mtl", f"mtllib {out.stem}.mtl")
                mtl = (tmp_root / "obj" / f"{name}.mtl").read_text().replace("../textures/",
                                                                             "textures/")
                staged.write_text(text)
                (tmp_root / "obj" / f"{name}.mtl").write_text(mtl)
            _move_textures(tmp_root, out.resolve().parent, ext)
            if ext == ".obj":
                os.replace(tmp_root / "obj" / f"{name}.mtl", out.with_suffix(".mtl"))
            shutil.copyfile(staged, tmp)
    finally:
        shutil.rmtree(tmp_root, ignore_errors=True)
    return out


def _move_textures(src_root: Path, dst_root: Path, ext: str) -> None:
    """Move baked textures into `dst_root/textures/` (not needed for self-contained files)."""
    if ext in (".glb", ".usdz"):
        return
    src = src_root / "textures"
    if not src.is_dir():
        return
    dst = dst_root / "textures"
    dst.mkdir(exist_ok=True)
    for p in src.iterdir():
        os.replace(p, dst / p.name)
