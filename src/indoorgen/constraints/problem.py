"""`Problem`: one room's constraint program, named hard constraints and named soft score terms,
the matching sets whose members share one design, and the dressing hung at its windows."""
from __future__ import annotations

from indoorgen.constraints.logic import Constraint
from indoorgen.constraints.scalars import ScoreTerm
from indoorgen.constraints.sets import ObjSet
from indoorgen.errors import ConstraintError


class Problem:
    """Named hard constraints, named soft score terms and named matching sets: one room's
    constraint program. A matching set (the chairs at a table, the nightstands at a bed) is a set
    whose members the solver makes alike: one generator, params and material seed. The language
    knows no windows: `window_dressing` names the generator (a curtain) the solver hangs at each
    of the room's windows once its furniture stands (`solver.window_dressing`), or None."""

    def __init__(self, constraints: dict[str, Constraint] | None = None,
                 score_terms: dict[str, ScoreTerm] | None = None,
                 matching: dict[str, ObjSet] | None = None,
                 window_dressing: str | None = None):
        self.constraints = dict(constraints or {})
        self.score_terms = dict(score_terms or {})
        self.matching = dict(matching or {})
        self.window_dressing = window_dressing
        for name, c in self.constraints.items():
            if not isinstance(c, Constraint):
                raise ConstraintError(f"constraint {name!r} is not a constraint expression "
                                      f"(got {type(c).__name__}); use in_range, <=, == ...")
        for name, t in self.score_terms.items():
            if not isinstance(t, ScoreTerm):
                raise ConstraintError(f"score term {name!r} must be expr.minimize() or "
                                      f".maximize(), got {type(t).__name__}")
        for name, s in self.matching.items():
            if not isinstance(s, ObjSet) or s.free_vars:
                raise ConstraintError(f"matching set {name!r} must be an object set outside "
                                      f"any loop (got {type(s).__name__})")

    def __add__(self, other: Problem) -> Problem:
        return Problem({**self.constraints, **other.constraints},
                       {**self.score_terms, **other.score_terms},
                       {**self.matching, **other.matching},
                       other.window_dressing or self.window_dressing)
