"""A bedroom: a bed against a wall with nightstands either side, storage for clothes, a rug,
lamps and pictures, and a few things on the surfaces."""
from indoorgen.constraints import (
    ObjSet,
    Problem,
    accessibility_cost,
    angle_alignment_cost,
    height,
    reflectional_asymmetry,
    scene,
)
from indoorgen.model.tags import Semantics as S
from indoorgen.programs.relations import against_wall, ceiling_lights, on_floor, on_top, on_wall


def bedroom(room: ObjSet) -> Problem:
    """One bed against a wall, nightstands mirroring each other beside it, clothes storage."""
    floor = scene().related_to(room, on_floor)
    beds = floor[S.Bed].excluding(S.BunkBed).related_to(room, against_wall)
    nightstands = floor[S.Nightstand].related_to(room, against_wall)
    wardrobes = floor[S.Wardrobe].related_to(room, against_wall)
    dressers = floor[S.Dresser].related_to(room, against_wall)
    clothes_storage = wardrobes | dressers
    rugs = floor[S.Rug]
    art = scene()[S.WallArt].related_to(room, on_wall)
    lights = ceiling_lights(room)
    lamps = scene()[S.Lighting].excluding(S.CeilingMounted, S.WallMounted, S.FloorLamp).related_to(
        nightstands, on_top)
    things = scene()[S.SmallObject].excluding(S.Food, S.Kitchenware, S.Tableware).related_to(
        nightstands | clothes_storage, on_top)
    return Problem(
        constraints={
            "a bed": beds.count() == 1,
            "one or two nightstands": nightstands.count().in_range(1, 2),
            "a wardrobe or a dresser": (wardrobes.count() + dressers.count()).in_range(1, 2),
            "a rug at most": rugs.count().in_range(0, 1),
            "a ceiling light": lights.count() == 1,
            "lamps on the nightstands": nightstands.all(lambda n: lamps.related_to(n, on_top).count() <= 1),
            "pictures": art.count().in_range(1, 2),
            "a few things on the surfaces": things.count().in_range(1, 6),
        },
        score_terms={
            "nightstands beside the bed": nightstands.mean(
                lambda n: n.distance(beds).hinge(0.0, 0.1)).minimize(4),
            "nightstands mirror each other": beds.mean(
                lambda b: reflectional_asymmetry(nightstands, b)).minimize(1),
            "bed side free": accessibility_cost(beds, floor.excluding(S.Rug, S.Nightstand)).minimize(2),
            "storage fronts free": accessibility_cost(clothes_storage, floor.excluding(S.Rug)).minimize(2),
            "rug under the bed's foot": rugs.mean(lambda r: r.distance(beds).hinge(0.0, 0.3)).minimize(1),
            "furniture square to the walls": angle_alignment_cost(floor, room).minimize(1),
            "a lamp per nightstand": lamps.count().maximize(0.5),
            "pictures at eye level": art.mean(lambda a: height(a).hinge(1.3, 1.8)).minimize(2),
            "pictures in view": accessibility_cost(art, floor).minimize(2),
        },
    )
