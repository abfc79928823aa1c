"""Cardinality bounding (Infinigen Indoors, appendix E.2).

Walks a problem's hard constraints and finds every *context* into which objects could be added or
from which they could be deleted, with the count bounds the constraints put on it, in the current
scene. A context is a chain `scene()[tags...].related_to(parents, relation)...`: the tags a new
object must carry and, per relation, the parent objects it may attach to. Bounds are read against
the current state, so `chairs.count() <= tables.count() * 4` bounds chairs by today's table count.
"""
from __future__ import annotations

import math
from collections.abc import Collection
from dataclasses import dataclass, field
from typing import Any

from indoorgen.constraints.evaluator import Evaluator
from indoorgen.constraints.logic import BoolOp, Compare, ForAll, InRange
from indoorgen.constraints.node import Env, Node, Tag
from indoorgen.constraints.problem import Problem
from indoorgen.constraints.relations import Relation
from indoorgen.constraints.scalars import BinOp, Count
from indoorgen.constraints.sets import FromGenerator, RelatedTo, SceneSet, Tagged, Var
from indoorgen.model.tags import Semantics, Subpart

#: (set node, lo, hi, loop bindings): one count bound found in a constraint.
CountBound = tuple[Node[frozenset[str]], float, float, Env]
#: What names a bound's counted set across `find_bounds` calls: its node's id and loop bindings.
BoundKey = tuple[int, tuple[tuple[Any, Any], ...]]
#: Per relation of a context, the parent objects a new member may attach to.
Parents = tuple[tuple[Relation, tuple[str, ...]], ...]


@dataclass(frozen=True)
class Context:
    """What an object must be to belong to a counted set: tags, excluded tags and relations
    (each with the set expression its parents come from)."""

    tags: frozenset[Tag]
    excluded: frozenset[Tag]
    relations: tuple[tuple[Relation, Node[frozenset[str]]], ...]
    generator: str | None = None
    #: params a new member gets (sorted (name, value) pairs; `ObjSet.of_generator`)
    params: tuple[tuple[str, Any], ...] = ()


@dataclass
class Bound:
    """A context bound in the current state: `lo <= count <= hi`, with concrete parent choices."""

    name: str
    context: Context
    set_node: Node[frozenset[str]]
    env: Env
    parents: Parents
    lo: float
    hi: float
    count: int
    members: frozenset[str] = field(default_factory=frozenset)

    @property
    def key(self) -> BoundKey:
        """What names the bound's counted set across `find_bounds` calls: its node and loop
        bindings (two constraints counting one set give two bounds with one key)."""
        return id(self.set_node), tuple(sorted(self.env.items()))

    @property
    def can_add(self) -> bool:
        """Whether one more member fits the bound and every relation has a parent to take it."""
        return self.count + 1 <= self.hi + 1e-9 and all(p for _, p in self.parents)

    @property
    def below(self) -> bool:
        """Whether the count is under the lower bound."""
        return self.count < self.lo - 1e-9

    @property
    def can_delete(self) -> bool:
        """Whether one member fewer still meets the lower bound."""
        return self.count - 1 >= self.lo - 1e-9

    def stage(self, room_ids: frozenset[str]) -> str:
        """The stage (large, medium, small) the bound's objects are placed in."""
        return context_stage(self.context, self.parents, room_ids)


def context_of(node: Node[Any]) -> Context | None:
    """The addable context of a set expression, or None if objects cannot be added to it
    (unions, differences, loop variables...). Memoised on the node (programs are immutable)."""
    if "_context" not in node.__dict__:
        node.__dict__["_context"] = _context_of(node)
    ctx: Context | None = node.__dict__["_context"]
    return ctx


def _context_of(node: Node[Any]) -> Context | None:
    tags: set[Tag] = set()
    excluded: set[Tag] = set()
    rels: list[tuple[Relation, Node[frozenset[str]]]] = []
    generator: str | None = None
    params: tuple[tuple[str, Any], ...] = ()
    while True:
        if isinstance(node, SceneSet):
            break
        if isinstance(node, Tagged):
            tags |= node.include
            excluded |= node.exclude
            node = node.children[0]
        elif isinstance(node, FromGenerator):
            generator, params = node.name, node.params
            node = node.children[0]
        elif isinstance(node, RelatedTo):
            rels.append((node.relation, node.children[1]))
            node = node.children[0]
        else:
            return None
    if Semantics.Room in tags:
        return None
    return Context(frozenset(tags), frozenset(excluded), tuple(reversed(rels)), generator,
                   params)


def across(relation: Relation) -> bool:
    """Whether `relation` places a child across the floor from its parent, front to front (a
    sofa across from the TV stand): floor furniture that frames the room, placed with the large
    stage rather than after it, so what the large stage adds cannot take its place."""
    return (getattr(relation, "child", None) == Subpart.Front
            and getattr(relation, "parent", None) == Subpart.Front
            and getattr(relation, "margin", 0.0) >= ACROSS_MIN)


#: the least front-to-front distance (m) that counts as "across the floor" (`across`)
ACROSS_MIN = 1.0


def placed_with_parent(relation: Relation) -> bool:
    """Whether a child of `relation` is placed in its parent's stage rather than after it: floor
    furniture across the floor from its parent (`across`), or set in line with it (`InLine`: a
    kitchen run's appliances and base units)."""
    return across(relation) or getattr(relation, "with_parent", False)


def context_stage(ctx: Context, parents: Parents, room_ids: frozenset[str]) -> str:
    """large: on the room's floor only, or placed with floor furniture (`placed_with_parent`);
    medium: on walls/ceiling, or on the floor beside a furniture parent; small: on or in other
    objects."""
    on_floor = any(getattr(r, "parent", None) == Subpart.Floor for r, _ in ctx.relations)
    object_parent = any(any(p not in room_ids for p in ps) for r, ps in parents
                        if not placed_with_parent(r))
    if object_parent:
        return "medium" if on_floor else "small"
    return "large" if on_floor else "medium"


STAGE_ORDER = {"large": 0, "medium": 1, "small": 2}


def _is_room_set(node: Node[Any]) -> bool:
    while True:
        if isinstance(node, Tagged) and Semantics.Room in node.include:
            return True
        if not node.children:
            return False
        node = node.children[0]


def static_stage(node: Node[Any]) -> str | None:
    """The stage whose objects a set expression's chain describes, judged from its relations
    alone (before anything exists); None if it names no relation."""
    rels: list[tuple[Relation, bool]] = []
    while True:
        if isinstance(node, RelatedTo):
            rels.append((node.relation, _is_room_set(node.children[1])))
        if not node.children or isinstance(node, Var):
            break
        node = node.children[0]
    if not rels:
        return None
    on_floor = any(getattr(r, "parent", None) == Subpart.Floor for r, _ in rels)
    object_parent = any(not room for r, room in rels if not placed_with_parent(r))
    if object_parent:
        return "medium" if on_floor else "small"
    return "large" if on_floor else "medium"


def term_stage(expr: Node[Any]) -> str:
    """The latest stage any set in `expr` belongs to: a term only counts from that stage on
    (chairs-per-table is ignored while the large stage places tables)."""
    best, seen, stack = "large", set[int](), [expr]
    while stack:
        n = stack.pop()
        if n.uid in seen:
            continue
        seen.add(n.uid)
        if isinstance(n, RelatedTo):
            s = static_stage(n)
            if s is not None and STAGE_ORDER[s] > STAGE_ORDER[best]:
                best = s
        stack.extend(n.children)
    return best


def _count_terms(x: Node[Any]) -> list[Node[frozenset[str]]] | None:
    """The set nodes of `x` if it is a count or a sum of counts (`a.count() + b.count()`),
    else None."""
    if isinstance(x, Count):
        return [x.children[0]]
    if isinstance(x, BinOp) and x.op == "+":
        a, b = (_count_terms(ch) for ch in x.children)
        if a is not None and b is not None:
            return a + b
    return None


def _split_sum(sets: list[Node[frozenset[str]]], lo: float, hi: float, ev: Evaluator, env: Env
               ) -> list[CountBound]:
    """Bounds on each set of a sum of counts bounded by [lo, hi]: each term may take what the
    others leave (so "a bath or a shower" lets the solver add either while none exists)."""
    counts = [len(ev.value(n, env)) for n in sets]
    total = sum(counts)
    return [(n, lo - (total - c), hi - (total - c), env) for n, c in zip(sets, counts, strict=True)]


def _count_bounds(c: Node[Any], ev: Evaluator, env: Env) -> list[CountBound]:
    """(set node, lo, hi, env) for each count bound found in constraint `c` under `env`."""
    out: list[CountBound] = []
    in_range_sets = _count_terms(c.children[0]) if isinstance(c, InRange) else None
    if isinstance(c, InRange) and in_range_sets is not None:
        out += _split_sum(in_range_sets, c.lo, c.hi, ev, env)
    elif isinstance(c, Compare):
        a, b = c.children
        op = c.op
        if _count_terms(b) is not None and _count_terms(a) is None:
            a, b = b, a
            op = {"<=": ">=", ">=": "<=", "<": ">", ">": "<", "==": "=="}[op]
        sets = _count_terms(a)
        if sets is not None:
            k = float(ev.value(b, env))
            lo, hi = {"<=": (0, k), ">=": (k, math.inf), "==": (k, k),
                      "<": (0, math.ceil(k) - 1), ">": (math.floor(k) + 1, math.inf)}[op]
            out += _split_sum(sets, lo, hi, ev, env)
    elif isinstance(c, BoolOp) and c.op == "and":
        for ch in c.children:
            out += _count_bounds(ch, ev, env)
    elif isinstance(c, ForAll):
        for m in sorted(ev.value(c.children[0], env)):
            out += _count_bounds(c.children[1], ev, {**env, c.var.uid: m})
    return out


def _merge_parents(rels: list[tuple[Relation, frozenset[str]]]) -> Parents:
    """One entry per distinct relation: a chain that names the same relation twice
    (`tvs_on_stands.related_to(this_stand, on_top)`) needs one parent in both sets."""
    merged: dict[Relation, frozenset[str]] = {}
    for rel, ps in rels:
        merged[rel] = merged[rel] & ps if rel in merged else frozenset(ps)
    return tuple((rel, tuple(sorted(ps))) for rel, ps in merged.items())


def find_bounds(problem: Problem, ev: Evaluator, names: Collection[str] | None = None) -> list[Bound]:
    """Every count bound of `problem`'s constraints (those in `names`, if given) on an addable
    context, in the current state."""
    out: list[Bound] = []
    for name, c in problem.constraints.items():
        if names is not None and name not in names:
            continue
        for set_node, lo, hi, env in _count_bounds(c, ev, {}):
            ctx = context_of(set_node)
            if ctx is None:
                continue
            parents = _merge_parents([(rel, ev.value(pnode, env)) for rel, pnode in ctx.relations])
            members = ev.value(set_node, env)
            out.append(Bound(name, ctx, set_node, env, parents, lo, hi, len(members), members))
    return _capped(out)


def _capped(bounds: list[Bound]) -> list[Bound]:
    """`bounds` with each one's maximum lowered to the least any bound on the same set allows:
    a set one constraint caps is not grown for another's sake (a compact shower barred from a
    large bathroom is not added as its "bath or shower")."""
    keys = [b.key for b in bounds]
    least: dict[BoundKey, float] = {}
    for k, b in zip(keys, bounds, strict=True):
        least[k] = min(least.get(k, math.inf), b.hi)
    for k, b in zip(keys, bounds, strict=True):
        b.hi = least[k]
    return bounds
