"""What furniture holds (`programs.contents`): caps per piece of furniture that grow with the
scene's fullness and never undercut a room program's minimum, every room's program carrying
them, and a generated kitchen that puts things away inside its cabinets: wholly inside, touching
nothing, within reach."""
from __future__ import annotations

import numpy as np
import pytest

from indoorgen import GenerateConfig, generate
from indoorgen.constraints import ObjSet, scene
from indoorgen.constraints.bounds import find_bounds
from indoorgen.constraints.evaluator import Evaluator
from indoorgen.model.frames import yaw_matrix
from indoorgen.model.tags import Semantics as S
from indoorgen.programs import ROOM_PROGRAMS, get_program
from indoorgen.programs.contents import EVERYDAY, HOLDS, REACH_HEIGHT, cap, contents
from indoorgen.programs.relations import inside, on_floor, on_top
from indoorgen.validate import validate_scene
from support.fakeview import FakeView


def _bedroom_with_a_wardrobe():
    view = FakeView()
    view.add_room("r", [(0, 0), (4, 0), (4, 4), (0, 4)])
    view.add("wardrobe_0", {S.Object, S.Furniture, S.Storage, S.Wardrobe},
             center=(1, 1, 1), extents=(0.6, 1.6, 2.0), relations=[(on_floor, "r")])
    return view, scene()[S.Room].named("r")


@pytest.mark.parametrize("fullness", [0.3, 1.0, 1.6])
def test_a_wardrobe_holds_clothes_up_to_its_cap(fullness):
    view, room = _bedroom_with_a_wardrobe()
    ev = Evaluator(contents(room, fullness), view)
    assert ev.evaluate().violation == 0  # no lower bounds: an empty wardrobe is allowed
    bounds = {b.name: b for b in find_bounds(contents(room, fullness), ev)}
    clothes = bounds["wardrobes hold folded clothes"]
    load = next(ld for ld in HOLDS["wardrobes"] if ld.name == "folded clothes")
    assert clothes.hi == cap(load, fullness) and clothes.can_add
    assert clothes.parents == ((inside, ("wardrobe_0",)),)


def test_caps_grow_with_fullness_and_keep_room_minimums():
    for loads in HOLDS.values():
        for load in loads:
            caps = [cap(load, f) for f in (0.2, 0.6, 1.0, 1.4, 2.0)]
            assert caps == sorted(caps) and caps[0] >= load.least >= 1
    books = next(ld for ld in HOLDS["shelving"] if ld.name == "books")
    assert cap(books, 0.1) >= 8  # the living room asks for 8 books per bookcase at least


@pytest.mark.parametrize("room_type", sorted(ROOM_PROGRAMS))
def test_every_room_program_carries_the_contents(room_type):
    room = scene()[S.Room].named(f"{room_type}_0")
    problem = get_program(room_type, 0.8)(room)
    extra = contents(room, 0.8, room_type)
    assert set(extra.constraints) <= set(problem.constraints)
    assert set(extra.score_terms) <= set(problem.score_terms)
    assert get_program(room_type).__name__ == ROOM_PROGRAMS[room_type].__name__


def _world_box(gen, name):
    o = gen.scene.objects[name]
    v = gen.cache.full(o.generator, o.params).mesh.vertices @ yaw_matrix(o.pose.yaw).T
    v = v + np.asarray(o.pose.position)
    return v.min(axis=0), v.max(axis=0)


@pytest.mark.slow
def test_a_kitchen_puts_things_away_wholly_inside_touching_nothing():
    gen = generate(0, GenerateConfig(room_type="kitchen"))
    put_away = [o for o in gen.scene.objects.values()
                if any(r.relation == repr(inside) for r in o.relations)]
    assert len(put_away) >= 3
    for o in put_away:
        lo, hi = _world_box(gen, o.name)
        plo, phi = _world_box(gen, o.relations[0].parent)
        assert np.all(lo >= plo - 1e-3) and np.all(hi <= phi + 1e-3), o.name
    report = validate_scene(gen.scene)
    assert not report["interpenetrating"] and not report["unsupported"]
    assert gen.report["quality"]["measures"]["collision_rate"] == 0.0
    for o in gen.scene.objects.values():
        if S.SmallObject.value in o.tags and any(t.value in o.tags for t in EVERYDAY):
            floor = gen.scene.rooms[o.room].elevation
            assert o.pose.position[2] - floor <= REACH_HEIGHT, o.name


@pytest.mark.parametrize("tags,name,bound,relation", [
    ({S.Storage, S.Wardrobe}, "wardrobe_0", "wardrobes hold shoes", inside),
    ({S.Appliance, S.KitchenAppliance, S.Dishwasher}, "dishwasher_0", "dishwashers hold plates",
     inside),
    ({S.Storage, S.Nightstand}, "nightstand_0", "bedside cupboards hold books", inside),
    ({S.Storage, S.Shelf, S.ShoeRack}, "shoe_rack_0", "shoe racks hold shoes", on_top),
])
def test_shoes_dishes_and_books_are_put_away_where_they_belong(tags, name, bound, relation):
    view = FakeView()
    view.add_room("r", [(0, 0), (4, 0), (4, 4), (0, 4)])
    made = {"generator": "nightstand", "params": {"layout": "drawer_shelf"}} if (
        S.Nightstand in tags) else {}
    view.add(name, {S.Object, S.Furniture, *tags}, center=(1, 1, 0.4), extents=(0.6, 0.6, 0.8),
             relations=[(on_floor, "r")], **made)
    room = scene()[S.Room].named("r")
    ev = Evaluator(contents(room, 1.0), view)
    b = {b.name: b for b in find_bounds(contents(room, 1.0), ev)}[bound]
    assert b.can_add and b.lo <= 0 and b.parents == ((relation, (name,)),)


def _room_with_a_nightstand() -> tuple[FakeView, ObjSet]:
    """A 4 x 4 m room holding one nightstand of two drawers (nothing behind a door)."""
    view = FakeView()
    view.add_room("r", [(0, 0), (4, 0), (4, 4), (0, 4)])
    view.add("nightstand_0", {S.Object, S.Furniture, S.Storage, S.Nightstand},
             center=(1, 1, 0.3), extents=(0.4, 0.5, 0.6), relations=[(on_floor, "r")],
             generator="nightstand", params={"layout": "two_drawers"})
    room = scene()[S.Room].named("r")
    return view, room


def test_a_nightstand_of_drawers_only_holds_nothing_inside():
    view, room = _room_with_a_nightstand()
    ev = Evaluator(contents(room, 1.0), view)
    bounds = {b.name: b for b in find_bounds(contents(room, 1.0), ev)}
    assert not any(b.can_add for name, b in bounds.items() if name.startswith("bedside"))


def test_a_closet_s_shelves_hold_clothes_and_towels_not_books():
    """The same bookcase holds books and decor in a living room, and clothes, towels, shoes,
    boxes and baskets in a closet."""
    view = FakeView()
    view.add_room("r", [(0, 0), (2, 0), (2, 2), (0, 2)])
    view.add("bookcase_0", {S.Object, S.Furniture, S.Storage, S.Bookcase},
             center=(0.2, 1, 0.9), extents=(0.35, 0.8, 1.8), relations=[(on_floor, "r")])
    room = scene()[S.Room].named("r")
    for room_type, held, not_held in (("closet", "towels", "books"), ("living_room", "books", "towels")):
        problem = contents(room, 1.0, room_type)
        names = {b.name for b in find_bounds(problem, Evaluator(problem, view))}
        assert f"shelving hold {held}" in names and f"shelving hold {not_held}" not in names


def test_a_nightstand_top_holds_a_lamp_and_a_few_things_at_most():
    """A 0.4 m nightstand top holds at most five things at the usual fullness (it had held
    nine as a chest: a lamp, four decor, three books and a basket)."""
    view, room = _room_with_a_nightstand()
    problem = contents(room, 1.0)
    on_it = [b for b in find_bounds(problem, Evaluator(problem, view))
             if b.can_add and any(rel == on_top for rel, _ in b.parents)]
    assert on_it and all(b.name.startswith("nightstand tops") for b in on_it)
    assert sum(b.hi for b in on_it) <= 5


def test_a_garage_s_shelves_hold_stored_things_and_a_shoe_rack_is_no_garage_shelving():
    """Garage and utility shelving holds boxes, baskets and shoes, not books and ornaments;
    the garage's shelving, which must hold a box, is never a shoe rack (whose tiers hold none)."""
    view = FakeView()
    view.add_room("r", [(0, 0), (3, 0), (3, 5), (0, 5)])
    view.add("cell_shelf_0", {S.Object, S.Furniture, S.Storage, S.Shelf, S.CellShelf},
             center=(0.2, 1, 0.6), extents=(0.35, 1.0, 1.2), relations=[(on_floor, "r")])
    room = scene()[S.Room].named("r")
    for room_type in ("garage", "utility"):
        problem = contents(room, 1.0, room_type)
        names = {b.name for b in find_bounds(problem, Evaluator(problem, view))}
        assert "shelving hold boxes" in names and "shelving hold books" not in names
    garage = get_program("garage")(room)
    shelving = [b for b in find_bounds(garage, Evaluator(garage, view)) if b.name == "shelving"]
    assert shelving and all(S.ShoeRack in b.context.excluded for b in shelving)
