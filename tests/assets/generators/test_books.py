"""Book groups (book_stack, leaning_books): the stack's top is its top cover, the leaning book
leans on the row. These checks came with the kitchenware tests; the generators are the books
family's."""
from __future__ import annotations

from indoorgen.assets.catalogue import factories_with
from indoorgen.model.tags import Semantics
from support.assetcheck import build, distances, sample_polygon
from support.generatorcheck import check_material_choices, check_small_objects

NAMES = ["book_stack", "leaning_books"]
SEEDS = range(5)


def test_catalogue_lists_every_kind():
    check_small_objects(NAMES)
    assert set(NAMES) <= set(factories_with([Semantics.Book]))


def test_material_choices_name_real_materials():
    check_material_choices(NAMES)


def test_book_stack_top_is_the_top_cover():
    for seed in SEEDS:
        f, p, _, a = build("book_stack", seed)
        specs = f._specs(p)
        expect = sum(s.params["thickness"] for s in specs) - (len(specs) - 1) * 0.001
        top = a.surface("top")
        assert abs(top.origin[2] - expect) < 1e-9
        assert abs(a.extents[2] - expect) < 1e-6
        assert distances(a.mesh, top.to_world(sample_polygon(top.polygon))).max() < 1e-3


def test_leaning_book_leans_against_the_row():
    for seed in SEEDS:
        f, p, _, a = build("leaning_books", seed)
        books = f._books(p)
        upright = sum(b["thickness"] for b in books[:-1])
        assert a.extents[2] <= max(b["height"] for b in books) + 1e-6
        # the leaning book takes more room than it would upright
        assert a.extents[1] > upright + books[-1]["thickness"]
        assert a.mesh.body_count == 1
