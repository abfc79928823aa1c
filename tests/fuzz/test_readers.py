"""Every reader of a user's data over structured mutations of real files and over hostile
payloads (deep nesting, huge and non-finite numbers, 10^6 vertices, wrong types, unknown names):
the only exception allowed out is an IndoorGenError, each example within the profile's deadline
and, for the hostile payloads, under 1 GB of memory.

Example budgets are the hypothesis profiles in tests/conftest.py (`ci` by default; run
`pytest --hypothesis-profile long tests/fuzz` for the long run)."""
from __future__ import annotations

import argparse
import contextlib
import copy
import json
import math
import re
import tempfile
import tracemalloc
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from indoorgen.cli.floorplan import _read_contour, _read_graph
from indoorgen.cli.generate import _room_config
from indoorgen.errors import IndoorGenError
from indoorgen.export.scene_files import export_scene, read_scene
from indoorgen.floorplan.contour import user_contour
from indoorgen.floorplan.graph import graph_from_spec
from indoorgen.floorplan.rooms import parse_room_counts
from indoorgen.model.floorplan_io import read_floorplan
from indoorgen.model.polygons import validate_polygon
from indoorgen.validate import validate_scene_dir

DATA = Path(__file__).resolve().parents[1] / "data"
FLOORPLAN = json.loads((DATA / "apartment.json").read_text())
SCENE = json.loads((DATA / "scene_bathroom.json").read_text())
POLYGON = [[0, 0], [5, 0], [5, 4], [2, 4], [2, 3], [0, 3]]
GRAPH = {"storeys": [{"rooms": ["living_room_0", "kitchen_0", "bedroom_0", "bathroom_0"],
                      "edges": [["living_room_0", "kitchen_0"], ["living_room_0", "bedroom_0"],
                                ["living_room_0", "bathroom_0"]]}],
         "entrance": "living_room_0"}
GIB = 1 << 30

#: values a hostile or careless file puts where a number, name or list belongs
HOSTILE = st.one_of(
    st.sampled_from([math.nan, math.inf, -math.inf, 1e308, -1e308, 10**400, -(10**30), -1, 0,
                     True, None, "", "ballroom_0", "hovercraft", "~" * 300, "NaN", [], {},
                     [[0, 0]], [0, 0, 0, 0], {"x": 1}, "StableAgainst(bottom, top, nan)"]),
    st.floats(allow_nan=True, allow_infinity=True),
    st.integers(min_value=-(2**70), max_value=2**70),
    st.text(max_size=20),
    st.recursive(st.none() | st.floats() | st.text(max_size=5),
                 lambda c: st.lists(c, max_size=3) | st.dictionaries(st.text(max_size=5), c,
                                                                       max_size=3),
                 max_leaves=10),
)


def _hostile(data: st.DataObject) -> Any:
    """A fresh hostile value (a copy: one drawn list or dict must not turn up twice in a file,
    which would make it circular)."""
    return copy.deepcopy(data.draw(HOSTILE))


def _paths(doc: Any, prefix: tuple = ()) -> list[tuple]:
    """Every path (keys and indices) into `doc`, the root included."""
    out = [prefix]
    if isinstance(doc, dict):
        for k, v in doc.items():
            out += _paths(v, prefix + (k,))
    elif isinstance(doc, list):
        for i, v in enumerate(doc):
            out += _paths(v, prefix + (i,))
    return out


def _mutated(doc: Any, data: st.DataObject, n_max: int = 3) -> Any:
    """`doc` (a copy) with up to `n_max` structured mutations: a value replaced by a hostile
    one, a key or item removed, an item duplicated, a key added."""
    doc = json.loads(json.dumps(doc))
    for _ in range(data.draw(st.integers(1, n_max))):
        paths = _paths(doc)
        path = data.draw(st.sampled_from(paths[1:] if len(paths) > 1 else paths))
        if not path:
            return _hostile(data)
        parent = doc
        for k in path[:-1]:
            parent = parent[k]
        key = path[-1]
        kind = data.draw(st.sampled_from(["replace", "remove", "duplicate", "add"]))
        if kind == "replace":
            parent[key] = _hostile(data)
        elif kind == "remove":
            del parent[key]
        elif kind == "duplicate" and isinstance(parent, list):
            parent.insert(key, json.loads(json.dumps(parent[key])))
        elif isinstance(parent, dict):
            parent[data.draw(st.sampled_from(["colour", "name", "rooms", "polygon"]))] = \
                _hostile(data)
    return doc


def _text(doc: Any) -> str:
    """JSON text of `doc`, non-finite numbers as the NaN / Infinity tokens a careless writer
    emits."""
    return json.dumps(doc, allow_nan=True)


def _only_indoorgen_errors(read: Callable[[Path], Any], text: str, name: str) -> None:
    """`read` the file holding `text`; anything but an IndoorGenError fails the test."""
    with tempfile.TemporaryDirectory() as d:
        p = Path(d) / name
        p.write_text(text)
        try:
            read(p)
        except IndoorGenError as e:
            assert "\n" not in str(e), str(e)


def _floorplan(p: Path) -> None:
    read_floorplan(p)


def _scene(p: Path) -> None:
    read_scene(p)


def _contour(p: Path) -> None:
    user_contour(_read_contour(str(p)))


def _graph(p: Path) -> None:
    graph_from_spec(_read_graph(str(p)))


def _polygon(p: Path) -> None:
    ns = argparse.Namespace(room=None, size=None, program=None, check=False, preset="default", style=None,
                            polygon=p.read_text())
    validate_polygon(_room_config(ns).polygon)


READERS = {"floorplan": (_floorplan, FLOORPLAN, "floorplan.json"),
           "scene": (_scene, SCENE, "scene.json"),
           "contour": (_contour, POLYGON, "contour.json"),
           "graph": (_graph, GRAPH, "graph.json"),
           "polygon": (_polygon, POLYGON, "polygon.json")}


@pytest.mark.parametrize("reader", sorted(READERS))
def test_real_files_read(reader):
    read, doc, name = READERS[reader]
    with tempfile.TemporaryDirectory() as d:
        (Path(d) / name).write_text(_text(doc))
        read(Path(d) / name)


@pytest.mark.parametrize("reader", sorted(READERS))
@given(data=st.data())
def test_mutated_files_give_only_indoorgen_errors(reader, data):
    read, doc, name = READERS[reader]
    _only_indoorgen_errors(read, _text(_mutated(doc, data)), name)


@given(text=st.text(max_size=200))
def test_room_counts_give_only_indoorgen_errors(text):
    with contextlib.suppress(IndoorGenError):
        parse_room_counts(text)


def _deep(n: int) -> str:
    return "[" * n + "]" * n


HOSTILE_TEXTS = {
    "deep nesting": _deep(200_000),
    "deep objects": '{"a":' * 50_000 + "1" + "}" * 50_000,
    "a million vertices": json.dumps([[i % 7, i % 5] for i in range(1_000_000)]),
    "huge numbers": json.dumps([[0, 0], [1e308, 0], [1e308, 1e308], [0, 1e308]]),
    "non-finite": "[[0, 0], [NaN, 0], [Infinity, -Infinity], [0, 1]]",
    "wrong types": json.dumps({"storeys": "three", "rooms": 7, "objects": {"a": 1}}),
    "not json": "\x00\xff{[",
    "empty": "",
}


@pytest.mark.parametrize("reader", sorted(READERS))
@pytest.mark.parametrize("payload", sorted(HOSTILE_TEXTS))
def test_hostile_payloads_are_refused_within_a_gigabyte(reader, payload):
    read, _, name = READERS[reader]
    tracemalloc.start()
    try:
        _only_indoorgen_errors(read, HOSTILE_TEXTS[payload], name)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak < GIB


@pytest.mark.slow
def test_a_huge_circle_of_a_floorplan_room_is_refused(tmp_path):
    """A valid 10^6-vertex room (the probe's 45 s and 1.8 GB) is refused from its size, before
    it is read; a 10^5-vertex one (under the size cap) by the vertex cap."""
    for n in (1_000_000, 100_000):
        doc = json.loads(json.dumps(FLOORPLAN))
        t = np.linspace(0, 2 * np.pi, n, endpoint=False)
        ring = np.round(np.c_[3 + 2 * np.cos(t), 2 + 2 * np.sin(t)], 6)
        doc["storeys"][0]["rooms"][0]["polygon"] = ring.tolist()
        (tmp_path / "f.json").write_text(json.dumps(doc))
        with pytest.raises(IndoorGenError, match="bytes; a floorplan file|at most 256 items"):
            read_floorplan(tmp_path / "f.json")


#: numbers the schema lets through, placed where the real file has numbers
IN_RANGE = st.one_of(st.floats(-999, 999, allow_nan=False), st.sampled_from([0.0, -0.0, 1e-9, 999.0]))


def _numbers_moved(doc: Any, data: st.DataObject) -> Any:
    """`doc` with a few object positions, yaws and parameters set to other in-range numbers."""
    doc = json.loads(json.dumps(doc))
    for _ in range(data.draw(st.integers(1, 3))):
        o = data.draw(st.sampled_from(doc["objects"]))
        where = data.draw(st.sampled_from(["x", "yaw", "param"]))
        if where == "x":
            o["pose"]["position"][data.draw(st.integers(0, 1))] = data.draw(IN_RANGE)
        elif where == "yaw":
            o["pose"]["yaw"] = data.draw(st.floats(-12, 12, allow_nan=False))
        elif o["params"]:
            k = data.draw(st.sampled_from(sorted(o["params"])))
            if isinstance(o["params"][k], float):
                o["params"][k] = data.draw(IN_RANGE)
    return doc


@pytest.mark.slow
@settings(max_examples=6, deadline=None)
@given(data=st.data())
def test_validate_and_export_of_schema_valid_scenes(data):
    """Past the reader: a scene whose numbers are in range but moved exports (no NaN reaches
    MJCF) and validates, or fails with an IndoorGenError."""
    doc = _numbers_moved(SCENE, data)
    with tempfile.TemporaryDirectory() as d:
        src = Path(d) / "src"
        src.mkdir()
        (src / "scene.json").write_text(_text(doc))
        try:
            out, _ = export_scene(src, Path(d) / "out", "mjcf", texture_resolution=0)
            xml = (out / "scene.xml").read_text()
            assert not re.search(r"(?<![\w.])[+-]?(nan|inf)(?![\w.])", xml, re.I)
            validate_scene_dir(src)
        except IndoorGenError as e:
            assert "\n" not in str(e)
