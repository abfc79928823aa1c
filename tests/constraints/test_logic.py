"""Constraints evaluate to a degree of violation: 0 when satisfied, growing with the miss."""
from indoorgen.constraints import all_of, scene
from indoorgen.model.tags import Semantics as S
from support.dsl import at_table, dining_view, value


def test_comparisons_and_ranges():
    v = dining_view()
    n = scene()[S.Chair].count()  # 4
    assert value(v, n.in_range(2, 3)) == 1.0 and value(v, n.in_range(4, 8)) == 0.0
    assert value(v, n <= 2) == 2 and value(v, n >= 6) == 2 and value(v, n == 4) == 0
    assert value(v, n < 4) > 0 and value(v, n > 3) == 0
    assert value(v, 2 >= n) == 2  # noqa: SIM300 (reflected: n <= 2)


def test_and_or_not():
    v = dining_view()
    n = scene()[S.Chair].count()
    assert value(v, (n <= 2) & (n >= 6)) == 4
    assert value(v, (n <= 2) | (n >= 6)) == 2
    assert value(v, ~(n == 4)) == 1.0 and value(v, ~(n == 3)) == 0.0
    assert value(v, all_of(n <= 2, n >= 6, n == 4)) == 4


def test_for_all_adds_up_each_members_violation():
    v = dining_view()
    tables, chairs = scene()[S.DiningTable], scene()[S.Chair]
    assert value(v, tables.all(lambda t: chairs.related_to(t, at_table).count().in_range(6, 8))) == 2
    assert value(v, chairs.all(lambda c: c.count() == 1)) == 0
    assert value(v, scene()[S.Sofa].all(lambda s: s.count() == 5)) == 0  # empty: holds
