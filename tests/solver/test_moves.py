"""Each move keeps the State consistent, stays within the object's degrees of freedom, carries
what rests on a moved object along, and is undone exactly; a refused move changes nothing."""
from __future__ import annotations

import numpy as np
import pytest
import shapely.geometry as sg

from indoorgen.assets import get_factory
from indoorgen.constraints import Problem, scene
from indoorgen.constraints.relations import CONTACT_GAP
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart
from indoorgen.programs.relations import hung_from, on_floor, on_top
from indoorgen.solver.moves import MOVES, MoveContext, MoveOutcome
from indoorgen.solver.placement import placements_hold, planar
from support.solverscene import (
    ROOM,
    assert_consistent,
    child_frame,
    floor,
    make_state,
    move_context,
    put,
    snapshot,
    top_of,
    wall,
)


def _scene():
    """Two tables (one with a plate), a picture on wall_0: every stage has something to move."""
    st = make_state(5.0, 4.0)
    t1 = put(st, "dining_table_rect", floor(), (1.5, 2.0))
    t2 = put(st, "dining_table_rect", floor(), (3.6, 2.0), seed=1)
    plate = put(st, "plate", top_of(t1), (1.5, 2.0), stage="small")
    art = put(st, "wall_art", wall(0), (2.5, 0.0, 1.5), stage="medium")
    return st, t1, t2, plate, art


def _apply(ctx: MoveContext, move: str) -> MoveOutcome | None:
    """Run a move and tell the evaluator, as the annealer does."""
    out = MOVES[move](ctx)
    if out is not None:
        ctx.ev.notify(out.changed, added=out.added, removed=out.removed, relinked=out.relinked)
    return out


def _undo(ctx: MoveContext, out: MoveOutcome) -> None:
    out.undo()
    ctx.ev.notify(out.changed, added=out.removed, removed=out.added, relinked=out.relinked)


def _on_their_planes(st, names) -> None:
    for n in names:
        ob = st.objects[n]
        for p in ob.placements:
            parent = st.surface_world(p.parent, p.parent_surface)
            child = st.surface_world(n, p.child_surface)
            d = float(np.dot(child.origin - parent.origin, parent.normal)) - planar(p.relation).margin
            assert d == pytest.approx(CONTACT_GAP, abs=1e-9), (n, p)
        assert placements_hold(st, n)


@pytest.mark.parametrize("move", sorted(MOVES))
@pytest.mark.parametrize("stage", ["large", "medium", "small"])
def test_a_move_keeps_the_state_consistent_and_its_undo_restores_it_exactly(move, stage):
    st, *_ = _scene()
    applied = 0
    for seed in range(6):
        ctx = move_context(st, stage, seed)
        before = snapshot(st)
        out = _apply(ctx, move)
        if out is None:
            assert snapshot(st) == before  # a refused move leaves nothing behind
            continue
        applied += 1
        assert_consistent(st)
        touched = set(out.changed) | set(out.added)
        assert touched <= set(st.objects)
        assert all(st.objects[n].stage == stage for n in out.changed[:1] + out.added)
        assert not any(st.collides(n) for n in touched)
        _on_their_planes(st, touched)
        _undo(ctx, out)
        assert snapshot(st) == before
        assert_consistent(st)
    if move in ("translate", "reinit") or (move, stage) in {("rotate", "large"), ("add", "medium"),
                                                           ("add", "small")}:
        assert applied, "the move never applied on a scene where it can"


def test_translate_on_the_floor_keeps_height_and_yaw_and_carries_the_plate():
    st, t1, _, plate, _ = _scene()
    ob = st.objects[t1]
    z, yaw, rel = ob.position[2], ob.yaw, child_frame(st, plate, t1)
    moved = 0
    for seed in range(10):
        ctx = move_context(st, "large", seed, temperature=0.05)
        start = st.objects[t1].position.copy()
        out = _apply(ctx, "translate")
        if out is None or t1 not in out.changed:
            continue
        moved += 1
        assert out.changed == (t1, plate)
        assert st.objects[t1].position[2] == z and st.objects[t1].yaw == yaw
        assert not np.array_equal(st.objects[t1].position, start)
        np.testing.assert_allclose(child_frame(st, plate, t1)[0], rel[0], atol=1e-12)
        assert child_frame(st, plate, t1)[1] == pytest.approx(rel[1])
    assert moved


def test_translate_on_a_wall_keeps_the_wall_normal_coordinate():
    st, *_, art = _scene()
    y, yaw = st.objects[art].position[1], st.objects[art].yaw
    moved = 0
    for seed in range(10):
        out = _apply(move_context(st, "medium", seed, temperature=0.05), "translate")
        if out is None:
            continue
        moved += 1
        assert st.objects[art].position[1] == pytest.approx(y, abs=1e-12)
        assert st.objects[art].yaw == yaw
    assert moved


def test_rotate_changes_only_the_yaw_and_turns_the_plate_with_the_table():
    st, t1, _, plate, _ = _scene()
    rel = child_frame(st, plate, t1)
    turned = 0
    for seed in range(12):
        before = st.objects[t1].position.copy(), st.objects[t1].yaw
        out = _apply(move_context(st, "large", seed), "rotate")
        if out is None or t1 not in out.changed:
            continue
        turned += 1
        np.testing.assert_array_equal(st.objects[t1].position[:2], before[0][:2])
        assert st.objects[t1].position[2] == pytest.approx(before[0][2], abs=1e-12)
        assert st.objects[t1].yaw != before[1]
        np.testing.assert_allclose(child_frame(st, plate, t1)[0], rel[0], atol=1e-9)
    assert turned


def test_rotate_refuses_an_object_its_planes_fix():
    st, *_ = _scene()
    before = snapshot(st)  # the medium stage has only the picture, whose wall fixes its yaw
    assert all(_apply(move_context(st, "medium", s), "rotate") is None for s in range(5))
    assert snapshot(st) == before


def test_reassign_plane_moves_to_another_surface_of_the_same_role():
    st, *_, art = _scene()
    done = 0
    for seed in range(10):
        ctx = move_context(st, "medium", seed)
        old = st.objects[art].placements[0].parent_surface
        out = _apply(ctx, "reassign_plane")
        if out is None:
            continue
        done += 1
        p = st.objects[art].placements[0]
        assert p.parent_surface != old and p.parent == ROOM
        assert st.surface_world(ROOM, p.parent_surface).subpart == Subpart.Wall
        _on_their_planes(st, [art])
        assert out.relinked == ()  # same parent
    assert done


def test_add_puts_a_new_object_on_a_parent_the_program_allows_and_undo_leaves_no_trace():
    st, t1, t2, *_ = _scene()
    ids, snap = st.all_ids(), snapshot(st)
    bp_names = sorted(st.broadphase[ROOM]._pieces)
    ctx = move_context(st, "small", 0)
    out = next(o for o in (_apply(ctx, "add") for _ in range(10)) if o is not None)
    (name,) = out.added
    ob = st.objects[name]
    assert S.Plate in ob.tags and ob.stage == "small" and ob.context is not None
    assert ob.placements[0].parent in (t1, t2)
    _undo(ctx, out)
    assert st.all_ids() == ids and snapshot(st) == snap
    assert sorted(st.broadphase[ROOM]._pieces) == bp_names
    assert name not in st.children(t1) | st.children(t2)
    assert_consistent(st)


def test_reassign_parent_moves_an_object_to_another_allowed_parent():
    st, t1, t2, *_ = _scene()
    room = scene()[S.Room].named(ROOM)
    tables = scene().related_to(room, on_floor)[S.DiningTable]
    plates_on_tables = Problem(constraints={  # any table will do: both are candidate parents
        "plates": scene()[S.Plate].related_to(tables, on_top).count().in_range(0, 6)})
    ctx = move_context(st, "small", 1, plates_on_tables)
    added = next(o for o in (_apply(ctx, "add") for _ in range(10)) if o is not None)
    (plate,) = added.added
    for seed in range(20):
        ctx = move_context(st, "small", seed, plates_on_tables)
        old = st.objects[plate].placements[0].parent
        out = _apply(ctx, "reassign_parent")
        if out is None or plate not in out.changed:
            continue
        new = st.objects[plate].placements[0].parent
        assert {old, new} == {t1, t2}
        assert set(out.relinked) == {t1, t2}
        assert plate in st.children(new) and plate not in st.children(old)
        _on_their_planes(st, [plate])
        assert_consistent(st)
        _undo(ctx, out)
        assert st.objects[plate].placements[0].parent == old
        assert plate in st.children(old) and plate not in st.children(new)
        assert_consistent(st)
        return
    pytest.fail("no reassign_parent applied")


def test_delete_spares_objects_something_rests_on_and_counts_at_their_minimum():
    st, t1, t2, plate, art = _scene()
    for seed in range(10):
        ctx = move_context(st, "large", seed)
        out = _apply(ctx, "delete")
        assert out is not None and out.removed == (t2,)  # t1 holds the plate
        _undo(ctx, out)
    st.remove(t2)
    assert _apply(move_context(st, "large", 0), "delete") is None  # one table is the minimum
    assert _apply(move_context(st, "medium", 0), "delete") is None  # one picture is the minimum


def test_resample_gives_new_params_and_undo_restores_the_old_asset():
    st, t1, t2, *_ = _scene()
    for seed in range(10):
        ctx = move_context(st, "large", seed)
        before = {n: (dict(st.objects[n].params), st.objects[n].asset) for n in (t1, t2)}
        out = _apply(ctx, "resample")
        if out is None:
            continue
        (name,) = out.changed
        assert name == t2  # t1 holds the plate: new params would mean new surfaces
        assert st.objects[name].params != before[name][0]
        _undo(ctx, out)
        assert st.objects[name].params == before[name][0]
        assert st.objects[name].asset is before[name][1]
        return
    pytest.fail("no resample applied")


def test_moves_table_names_every_move_function():
    assert set(MOVES) == {"add", "delete", "resample", "reinit", "reassign_plane",
                          "reassign_parent", "translate", "rotate"}
    assert all(fn.__name__ == name for name, fn in MOVES.items())


def _chairs_program() -> tuple[Problem, object]:
    """Chairs on the floor of `ROOM`, declared a matching set."""
    room = scene()[S.Room].named(ROOM)
    chairs = scene().related_to(room, on_floor)[S.DiningChair]
    return Problem(constraints={"chairs": chairs.count().in_range(0, 4)},
                   matching={"chairs": chairs}), chairs


def _design(st, n: str) -> tuple:
    ob = st.objects[n]
    return ob.generator, repr(sorted(ob.params.items())), ob.seed


def test_add_copies_the_design_of_a_matching_set_member():
    st = make_state(5.0, 4.0)
    first = put(st, "dining_chair", floor(), (1.0, 1.0), seed=7, name="first")
    problem, _ = _chairs_program()
    added = []
    ctx = move_context(st, "large", 0, problem)
    for _ in range(20):
        out = _apply(ctx, "add")
        if out is not None:
            added += out.added
    assert added, "no chair added"
    assert {_design(st, n) for n in [first, *added]} == {_design(st, first)}
    assert_consistent(st)


def test_resample_changes_a_matching_set_together_and_undo_restores_every_member():
    st = make_state(5.0, 4.0)
    a = put(st, "dining_chair", floor(), (1.0, 1.0), seed=3)
    b = put(st, "dining_chair", floor(), (3.5, 2.5), seed=3)
    problem, _ = _chairs_program()
    before = {n: _design(st, n) for n in (a, b)}
    for seed in range(20):
        ctx = move_context(st, "large", seed, problem)
        out = _apply(ctx, "resample")
        if out is None:
            continue
        assert set(out.changed) == {a, b}
        assert _design(st, a) == _design(st, b) != before[a]
        _on_their_planes(st, [a, b])
        _undo(ctx, out)
        assert {n: _design(st, n) for n in (a, b)} == before
        assert_consistent(st)
        return
    pytest.fail("no resample applied")


def test_add_gives_an_object_the_params_its_context_fixes():
    st = make_state(5.0, 4.0)
    room = scene()[S.Room].named(ROOM)
    beds = scene().related_to(room, on_floor).of_generator("bed", drawers=False)
    problem = Problem(constraints={"a bed": beds.count() == 1})
    for seed in range(10):
        out = _apply(move_context(st, "large", seed, problem), "add")
        if out is not None:
            (name,) = out.added
            assert st.objects[name].params["drawers"] is False
            return
    pytest.fail("no bed added")


def test_pick_weighted_draws_equal_weights_as_pick_does():
    st = make_state(5.0, 4.0)
    a, b = move_context(st, "small", 3), move_context(st, "small", 3)
    items = ["x", "y", "z", "w"]
    assert [a.pick_weighted(items, [1.0] * 4) for _ in range(50)] == \
        [b.pick(items) for _ in range(50)]


def test_add_draws_small_decor_by_its_generators_frequency():
    """Over the generators `add` chooses among for decor on furniture, each comes up in
    proportion to its `frequency`: table clocks are rare, photo frames common."""
    st = make_state(5.0, 4.0)
    ctx = move_context(st, "small", 7)
    gens = ctx.generators(frozenset({S.Decor, S.SmallObject}), frozenset({S.Book, S.Balloon}))
    assert {"photo_frame", "sculpture", "decor_bowl", "table_clock", "candle"} <= set(gens)
    weights = [get_factory(g).frequency for g in gens]
    n = 4000
    drawn = [ctx.pick_weighted(gens, weights) for _ in range(n)]
    for g, w in zip(gens, weights, strict=True):
        expected = n * w / sum(weights)
        assert abs(drawn.count(g) - expected) < 4 * np.sqrt(expected), g
    assert drawn.count("table_clock") * 5 < drawn.count("photo_frame")


def test_add_fills_a_bookcase_with_things_wholly_on_its_shelves_and_clear_of_each_other():
    """Boxes, baskets and books put on shelving land where they fit: whole on a shelf, under the
    shelf above, beside what is there; a thing too big for the shelf drawn gets another draw."""
    st = make_state(5.0, 4.0)
    case = put(st, "bookcase", floor(), (2.5, 2.0))
    cases = scene().related_to(scene()[S.Room].named(ROOM), on_floor)[S.Bookcase]
    problem = Problem(constraints={kind: scene()[tag].related_to(cases, on_top).count() <= 12
                                   for kind, tag in (("books", S.Book), ("boxes", S.Box),
                                                     ("baskets", S.Basket))})
    ctx = move_context(st, "small", 2, problem)
    added = [n for _ in range(30) if (out := _apply(ctx, "add")) for n in out.added]
    assert len(added) >= 12
    for n in added:
        assert placements_hold(st, n) and not st.collides(n), n
        (p,) = st.objects[n].placements
        shelf = st.surface_world(case, p.parent_surface)
        corners = st.footprint(n).exterior.coords
        assert all(shelf.polygon.buffer(1e-6).contains(
            sg.Point(np.dot(np.subtract(c, shelf.origin[:2]), shelf.u[:2]),
                     np.dot(np.subtract(c, shelf.origin[:2]), shelf.v[:2]))) for c in corners), n
    assert_consistent(st)


def test_add_hangs_clothes_from_a_wardrobes_rail():
    """Garments on hangers are added on the wardrobe's rail, across it and clear of each other
    (a rail's top is a level surface, but no outline fits on it: what hangs is placed by its
    hook, not by its footprint)."""
    st = make_state(5.0, 4.0)
    put(st, "wardrobe", floor(), (2.5, 2.0))
    wardrobes = scene().related_to(scene()[S.Room].named(ROOM), on_floor)[S.Wardrobe]
    problem = Problem(constraints={
        "hung clothes": scene()[S.Garment].related_to(wardrobes, hung_from).count() <= 8})
    ctx = move_context(st, "small", 3, problem)
    added = [n for _ in range(20) if (out := _apply(ctx, "add")) for n in out.added]
    assert len(added) >= 4
    for n in added:
        (p,) = st.objects[n].placements
        assert p.parent_surface.startswith("rail_")
        assert placements_hold(st, n) and not st.collides(n), n
    assert_consistent(st)
