"""Relations every room program uses, named for what they mean in a room, and the ceiling
lights every room counts."""
from indoorgen.constraints import ObjSet, StableAgainst, SupportedBy, scene
from indoorgen.model.tags import Semantics, Subpart

#: standing on the room's floor
on_floor = StableAgainst(Subpart.Bottom, Subpart.Floor)
#: back to a wall, 5 cm off it (skirting boards, cables)
against_wall = StableAgainst(Subpart.Back, Subpart.Wall, margin=0.05)
#: hanging flat on a wall (pictures, mirrors), not overhanging its edges
on_wall = StableAgainst(Subpart.Back, Subpart.Wall)
#: resting on a tabletop, shelf or stand without tipping over
on_top = SupportedBy(Subpart.Bottom, Subpart.SupportSurface)
#: put away inside: on a shelf or floor behind a cabinet's, wardrobe's or fridge's doors
inside = SupportedBy(Subpart.Bottom, Subpart.Interior)
#: a chair pulled up to a table: its front 4 cm under the table's edge (clear of legs inset
#: from the edge and of stretchers between them)
at_table = StableAgainst(Subpart.Front, Subpart.Side, margin=-0.04, overhang=False)
#: hanging from the ceiling by its top (ceiling lights, pendants)
on_ceiling = StableAgainst(Subpart.Top, Subpart.Ceiling)
#: a side flush against a wall (the second wall of a corner: a bathtub, a kitchen run's end)
side_to_wall = StableAgainst(Subpart.Side, Subpart.Wall, margin=0.02)
#: standing wholly on a surface, nothing overhanging (a TV on its stand, a microwave)
fully_on = StableAgainst(Subpart.Bottom, Subpart.SupportSurface)


def ceiling_lights(room: ObjSet) -> ObjSet:
    """The lights hanging from `room`'s ceiling (every room program counts them)."""
    return scene()[Semantics.CeilingMounted, Semantics.Lighting].related_to(room, on_ceiling)
