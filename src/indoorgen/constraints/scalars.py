"""Scalar nodes: real-valued expressions, their arithmetic, counts and reductions over sets.

Scalars combine with the ordinary operators (`2 * n - 1`, `abs(x)`), compare into constraints
(`n <= 4`, `x.in_range(1, 2)`) and become soft score terms with `minimize` / `maximize`.
"""
from __future__ import annotations

import math
from typing import Any, TypeAlias

import numpy as np

from indoorgen.constraints.logic import Compare, Constraint, InRange
from indoorgen.constraints.node import Env, EvalContext, Node
from indoorgen.errors import ConstraintError

#: What scalar operators accept: a scalar expression or a plain number.
ScalarLike: TypeAlias = "Scalar | float | np.integer[Any] | np.floating[Any]"


def as_scalar(x: ScalarLike) -> Scalar:
    """`x` as a scalar expression: numbers become constants (anything else is an error)."""
    if isinstance(x, Scalar):
        return x
    return Const(finite(x, "a constant"))


def finite(x: Any, what: str) -> float:
    """`x` as a float, or ConstraintError naming `what` unless it is a finite number."""
    if isinstance(x, (int, float, np.integer, np.floating)) and not isinstance(x, bool) \
            and math.isfinite(x):
        return float(x)
    raise ConstraintError(f"{what} must be a finite number, got {x!r}")


class Scalar(Node[float]):
    """A real-valued expression."""

    def __add__(self, o: ScalarLike) -> Scalar: return BinOp("+", self, as_scalar(o))
    def __radd__(self, o: ScalarLike) -> Scalar: return BinOp("+", as_scalar(o), self)
    def __sub__(self, o: ScalarLike) -> Scalar: return BinOp("-", self, as_scalar(o))
    def __rsub__(self, o: ScalarLike) -> Scalar: return BinOp("-", as_scalar(o), self)
    def __mul__(self, o: ScalarLike) -> Scalar: return BinOp("*", self, as_scalar(o))
    def __rmul__(self, o: ScalarLike) -> Scalar: return BinOp("*", as_scalar(o), self)
    def __truediv__(self, o: ScalarLike) -> Scalar: return BinOp("/", self, as_scalar(o))
    def __rtruediv__(self, o: ScalarLike) -> Scalar: return BinOp("/", as_scalar(o), self)
    def __pow__(self, o: ScalarLike) -> Scalar: return BinOp("pow", self, as_scalar(o))
    def __neg__(self) -> Scalar: return BinOp("*", Const(-1.0), self)
    def __abs__(self) -> Scalar: return UnOp("abs", self)

    def safediv(self, o: ScalarLike, default: float = 0.0) -> Scalar:
        """Division that yields `default` where the divisor is 0."""
        return BinOp("safediv", self, as_scalar(o), default)

    def log(self) -> Scalar:
        """Natural logarithm (of at least 1e-12, so 0 stays finite)."""
        return UnOp("log", self)

    def abs(self) -> Scalar:
        """Absolute value (the same as `abs(x)`)."""
        return UnOp("abs", self)

    def clip(self, lo: float, hi: float) -> Scalar:
        """The value clamped into [lo, hi]."""
        if lo > hi:
            raise ConstraintError(f"clip({lo}, {hi}): lower bound exceeds upper bound")
        return UnOp("clip", self, (float(lo), float(hi)))

    def hinge(self, lo: float, hi: float) -> Scalar:
        """0 inside [lo, hi], growing linearly outside it."""
        lo, hi = finite(lo, "hinge's lower bound"), finite(hi, "hinge's upper bound")
        if lo > hi:
            raise ConstraintError(f"hinge({lo:g}, {hi:g}): lower bound exceeds upper bound")
        return UnOp("hinge", self, (lo, hi))

    # comparisons -> constraints
    def __le__(self, o: ScalarLike) -> Constraint: return Compare("<=", self, as_scalar(o))
    def __ge__(self, o: ScalarLike) -> Constraint: return Compare(">=", self, as_scalar(o))
    def __lt__(self, o: ScalarLike) -> Constraint: return Compare("<", self, as_scalar(o))
    def __gt__(self, o: ScalarLike) -> Constraint: return Compare(">", self, as_scalar(o))

    def __eq__(self, o: ScalarLike) -> Constraint:  # type: ignore[override]
        return Compare("==", self, as_scalar(o))

    __hash__ = Node.__hash__

    def in_range(self, lo: float, hi: float) -> Constraint:
        """The constraint `lo <= self <= hi`."""
        lo, hi = finite(lo, "in_range's lower bound"), finite(hi, "in_range's upper bound")
        if lo > hi:
            raise ConstraintError(f"in_range({lo:g}, {hi:g}): the lower bound exceeds the upper; "
                                  "write in_range(low, high) with low <= high")
        return InRange(self, lo, hi)

    def minimize(self, weight: float = 1.0) -> ScoreTerm:
        """A score term that rewards a smaller value, weighted by `weight`."""
        return ScoreTerm(self, finite(weight, "minimize's weight"), +1.0)

    def maximize(self, weight: float = 1.0) -> ScoreTerm:
        """A score term that rewards a larger value, weighted by `weight`."""
        return ScoreTerm(self, finite(weight, "maximize's weight"), -1.0)


class Const(Scalar):
    """A number."""

    def __init__(self, value: float):
        super().__init__()
        self.value = float(value)

    def compute(self, ev: EvalContext, env: Env) -> float:
        """The number."""
        return self.value

    def label(self) -> str:
        """The number, shortest form."""
        return f"{self.value:g}"


def _binop(op: str, a: float, b: float, default: float) -> float:
    if op == "+":
        return a + b
    if op == "-":
        return a - b
    if op == "*":
        return a * b
    if op == "/":
        if b == 0:
            raise ConstraintError("division by zero in a constraint program; use safediv")
        return a / b
    if op == "safediv":
        return a / b if b != 0 else default
    if op == "pow":
        p: float = float(a) ** b
        return p
    raise ValueError(op)


class BinOp(Scalar):
    """`a <op> b` for op in +, -, *, /, safediv (`default` where b is 0) and pow."""

    def __init__(self, op: str, a: Scalar, b: Scalar, default: float = 0.0):
        super().__init__(a, b)
        self.op, self.default = op, default

    def compute(self, ev: EvalContext, env: Env) -> float:
        """The operation applied to the two operands' values."""
        return _binop(self.op, ev.get(self.children[0], env), ev.get(self.children[1], env),
                      self.default)

    def label(self) -> str:
        """The operator."""
        return self.op


class UnOp(Scalar):
    """`op(a)` for op in abs, log, clip and hinge (the last two with `args` = (lo, hi))."""

    def __init__(self, op: str, a: Scalar, args: tuple[float, ...] = ()):
        super().__init__(a)
        self.op, self.args = op, args

    def compute(self, ev: EvalContext, env: Env) -> float:
        """The function applied to the operand's value."""
        x: float = ev.get(self.children[0], env)
        if self.op == "abs":
            return abs(x)
        if self.op == "log":
            return math.log(max(x, 1e-12))
        lo, hi = self.args
        if self.op == "clip":
            return min(max(x, lo), hi)
        if self.op == "hinge":
            return max(0.0, lo - x) + max(0.0, x - hi)
        raise ValueError(self.op)

    def label(self) -> str:
        """The function's name."""
        return self.op


class Count(Scalar):
    """The number of members of a set."""

    def __init__(self, objs: Node[frozenset[str]]):
        super().__init__(objs)

    def compute(self, ev: EvalContext, env: Env) -> float:
        """The set's size."""
        return float(len(ev.get(self.children[0], env)))


class Reduce(Scalar):
    """sum / mean / max of `body` over the members of a set (0 for an empty set)."""

    def __init__(self, kind: str, objs: Node[frozenset[str]], var: Node[frozenset[str]],
                 body: Scalar):
        super().__init__(objs, body)
        self.kind, self.var = kind, var
        self.__dict__["_fv"] = objs.free_vars | (body.free_vars - {var.uid})

    def compute(self, ev: EvalContext, env: Env) -> float:
        """The reduction of the body's values, members taken in name order."""
        members: frozenset[str] = ev.get(self.children[0], env)
        vals: list[float] = [ev.get(self.children[1], {**env, self.var.uid: m})
                             for m in sorted(members)]
        if not vals:
            return 0.0
        if self.kind == "sum":
            return float(math.fsum(vals))
        if self.kind == "mean":
            return float(math.fsum(vals) / len(vals))
        return float(max(vals))

    def label(self) -> str:
        """`sum`, `mean` or `max`."""
        return self.kind


class ScoreTerm:
    """A soft term: `expr` weighted, minimised (sign +1) or maximised (sign -1)."""

    def __init__(self, expr: Scalar, weight: float, sign: float):
        if not isinstance(expr, Scalar):
            raise ConstraintError("minimize/maximize apply to scalar expressions")
        self.expr, self.weight, self.sign = expr, weight, sign
