"""Scalar expressions: arithmetic, functions, reductions over sets, and their errors."""
import math

import numpy as np
import pytest

from indoorgen.constraints import scene
from indoorgen.constraints.scalars import Const, as_scalar
from indoorgen.errors import ConstraintError
from indoorgen.model.tags import Semantics as S
from support.dsl import dining_view, value


def test_arithmetic_and_functions():
    v = dining_view()
    n = scene()[S.Chair].count()  # 4
    assert value(v, n + 1) == 5 and value(v, 2 * n - 1) == 7 and value(v, n / 2) == 2
    assert value(v, 1 - n) == -3 and value(v, 8 / n) == 2
    assert value(v, n ** 2) == 16 and value(v, abs(n - 10)) == 6 and value(v, -n) == -4
    assert value(v, (n - 10).abs()) == 6
    assert value(v, (n - 4).safediv(0, default=7.0)) == 7.0
    assert value(v, n.log()) == pytest.approx(math.log(4))
    assert value(v, n.clip(0, 3)) == 3
    assert value(v, n.hinge(1, 2)) == 2 and value(v, n.hinge(6, 8)) == 2 and value(v, n.hinge(3, 5)) == 0


def test_reductions_over_a_set():
    v = dining_view()
    tables, chairs = scene()[S.DiningTable], scene()[S.Chair]
    assert value(v, chairs.sum(lambda c: c.count())) == 4
    assert value(v, chairs.mean(lambda c: c.count() * 2)) == 2
    # chair centre 1 m from the table centre: 1 - 0.6 (table half) - 0.25 (chair half depth)
    assert value(v, chairs.max(lambda c: c.distance(tables))) == pytest.approx(0.15, abs=1e-6)
    assert value(v, scene()[S.Sofa].sum(lambda s: s.count())) == 0.0  # empty: 0


def test_numbers_become_constants():
    assert isinstance(as_scalar(2), Const) and as_scalar(np.float32(1.5)).value == 1.5
    x = scene().count()
    assert as_scalar(x) is x
    with pytest.raises(ConstraintError):
        as_scalar(True)
    with pytest.raises(ConstraintError):
        as_scalar("3")


def test_bad_scalar_expressions_raise_constraint_errors():
    n = scene().count()
    with pytest.raises(ConstraintError, match="in_range"):
        n.in_range(5, 2)
    with pytest.raises(ConstraintError):
        n.hinge(3, 1)
    with pytest.raises(ConstraintError):
        n.clip(3, 1)
    with pytest.raises(ConstraintError, match="safediv"):
        value(dining_view(), n / 0)


def test_score_terms_carry_weight_and_direction():
    n = scene().count()
    low, high = n.minimize(2), n.maximize()
    assert (low.expr, low.weight, low.sign) == (n, 2.0, 1.0)
    assert (high.weight, high.sign) == (1.0, -1.0)


@pytest.mark.parametrize("make", [lambda n: n.in_range(float("nan"), 2), lambda n: n.in_range(0, math.inf),
                                  lambda n: n.hinge(-math.inf, 1), lambda n: n <= float("nan"),
                                  lambda n: n.minimize(math.nan), lambda n: n + math.inf])
def test_bounds_and_constants_must_be_finite(make):
    """A NaN bound would make every comparison false: refused where the program is written."""
    with pytest.raises(ConstraintError, match="must be a finite number"):
        make(scene()[S.Chair].count())
