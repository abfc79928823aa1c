"""The base of every DSL expression node, and the interfaces nodes compute through.

A node only describes a computation. It computes its value from an `EvalContext` (the evaluator:
children's values, cached, and the watches that tell it when to recompute) reading an
`ObjectView` (what the scene knows about each object). Both are protocols here, on the
language's side, so the language never imports the evaluator that runs it.
"""
from __future__ import annotations

from collections.abc import Iterable
from typing import Any, Generic, Protocol, TypeVar

import numpy as np
import shapely.geometry as sg
import trimesh

from indoorgen.constraints.relations import Relation
from indoorgen.model.tags import Semantics

#: A tag in `objs[...]`: a semantic class, or a plain string (a room type, "storey").
Tag = Semantics | str
#: Loop bindings: the uid of each bound loop variable -> the object it is bound to.
Env = dict[int, str]

T = TypeVar("T")


class ObjectView(Protocol):
    """What the evaluator needs to know about objects; the solver state implements it."""

    def all_ids(self) -> frozenset[str]:
        """Every object (and room) in the scene."""

    def tags(self, o: str) -> frozenset[Tag]:
        """The tags of `o`."""

    def generator(self, o: str) -> str:
        """The generator that made `o` ("" for rooms)."""

    def params(self, o: str) -> dict[str, Any]:
        """The generator params of `o` (empty for rooms)."""

    def relations(self, o: str) -> list[tuple[Relation, str]]:
        """`o`'s relations, each with the parent it relates `o` to."""

    def children(self, o: str) -> set[str]:
        """The objects related to `o` (it is their parent)."""

    def center(self, o: str) -> np.ndarray:
        """World centre of `o`'s bounding box."""

    def front(self, o: str) -> np.ndarray:
        """World direction `o` faces (its local +X)."""

    def front_point(self, o: str) -> np.ndarray:
        """A point on `o`'s front plane."""

    def side_axis(self, o: str) -> np.ndarray:
        """World direction of `o`'s local +Y."""

    def yaw(self, o: str) -> float:
        """Angle of `o`'s front from +X (radians)."""

    def floor_z(self, o: str) -> float:
        """Height of the floor of `o`'s room."""

    def extents(self, o: str) -> np.ndarray:
        """Bounding-box size of `o` (3,)."""

    def footprint(self, o: str) -> sg.Polygon:
        """World XY footprint of `o`."""

    def outline(self, o: str) -> Any:
        """What plan distances are measured to: a footprint, or a room's walls."""

    def world_mesh(self, o: str) -> trimesh.Trimesh:
        """`o`'s mesh in world coordinates."""

    def support_polygon(self, o: str) -> sg.Polygon | None:
        """World XY polygon of the surface `o` rests on, if any."""


class EvalContext(Protocol):
    """What a node computes through: its children's values and the watches that tell the
    evaluator when the node's value may have changed."""

    view: ObjectView

    def get(self, node: Node[T], env: Env) -> T:
        """The value of `node` under loop bindings `env`."""

    def watch(self, objs: Iterable[str]) -> None:
        """The node being computed depends on the state of `objs`."""

    def watch_children(self, parents: Iterable[str]) -> None:
        """The node being computed depends on which objects are related to `parents`."""

    def watch_membership(self) -> None:
        """The node being computed depends on which objects exist."""


class Node(Generic[T]):
    """Base of all expression nodes, whose values are `T`. `children` are evaluated in the same
    loop bindings."""

    children: tuple[Node[Any], ...] = ()

    def __init__(self, *children: Node[Any]):
        #: identity of this node while it lives (a program keeps its nodes alive), the key of
        #: evaluator caches and loop bindings; no process-wide counter needed
        self.uid = id(self)
        self.children = tuple(children)

    __hash__ = object.__hash__

    @property
    def free_vars(self) -> frozenset[int]:
        """Loop variables this node's value depends on (so its cache key includes them)."""
        fv: frozenset[int] | None = self.__dict__.get("_fv")
        if fv is None:
            fv = frozenset().union(*(c.free_vars for c in self.children)) if self.children else frozenset()
            self.__dict__["_fv"] = fv
        return fv

    @property
    def key_vars(self) -> tuple[int, ...]:
        """`free_vars` in a fixed order: the loop bindings that key this node's cache entries."""
        kv: tuple[int, ...] | None = self.__dict__.get("_kv")
        if kv is None:
            kv = self.__dict__["_kv"] = tuple(sorted(self.free_vars))
        return kv

    def compute(self, ev: EvalContext, env: Env) -> T:  # pragma: no cover
        """This node's value under `env`, reading children through `ev`."""
        raise NotImplementedError

    def label(self) -> str:
        """A short name for this node in messages and traces."""
        return type(self).__name__
