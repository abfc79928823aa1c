"""Geometric scalar nodes: terms computed from the poses and shapes of their sets' members.

Each term reads its sets' members from the `ObjectView` and hands plain arrays, footprints or
meshes to the maths in `geometry`. A term watches every member it reads, so the evaluator
recomputes it after a move of any of them and never otherwise. Programs reach these through
the functions in `measures` and the `ObjSet` methods.
"""
from __future__ import annotations

import math
from collections.abc import Iterable

import numpy as np

from indoorgen.constraints import geometry
from indoorgen.constraints.node import Env, EvalContext, Node, ObjectView
from indoorgen.constraints.scalars import Scalar


class GeometricTerm(Scalar):
    """A scalar computed from the geometry of its sets' members; it watches every member so a
    move of any of them re-evaluates it."""

    def members(self, ev: EvalContext, env: Env) -> list[frozenset[str]]:
        """The members of each child set, all watched."""
        sets: list[frozenset[str]] = [ev.get(c, env) for c in self.children]
        for s in sets:
            ev.watch(s)
        return sets


class Volume(GeometricTerm):
    """Total bounding-box volume of a set (the product of the extents along `dims`)."""

    def __init__(self, objs: Node[frozenset[str]], dims: tuple[int, ...]):
        super().__init__(objs)
        self.dims = dims

    def compute(self, ev: EvalContext, env: Env) -> float:
        """`geometry.bbox_volume` of the members' extents."""
        (s,) = self.members(ev, env)
        if not s:
            return 0.0
        return geometry.bbox_volume(np.array([ev.view.extents(o) for o in sorted(s)]), self.dims)


class Area(GeometricTerm):
    """Total bounding-box area of a set (each member's two largest extents)."""

    def compute(self, ev: EvalContext, env: Env) -> float:
        """`geometry.bbox_area` of the members' extents."""
        (s,) = self.members(ev, env)
        if not s:
            return 0.0
        return geometry.bbox_area(np.array([ev.view.extents(o) for o in sorted(s)]))


class Distance(GeometricTerm):
    """Smallest 2D (plan view) distance between two sets; a room counts as its walls."""

    def compute(self, ev: EvalContext, env: Env) -> float:
        """The least outline distance over pairs of distinct members (0 if there is none)."""
        a, b = self.members(ev, env)
        best = math.inf
        for x in sorted(a):
            gx = ev.view.outline(x)
            for y in sorted(b):
                if y != x:
                    best = min(best, gx.distance(ev.view.outline(y)))
        return best if best < math.inf else 0.0


class CenterDistance(GeometricTerm):
    """Smallest plan distance between the bounding-box centres of two sets' members: "centred
    over" (a hood over a range, a light over a table), where outline distance is 0 for any
    overlap."""

    def compute(self, ev: EvalContext, env: Env) -> float:
        """The least centre-to-centre plan distance over pairs of distinct members (0 if none)."""
        a, b = self.members(ev, env)
        best = math.inf
        for x in sorted(a):
            cx = ev.view.center(x)[:2]
            for y in sorted(b):
                if y != x:
                    best = min(best, float(np.linalg.norm(ev.view.center(y)[:2] - cx)))
        return best if best < math.inf else 0.0


def front_centre(view: ObjectView, o: str) -> np.ndarray:
    """Plan point at the middle of `o`'s front face (where one stands to use it)."""
    c, f = view.center(o)[:2], view.front(o)[:2]
    return c + float(np.dot(view.front_point(o)[:2] - c, f)) * f


class FrontDistance(GeometricTerm):
    """Smallest plan distance between the front-face centres of two sets' members: the legs of a
    kitchen's work triangle, walked between where one stands at each (the quality report's)."""

    def compute(self, ev: EvalContext, env: Env) -> float:
        """The least front-to-front plan distance over pairs of distinct members (0 if none)."""
        a, b = self.members(ev, env)
        best = math.inf
        for x in sorted(a):
            fx = front_centre(ev.view, x)
            for y in sorted(b):
                if y != x:
                    best = min(best, float(np.linalg.norm(front_centre(ev.view, y) - fx)))
        return best if best < math.inf else 0.0


class MinDistance(GeometricTerm):
    """Smallest 3D mesh-to-mesh distance between two sets."""

    def compute(self, ev: EvalContext, env: Env) -> float:
        """The least `geometry.min_distance` over pairs of distinct members (0 if none)."""
        a, b = self.members(ev, env)
        best = math.inf
        for x in sorted(a):
            others = [ev.view.world_mesh(y) for y in sorted(b) if y != x]
            if others:
                best = min(best, geometry.min_distance([ev.view.world_mesh(x)], others))
        return best if best < math.inf else 0.0


def _nearest(ev: EvalContext, o: str, candidates: Iterable[str]) -> str | None:
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
    """How far a set's members are from facing along the inward normal of the nearest edge of
    the nearest reference footprint."""

    def compute(self, ev: EvalContext, env: Env) -> float:
        """The sum of `geometry.angle_alignment_cost` over the members."""
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
    """How far a set's members turn away from their nearest target."""

    def compute(self, ev: EvalContext, env: Env) -> float:
        """The sum of `geometry.focus_score` over the members."""
        a, ref = self.members(ev, env)
        total = 0.0
        for o in sorted(a):
            r = _nearest(ev, o, ref)
            if r is None:
                continue
            total += geometry.focus_score(ev.view.center(o)[None, :2], ev.view.front(o)[None, :2],
                                          ev.view.center(r)[:2])
        return total


class FacingAngle(GeometricTerm):
    """Angle (deg) between each member's front and the direction to its nearest target's
    centre, summed."""

    def compute(self, ev: EvalContext, env: Env) -> float:
        """The sum of `geometry.facing_angle` over the members (a member without a target: 0)."""
        a, ref = self.members(ev, env)
        total = 0.0
        for o in sorted(a):
            r = _nearest(ev, o, ref)
            if r is not None:
                total += geometry.facing_angle(ev.view.center(o), ev.view.front(o),
                                               ev.view.center(r))
        return total


#: the faces a clearance is measured before: (axis of the extent along the face's normal,
#: sign along the front (+1) or the side axis (+1: local +Y, the left))
FACES = {"front": (0, 1.0), "left": (1, 1.0), "right": (1, -1.0)}


class FrontClearance(GeometricTerm):
    """Free plan depth before each member's `face` (front, left or right side) over its width
    (less `margin` at either end) to the nearest blocker's footprint or wall, at most `probe`;
    summed."""

    def __init__(self, a: Node[frozenset[str]], b: Node[frozenset[str]], probe: float,
                 margin: float, face: str = "front"):
        super().__init__(a, b)
        self.probe, self.margin, self.face = probe, margin, face

    def compute(self, ev: EvalContext, env: Env) -> float:
        """The sum of `geometry.front_free_depth` over the members."""
        a, b = self.members(ev, env)
        v = ev.view
        axis, sign = FACES[self.face]
        total = 0.0
        for o in sorted(a):
            ext = v.extents(o)
            f, s = v.front(o)[:2], v.side_axis(o)[:2]
            normal, along = (f * sign, s) if axis == 0 else (s * sign, f)
            mid = v.center(o)[:2] + normal * float(ext[axis]) / 2
            hw = max(float(ext[1 - axis]) / 2 - self.margin, 0.01)
            edge = (mid - along * hw, mid + along * hw)
            total += geometry.front_free_depth(edge, normal, [v.outline(y) for y in sorted(b)
                                                              if y != o], self.probe)
        return total


class Accessibility(GeometricTerm):
    """How much blockers stand in front of a set's members (`fast`: bounding boxes, else
    exact meshes)."""

    def __init__(self, a: Node[frozenset[str]], b: Node[frozenset[str]], fast: bool = True):
        super().__init__(a, b)
        self.fast = fast

    def compute(self, ev: EvalContext, env: Env) -> float:
        """The sum of `geometry.accessibility_cost_fast` (or `_slow`) over the members."""
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
    """How far a set is from an evenly spaced ring of members facing its centre."""

    def compute(self, ev: EvalContext, env: Env) -> float:
        """`geometry.rotational_asymmetry` of the members (0 for fewer than two)."""
        (s,) = self.members(ev, env)
        if len(s) < 2:
            return 0.0
        objs = sorted(s)
        return geometry.rotational_asymmetry(np.array([ev.view.center(o)[:2] for o in objs]),
                                             np.array([ev.view.front(o)[:2] for o in objs]))


class ReflectionalAsymmetry(GeometricTerm):
    """Mirror asymmetry of a set about the first reference's front-back median plane."""

    def compute(self, ev: EvalContext, env: Env) -> float:
        """`geometry.reflectional_asymmetry` of the members (0 if either set is empty)."""
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
    """Free plan area left on a set's footprints once the occupants are placed."""

    def compute(self, ev: EvalContext, env: Env) -> float:
        """`geometry.freespace_2d` of the members' and the other occupants' footprints."""
        a, b = self.members(ev, env)
        return geometry.freespace_2d([ev.view.footprint(o) for o in sorted(a)],
                                     [ev.view.footprint(o) for o in sorted(b - a)])


class CenterOfSupport(GeometricTerm):
    """Plan distance from each member to the centre of the surface it rests on, summed."""

    def compute(self, ev: EvalContext, env: Env) -> float:
        """The sum of `geometry.center_of_support_distance` over supported members."""
        (s,) = self.members(ev, env)
        total = 0.0
        for o in sorted(s):
            sup = ev.view.support_polygon(o)
            if sup is not None:
                total += geometry.center_of_support_distance(ev.view.center(o)[:2], sup)
        return total


class Height(GeometricTerm):
    """Height of each member's bounding-box centre above its room's floor, summed."""

    def compute(self, ev: EvalContext, env: Env) -> float:
        """The sum of centre heights over the floor."""
        (s,) = self.members(ev, env)
        return float(math.fsum(float(ev.view.center(o)[2]) - ev.view.floor_z(o)
                               for o in sorted(s)))
