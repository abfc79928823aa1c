"""The DSL's geometric measures, as functions of sets: what programs score rooms with.

`angle_alignment_cost(furniture, room)`, `focus_score(seating, tv_stands)`,
`accessibility_cost(beds, floor)`... Per-object measures are written as a sum over the set
(a quantifier), so the evaluator caches each object's share and a move recomputes only the moved
object's. The maths behind each lives in `geometry`, the nodes in `terms`.
"""
from __future__ import annotations

from collections.abc import Callable, Iterable

from indoorgen.constraints.scalars import Scalar
from indoorgen.constraints.sets import ObjSet
from indoorgen.constraints.terms import (
    FACES,
    Accessibility,
    AngleAlignment,
    CenterOfSupport,
    FacingAngle,
    Focus,
    Freespace2D,
    FrontClearance,
    Height,
    ReflectionalAsymmetry,
    RotationalAsymmetry,
)
from indoorgen.errors import ConstraintError


def _per_object(objs: ObjSet, make: Callable[[ObjSet], Scalar]) -> Scalar:
    """A sum over `objs` of a per-object term, written as a quantifier so the evaluator caches
    each object's share and a move re-computes only the moved object's."""
    return objs.sum(make)


def angle_alignment_cost(objs: ObjSet, reference: ObjSet) -> Scalar:
    """Sum over objs of (1 - cos angle)/2 between each front and the inward normal of the
    nearest edge of the nearest reference footprint (a room: its nearest wall)."""
    return _per_object(objs, lambda o: AngleAlignment(o, reference))


def focus_score(objs: ObjSet, target: ObjSet) -> Scalar:
    """Sum over objs of how far each one's front turns away from its nearest target (0..1 each)."""
    return _per_object(objs, lambda o: Focus(o, target))


def facing_angle(objs: ObjSet, target: ObjSet) -> Scalar:
    """Sum over objs of the angle (deg) between each front and the direction to its nearest
    target's centre: `sofas.all(lambda s: facing_angle(s, tv_stands) <= 20)`."""
    return _per_object(objs, lambda o: FacingAngle(o, target))


def front_clearance(objs: ObjSet, blockers: ObjSet, probe: float = 1.5,
                    margin: float = 0.05, face: str = "front") -> Scalar:
    """Sum over objs of the free depth (m, at most `probe`) before each one's `face` ("front",
    "left" or "right" side), over its width less `margin` at either end, to the nearest
    blocker or wall (a room among the blockers counts as its walls):
    `wardrobes.all(lambda w: front_clearance(w, floor | room) >= 0.6)`."""
    if face not in FACES:
        raise ConstraintError(f"front_clearance face {face!r} is not one of {sorted(FACES)}")
    return _per_object(objs, lambda o: FrontClearance(o, blockers, probe, margin, face))


def accessibility_cost(objs: ObjSet, blockers: ObjSet, fast: bool = True) -> Scalar:
    """How much `blockers` stand in front of `objs` (closer, bigger, more frontal = worse)."""
    return _per_object(objs, lambda o: Accessibility(o, blockers, fast))


def rotational_asymmetry(objs: ObjSet) -> Scalar:
    """How far objs are from an evenly spaced ring facing its centre (chairs round a table)."""
    return RotationalAsymmetry(objs)


def reflectional_asymmetry(objs: ObjSet, reference: ObjSet) -> Scalar:
    """Mirror asymmetry of objs about the reference's front-back median plane."""
    return ReflectionalAsymmetry(objs, reference)


def freespace_2d(objs: ObjSet, occupants: ObjSet) -> Scalar:
    """Plan area of objs' footprints left free by the occupants (space left on a table)."""
    return Freespace2D(objs, occupants)


def center_of_support_distance(objs: ObjSet) -> Scalar:
    """Sum of plan distances from each object to the centre of the surface it rests on."""
    return _per_object(objs, CenterOfSupport)


def height(objs: ObjSet) -> Scalar:
    """Sum of the heights above their room's floor of the objects' bounding-box centres (for
    hanging pictures at eye level, on any storey)."""
    return _per_object(objs, Height)


def volume(objs: ObjSet, dims: Iterable[int] = (0, 1, 2)) -> Scalar:
    """Sum of the objects' bounding-box volumes along `dims` (see `ObjSet.volume`)."""
    return objs.volume(dims)


def area(objs: ObjSet) -> Scalar:
    """Sum of the objects' bounding-box areas (see `ObjSet.area`)."""
    return objs.area()


def distance(a: ObjSet, b: ObjSet) -> Scalar:
    """Smallest plan distance between the two sets (see `ObjSet.distance`)."""
    return a.distance(b)


def min_distance(a: ObjSet, b: ObjSet) -> Scalar:
    """Smallest 3D mesh-to-mesh distance between the two sets (see `ObjSet.min_distance`)."""
    return a.min_distance(b)
