"""`Problem`: one room's constraint program, named hard constraints and named soft score terms."""
from __future__ import annotations

from indoorgen.constraints.logic import Constraint
from indoorgen.constraints.scalars import ScoreTerm
from indoorgen.errors import ConstraintError


class Problem:
    """Named hard constraints and named soft score terms: one room's constraint program."""

    def __init__(self, constraints: dict[str, Constraint] | None = None,
                 score_terms: dict[str, ScoreTerm] | None = None):
        self.constraints = dict(constraints or {})
        self.score_terms = dict(score_terms or {})
        for name, c in self.constraints.items():
            if not isinstance(c, Constraint):
                raise ConstraintError(f"constraint {name!r} is not a constraint expression "
                                      f"(got {type(c).__name__}); use in_range, <=, == ...")
        for name, t in self.score_terms.items():
            if not isinstance(t, ScoreTerm):
                raise ConstraintError(f"score term {name!r} must be expr.minimize() or "
                                      f".maximize(), got {type(t).__name__}")

    def __add__(self, other: Problem) -> Problem:
        return Problem({**self.constraints, **other.constraints},
                       {**self.score_terms, **other.score_terms})
