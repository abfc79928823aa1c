"""A warehouse bay: pallet racks in rows along the walls and across the floor, pallets on the
floor and on the racks' levels, boxes on the pallets, aisles kept clear."""
from indoorgen.constraints import ObjSet, Problem, accessibility_cost, angle_alignment_cost, scene
from indoorgen.model.tags import Semantics as S
from indoorgen.programs.relations import against_wall, on_floor, on_top


def warehouse(room: ObjSet) -> Problem:
    """Racks along the walls and across the floor, stocked pallets, aisles clear."""
    floor = scene().related_to(room, on_floor)
    racks = floor[S.PalletRack]
    wall_racks = racks.related_to(room, against_wall)
    pallets_on_floor = floor[S.Pallet]
    pallets_on_racks = scene()[S.Pallet].related_to(racks, on_top)
    pallets = pallets_on_floor | pallets_on_racks
    boxes = scene()[S.Box].related_to(pallets, on_top)
    return Problem(
        constraints={
            "racks along the walls": wall_racks.count().in_range(1, 6),
            "racks": racks.count().in_range(2, 12),
            "pallets on the floor": pallets_on_floor.count().in_range(0, 8),
            "pallets on the racks": pallets_on_racks.count().in_range(2, 40),
            "boxes on the pallets": boxes.count().in_range(2, 80),
        },
        score_terms={
            "storage": racks.count().maximize(1),
            "stock": pallets_on_racks.count().maximize(0.3),
            "goods": boxes.count().maximize(0.05),
            "aisles clear": accessibility_cost(racks, floor).minimize(2),
            "racks square to the walls": angle_alignment_cost(racks, room).minimize(2),
        },
    )
