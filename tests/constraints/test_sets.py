"""Set expressions: tag filters, unions, differences, relations, names, generators."""
import pytest

from indoorgen.constraints import Not, scene
from indoorgen.errors import ConstraintError, UnknownGeneratorError
from indoorgen.model.tags import Semantics as S
from support.dsl import at_table, dining_view, on_floor, value


def test_sets_filter_union_difference_related():
    v = dining_view()
    v.add("sofa", {S.Furniture, S.Seating, S.Sofa}, (1, 4, 0.4), relations=[(on_floor, "r")])
    furn = scene()[S.Furniture]
    assert value(v, furn.count()) == 6
    assert value(v, furn[S.Chair].count()) == 4
    assert value(v, furn[Not(S.Chair)].count()) == 2
    assert value(v, furn.excluding(S.Chair, S.Sofa).count()) == 1
    assert value(v, (furn[S.Sofa] | furn[S.Table]).count()) == 2
    assert value(v, (furn - furn[S.Seating]).count()) == 1
    table = furn[S.DiningTable]
    assert value(v, furn.related_to(table, at_table).count()) == 4
    assert value(v, furn.related_to(scene()[S.Room], on_floor).count()) == 6
    assert value(v, scene()[S.Room].named("r").count()) == 1
    assert value(v, furn.related_to(table, ~at_table).count()) == 0


def test_sets_evaluate_to_names():
    v = dining_view()
    assert value(v, scene()[S.Chair]) == frozenset(f"chair{i}" for i in range(4))
    assert value(v, scene().named("nobody")) == frozenset()


def test_of_generator_checks_the_name_and_filters_by_generator():
    v = dining_view()
    v.objs["chair0"]["generator"] = "dining_chair"
    assert value(v, scene()[S.Chair].of_generator("dining_chair")) == frozenset({"chair0"})
    with pytest.raises(UnknownGeneratorError, match="no_such_thing"):
        scene().of_generator("no_such_thing")


def test_bad_set_expressions_raise_constraint_errors():
    with pytest.raises(ConstraintError, match="Semantics"):
        scene()[3.5]
    with pytest.raises(ConstraintError, match="Relation"):
        scene().related_to(scene(), "on the floor")
    with pytest.raises(ConstraintError, match="constraint"):
        scene().all(lambda o: o.count())


def test_loop_variables_key_the_cache_of_what_reads_them():
    chairs = scene()[S.Chair]
    body = chairs.related_to(scene()[S.Room], on_floor).count()
    per_chair = chairs.sum(lambda c: c.distance(scene()[S.DiningTable]))
    assert body.free_vars == frozenset() and per_chair.free_vars == frozenset()
    inner = per_chair.children[1]
    assert len(inner.free_vars) == 1 and inner.key_vars == tuple(inner.free_vars)


def test_of_generator_with_params_filters_by_them_and_rejects_unknown_params():
    v = dining_view()
    v.objs["chair0"].update(generator="bed", params={"drawers": False})
    v.objs["chair1"].update(generator="bed", params={"drawers": True})
    plain = scene().of_generator("bed", drawers=False)
    assert value(v, plain) == frozenset({"chair0"})
    assert value(v, scene().of_generator("bed")) == frozenset({"chair0", "chair1"})
    with pytest.raises(ConstraintError, match="no_such_param"):
        scene().of_generator("bed", no_such_param=1)
