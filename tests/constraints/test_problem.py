"""`Problem`: named constraints and score terms, checked when built, combined with `+`."""
import pytest

from indoorgen.constraints import Problem, rotational_asymmetry, scene
from indoorgen.constraints.evaluator import Evaluator
from indoorgen.errors import ConstraintError
from indoorgen.model.tags import Semantics as S
from support.dsl import dining_view


def test_bad_problems_raise_constraint_errors():
    n = scene().count()
    with pytest.raises(ConstraintError):
        Problem(constraints={"x": n})
    with pytest.raises(ConstraintError):
        Problem(score_terms={"x": n})


def test_problem_result_loss_and_violations():
    v = dining_view()
    chairs = scene()[S.Chair]
    p = Problem(constraints={"few": chairs.count() <= 3, "ok": chairs.count() >= 1},
                score_terms={"many": chairs.count().maximize(2.0),
                             "sym": rotational_asymmetry(chairs).minimize(1.0)})
    r = Evaluator(p, v).evaluate()
    assert r.violations == {"few": 1.0, "ok": 0.0}
    assert r.n_violated == 1 and r.violation == 1.0
    assert r.loss == pytest.approx(-8.0)


def test_problems_add_up_later_names_winning():
    n = scene().count()
    a = Problem({"x": n <= 1, "y": n >= 0}, {"s": n.minimize()})
    b = Problem({"x": n <= 2}, {"t": n.maximize()})
    both = a + b
    assert list(both.constraints) == ["x", "y"] and both.constraints["x"] is b.constraints["x"]
    assert list(both.score_terms) == ["s", "t"]
