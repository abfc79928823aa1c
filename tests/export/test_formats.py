"""Export format names: parsed, aliased, deduplicated and checked."""
from __future__ import annotations

import pytest

from indoorgen.errors import IndoorGenError
from indoorgen.export.formats import DEFAULT_FORMATS, FORMATS, UnknownFormatError, parse_formats


def test_parse_formats():
    assert parse_formats(None) == ["usd", "urdf", "mjcf"] == list(DEFAULT_FORMATS)
    assert parse_formats("glTF, usd,usd") == ["glb", "usd"]
    assert parse_formats(["xml", "mujoco", "OBJ"]) == ["mjcf", "obj"]
    assert parse_formats(",".join(FORMATS)) == list(FORMATS)
    with pytest.raises(IndoorGenError, match="'fbx'.*valid: usd"):
        parse_formats("usd,fbx")
    with pytest.raises(UnknownFormatError, match="no export format"):
        parse_formats(" , ")
