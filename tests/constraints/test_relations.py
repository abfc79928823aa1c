"""Relations: the implies/intersects algebra the solver reasons with, and reading them back from
their scene.json text."""
import pytest

from indoorgen.constraints import (
    AnyRelation,
    CoPlanar,
    InLine,
    StableAgainst,
    SupportedBy,
    Touching,
)
from indoorgen.constraints.relations import parse_relation
from indoorgen.errors import ConfigError
from indoorgen.model.tags import Subpart

on_floor = StableAgainst(Subpart.Bottom, Subpart.Floor)
against_wall = StableAgainst(Subpart.Back, Subpart.Wall, margin=0.05)
on_top = SupportedBy(Subpart.Bottom, Subpart.SupportSurface)
fully_on = StableAgainst(Subpart.Bottom, Subpart.SupportSurface)
in_line = InLine(Subpart.Side, Subpart.Side, 0.048)


def test_implies():
    assert on_floor.implies(on_floor) and on_floor.implies(AnyRelation())
    assert not on_floor.implies(against_wall)
    assert fully_on.implies(on_top) and not on_top.implies(fully_on)  # no overhang is stricter
    assert on_floor.implies(Touching(Subpart.Bottom, None)) and on_floor.implies(Touching())
    assert not against_wall.implies(Touching())  # 5 cm off the wall: not touching
    assert on_floor.implies(~against_wall) and not on_floor.implies(~on_floor)
    assert (~on_top).implies(~fully_on) and not (~fully_on).implies(~on_top)
    assert not AnyRelation().implies(on_floor) and AnyRelation().implies(AnyRelation())


def test_intersects():
    assert on_floor.intersects(AnyRelation()) and AnyRelation().intersects(on_floor)
    assert not on_floor.intersects(~on_floor) and not (~on_floor).intersects(on_floor)
    assert not AnyRelation().intersects(~AnyRelation())
    assert on_top.intersects(fully_on)  # one implies the other


def test_planar_relations():
    assert on_floor.is_planar and CoPlanar(Subpart.Front, Subpart.Front).is_planar
    assert not Touching().is_planar and not AnyRelation().is_planar


@pytest.mark.parametrize("rel", [on_floor, against_wall, on_top, fully_on, Touching(),
                                 Touching(Subpart.Bottom, Subpart.Top),
                                 CoPlanar(Subpart.Front, Subpart.Front, 0.01), AnyRelation(),
                                 ~on_floor, in_line])
def test_parse_relation_reads_back_the_repr(rel):
    assert parse_relation(repr(rel)) == rel


def test_parse_relation_rejects_junk():
    with pytest.raises(ConfigError):
        parse_relation("on the floor")
    with pytest.raises(ConfigError):
        parse_relation("Hovering(bottom,floor,0)")


def test_in_line_means_what_supported_by_means():
    beside = SupportedBy(Subpart.Side, Subpart.Side, 0.048)
    assert in_line != beside and repr(in_line).startswith("InLine(")
    assert in_line.implies(beside) and beside.implies(in_line)  # the same geometry
