"""The constraint DSL: expression nodes over sets of objects, scalars and constraints.

A program builds a graph of these nodes with ordinary Python operators and methods::

    chairs = scene()[Semantics.Chair].related_to(room, on_floor)
    chairs.count().in_range(2, 8)

Nodes only describe computations; `evaluator.Evaluator` runs them against a solver state, caching
each node's value per binding of its loop variables. Set nodes evaluate to frozensets of object
names, scalar nodes to floats, and constraint (boolean) nodes to a *degree of violation*: 0.0 when
satisfied, growing with how badly they fail. Every node is immutable once built.
"""
from __future__ import annotations

import itertools
import math
from typing import TYPE_CHECKING, Any, Callable, Iterable

import numpy as np

from indoorgen.constraints.relations import Relation
from indoorgen.errors import ConstraintError
from indoorgen.model.tags import Semantics

if TYPE_CHECKING:  # pragma: no cover
    from indoorgen.constraints.evaluator import Evaluation

_ids = itertools.count()


class Node:
    """Base of all expression nodes. `children` are evaluated in the same loop bindings."""

    children: tuple["Node", ...] = ()

    def __init__(self, *children: "Node"):
        self.uid = next(_ids)
        self.children = tuple(children)

    __hash__ = object.__hash__

    @property
    def free_vars(self) -> frozenset[int]:
        """Loop variables this node's value depends on (so its cache key includes them)."""
        fv = self.__dict__.get("_fv")
        if fv is None:
            fv = frozenset().union(*(c.free_vars for c in self.children)) if self.children else frozenset()
            self.__dict__["_fv"] = fv
        return fv

    @property
    def key_vars(self) -> tuple[int, ...]:
        """`free_vars` in a fixed order: the loop bindings that key this node's cache entries."""
        kv = self.__dict__.get("_kv")
        if kv is None:
            kv = self.__dict__["_kv"] = tuple(sorted(self.free_vars))
        return kv

    def compute(self, ev: "Evaluation", env: dict[int, str]) -> Any:  # pragma: no cover
        raise NotImplementedError

    def label(self) -> str:
        return type(self).__name__


# ---------------------------------------------------------------------------------------------
# Object sets


class TagNot:
    """A negated tag inside `objs[...]`: `objs[Not(Semantics.Rug)]`."""

    def __init__(self, tag):
        self.tag = tag


def Not(tag) -> TagNot:
    return TagNot(tag)


class ObjSet(Node):
    """A set of objects (and rooms): filter, combine, relate and measure it."""

    def __getitem__(self, tags) -> "ObjSet":
        if not isinstance(tags, tuple):
            tags = (tags,)
        inc = frozenset(t for t in tags if not isinstance(t, TagNot))
        exc = frozenset(t.tag for t in tags if isinstance(t, TagNot))
        for t in inc | exc:
            if not isinstance(t, (Semantics, str)):
                raise ConstraintError(f"objs[...] takes Semantics tags, got {t!r}")
        return Tagged(self, inc, exc)

    def excluding(self, *tags) -> "ObjSet":
        return self[tuple(Not(t) for t in tags)]

    def of_generator(self, name: str) -> "ObjSet":
        """Members made by generator `name` (checked now: an unknown name is an error)."""
        from indoorgen.assets import get_factory
        get_factory(name)
        return FromGenerator(self, name)

    def named(self, name: str) -> "ObjSet":
        return Named(self, name)

    def __or__(self, other: "ObjSet") -> "ObjSet":
        return SetUnion(self, other)

    def __sub__(self, other: "ObjSet") -> "ObjSet":
        return SetDifference(self, other)

    def related_to(self, parents: "ObjSet", relation: Relation) -> "ObjSet":
        if not isinstance(relation, Relation):
            raise ConstraintError(f"related_to needs a Relation, got {relation!r}")
        return RelatedTo(self, parents, relation)

    # scalars over the set
    def count(self) -> "Scalar":
        return Count(self)

    def volume(self, dims: Iterable[int] = (0, 1, 2)) -> "Scalar":
        return volume(self, dims)

    def area(self) -> "Scalar":
        return area(self)

    def distance(self, other: "ObjSet") -> "Scalar":
        """Smallest 2D (plan view) distance between the two sets; a room counts as its walls."""
        return Distance(self, other)

    def min_distance(self, other: "ObjSet") -> "Scalar":
        """Smallest 3D mesh-to-mesh distance between the two sets."""
        return MinDistance(self, other)

    # quantifiers
    def all(self, fn: Callable[["ObjSet"], "Constraint"]) -> "Constraint":
        var, body = _bind(fn)
        if not isinstance(body, Constraint):
            raise ConstraintError("all(...) needs a lambda returning a constraint")
        return ForAll(self, var, body)

    def sum(self, fn: Callable[["ObjSet"], "Scalar"]) -> "Scalar":
        var, body = _bind(fn)
        return Reduce("sum", self, var, _scalar(body))

    def mean(self, fn: Callable[["ObjSet"], "Scalar"]) -> "Scalar":
        var, body = _bind(fn)
        return Reduce("mean", self, var, _scalar(body))

    def max(self, fn: Callable[["ObjSet"], "Scalar"]) -> "Scalar":
        var, body = _bind(fn)
        return Reduce("max", self, var, _scalar(body))


class SceneSet(ObjSet):
    def compute(self, ev, env):
        ev.watch_membership()
        return ev.view.all_ids()

    def label(self):
        return "scene()"


def scene() -> ObjSet:
    """Every object (and room) in the scene: the leaf of all set expressions."""
    return SceneSet()


class Tagged(ObjSet):
    def __init__(self, child: ObjSet, include: frozenset, exclude: frozenset):
        super().__init__(child)
        self.include, self.exclude = include, exclude

    def compute(self, ev, env):
        view = ev.view
        inc, exc = self.include, self.exclude
        return frozenset(o for o in ev.get(self.children[0], env)
                         if inc <= view.tags(o) and not (exc & view.tags(o)))

    def label(self):
        return "[" + ",".join(sorted(getattr(t, "value", str(t)) for t in self.include)) + "]"


class FromGenerator(ObjSet):
    def __init__(self, child: ObjSet, name: str):
        super().__init__(child)
        self.name = name

    def compute(self, ev, env):
        return frozenset(o for o in ev.get(self.children[0], env)
                         if ev.view.generator(o) == self.name)

    def label(self):
        return f"generator({self.name})"


class Named(ObjSet):
    def __init__(self, child: ObjSet, name: str):
        super().__init__(child)
        self.name = name

    def compute(self, ev, env):
        s = ev.get(self.children[0], env)
        return frozenset([self.name]) if self.name in s else frozenset()

    def label(self):
        return f"named({self.name})"


class SetUnion(ObjSet):
    def compute(self, ev, env):
        return ev.get(self.children[0], env) | ev.get(self.children[1], env)


class SetDifference(ObjSet):
    def compute(self, ev, env):
        return ev.get(self.children[0], env) - ev.get(self.children[1], env)


class RelatedTo(ObjSet):
    def __init__(self, child: ObjSet, parents: ObjSet, relation: Relation):
        super().__init__(child, parents)
        self.relation = relation

    def compute(self, ev, env):
        objs = ev.get(self.children[0], env)
        parents = ev.get(self.children[1], env)
        # which objects relate to the parents: poses don't matter, so a move never re-computes
        # this; a changed set of objects (input version) or a reassigned parent does
        ev.watch_children(parents)
        rel, view = self.relation, ev.view
        related = set().union(*(view.children(p) for p in parents)) & objs if parents else set()
        return frozenset(o for o in related
                         if any(p in parents and r.implies(rel) for r, p in view.relations(o)))

    def label(self):
        return f"related_to({self.relation!r})"


class Var(ObjSet):
    """A loop variable: the single object bound by an enclosing all/sum/mean/max."""

    def __init__(self):
        super().__init__()
        self.__dict__["_fv"] = frozenset([self.uid])

    def compute(self, ev, env):
        return frozenset([env[self.uid]])

    def label(self):
        return f"var{self.uid}"


def _bind(fn: Callable) -> tuple[Var, Node]:
    var = Var()
    return var, fn(var)


# ---------------------------------------------------------------------------------------------
# Scalars


def _scalar(x) -> "Scalar":
    if isinstance(x, Scalar):
        return x
    if isinstance(x, (int, float, np.integer, np.floating)) and not isinstance(x, bool):
        return Const(float(x))
    raise ConstraintError(f"expected a scalar expression or number, got {x!r}")


class Scalar(Node):
    """A real-valued expression."""

    def __add__(self, o): return BinOp("+", self, _scalar(o))
    def __radd__(self, o): return BinOp("+", _scalar(o), self)
    def __sub__(self, o): return BinOp("-", self, _scalar(o))
    def __rsub__(self, o): return BinOp("-", _scalar(o), self)
    def __mul__(self, o): return BinOp("*", self, _scalar(o))
    def __rmul__(self, o): return BinOp("*", _scalar(o), self)
    def __truediv__(self, o): return BinOp("/", self, _scalar(o))
    def __rtruediv__(self, o): return BinOp("/", _scalar(o), self)
    def __pow__(self, o): return BinOp("pow", self, _scalar(o))
    def __neg__(self): return BinOp("*", Const(-1.0), self)
    def __abs__(self): return UnOp("abs", self)

    def safediv(self, o, default: float = 0.0) -> "Scalar":
        """Division that yields `default` where the divisor is 0."""
        return BinOp("safediv", self, _scalar(o), default)

    def log(self) -> "Scalar":
        return UnOp("log", self)

    def abs(self) -> "Scalar":
        return UnOp("abs", self)

    def clip(self, lo: float, hi: float) -> "Scalar":
        if lo > hi:
            raise ConstraintError(f"clip({lo}, {hi}): lower bound exceeds upper bound")
        return UnOp("clip", self, (float(lo), float(hi)))

    def hinge(self, lo: float, hi: float) -> "Scalar":
        """0 inside [lo, hi], growing linearly outside it."""
        if lo > hi:
            raise ConstraintError(f"hinge({lo}, {hi}): lower bound exceeds upper bound")
        return UnOp("hinge", self, (float(lo), float(hi)))

    # comparisons -> constraints
    def __le__(self, o): return Compare("<=", self, _scalar(o))
    def __ge__(self, o): return Compare(">=", self, _scalar(o))
    def __lt__(self, o): return Compare("<", self, _scalar(o))
    def __gt__(self, o): return Compare(">", self, _scalar(o))

    def __eq__(self, o):  # type: ignore[override]
        return Compare("==", self, _scalar(o))

    __hash__ = Node.__hash__

    def in_range(self, lo: float, hi: float) -> "Constraint":
        if lo > hi:
            raise ConstraintError(f"in_range({lo}, {hi}): the lower bound exceeds the upper; "
                                  "write in_range(low, high) with low <= high")
        return InRange(self, float(lo), float(hi))

    def minimize(self, weight: float = 1.0) -> "ScoreTerm":
        return ScoreTerm(self, float(weight), +1.0)

    def maximize(self, weight: float = 1.0) -> "ScoreTerm":
        return ScoreTerm(self, float(weight), -1.0)


class Const(Scalar):
    def __init__(self, value: float):
        super().__init__()
        self.value = float(value)

    def compute(self, ev, env):
        return self.value

    def label(self):
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
        return float(a) ** b
    raise ValueError(op)


class BinOp(Scalar):
    def __init__(self, op: str, a: Scalar, b: Scalar, default: float = 0.0):
        super().__init__(a, b)
        self.op, self.default = op, default

    def compute(self, ev, env):
        return _binop(self.op, ev.get(self.children[0], env), ev.get(self.children[1], env),
                      self.default)

    def label(self):
        return self.op


class UnOp(Scalar):
    def __init__(self, op: str, a: Scalar, args: tuple = ()):
        super().__init__(a)
        self.op, self.args = op, args

    def compute(self, ev, env):
        x = ev.get(self.children[0], env)
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

    def label(self):
        return self.op


class Count(Scalar):
    def __init__(self, objs: ObjSet):
        super().__init__(objs)

    def compute(self, ev, env):
        return float(len(ev.get(self.children[0], env)))


class Reduce(Scalar):
    """sum / mean / max of `body` over the members of a set (0 for an empty set)."""

    def __init__(self, kind: str, objs: ObjSet, var: Var, body: Scalar):
        super().__init__(objs, body)
        self.kind, self.var = kind, var
        self.__dict__["_fv"] = objs.free_vars | (body.free_vars - {var.uid})

    def compute(self, ev, env):
        vals = [ev.get(self.children[1], {**env, self.var.uid: m})
                for m in sorted(ev.get(self.children[0], env))]
        if not vals:
            return 0.0
        if self.kind == "sum":
            return float(math.fsum(vals))
        if self.kind == "mean":
            return float(math.fsum(vals) / len(vals))
        return float(max(vals))

    def label(self):
        return self.kind


class GeometricTerm(Scalar):
    """A scalar computed from the geometry of its sets' members; it watches every member so a
    move of any of them re-evaluates it."""

    def members(self, ev, env) -> list[frozenset]:
        sets = [ev.get(c, env) for c in self.children]
        for s in sets:
            ev.watch(s)
        return sets


class Volume(GeometricTerm):
    def __init__(self, objs, dims):
        super().__init__(objs)
        self.dims = dims

    def compute(self, ev, env):
        from indoorgen.constraints import geometry
        (s,) = self.members(ev, env)
        if not s:
            return 0.0
        return geometry.bbox_volume(np.array([ev.view.extents(o) for o in sorted(s)]), self.dims)


class Area(GeometricTerm):
    def compute(self, ev, env):
        from indoorgen.constraints import geometry
        (s,) = self.members(ev, env)
        if not s:
            return 0.0
        return geometry.bbox_area(np.array([ev.view.extents(o) for o in sorted(s)]))


class Distance(GeometricTerm):
    def compute(self, ev, env):
        a, b = self.members(ev, env)
        best = math.inf
        for x in sorted(a):
            gx = ev.view.outline(x)
            for y in sorted(b):
                if y != x:
                    best = min(best, gx.distance(ev.view.outline(y)))
        return best if best < math.inf else 0.0


class MinDistance(GeometricTerm):
    def compute(self, ev, env):
        from indoorgen.constraints import geometry
        a, b = self.members(ev, env)
        best = math.inf
        for x in sorted(a):
            others = [ev.view.world_mesh(y) for y in sorted(b) if y != x]
            if others:
                best = min(best, geometry.min_distance([ev.view.world_mesh(x)], others))
        return best if best < math.inf else 0.0


def _nearest(ev, o: str, candidates: Iterable[str]) -> str | None:
    c = ev.view.center(o)[:2]
    best, arg = math.inf, None
    for y in sorted(candidates):
        if y == o:
            continue
        d = float(np.linalg.norm(ev.view.center(y)[:2] - c))
        if d < best:
            best, arg = d, y
    return arg


class AngleAlignment(GeometricTerm):
    def compute(self, ev, env):
        from indoorgen.constraints import geometry
        a, ref = self.members(ev, env)
        total = 0.0
        for o in sorted(a):
            r = _nearest(ev, o, ref) if len(ref) != 1 else next(iter(ref))
            if r is None or r == o:
                continue
            total += geometry.angle_alignment_cost(ev.view.front(o)[None, :2],
                                                   ev.view.center(o)[None, :2],
                                                   ev.view.footprint(r))
        return total


class Focus(GeometricTerm):
    def compute(self, ev, env):
        from indoorgen.constraints import geometry
        a, ref = self.members(ev, env)
        total = 0.0
        for o in sorted(a):
            r = _nearest(ev, o, ref)
            if r is None:
                continue
            total += geometry.focus_score(ev.view.center(o)[None, :2], ev.view.front(o)[None, :2],
                                          ev.view.center(r)[:2])
        return total


class Accessibility(GeometricTerm):
    def __init__(self, a, b, fast: bool = True):
        super().__init__(a, b)
        self.fast = fast

    def compute(self, ev, env):
        from indoorgen.constraints import geometry
        a, b = self.members(ev, env)
        v = ev.view
        total = 0.0
        for o in sorted(a):
            blockers = [y for y in sorted(b) if y != o]
            if not blockers:
                continue
            n = v.front(o)
            c = v.center(o)
            fp = v.front_point(o)
            if self.fast:
                total += geometry.accessibility_cost_fast(
                    c[None], n[None], fp[None], np.array([v.center(y) for y in blockers]),
                    np.array([float(np.linalg.norm(v.extents(y))) for y in blockers]))
            else:
                total += geometry.accessibility_cost_slow(
                    [v.world_mesh(o)], n[None], fp[None], [v.world_mesh(y) for y in blockers])
        return total


class RotationalAsymmetry(GeometricTerm):
    def compute(self, ev, env):
        from indoorgen.constraints import geometry
        (s,) = self.members(ev, env)
        if len(s) < 2:
            return 0.0
        objs = sorted(s)
        return geometry.rotational_asymmetry(np.array([ev.view.center(o)[:2] for o in objs]),
                                             np.array([ev.view.front(o)[:2] for o in objs]))


class ReflectionalAsymmetry(GeometricTerm):
    def compute(self, ev, env):
        from indoorgen.constraints import geometry
        s, ref = self.members(ev, env)
        if not s or not ref:
            return 0.0
        objs = sorted(s)
        r = sorted(ref)[0]
        return geometry.reflectional_asymmetry(
            np.array([ev.view.center(o)[:2] for o in objs]),
            np.array([ev.view.yaw(o) for o in objs]),
            np.array([float(np.prod(ev.view.extents(o))) for o in objs]),
            ev.view.center(r)[:2], ev.view.side_axis(r)[:2])


class Freespace2D(GeometricTerm):
    def compute(self, ev, env):
        from indoorgen.constraints import geometry
        a, b = self.members(ev, env)
        return geometry.freespace_2d([ev.view.footprint(o) for o in sorted(a)],
                                     [ev.view.footprint(o) for o in sorted(b - a)])


class CenterOfSupport(GeometricTerm):
    def compute(self, ev, env):
        from indoorgen.constraints import geometry
        (s,) = self.members(ev, env)
        total = 0.0
        for o in sorted(s):
            sup = ev.view.support_polygon(o)
            if sup is not None:
                total += geometry.center_of_support_distance(ev.view.center(o)[:2], sup)
        return total


class Height(GeometricTerm):
    def compute(self, ev, env):
        (s,) = self.members(ev, env)
        return float(math.fsum(float(ev.view.center(o)[2]) - ev.view.floor_z(o)
                               for o in sorted(s)))


def _per_object(objs: ObjSet, make: Callable[[ObjSet], Scalar]) -> Scalar:
    """A sum over `objs` of a per-object term, written as a quantifier so the evaluator caches
    each object's share and a move re-computes only the moved object's."""
    return objs.sum(make)


# public functional forms -------------------------------------------------------------------
def angle_alignment_cost(objs: ObjSet, reference: ObjSet) -> Scalar:
    """Sum over objs of (1 - cos angle)/2 between each front and the inward normal of the
    nearest edge of the nearest reference footprint (a room: its nearest wall)."""
    return _per_object(objs, lambda o: AngleAlignment(o, reference))


def focus_score(objs: ObjSet, target: ObjSet) -> Scalar:
    """Sum over objs of how far each one's front turns away from its nearest target (0..1 each)."""
    return _per_object(objs, lambda o: Focus(o, target))


def accessibility_cost(objs: ObjSet, blockers: ObjSet, fast: bool = True) -> Scalar:
    """How much `blockers` stand in front of `objs` (closer, bigger, more frontal = worse)."""
    return _per_object(objs, lambda o: Accessibility(o, blockers, fast))


def rotational_asymmetry(objs: ObjSet) -> Scalar:
    return RotationalAsymmetry(objs)


def reflectional_asymmetry(objs: ObjSet, reference: ObjSet) -> Scalar:
    """Mirror asymmetry of objs about the reference's front-back median plane."""
    return ReflectionalAsymmetry(objs, reference)


def freespace_2d(objs: ObjSet, occupants: ObjSet) -> Scalar:
    return Freespace2D(objs, occupants)


def center_of_support_distance(objs: ObjSet) -> Scalar:
    """Sum of plan distances from each object to the centre of the surface it rests on."""
    return _per_object(objs, CenterOfSupport)


def height(objs: ObjSet) -> Scalar:
    """Sum of the heights above their room's floor of the objects' bounding-box centres (for
    hanging pictures at eye level, on any storey)."""
    return _per_object(objs, Height)


def volume(objs: ObjSet, dims: Iterable[int] = (0, 1, 2)) -> Scalar:
    return _per_object(objs, lambda o: Volume(o, tuple(dims)))


def area(objs: ObjSet) -> Scalar:
    return _per_object(objs, Area)


def distance(a: ObjSet, b: ObjSet) -> Scalar:
    return Distance(a, b)


def min_distance(a: ObjSet, b: ObjSet) -> Scalar:
    return MinDistance(a, b)


# ---------------------------------------------------------------------------------------------
# Constraints (value = degree of violation, 0 when satisfied)


class Constraint(Node):
    def __and__(self, o: "Constraint") -> "Constraint":
        return BoolOp("and", self, o)

    def __or__(self, o: "Constraint") -> "Constraint":
        return BoolOp("or", self, o)

    def __invert__(self) -> "Constraint":
        return BoolNot(self)


class Compare(Constraint):
    def __init__(self, op: str, a: Scalar, b: Scalar):
        super().__init__(a, b)
        self.op = op

    def compute(self, ev, env):
        a, b = ev.get(self.children[0], env), ev.get(self.children[1], env)
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

    def label(self):
        return self.op


class InRange(Constraint):
    def __init__(self, x: Scalar, lo: float, hi: float):
        super().__init__(x)
        self.lo, self.hi = lo, hi

    def compute(self, ev, env):
        x = ev.get(self.children[0], env)
        return max(0.0, self.lo - x) + max(0.0, x - self.hi)

    def label(self):
        return f"in_range({self.lo:g},{self.hi:g})"


class BoolOp(Constraint):
    def __init__(self, op: str, a: Constraint, b: Constraint):
        super().__init__(a, b)
        self.op = op

    def compute(self, ev, env):
        a, b = ev.get(self.children[0], env), ev.get(self.children[1], env)
        return a + b if self.op == "and" else min(a, b)


class BoolNot(Constraint):
    def compute(self, ev, env):
        return 1.0 if ev.get(self.children[0], env) == 0.0 else 0.0


class ForAll(Constraint):
    def __init__(self, objs: ObjSet, var: Var, body: Constraint):
        super().__init__(objs, body)
        self.var = var
        self.__dict__["_fv"] = objs.free_vars | (body.free_vars - {var.uid})

    def compute(self, ev, env):
        return float(math.fsum(ev.get(self.children[1], {**env, self.var.uid: m})
                               for m in sorted(ev.get(self.children[0], env))))

    def label(self):
        return "all"


def all_of(*cs: Constraint) -> Constraint:
    out = cs[0]
    for c in cs[1:]:
        out = out & c
    return out


class ScoreTerm:
    """A soft term: `expr` weighted, minimised (sign +1) or maximised (sign -1)."""

    def __init__(self, expr: Scalar, weight: float, sign: float):
        if not isinstance(expr, Scalar):
            raise ConstraintError("minimize/maximize apply to scalar expressions")
        self.expr, self.weight, self.sign = expr, weight, sign


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

    def __add__(self, other: "Problem") -> "Problem":
        return Problem({**self.constraints, **other.constraints},
                       {**self.score_terms, **other.score_terms})
