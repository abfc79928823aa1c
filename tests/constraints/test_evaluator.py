"""Incremental evaluation: same values as a full evaluation, while recomputing only what a move
touches."""
import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from indoorgen.constraints.evaluator import Evaluator
from indoorgen.model.tags import Semantics as S
from support.dsl import at_table, base_view, on_floor, on_top, program, room


def test_moving_one_object_recomputes_few_nodes_and_matches_full():
    v = base_view()
    for i in range(6):
        v.add(f"t{i}", {S.Furniture, S.Table}, (1 + i, 1, 0.4), extents=(0.8, 0.8, 0.75),
              relations=[(on_floor, "r")])
        for k in range(3):
            v.add(f"c{i}_{k}", {S.Furniture, S.Chair}, (1 + i + 0.3 * k, 2, 0.4), yaw=-math.pi / 2,
                  extents=(0.4, 0.4, 0.9), relations=[(on_floor, "r"), (at_table, f"t{i}")])
    ev = Evaluator(program(room()), v, check=True)
    ev.evaluate()
    n_full = ev.recomputed
    before = ev.recomputed
    v.move("c3_1", center=(4.4, 2.2, 0.4))
    ev.notify(["c3_1"])
    ev.evaluate()
    moved_cost = ev.recomputed - before
    assert 0 < moved_cost < n_full / 4
    # deleting is incremental too
    before = ev.recomputed
    del v.objs["c5_2"]
    ev.notify(removed=["c5_2"])
    ev.evaluate()
    assert ev.recomputed - before < n_full / 2


def test_objects_taken_out_and_put_back_unseen_are_watched_again():
    """A solve set aside and restored (a stage's repair keeping the better of two solves):
    objects removed and added back before any evaluation. Their per-object entries are built
    again, and everything reading them must know the new ones: a chair moved afterwards
    re-evaluates its table's terms (once it did not, and the solver saw a stale triangle)."""
    v = base_view()
    for i in range(3):
        v.add(f"t{i}", {S.Furniture, S.Table}, (1 + 2 * i, 1, 0.4), extents=(0.8, 0.8, 0.75),
              relations=[(on_floor, "r")])
        v.add(f"c{i}", {S.Furniture, S.Chair}, (1 + 2 * i, 1.6, 0.4), yaw=-math.pi / 2,
              extents=(0.4, 0.4, 0.9), relations=[(on_floor, "r"), (at_table, f"t{i}")])
    ev = Evaluator(program(room()), v, check=True)  # every evaluation checked against a full one
    ev.evaluate()
    aside = {n: v.objs.pop(n) for n in ("t1", "c1")}
    ev.notify(removed=list(aside))
    v.objs.update(aside)
    ev.notify(added=list(aside))
    ev.evaluate()
    for step in range(4):
        v.move("c1", center=(3.0 + 0.7 * step, 1.6 + 0.9 * step, 0.4))
        ev.notify(["c1"])
        ev.evaluate()


def test_unrelated_move_recomputes_nothing():
    v = base_view()
    v.add("t", {S.Furniture, S.Table}, (2, 2, 0.4), relations=[(on_floor, "r")])
    v.add("lamp", {S.Decor}, (5, 5, 0.4))
    ev = Evaluator(program(room()), v)
    ev.evaluate()
    before = ev.recomputed
    v.move("lamp", center=(6, 5, 0.4))
    ev.notify(["lamp"])
    ev.evaluate()
    assert ev.recomputed == before


ops = st.lists(st.tuples(st.sampled_from(["table", "chair", "cup", "move", "delete", "relink"]),
                         st.integers(0, 10**6)), min_size=1, max_size=30)


@settings(max_examples=60, deadline=None)
@given(ops)
def test_incremental_equals_full_for_random_edit_sequences(seq):
    v = base_view()
    ev = Evaluator(program(room()), v, check=True)
    ev.evaluate()
    for n, (op, r) in enumerate(seq):
        rng = np.random.default_rng(r)
        tables = sorted(k for k, o in v.objs.items() if S.Table in o["tags"])
        names = sorted(v.objs)
        pos = (float(rng.uniform(0, 8)), float(rng.uniform(0, 6)), 0.4)
        if op == "table":
            name = f"t{n}"
            v.add(name, {S.Furniture, S.Table}, pos, yaw=float(rng.uniform(-3, 3)),
                  relations=[(on_floor, "r")])
            ev.notify(added=[name])
        elif op in ("chair", "cup") and tables:
            name = f"{op}{n}"
            parent = tables[int(rng.integers(len(tables)))]
            if op == "chair":
                v.add(name, {S.Furniture, S.Chair}, pos, yaw=float(rng.uniform(-3, 3)),
                      extents=(0.4, 0.4, 0.9), relations=[(on_floor, "r"), (at_table, parent)])
            else:
                v.add(name, {S.Cup}, pos, extents=(0.1, 0.1, 0.1), relations=[(on_top, parent)])
            ev.notify(added=[name])
        elif op == "move" and names:
            name = names[int(rng.integers(len(names)))]
            v.move(name, center=pos, yaw=float(rng.uniform(-3, 3)))
            ev.notify([name])
        elif op == "relink" and len(tables) > 1:
            # a chair or cup moved to another table (the solver's reassign-parent move)
            kids = sorted(k for k, o in v.objs.items() if len(o["relations"]) and
                          o["relations"][-1][1] in tables)
            if kids:
                name = kids[int(rng.integers(len(kids)))]
                rels = v.objs[name]["relations"]
                old_parent = rels[-1][1]
                new_parent = tables[int(rng.integers(len(tables)))]
                v.objs[name]["relations"] = rels[:-1] + [(rels[-1][0], new_parent)]
                v.move(name, center=pos)
                ev.notify([name], relinked=[old_parent, new_parent])
        elif op == "delete" and names:
            name = names[int(rng.integers(len(names)))]
            # deleting a table orphans its children's relations; that is fine for the DSL
            del v.objs[name]
            ev.notify(removed=[name])
        inc = ev.evaluate()   # check=True compares against a full evaluation
        full = Evaluator(program(room()), v).evaluate()
        assert inc.violations == full.violations
        assert all(abs(inc.scores[k] - full.scores[k]) < 1e-9 for k in full.scores)
