"""The constraint DSL: object sets, relations, scalar terms, constraints and `Problem`."""
from indoorgen.constraints.expressions import (
           Constraint,
           Not,
           ObjSet,
           Problem,
           Scalar,
           ScoreTerm,
           accessibility_cost,
           all_of,
           angle_alignment_cost,
           area,
           center_of_support_distance,
           distance,
           focus_score,
           freespace_2d,
           height,
           min_distance,
           reflectional_asymmetry,
           rotational_asymmetry,
           scene,
           volume,
)
from indoorgen.constraints.relations import (
           AnyRelation,
           CoPlanar,
           NegatedRelation,
           Relation,
           StableAgainst,
           SupportedBy,
           Touching,
)

__all__ = ["Constraint", "Not", "ObjSet", "Problem", "Scalar", "ScoreTerm", "accessibility_cost",
           "all_of", "angle_alignment_cost", "area", "center_of_support_distance", "distance",
           "focus_score", "freespace_2d", "height", "min_distance", "reflectional_asymmetry",
           "rotational_asymmetry", "scene", "volume", "AnyRelation", "CoPlanar",
           "NegatedRelation", "Relation", "StableAgainst", "SupportedBy", "Touching"]
