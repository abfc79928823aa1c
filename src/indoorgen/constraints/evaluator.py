"""Incremental evaluation of a `Problem` against a changing scene.

The problem is compiled once into a DAG of expression nodes. Each (node, loop-binding) pair gets a
cache entry holding its value, the entries it read (with their versions) and the objects it
watched. After a move the solver calls `notify` with the objects it touched:

1. entries watching a touched object (and `scene()` entries, when objects were added or deleted)
   are marked dirty, and everything downstream of them is marked suspect;
2. `evaluate` walks from the roots; an entry that is neither dirty nor suspect returns its cached
   value at once, a suspect entry first re-checks its inputs and is recomputed only if one of
   them really changed (early cut-off), and a dirty entry is recomputed.

So a move re-evaluates only the nodes whose object sets contain the moved, added or deleted
object, and deletions are as incremental as moves. `check=True` verifies every incremental result
against a fresh full evaluation.
"""
from __future__ import annotations

import logging
from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import Any, TypeVar

from indoorgen.constraints.node import Env, Node, ObjectView
from indoorgen.constraints.problem import Problem

log = logging.getLogger(__name__)

#: A cache entry's key: (node uid, bound object names of the node's free variables).
Key = tuple[int, tuple[str, ...]]
#: A root's key: ("c", constraint name) or ("s", score term name).
RootKey = tuple[str, str]
#: What an entry watches: an object, or (CHILDREN, parent) for "which objects relate to it".
WatchKey = str | tuple[str, str]
#: watch-key tag of "which objects are related to this parent" (see `watch_children`)
CHILDREN = "@children"

V = TypeVar("V")


#: What a node's computation recorded: (its old entry, inputs read with their versions, what it
#: watched, whether it depends on which objects exist).
_Frame = tuple["_Entry | None", dict[Key, int], set[WatchKey], bool]


@dataclass
class _Entry:
    node: Node[Any]
    env: Env
    value: Any = None
    version: int = 0
    inputs: dict[Key, int] = field(default_factory=dict)   # child key -> child version when read
    parents: set[Key] = field(default_factory=set)
    watched: frozenset[WatchKey] = frozenset()
    membership: bool = False


@dataclass
class Result:
    """One evaluation of a problem: every named constraint's violation and score term's value."""

    violations: dict[str, float]
    scores: dict[str, float]
    loss: float

    @property
    def violation(self) -> float:
        """The sum of all constraints' violations."""
        return float(sum(self.violations.values()))

    @property
    def n_violated(self) -> int:
        """How many constraints are violated (by more than 1e-9)."""
        return sum(1 for v in self.violations.values() if v > 1e-9)


class Evaluator:
    """Evaluates one `Problem` over an `ObjectView`, incrementally between `notify` calls."""

    def __init__(self, problem: Problem, view: ObjectView, *, check: bool = False):
        self.problem, self.view, self.check = problem, view, check
        self._entries: dict[Key, _Entry] = {}
        self._watchers: dict[WatchKey, set[Key]] = {}
        self._membership: set[Key] = set()
        self._by_env_obj: dict[str, set[Key]] = {}
        self._dirty: set[Key] = set()
        self._suspect: set[Key] = set()
        self._frames: list[_Frame] = []
        self._key_vars: dict[int, tuple[int, ...]] = {}  # node uid -> its key_vars
        self._all_roots: list[tuple[RootKey, Node[float]]] = [
            (("c", n), c) for n, c in problem.constraints.items()]
        self._all_roots += [(("s", n), t.expr) for n, t in problem.score_terms.items()]
        self._roots = self._all_roots
        self.recomputed = 0  # entries recomputed since construction (for tests and benchmarks)
        #: how many times `notify` was called: while it stays the same, nothing changed, so a
        #: caller may keep what it derived from the values (the solver's count bounds)
        self.changes = 0

    # -- the interface nodes use while computing ------------------------------------------
    def get(self, node: Node[V], env: Env) -> V:
        """The value of `node` under loop bindings `env`, from cache when still valid."""
        uid = node.uid
        kv = self._key_vars.get(uid)
        if kv is None:
            kv = self._key_vars[uid] = node.key_vars
        key = (uid, tuple([env[v] for v in kv]) if kv else ())
        e = self._entries.get(key)
        if e is None or key in self._suspect:  # else clean: its cached value holds
            e = self._refresh(key, node, env)
        if self._frames:
            self._frames[-1][1][key] = e.version
        value: V = e.value
        return value

    def watch(self, objs: Iterable[str]) -> None:
        """Mark the entry being computed as depending on the state of `objs`."""
        self._frames[-1][2].update(objs)

    def watch_children(self, parents: Iterable[str]) -> None:
        """Mark the entry being computed as depending on which objects are related to
        `parents` (not on anyone's pose): it is re-computed when `notify(relinked=...)` names
        one of them."""
        self._frames[-1][2].update((CHILDREN, p) for p in parents)

    def watch_membership(self) -> None:
        """Mark the entry being computed as depending on which objects exist."""
        f = self._frames[-1]
        self._frames[-1] = (f[0], f[1], f[2], True)

    # -- driving it ----------------------------------------------------------------------------
    def notify(self, changed: Iterable[str] = (), *, added: Iterable[str] = (),
               removed: Iterable[str] = (), relinked: Iterable[str] = ()) -> None:
        """Tell the evaluator which objects moved or changed relations/params (`changed`), were
        added or were deleted since the last evaluation, and which parents gained or lost a
        related object without an addition or deletion (`relinked`: a reassigned parent)."""
        self.changes += 1
        added_l, removed_l = list(added), list(removed)
        dirty: set[Key] = set()
        for o in list(changed) + removed_l:
            dirty |= self._watchers.get(o, set())
        for p in relinked:
            dirty |= self._watchers.get((CHILDREN, p), set())
        if added_l or removed_l:
            dirty |= self._membership
        for o in removed_l:
            for key in list(self._by_env_obj.pop(o, ())):
                # what read a dropped entry must read again (and so link to its successor)
                e = self._entries.get(key)
                if e is not None:
                    dirty |= e.parents
                self._drop(key)
            self._watchers.pop(o, None)
        dirty = {k for k in dirty if k in self._entries}
        self._dirty |= dirty
        stack = list(dirty)
        suspect = self._suspect
        while stack:
            k = stack.pop()
            if k in suspect:
                continue
            suspect.add(k)
            e = self._entries.get(k)
            if e is not None:
                stack.extend(p for p in e.parents if p not in suspect)

    def evaluate(self) -> Result:
        """Bring every root up to date and return the problem's current result."""
        vals: dict[RootKey, float] = {}
        for key, node in self._roots:
            vals[key] = self.get(node, {})
        res = self._result(vals)
        if self.check:
            fresh = Evaluator(self.problem, self.view)
            fresh.set_active(self.active)
            full = fresh.evaluate()
            for name in res.violations:
                if not _same(res.violations[name], full.violations[name]):
                    raise AssertionError(f"incremental != full for constraint {name!r}: "
                                         f"{res.violations[name]} vs {full.violations[name]}")
            for name in res.scores:
                if not _same(res.scores[name], full.scores[name]):
                    raise AssertionError(f"incremental != full for score {name!r}: "
                                         f"{res.scores[name]} vs {full.scores[name]}")
        return res

    def set_active(self, names: set[str] | None) -> None:
        """Evaluate only the named constraints and score terms (None: all of them). Inactive
        terms are neither computed nor reported, so a stage pays only for what it can change."""
        self._roots = [(k, n) for k, n in self._all_roots if names is None or k[1] in names]

    @property
    def active(self) -> set[str]:
        """Names of the constraints and score terms being evaluated."""
        return {k[1] for k, _ in self._roots}

    def value(self, node: Node[V], env: Env | None = None) -> V:
        """Evaluate any node of the program (e.g. a set expression, for bound reasoning)."""
        return self.get(node, env or {})

    # -- internals -----------------------------------------------------------------------------
    def _result(self, vals: dict[RootKey, float]) -> Result:
        viol = {n: float(vals[("c", n)]) for n in self.problem.constraints if ("c", n) in vals}
        scores = {n: float(vals[("s", n)]) for n in self.problem.score_terms if ("s", n) in vals}
        loss = sum(self.problem.score_terms[n].weight * self.problem.score_terms[n].sign * v
                   for n, v in scores.items())
        return Result(viol, scores, float(loss))

    def _refresh(self, key: Key, node: Node[Any], env: Env) -> _Entry:
        e = self._entries.get(key)
        if e is not None and key not in self._suspect:
            return e
        if e is not None and key not in self._dirty:
            # suspect: recompute only if one of its inputs really changed
            unchanged = True
            entries, suspect = self._entries, self._suspect
            for ck, ver in list(e.inputs.items()):
                ce = entries.get(ck)
                if ce is None:
                    unchanged = False
                    break
                if ck in suspect:  # a clean input is up to date already
                    ce = self._refresh(ck, ce.node, ce.env)
                if ce.version != ver:
                    unchanged = False
                    break
            if unchanged:
                self._suspect.discard(key)
                return e
        return self._compute(key, node, env, e)

    def _compute(self, key: Key, node: Node[Any], env: Env, old: _Entry | None) -> _Entry:
        benv = {v: env[v] for v in node.free_vars}
        self._frames.append((old, {}, set[WatchKey](), False))
        try:
            value = node.compute(self, benv)
        finally:
            _, inputs, watched, membership = self._frames.pop()
        self.recomputed += 1
        if old is None:
            e = _Entry(node, benv)
            self._entries[key] = e
            for o in benv.values():
                self._by_env_obj.setdefault(o, set()).add(key)
        else:
            e = old
        # re-link inputs: every input read, not only the new ones (an input dropped and built
        # again since this entry last read it is a new entry that does not know its readers)
        for ck in e.inputs.keys() - inputs.keys():
            self._unlink(ck, key)
        for ck in inputs:
            ce = self._entries.get(ck)
            if ce is not None:
                ce.parents.add(key)
        e.inputs = inputs
        # re-register watches
        now_watched = frozenset(watched)
        if now_watched != e.watched:
            for w in e.watched - now_watched:
                s = self._watchers.get(w)
                if s is not None:
                    s.discard(key)
            for w in now_watched - e.watched:
                self._watchers.setdefault(w, set()).add(key)
            e.watched = now_watched
        if membership != e.membership:
            (self._membership.add if membership else self._membership.discard)(key)
            e.membership = membership
        if old is None or not _same_value(old.value, value):
            e.version += 1
        e.value = value
        self._dirty.discard(key)
        self._suspect.discard(key)
        return e

    def _unlink(self, child: Key, parent: Key) -> None:
        ce = self._entries.get(child)
        if ce is None:
            return
        ce.parents.discard(parent)
        if not ce.parents and ce.env:  # an orphaned per-binding entry: nobody reads it now
            self._drop(child)

    def _drop(self, key: Key) -> None:
        e = self._entries.pop(key, None)
        if e is None:
            return
        for w in e.watched:
            s = self._watchers.get(w)
            if s is not None:
                s.discard(key)
        self._membership.discard(key)
        for o in e.env.values():
            s = self._by_env_obj.get(o)
            if s is not None:
                s.discard(key)
        self._dirty.discard(key)
        self._suspect.discard(key)
        for ck in e.inputs:
            self._unlink(ck, key)


def _same_value(a: Any, b: Any) -> bool:
    if isinstance(a, float) and isinstance(b, float):
        return a == b or (a != a and b != b)
    same: bool = a == b
    return same


def _same(a: float, b: float) -> bool:
    return abs(a - b) <= 1e-9 * max(1.0, abs(a), abs(b))
