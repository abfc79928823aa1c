"""The constraint DSL: object sets, relations, scalar terms, constraints and `Problem`.

Programs import what they write with from here; the modules hold the language by job:
`sets` (ObjSet, scene(), Not), `scalars` (Scalar, arithmetic, counts, score terms), `logic`
(constraints), `measures` (geometric terms over sets), `relations`, `problem` (Problem);
`room_terms` has the room-level terms of floorplan programs, `evaluator` runs a problem
incrementally and `bounds` reads count bounds from it for the solver.
"""
from indoorgen.constraints.logic import Constraint, all_of
from indoorgen.constraints.measures import (
    accessibility_cost,
    angle_alignment_cost,
    area,
    center_of_support_distance,
    distance,
    facing_angle,
    focus_score,
    freespace_2d,
    front_clearance,
    height,
    min_distance,
    reflectional_asymmetry,
    rotational_asymmetry,
    volume,
)
from indoorgen.constraints.problem import Problem
from indoorgen.constraints.relations import (
    AnyRelation,
    CoPlanar,
    InLine,
    NegatedRelation,
    Relation,
    StableAgainst,
    SupportedBy,
    Touching,
)
from indoorgen.constraints.scalars import Scalar, ScoreTerm
from indoorgen.constraints.sets import Not, ObjSet, scene

__all__ = ["Constraint", "Not", "ObjSet", "Problem", "Scalar", "ScoreTerm", "accessibility_cost",
           "all_of", "angle_alignment_cost", "area", "center_of_support_distance", "distance",
           "facing_angle", "focus_score", "front_clearance", "freespace_2d", "height",
           "min_distance", "reflectional_asymmetry",
           "rotational_asymmetry", "scene", "volume", "AnyRelation", "CoPlanar",
           "InLine", "NegatedRelation", "Relation", "StableAgainst", "SupportedBy", "Touching"]
