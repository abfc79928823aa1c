"""Baked textures: written once per (material, seed), cached on disk, or left out entirely."""
from __future__ import annotations

from indoorgen.export.bundle import MatRef
from indoorgen.export.textures import TextureStore, default_cache_dir

REF = MatRef("oak", 7)


def test_cache_dir_follows_the_environment(monkeypatch, tmp_path):
    monkeypatch.setenv("INDOORGEN_TEXTURE_CACHE", str(tmp_path))
    assert default_cache_dir() == tmp_path
    monkeypatch.setenv("INDOORGEN_TEXTURE_CACHE", "")
    assert default_cache_dir() is None


def test_resolution_zero_writes_no_files_but_knows_the_material(tmp_path):
    store = TextureStore(tmp_path, 0, cache_dir=None)
    assert not store.enabled and store.paths(REF) == {} and store.relpath(REF, "normal", tmp_path) is None
    info = store.info(REF)
    assert info.name == "oak" and len(info.mean_color) == 3 and store.uv_scale(REF) > 0
    assert not (tmp_path / "textures").exists()


def test_maps_written_once_and_served_from_the_cache(tmp_path):
    cache = tmp_path / "cache"
    first = TextureStore(tmp_path / "a", 16, cache_dir=cache, workers=1)
    first.ensure([REF, REF])
    paths = first.paths(REF)
    assert {"base_color", "roughness", "normal"} <= set(paths) and all(p.is_file() for p in paths.values())
    assert first.relpath(REF, "base_color", tmp_path / "a") == f"textures/{REF.key}_basecolor.png"
    second = TextureStore(tmp_path / "b", 16, cache_dir=cache, workers=1)
    assert second.info(REF) == first.info(REF)
    again = second.paths(REF)
    assert {k: p.read_bytes() for k, p in again.items()} == {k: p.read_bytes() for k, p in paths.items()}
