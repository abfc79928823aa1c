"""Set nodes: sets of objects (and rooms) to filter, combine, relate, measure and loop over.

Every set expression starts at `scene()` and narrows it::

    chairs = scene()[Semantics.Chair].related_to(room, on_floor)
    chairs.count().in_range(2, 8)

A set evaluates to a frozenset of object names. `all`, `sum`, `mean` and `max` bind a loop
variable (`Var`) to each member in turn, so `tables.all(lambda t: chairs.related_to(t, at).count()
>= 2)` states something of every table.
"""
from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import Any, TypeVar

from indoorgen.assets import get_factory
from indoorgen.constraints.logic import Constraint, ForAll
from indoorgen.constraints.node import Env, EvalContext, Node, Tag
from indoorgen.constraints.relations import Relation
from indoorgen.constraints.scalars import Count, Reduce, Scalar, ScalarLike, as_scalar
from indoorgen.constraints.terms import (
    Area,
    CenterDistance,
    Distance,
    FrontDistance,
    MinDistance,
    Volume,
)
from indoorgen.errors import ConstraintError
from indoorgen.model.tags import Semantics

B = TypeVar("B")


class TagNot:
    """A negated tag inside `objs[...]`: `objs[Not(Semantics.Rug)]`."""

    def __init__(self, tag: Tag):
        self.tag = tag


def Not(tag: Tag) -> TagNot:
    """`tag` negated, for `objs[...]`: the members that do not carry it."""
    return TagNot(tag)


class ObjSet(Node[frozenset[str]]):
    """A set of objects (and rooms): filter, combine, relate and measure it."""

    def __getitem__(self, tags: Tag | TagNot | tuple[Tag | TagNot, ...]) -> ObjSet:
        if not isinstance(tags, tuple):
            tags = (tags,)
        inc = frozenset(t for t in tags if not isinstance(t, TagNot))
        exc = frozenset(t.tag for t in tags if isinstance(t, TagNot))
        for t in inc | exc:
            if not isinstance(t, (Semantics, str)):
                raise ConstraintError(f"objs[...] takes Semantics tags, got {t!r}")
        return Tagged(self, inc, exc)

    def excluding(self, *tags: Tag) -> ObjSet:
        """The members carrying none of `tags`."""
        return self[tuple(Not(t) for t in tags)]

    def of_generator(self, name: str, **params: Any) -> ObjSet:
        """Members made by generator `name` with the given param values (checked now: an
        unknown generator or param is an error); objects the solver adds here get those values:
        `floor.of_generator("bed", drawers=False)`."""
        fac = get_factory(name)
        unknown = sorted(set(params) - set(fac.params))
        if unknown:
            raise ConstraintError(f"generator {name!r} has no params {unknown}; "
                                  f"it has {sorted(fac.params)}")
        return FromGenerator(self, name, tuple(sorted(params.items())))

    def named(self, name: str) -> ObjSet:
        """The member called `name` (empty if it is not a member)."""
        return Named(self, name)

    def __or__(self, other: ObjSet) -> ObjSet:
        return SetUnion(self, other)

    def __sub__(self, other: ObjSet) -> ObjSet:
        return SetDifference(self, other)

    def related_to(self, parents: ObjSet, relation: Relation) -> ObjSet:
        """The members holding `relation` (or one implying it) to a member of `parents`."""
        if not isinstance(relation, Relation):
            raise ConstraintError(f"related_to needs a Relation, got {relation!r}")
        return RelatedTo(self, parents, relation)

    # scalars over the set
    def count(self) -> Scalar:
        """The number of members."""
        return Count(self)

    def volume(self, dims: Iterable[int] = (0, 1, 2)) -> Scalar:
        """Sum of the members' bounding-box volumes (the product of their extents along `dims`;
        `dims=(0, 1)` gives footprint areas)."""
        return self.sum(lambda o: Volume(o, tuple(dims)))

    def area(self) -> Scalar:
        """Sum of the members' bounding-box areas (each member's two largest extents)."""
        return self.sum(Area)

    def distance(self, other: ObjSet) -> Scalar:
        """Smallest 2D (plan view) distance between the two sets; a room counts as its walls."""
        return Distance(self, other)

    def min_distance(self, other: ObjSet) -> Scalar:
        """Smallest 3D mesh-to-mesh distance between the two sets."""
        return MinDistance(self, other)

    def center_distance(self, other: ObjSet) -> Scalar:
        """Smallest plan distance between the two sets' members' centres ("centred over")."""
        return CenterDistance(self, other)

    def front_distance(self, other: ObjSet) -> Scalar:
        """Smallest plan distance between the two sets' members' front-face centres (where one
        stands to use each)."""
        return FrontDistance(self, other)

    # quantifiers
    def all(self, fn: Callable[[ObjSet], Constraint]) -> Constraint:
        """`fn(member)` holds for every member (violations add up)."""
        var, body = _bind(fn)
        if not isinstance(body, Constraint):
            raise ConstraintError("all(...) needs a lambda returning a constraint")
        return ForAll(self, var, body)

    def sum(self, fn: Callable[[ObjSet], ScalarLike]) -> Scalar:
        """The sum of `fn(member)` over the members (0 for an empty set)."""
        var, body = _bind(fn)
        return Reduce("sum", self, var, as_scalar(body))

    def mean(self, fn: Callable[[ObjSet], ScalarLike]) -> Scalar:
        """The mean of `fn(member)` over the members (0 for an empty set)."""
        var, body = _bind(fn)
        return Reduce("mean", self, var, as_scalar(body))

    def max(self, fn: Callable[[ObjSet], ScalarLike]) -> Scalar:
        """The largest `fn(member)` over the members (0 for an empty set)."""
        var, body = _bind(fn)
        return Reduce("max", self, var, as_scalar(body))


class SceneSet(ObjSet):
    """Every object and room in the scene."""

    def compute(self, ev: EvalContext, env: Env) -> frozenset[str]:
        """All ids of the view (watching which objects exist)."""
        ev.watch_membership()
        return ev.view.all_ids()

    def label(self) -> str:
        """`scene()`."""
        return "scene()"


def scene() -> ObjSet:
    """Every object (and room) in the scene: the leaf of all set expressions."""
    return SceneSet()


class Tagged(ObjSet):
    """The members of a set carrying every `include` tag and no `exclude` tag."""

    def __init__(self, child: ObjSet, include: frozenset[Tag], exclude: frozenset[Tag]):
        super().__init__(child)
        self.include, self.exclude = include, exclude

    def compute(self, ev: EvalContext, env: Env) -> frozenset[str]:
        """The child's members filtered by tags."""
        tags = ev.view.tags
        inc, exc = self.include, self.exclude
        members: frozenset[str] = ev.get(self.children[0], env)
        if not exc:
            return frozenset(o for o in members if inc <= tags(o))
        return frozenset(o for o in members if inc <= (t := tags(o)) and not exc & t)

    def label(self) -> str:
        """The included tags, e.g. `[chair,furniture]`."""
        return "[" + ",".join(sorted(getattr(t, "value", str(t)) for t in self.include)) + "]"


class FromGenerator(ObjSet):
    """The members of a set made by one generator, with some params fixed (`params`: sorted
    (name, value) pairs)."""

    def __init__(self, child: ObjSet, name: str, params: tuple[tuple[str, Any], ...] = ()):
        super().__init__(child)
        self.name, self.params = name, params

    def compute(self, ev: EvalContext, env: Env) -> frozenset[str]:
        """The child's members whose generator is `name` and whose params hold `params`."""
        members: frozenset[str] = ev.get(self.children[0], env)
        out = frozenset(o for o in members if ev.view.generator(o) == self.name)
        if self.params:
            ev.watch(out)  # a resample changes params
            out = frozenset(o for o in out
                            if all(ev.view.params(o).get(k) == v for k, v in self.params))
        return out

    def label(self) -> str:
        """`generator(<name>, params)`."""
        fixed = "".join(f", {k}={v!r}" for k, v in self.params)
        return f"generator({self.name}{fixed})"


class Named(ObjSet):
    """The member of a set with a given name (or nothing)."""

    def __init__(self, child: ObjSet, name: str):
        super().__init__(child)
        self.name = name

    def compute(self, ev: EvalContext, env: Env) -> frozenset[str]:
        """{name} if the child holds it, else the empty set."""
        s: frozenset[str] = ev.get(self.children[0], env)
        return frozenset([self.name]) if self.name in s else frozenset()

    def label(self) -> str:
        """`named(<name>)`."""
        return f"named({self.name})"


class SetUnion(ObjSet):
    """`a | b`: the members of either set."""

    def compute(self, ev: EvalContext, env: Env) -> frozenset[str]:
        """The union of the two sets."""
        a: frozenset[str] = ev.get(self.children[0], env)
        b: frozenset[str] = ev.get(self.children[1], env)
        return a | b


class SetDifference(ObjSet):
    """`a - b`: the members of a that are not in b."""

    def compute(self, ev: EvalContext, env: Env) -> frozenset[str]:
        """The difference of the two sets."""
        a: frozenset[str] = ev.get(self.children[0], env)
        b: frozenset[str] = ev.get(self.children[1], env)
        return a - b


class RelatedTo(ObjSet):
    """The members of a set related (by `relation` or one implying it) to a parent set."""

    def __init__(self, child: ObjSet, parents: ObjSet, relation: Relation):
        super().__init__(child, parents)
        self.relation = relation

    def compute(self, ev: EvalContext, env: Env) -> frozenset[str]:
        """The child's members with a matching relation to one of the parents."""
        objs: frozenset[str] = ev.get(self.children[0], env)
        parents: frozenset[str] = ev.get(self.children[1], env)
        # which objects relate to the parents: poses don't matter, so a move never re-computes
        # this; a changed set of objects (input version) or a reassigned parent does
        ev.watch_children(parents)
        rel, view = self.relation, ev.view
        related = set[str]().union(*(view.children(p) for p in parents)) & objs if parents else set()
        return frozenset(o for o in related
                         if any(p in parents and r.implies(rel) for r, p in view.relations(o)))

    def label(self) -> str:
        """`related_to(<relation>)`."""
        return f"related_to({self.relation!r})"


class Var(ObjSet):
    """A loop variable: the single object bound by an enclosing all/sum/mean/max."""

    def __init__(self) -> None:
        super().__init__()
        self.__dict__["_fv"] = frozenset([self.uid])

    def compute(self, ev: EvalContext, env: Env) -> frozenset[str]:
        """{the bound object}."""
        return frozenset([env[self.uid]])

    def label(self) -> str:
        """`var<uid>`."""
        return f"var{self.uid}"


def _bind(fn: Callable[[ObjSet], B]) -> tuple[Var, B]:
    var = Var()
    return var, fn(var)
