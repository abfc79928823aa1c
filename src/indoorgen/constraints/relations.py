"""Relations between a child object's surface and a parent's surface, with the small algebra the
solver needs: `implies` (does holding this relation also satisfy that query?) and `intersects`
(can one relation instance satisfy both?)."""
from __future__ import annotations

import re
from dataclasses import dataclass

from indoorgen.errors import ConfigError
from indoorgen.model.tags import Subpart

#: Gap the solver leaves between surfaces declared in contact, so that touching placeholders are
#: never reported as colliding. Validators accept up to 5 mm.
CONTACT_GAP = 0.001


class Relation:
    """Base class. A relation is a predicate over (child, parent) pairs."""

    #: relations that pin a child surface to a parent plane (the solver derives DoF from these)
    is_planar: bool = False

    def implies(self, other: Relation) -> bool:
        """Whether holding this relation also satisfies the query `other`."""
        if isinstance(other, AnyRelation):
            return True
        if isinstance(other, NegatedRelation):
            return not self.intersects(other.inner)
        return self == other

    def intersects(self, other: Relation) -> bool:
        """Whether one relation instance can satisfy both this and `other`."""
        if isinstance(other, NegatedRelation):
            return not self.implies(other.inner)
        return self.implies(other) or other.implies(self)

    def __invert__(self) -> Relation:
        return NegatedRelation(self)


def _sub_ok(mine: Subpart | None, query: Subpart | None) -> bool:
    return query is None or mine == query


def _optional_subpart(text: str) -> Subpart | None:
    return None if text in ("None", "") else Subpart(text)


@dataclass(frozen=True)
class StableAgainst(Relation):
    """The child's `child` surface lies on the parent's `parent` surface, facing it, at `margin`
    metres. With `overhang=False` only the child's centroid must project inside the parent
    surface (SupportedBy semantics); otherwise the whole child surface must."""

    child: Subpart
    parent: Subpart
    margin: float = 0.0
    overhang: bool = True
    #: placed together with its parent (in its parent's stage) rather than after it (`InLine`)
    with_parent: bool = False
    is_planar = True

    def implies(self, other: Relation) -> bool:
        """Same surfaces and margin, overhang no looser; or touching when flush (margin 0)."""
        if isinstance(other, StableAgainst):
            return (self.child == other.child and self.parent == other.parent
                    and abs(self.margin - other.margin) < 1e-9
                    and (self.overhang or not other.overhang))
        if isinstance(other, Touching):
            return (abs(self.margin) < 1e-9 and _sub_ok(self.child, other.child)
                    and _sub_ok(self.parent, other.parent))
        return super().implies(other)

    def __repr__(self) -> str:
        kind = "InLine" if self.with_parent else "StableAgainst" if self.overhang else "SupportedBy"
        return f"{kind}({self.child.value},{self.parent.value},{self.margin:g})"


def SupportedBy(child: Subpart = Subpart.Bottom, parent: Subpart = Subpart.SupportSurface,
                margin: float = 0.0) -> StableAgainst:
    """The child rests on the parent's surface without tipping: its centroid projects inside it
    (it may overhang, like a plate at a table's edge)."""
    return StableAgainst(child, parent, margin, overhang=False)


def InLine(child: Subpart, parent: Subpart, margin: float = 0.0) -> StableAgainst:
    """`SupportedBy`, placed together with its floor-standing parent rather than after it: the
    appliances and base units of a kitchen run, built beside one another in one stage."""
    return StableAgainst(child, parent, margin, overhang=False, with_parent=True)


@dataclass(frozen=True)
class Touching(Relation):
    """Some surface of the child (of role `child`, any if None) touches the parent's."""

    child: Subpart | None = None
    parent: Subpart | None = None

    def implies(self, other: Relation) -> bool:
        """Touching implies touching with the same (or unspecified) surface roles."""
        if isinstance(other, Touching):
            return _sub_ok(self.child, other.child) and _sub_ok(self.parent, other.parent)
        return super().implies(other)

    def __repr__(self) -> str:
        return f"Touching({getattr(self.child, 'value', None)},{getattr(self.parent, 'value', None)})"


@dataclass(frozen=True)
class CoPlanar(Relation):
    """The child's surface lies in the same plane as the parent's, facing the same way (fronts of
    a kitchen run in line)."""

    child: Subpart
    parent: Subpart
    margin: float = 0.0
    is_planar = True

    def __repr__(self) -> str:
        return f"CoPlanar({self.child.value},{self.parent.value},{self.margin:g})"


@dataclass(frozen=True)
class AnyRelation(Relation):
    """Matches every relation: `objs.related_to(parent, AnyRelation())` = anything attached."""

    def implies(self, other: Relation) -> bool:
        """Only the query "any relation" is implied by it."""
        return isinstance(other, AnyRelation)

    def intersects(self, other: Relation) -> bool:
        """Every relation but "no relation at all" can hold with it."""
        return not isinstance(other, NegatedRelation) or not isinstance(other.inner, AnyRelation)

    def __repr__(self) -> str:
        return "AnyRelation()"


@dataclass(frozen=True)
class NegatedRelation(Relation):
    """Holds when `inner` does not."""

    inner: Relation

    def implies(self, other: Relation) -> bool:
        """not-A implies not-B when B implies A; and it implies "any relation"."""
        if isinstance(other, NegatedRelation):
            return other.inner.implies(self.inner)
        return isinstance(other, AnyRelation)

    def intersects(self, other: Relation) -> bool:
        """not-A can hold with B unless B implies A."""
        return not other.implies(self.inner)

    def __repr__(self) -> str:
        return f"~{self.inner!r}"


def parse_relation(text: str) -> Relation:
    """Read back a relation from its `repr` (as stored in scene.json)."""
    t = text.strip()
    if t.startswith("~"):
        return NegatedRelation(parse_relation(t[1:]))
    if t == "AnyRelation()":
        return AnyRelation()
    m = re.fullmatch(r"(\w+)\(([^)]*)\)", t)
    if not m:
        raise ConfigError(f"unreadable relation {text!r}")
    kind, args = m.group(1), [a.strip() for a in m.group(2).split(",")]
    if kind == "StableAgainst":
        return StableAgainst(Subpart(args[0]), Subpart(args[1]), float(args[2]))
    if kind == "SupportedBy":
        return StableAgainst(Subpart(args[0]), Subpart(args[1]), float(args[2]), overhang=False)
    if kind == "InLine":
        return InLine(Subpart(args[0]), Subpart(args[1]), float(args[2]))
    if kind == "CoPlanar":
        return CoPlanar(Subpart(args[0]), Subpart(args[1]), float(args[2]))
    if kind == "Touching":
        return Touching(_optional_subpart(args[0]), _optional_subpart(args[1]))
    raise ConfigError(f"unknown relation kind in {text!r}")
