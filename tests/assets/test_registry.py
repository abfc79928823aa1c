"""The generator registry: every generator module is found (sub-packages included), names are
unique and sorted, unknown names fail with the valid ones listed, tag queries filter."""
from __future__ import annotations

import pytest

from indoorgen.assets import generators
from indoorgen.assets.catalogue import factories_with, factory_names, get_factory
from indoorgen.assets.protocol import AssetFactory
from indoorgen.assets.registry import register
from indoorgen.errors import UnknownGeneratorError
from indoorgen.model.tags import Semantics


def test_every_generator_is_registered_once():
    names = factory_names()
    assert len(names) == 135 and names == sorted(set(names))
    # family sub-packages are walked too
    assert {"side_chair", "cabinet", "desk", "clock", "pendant_light"} <= set(names)
    assert generators.__path__


def test_get_factory():
    f = get_factory("bookcase")
    assert isinstance(f, AssetFactory) and f.name == "bookcase"
    with pytest.raises(UnknownGeneratorError, match="valid: .*bookcase"):
        get_factory("no_such_thing")


def test_factories_with_tags():
    chairs = factories_with([Semantics.Chair])
    assert "office_chair" in chairs and "sofa" not in chairs
    assert "office_chair" not in factories_with([Semantics.Chair], without=[Semantics.OfficeChair])


def test_register_refuses_nameless_and_duplicate_generators():
    class Nameless(AssetFactory):
        pass

    class Impostor(AssetFactory):
        name = "bookcase"

    with pytest.raises(ValueError, match="no name"):
        register(Nameless)
    with pytest.raises(ValueError, match="duplicate"):
        register(Impostor)
    assert type(get_factory("bookcase")).__name__ == "Bookcase"
