"""Constraint nodes: comparisons, ranges, and/or/not and for-all over a set.

A constraint's value is its *degree of violation*: 0.0 when satisfied, growing with how badly it
fails, so the solver can tell a near miss from a wild one. Constraints are built from scalars
(`count() <= 4`, `x.in_range(1, 2)`) and combined with `&`, `|` and `~`.
"""
from __future__ import annotations

import math

from indoorgen.constraints.node import Env, EvalContext, Node


class Constraint(Node[float]):
    """A hard requirement; combine with `&` (both), `|` (either) and `~` (not)."""

    def __and__(self, o: Constraint) -> Constraint:
        return BoolOp("and", self, o)

    def __or__(self, o: Constraint) -> Constraint:
        return BoolOp("or", self, o)

    def __invert__(self) -> Constraint:
        return BoolNot(self)


class Compare(Constraint):
    """`a <op> b` for op in <=, >=, <, >, ==; violated by how far a is on the wrong side."""

    def __init__(self, op: str, a: Node[float], b: Node[float]):
        super().__init__(a, b)
        self.op = op

    def compute(self, ev: EvalContext, env: Env) -> float:
        """The violation: the gap by which a misses b (plus 1 mm for strict comparisons)."""
        a: float = ev.get(self.children[0], env)
        b: float = ev.get(self.children[1], env)
        op = self.op
        if op == "<=":
            return max(0.0, a - b)
        if op == ">=":
            return max(0.0, b - a)
        if op == "<":
            return 0.0 if a < b else (a - b) + 1e-3
        if op == ">":
            return 0.0 if a > b else (b - a) + 1e-3
        return abs(a - b)

    def label(self) -> str:
        """The operator."""
        return self.op


class InRange(Constraint):
    """`lo <= x <= hi`; violated by how far x lies outside the range."""

    def __init__(self, x: Node[float], lo: float, hi: float):
        super().__init__(x)
        self.lo, self.hi = lo, hi

    def compute(self, ev: EvalContext, env: Env) -> float:
        """The distance from x to the range (0 inside it)."""
        x: float = ev.get(self.children[0], env)
        return max(0.0, self.lo - x) + max(0.0, x - self.hi)

    def label(self) -> str:
        """`in_range(lo,hi)`."""
        return f"in_range({self.lo:g},{self.hi:g})"


class BoolOp(Constraint):
    """`a & b` (violations add up) or `a | b` (the smaller violation counts)."""

    def __init__(self, op: str, a: Constraint, b: Constraint):
        super().__init__(a, b)
        self.op = op

    def compute(self, ev: EvalContext, env: Env) -> float:
        """The sum ("and") or the minimum ("or") of the two violations."""
        a: float = ev.get(self.children[0], env)
        b: float = ev.get(self.children[1], env)
        return a + b if self.op == "and" else min(a, b)


class BoolNot(Constraint):
    """`~c`: violated (1.0) exactly when c is satisfied."""

    def compute(self, ev: EvalContext, env: Env) -> float:
        """1.0 if the inner constraint holds, else 0.0."""
        return 1.0 if ev.get(self.children[0], env) == 0.0 else 0.0


class ForAll(Constraint):
    """`objs.all(lambda o: body)`: the body must hold for every member; violations add up."""

    def __init__(self, objs: Node[frozenset[str]], var: Node[frozenset[str]], body: Constraint):
        super().__init__(objs, body)
        self.var = var
        self.__dict__["_fv"] = objs.free_vars | (body.free_vars - {var.uid})

    def compute(self, ev: EvalContext, env: Env) -> float:
        """The sum of the body's violations over the members, in name order."""
        members: frozenset[str] = ev.get(self.children[0], env)
        return float(math.fsum(ev.get(self.children[1], {**env, self.var.uid: m})
                               for m in sorted(members)))

    def label(self) -> str:
        """`all`."""
        return "all"


def all_of(*cs: Constraint) -> Constraint:
    """Every one of `cs` (their violations add up)."""
    out = cs[0]
    for c in cs[1:]:
        out = out & c
    return out
