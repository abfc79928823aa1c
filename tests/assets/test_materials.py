"""The procedural material library (assets/materials): every registered material over a few
seeds against the map contract (shapes, dtypes, ranges, unit normals), tileability across the
wrap seam, determinism; plus the registry, slots, bake cache and save_maps."""
from __future__ import annotations

from functools import cache

import numpy as np
import pytest
from PIL import Image

from indoorgen.assets.materials import (
    FAMILIES,
    SLOT_CHOICES,
    MaterialMaps,
    bake,
    choose_materials,
    get_material,
    material_names,
    materials_in_family,
    normal_from_height,
    save_maps,
)
from indoorgen.assets.materials import noise as nz
from indoorgen.errors import ParameterError, UnknownGeneratorError

NAMES = material_names()
SEEDS = (0, 1, 2)
RES = 128
REQUIRED_SLOTS = {"wood", "metal", "fabric", "leather", "ceramic", "glass", "plastic", "stone",
                  "marble", "paper", "cardboard", "rubber", "front", "back", "body", "upholstery",
                  "frame", "screen", "shade", "canvas", "mirror", "foliage", "soil", "food", "wax",
                  "carpet", "tile", "plaster", "brick", "countertop", "appliance", "porcelain"}


@cache
def maps(name: str, seed: int, res: int = RES) -> MaterialMaps:
    return get_material(name).generate({}, res, seed)


def seam_stats(m: np.ndarray, axis: int) -> tuple[float, float]:
    """(mean |difference| across the wrap seam, mean |difference| between neighbouring interior
    columns (axis=1) or rows (axis=0))."""
    m = np.asarray(m, np.float64)
    first = np.take(m, 0, axis=axis)
    last = np.take(m, -1, axis=axis)
    seam = float(np.abs(last - first).mean())
    interior = float(np.abs(np.diff(m, axis=axis)).mean())
    return seam, interior


def assert_tiles(maps_: np.ndarray | list[np.ndarray], what: str) -> None:
    """The seam is no worse than 1.5 x the interior, for columns and for rows. Given several
    maps (one per seed), the means are taken over all of them: the seam is a single column, so
    for textures with sparse features (a few specks, veins, knots) one seed's seam column is a
    noisy sample; a real seam shows up in every seed and survives the averaging."""
    group = maps_ if isinstance(maps_, list) else [maps_]
    for axis, label in ((1, "columns"), (0, "rows")):
        stats = np.array([seam_stats(m, axis) for m in group])
        seam, interior = stats.mean(axis=0)
        assert seam <= 1.5 * interior + 1e-4, (
            f"{what}: seam between last and first {label} {seam:.5f} > 1.5 x interior "
            f"{interior:.5f}")


# --------------------------------------------------------------------------- registry

def test_registry_has_enough_materials_covering_every_family():
    assert len(NAMES) >= 32
    for fam in FAMILIES:
        assert materials_in_family(fam), f"no material in family {fam}"
    assert materials_in_family("no_such_family") == []
    # the coverage the library promises, by name
    for name in ("oak", "walnut", "pine_planks", "painted_wood", "plywood", "brushed_steel",
                 "chrome", "painted_metal", "rusty_metal", "galvanized_steel", "glazed_ceramic",
                 "matte_ceramic", "porcelain", "clear_glass", "frosted_glass", "glossy_plastic",
                 "matte_plastic", "textured_plastic", "plain_weave", "knit", "velvet", "linen",
                 "leather", "marble", "granite", "concrete", "terrazzo", "square_tile",
                 "hex_tile", "herringbone_tile", "subway_tile", "plaster", "brick",
                 "striped_wallpaper", "damask_wallpaper", "geometric_wallpaper", "carpet",
                 "paper", "cardboard", "book_cover", "rubber", "cork", "slate"):
        assert name in NAMES


@pytest.mark.parametrize("name", NAMES)
def test_generator_declares_family_density_and_documented_params(name):
    gen = get_material(name)
    assert gen.name == name
    assert gen.family in FAMILIES
    assert 100.0 <= gen.density <= 22000.0
    assert gen.params, "a material should expose at least one parameter"
    for k, p in gen.params.items():
        assert p.doc, f"{name}.{k} has no doc"
        assert p.describe()
    sampled = gen.sample_params(np.random.default_rng(0))
    assert set(sampled) == set(gen.params)
    assert gen.validate_params(sampled) == sampled


def test_tile_size_gives_a_true_scale_repeat():
    for name in NAMES:
        m = maps(name, 0)
        assert 0.01 <= m.tile_size_m <= 5.0, (name, m.tile_size_m)
    # a brick wall texture spans whole bricks of 225 mm
    b = bake("brick", 0, 64, params={"bricks": 4})
    assert b.tile_size_m == pytest.approx(0.9)


def test_densities_are_physically_ordered():
    d = {n: get_material(n).density for n in NAMES}
    assert d["cork"] < d["pine_planks"] < d["oak"] < d["water"] < d["rubber"] < d["concrete"] \
        < d["granite"] < d["brushed_steel"] < d["brass"]


def test_unknown_material_raises_naming_valid_ones():
    with pytest.raises(UnknownGeneratorError, match="oak"):
        get_material("unobtainium")
    with pytest.raises(UnknownGeneratorError):
        bake("unobtainium", 0, 64)


def test_bad_params_and_resolution_raise_parameter_error():
    gen = get_material("oak")
    with pytest.raises(ParameterError, match="no parameter"):
        gen.generate({"sparkle": 1.0}, 64, 0)
    with pytest.raises(ParameterError):
        gen.generate({"ring_density": 1e6}, 64, 0)
    with pytest.raises(ParameterError):
        gen.generate({"finish": "lacquered_unicorn"}, 64, 0)
    with pytest.raises(ParameterError):
        bake("oak", 0, 64, params={"boards": 99})
    with pytest.raises(ParameterError):
        gen.generate({}, 4, 0)


def test_param_overrides_are_used_and_missing_ones_sampled():
    full = bake("brick", 5, 64)
    part = bake("brick", 5, 64, params={"color": "buff"})
    assert part.params["color"] == "buff"
    others = {k: v for k, v in full.params.items() if k != "color"}
    assert {k: part.params[k] for k in others} == others
    # bake(name, seed) == generate({}, res, seed): the same params are drawn either way
    assert np.array_equal(full.base_color, get_material("brick").generate({}, 64, 5).base_color)


# --------------------------------------------------------------------------- map contract

@pytest.mark.parametrize("name", NAMES)
def test_maps_have_right_shapes_dtypes_and_ranges(name):
    for seed in SEEDS:
        m = maps(name, seed)
        assert m.name == name and m.family == get_material(name).family
        assert m.base_color.shape == (RES, RES, 3) and m.base_color.dtype == np.float32
        assert m.roughness.shape == (RES, RES) and m.roughness.dtype == np.float32
        assert m.normal.shape == (RES, RES, 3) and m.normal.dtype == np.float32
        for arr in (m.base_color, m.roughness, m.normal):
            assert np.isfinite(arr).all()
            assert arr.min() >= 0.0 and arr.max() <= 1.0
        if m.metallic is not None:
            assert m.metallic.shape == (RES, RES) and m.metallic.dtype == np.float32
            assert m.metallic.min() >= 0.0 and m.metallic.max() <= 1.0
            assert m.metallic_value == pytest.approx(float(m.metallic.mean()), abs=1e-5)
        else:
            assert m.metallic_value == 0.0
        n = m.normal * 2.0 - 1.0
        length = np.linalg.norm(n, axis=-1)
        assert np.abs(length - 1.0).max() <= 0.02
        assert n[..., 2].min() > 0.0
        assert len(m.mean_color) == 3 and all(0.0 <= c <= 1.0 for c in m.mean_color)
        assert 0.0 <= m.mean_roughness <= 1.0
        assert 0.0 < m.opacity <= 1.0 and 1.0 <= m.ior <= 3.0


def test_metals_are_metallic_and_glass_is_transparent():
    for name in materials_in_family("metal"):
        m = maps(name, 0)
        assert m.metallic is not None, name
        if name != "painted_metal":  # paint is a dielectric; only chips are bare metal
            assert m.metallic_value > 0.3, name
    for name in ("clear_glass", "frosted_glass", "water"):
        assert maps(name, 0).opacity < 1.0
    assert maps("water", 0).ior == pytest.approx(1.33)
    assert maps("clear_glass", 0).opacity < maps("frosted_glass", 0).opacity
    assert maps("screen_glass", 0).opacity == 1.0
    for name in ("oak", "plain_weave", "concrete", "glossy_plastic", "leather"):
        assert maps(name, 0).metallic is None


def test_finishes_change_roughness():
    gloss = bake("oak", 1, 64, params={"finish": "gloss"}).mean_roughness
    matte = bake("oak", 1, 64, params={"finish": "matte"}).mean_roughness
    assert gloss + 0.2 < matte
    assert maps("chrome", 0).mean_roughness < 0.2 < maps("carpet", 0).mean_roughness


@pytest.mark.parametrize("name", NAMES)
def test_maps_tile_across_the_wrap_seam(name):
    group = [maps(name, seed) for seed in SEEDS]
    for kind in ("base_color", "roughness", "normal"):
        assert_tiles([getattr(m, kind) for m in group], f"{name} {kind} (seeds {SEEDS})")
    # and no single seed has a gross seam (a real one is many times the interior)
    for m, seed in zip(group, SEEDS, strict=True):
        for kind in ("base_color", "roughness", "normal"):
            for axis in (0, 1):
                seam, interior = seam_stats(getattr(m, kind), axis)
                assert seam <= 3.0 * interior + 1e-4, f"{name} seed {seed} {kind} axis {axis}"


def test_seam_check_catches_real_seams():
    """The tileability check is not vacuous: a non-periodic crop of a material, or a tiling map
    with its seam moved inside, fails it."""
    for name in ("oak", "marble"):
        big = maps(name, 0, 256)
        with pytest.raises(AssertionError):
            assert_tiles([big.base_color[:128, :128]], f"{name} crop")
    m = maps("oak", 1)
    with pytest.raises(AssertionError):  # truncated: columns 99 and 0 were never neighbours
        assert_tiles([m.base_color[:, :100]], "truncated")


@pytest.mark.parametrize("name", NAMES)
def test_generation_is_deterministic_and_seed_dependent(name):
    gen = get_material(name)
    a = maps(name, 0)
    b = gen.generate({}, RES, 0)
    for k in ("base_color", "roughness", "normal", "metallic"):
        x, y = getattr(a, k), getattr(b, k)
        assert (x is None) == (y is None)
        if x is not None:
            assert np.array_equal(x, y), k
    c = maps(name, 1)
    assert not np.array_equal(a.base_color, c.base_color) or not np.array_equal(a.normal, c.normal)


def test_tileable_at_a_second_resolution():
    for name in ("oak", "brick", "hex_tile", "herringbone_tile", "marble", "knit",
                 "damask_wallpaper", "patterned_rug", "terrazzo"):
        m = maps(name, 3, 256)
        assert m.base_color.shape == (256, 256, 3)
        assert_tiles(m.base_color, f"{name} @256")
        assert_tiles(m.normal, f"{name} @256 normal")


# --------------------------------------------------------------------------- bake and save

def test_bake_is_memoised_read_only_and_deterministic():
    a = bake("walnut", 7, 64)
    b = bake("walnut", 7, 64)
    assert a is b
    assert not a.base_color.flags.writeable
    with pytest.raises(ValueError):
        a.base_color[0, 0, 0] = 0.0
    fresh = get_material("walnut").generate(a.params, 64, 7)
    assert np.array_equal(a.base_color, fresh.base_color)
    assert np.array_equal(a.normal, fresh.normal)
    assert not np.array_equal(bake("walnut", 8, 64).base_color, a.base_color)


def test_save_maps_writes_pngs_pillow_reads_back(tmp_path):
    steel = bake("brushed_steel", 0, 64)
    paths = save_maps(steel, tmp_path / "tex", "steel")
    assert set(paths) == {"base_color", "roughness", "normal", "metallic"}
    assert paths["base_color"].name == "steel_basecolor.png"
    assert paths["normal"].name == "steel_normal.png"
    for kind, path in paths.items():
        with Image.open(path) as im:
            assert im.size == (64, 64)
            assert im.mode == ("RGB" if kind in ("base_color", "normal") else "L")
    with Image.open(paths["base_color"]) as im:
        back = np.asarray(im, np.float32) / 255.0
    assert np.abs(back - steel.base_color).max() <= 1.0 / 255.0 + 1e-6
    wood = save_maps(bake("oak", 0, 32), tmp_path, "oak")
    assert set(wood) == {"base_color", "roughness", "normal"}


# --------------------------------------------------------------------------- slots

def test_slot_choices_cover_required_slots_with_valid_materials():
    assert set(SLOT_CHOICES) >= REQUIRED_SLOTS
    valid = set(NAMES)
    for slot, choices in SLOT_CHOICES.items():
        assert choices and set(choices) <= valid, slot
        assert all(w > 0 for w in choices.values()), slot
    assert set(SLOT_CHOICES["screen"]) == {"screen_glass"}
    assert {"marble", "granite", "concrete"} <= set(SLOT_CHOICES["countertop"])


def test_choose_materials_is_valid_and_deterministic():
    slots = sorted(SLOT_CHOICES) + ["no_such_slot"]
    a = choose_materials(slots, np.random.default_rng(11))
    b = choose_materials(slots, np.random.default_rng(11))
    assert a == b
    assert set(a) == set(slots)
    for slot, mat in a.items():
        assert mat in SLOT_CHOICES.get(slot, SLOT_CHOICES["body"])
    seen = {choose_materials(["wood"], np.random.default_rng(s))["wood"] for s in range(40)}
    assert len(seen) > 1


def test_choose_materials_overrides_and_errors():
    rng = np.random.default_rng(0)
    out = choose_materials(["front", "body"], rng, overrides={"front": {"chrome": 1.0}})
    assert out["front"] == "chrome"
    with pytest.raises(UnknownGeneratorError):
        choose_materials(["front"], rng, overrides={"front": {"unobtainium": 1.0}})


# --------------------------------------------------------------------------- building blocks

NOISES = {
    "spectral": lambda res, rng: nz.spectral_noise(res, rng, knee=4.0, beta=1.5),
    "spectral_aniso": lambda res, rng: nz.spectral_noise(res, rng, knee=8.0, stretch=(10.0, 1.0),
                                                         angle=0.4),
    "band": lambda res, rng: nz.band_noise(res, rng, 12.0),
    "grain": nz.grain,
    "value": lambda res, rng: nz.value_noise(res, 6, rng),
    "gradient": lambda res, rng: nz.gradient_noise(res, 5, rng),
    "fbm": lambda res, rng: nz.fbm(res, rng, 3, 4),
    "worley": lambda res, rng: nz.worley(res, 7, rng).f1,
    "worley_border": lambda res, rng: nz.worley(res, 9, rng).border,
    "warped": lambda res, rng: nz.warp(nz.spectral_noise(res, rng, knee=5.0),
                                       *[0.05 * w for w in nz.warp_fields(res, rng)]),
    "blur": lambda res, rng: nz.blur(nz.spectral_noise(res, rng, knee=20.0), 0.02),
}


@pytest.mark.parametrize("kind", sorted(NOISES))
def test_noise_primitives_tile(kind):
    res = 96
    fields = [NOISES[kind](res, np.random.default_rng(s)) for s in range(4)]
    for f in fields:
        assert f.shape == (res, res) and f.dtype == np.float32, kind
        assert np.isfinite(f).all() and f.std() > 0, kind
    assert_tiles(fields, kind)
    again = NOISES[kind](res, np.random.default_rng(0))
    assert np.array_equal(again, fields[0])  # deterministic given the rng


def test_layouts_are_periodic_with_expected_tile_counts():
    res = 120
    g = nz.grid_layout(res, 4, 6)
    assert len(np.unique(g.tile)) == 24
    for ratio, rep in ((2, 1), (3, 2), (4, 1)):
        hb = nz.herringbone_layout(res, ratio, rep)
        period = 2 * ratio * rep  # plank widths per texture; each plank covers `ratio` cells
        assert len(np.unique(hb.tile)) == period * period // ratio
        assert hb.vertical is not None and abs(hb.vertical.mean() - 0.5) < 0.05
        assert np.all(hb.tile[hb.vertical] >= period * period)  # ids split by orientation
    hx = nz.hex_layout(res, 6)
    assert len(np.unique(hx.tile)) == hx.count
    for lay in (g, hb, hx):
        assert lay.edge.min() >= -1e-6
        mask = nz.joint_mask(lay.edge, 0.004, 0.004, res)
        assert_tiles(mask, "layout joints")
        assert_tiles(lay.tile.astype(np.float32) * 0 + mask, "mask")


def test_worley_matches_brute_force_on_the_torus():
    res, n = 48, 4
    c = nz.worley(res, n, np.random.default_rng(3), jitter=0.9)
    r = np.random.default_rng(3)
    jx = 0.5 + 0.9 * (r.random((n, n)) - 0.5)
    jy = 0.5 + 0.9 * (r.random((n, n)) - 0.5)
    # feature points sit in a grid shifted back by a quarter cell (see noise.worley)
    pts = np.stack([(np.arange(n)[None, :] + jx - 0.25).ravel() / n,
                    (np.arange(n)[:, None] + jy - 0.25).ravel() / n], axis=1)
    u = (np.arange(res) + 0.5) / res
    X, Y = np.meshgrid(u, u)
    dx = np.abs(X[..., None] - pts[:, 0])
    dy = np.abs(Y[..., None] - pts[:, 1])
    d = np.hypot(np.minimum(dx, 1 - dx), np.minimum(dy, 1 - dy)) * n
    ds = np.sort(d, axis=-1)
    assert np.allclose(c.f1, ds[..., 0], atol=1e-5)
    assert np.allclose(c.f2, ds[..., 1], atol=1e-5)
    assert (c.cell == d.argmin(axis=-1)).mean() > 0.999


def test_normal_map_convention():
    res = 64
    ramp_x = np.tile(np.linspace(0, 1, res, dtype=np.float32), (res, 1))
    n = normal_from_height(ramp_x, 1.0)[res // 2, res // 2] * 2 - 1
    assert n[0] < 0 and abs(n[1]) < 1e-6 and n[2] > 0  # rising to the right faces left
    rising_up = ramp_x.T[::-1].copy()  # height grows towards row 0 (image top, +Y)
    n = normal_from_height(rising_up, 1.0)[res // 2, res // 2] * 2 - 1
    assert n[1] < 0 and abs(n[0]) < 1e-6  # OpenGL: +Y up, so it faces -Y
    flat = normal_from_height(np.zeros((8, 8), np.float32), 1.0)
    assert np.allclose(flat, [0.5, 0.5, 1.0])
