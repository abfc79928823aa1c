"""Which solid pieces of a room overlap: axis-aligned boxes in numpy, then fcl's narrow phase.

The annealer asks one question thousands of times: does the object just moved collide with
anything else? python-fcl's broadphase managers answer it, but only for an object that is not
in the manager itself, and taking one out scans a Python list of every registered piece, so a
step cost grew with the room's size. Here every object keeps its pieces' world boxes; a query
tests the moved object's box against all other objects' boxes and the architecture's in a few
vectorised comparisons, then runs `fcl.collide` on the piece pairs whose boxes overlap.

Not every pair of pieces may collide. An object's *keep-free* pieces (`solver.keep_free`: a
drawer's sweep, a toilet's clear space) meet walls and other objects' solid pieces only, and not
the pieces of what the object carries (what rests on or in it), nor of what yields to them
(rugs to everything, small objects to use zones, as the quality rules count them). A floor
covering lies *under* other objects: furniture stands on the floor through it, so its solid
pieces meet only solid architecture and other floor coverings (a door swings over it). Fixed
pieces are of a `kind`: solid architecture, door keep-out zones (solid pieces only) and window
keep-out zones (solid pieces of objects the window rule names only).
"""
from __future__ import annotations

from collections.abc import Callable

import fcl
import numpy as np

#: boxes closer than this count as overlapping (fcl reports touching solids as colliding)
BOX_TOL = 1e-9
#: kinds of fixed pieces: walls, floors and ceilings; door keep-out zones; window keep-out zones;
#: the zones before windows down to the floor, where no screen's stand goes
SOLID, DOOR_ZONE, WINDOW_ZONE, SCREEN_ZONE = 0, 1, 2, 3
#: kinds of an object's pieces: solid; keep-free sweeps of moving parts; keep-free use zones
#: (a toilet's clearance, a front's)
PIECE_SOLID, PIECE_SWEEP, PIECE_ZONE = 0, 1, 2
#: what an object's solid pieces yield to other objects' keep-free pieces: nothing; use zones
#: (small objects: a cup may stand before a cabinet); everything (a drawer opens over it); and
#: everything lies on it too, even solids (rugs: a sofa's legs stand on the floor through one)
YIELD_NONE, YIELD_ZONES, YIELD_ALL, YIELD_UNDER = 0, 1, 2, 3


def world_boxes(local: np.ndarray, rotation: np.ndarray, translation: np.ndarray) -> np.ndarray:
    """World boxes (k, 6: min xyz, max xyz) of local boxes `local` (k, 2, 3) under a rigid
    transform: each rotated box's own bounding box (exact for turns about +Z of upright boxes,
    conservative otherwise)."""
    lo, hi = local[:, 0], local[:, 1]
    centre = (lo + hi) / 2 @ rotation.T + translation
    half = (hi - lo) / 2 @ np.abs(rotation).T
    return np.concatenate([centre - half, centre + half], axis=1)


def _keys(boxes: np.ndarray) -> np.ndarray:
    """Boxes (n, 6: min, max) as overlap keys (min, -max): a box overlaps a query box q when
    its keys are all <= `_query(q)`, one comparison per row (this runs thousands of times a
    second on a handful of rows, where each numpy call's overhead is what costs)."""
    return np.concatenate([boxes[:, :3], -boxes[:, 3:]], axis=1)


def _query(box: np.ndarray) -> np.ndarray:
    return np.concatenate([box[3:], -box[:3]]) + BOX_TOL


def _overlapping(keys: np.ndarray, query: np.ndarray) -> np.ndarray:
    """Indices of the rows of `keys` whose boxes overlap the query box."""
    return np.flatnonzero((keys <= query).all(axis=1))


class Broadphase:
    """The pieces of one room: fixed architecture and keep-out volumes (by kind), and movable
    objects' solid and keep-free pieces by object name (state: the pieces and their current
    world boxes)."""

    def __init__(self, static: list[fcl.CollisionObject], static_boxes: np.ndarray,
                 static_kinds: np.ndarray | None = None) -> None:
        self._static = list(static)
        self._static_keys = _keys(np.asarray(static_boxes, float).reshape(-1, 6))
        self._static_kinds = np.zeros(len(self._static), int) if static_kinds is None \
            else np.asarray(static_kinds, int)
        # name -> (pieces, their boxes, their keys, their kinds)
        self._pieces: dict[str, tuple[list[fcl.CollisionObject], np.ndarray, np.ndarray,
                                      np.ndarray]] = {}
        self._yields: dict[str, int] = {}
        self._names: list[str] = []            # row i of _union belongs to _names[i]
        self._row: dict[str, int] = {}
        self._union = np.zeros((0, 6))         # keys of each object's box round all its pieces

    def add(self, name: str, pieces: list[fcl.CollisionObject], boxes: np.ndarray,
            kinds: np.ndarray | None = None, yields: int = YIELD_NONE) -> None:
        """Register object `name` with its pieces (already posed), their world boxes, their
        kinds (default: all solid) and what its solid pieces yield to others' keep-free ones."""
        kind = np.zeros(len(pieces), int) if kinds is None else np.asarray(kinds, int)
        self._pieces[name] = (pieces, boxes, _keys(boxes), kind)
        self._yields[name] = yields
        self._row[name] = len(self._names)
        self._names.append(name)
        self._union = np.vstack([self._union, _keys(_union_box(boxes)[None])])

    def remove(self, name: str) -> None:
        """Forget object `name` (the last row moves into its place)."""
        del self._pieces[name]
        del self._yields[name]
        i = self._row.pop(name)
        last = self._names.pop()
        if last != name:
            self._names[i] = last
            self._row[last] = i
            self._union[i] = self._union[-1]
        self._union = self._union[:-1]

    def move(self, name: str, boxes: np.ndarray) -> None:
        """New world boxes of object `name`'s pieces (their fcl transforms are already set)."""
        pieces, _, _, kinds = self._pieces[name]
        self._pieces[name] = (pieces, boxes, _keys(boxes), kinds)
        self._union[self._row[name]] = _keys(_union_box(boxes)[None])[0]

    def collides(self, name: str, *, windows: bool = False, screens: bool = False,
                 carries: Callable[[str, str], bool] | None = None) -> bool:
        """Does a piece of object `name` overlap a piece it may not: of the architecture (window
        zones only if `windows`, the zones below them only if `screens`), or of another object
        (keep-free pieces only against solid ones, not against what yields to them, and not
        against what the keep-free piece's owner carries: `carries(a, b)`, does `b` rest on or
        in `a`, as a drawer's contents do)?"""
        pieces, boxes, keys, kinds = self._pieces[name]
        if not pieces:
            return False
        own = _query(_union_box(boxes))
        request = fcl.CollisionRequest()
        free = kinds != PIECE_SOLID
        has_free = bool(free.any())
        solid_only = ~free if has_free else None
        # which of my pieces meet another's solid pieces, by what those yield
        meet = {YIELD_NONE: None, YIELD_ZONES: kinds != PIECE_ZONE if has_free else None,
                YIELD_ALL: solid_only, YIELD_UNDER: solid_only}
        under = self._yields[name] == YIELD_UNDER
        for j in _overlapping(self._static_keys, own):
            kind = self._static_kinds[j]
            if (kind == WINDOW_ZONE and not windows) or (kind == SCREEN_ZONE and not screens) \
                    or (kind == DOOR_ZONE and under):
                continue  # a rug may lie where a door swings and one walks through
            mask = None if kind == SOLID else solid_only
            if self._any_hit(pieces, keys, mask, self._static[j], self._static_keys[j], request):
                return True
        held = _Memo(carries)
        mine = self._yields[name]
        for i in _overlapping(self._union, own):
            other = self._names[i]
            if other == name or (self._yields[other] == YIELD_UNDER) != under:
                continue  # a floor covering and what stands on it
            other_pieces, _, other_keys, other_kinds = self._pieces[other]
            for k in _overlapping(other_keys, own):
                ok = other_kinds[k]
                if ok != PIECE_SOLID:  # their keep-free piece: only my solid pieces, if not theirs
                    if mine >= (YIELD_ZONES if ok == PIECE_ZONE else YIELD_ALL) or \
                            held(other, name):
                        continue
                    mask = ~free
                else:  # their solid piece: my keep-free pieces too, unless it yields or I carry it
                    mask = solid_only if has_free and held(name, other) else \
                        meet[self._yields[other]]
                if self._any_hit(pieces, keys, mask, other_pieces[k], other_keys[k], request):
                    return True
        return False

    @staticmethod
    def _any_hit(pieces, keys, mask: np.ndarray | None, other: fcl.CollisionObject,
                 other_key: np.ndarray, request: fcl.CollisionRequest) -> bool:
        """Does one of `pieces` (overlap keys `keys`; only those `mask` selects, if given)
        collide with `other` (key `other_key`)?"""
        query = np.concatenate([-other_key[3:], -other_key[:3]]) + BOX_TOL  # its box, as a query
        for k in _overlapping(keys, query):
            if mask is not None and not mask[k]:
                continue
            if fcl.collide(pieces[k], other, request, fcl.CollisionResult()) > 0:
                return True
        return False


class _Memo:
    """`carries(a, b)` asked once per pair during one query (False without a `carries`)."""

    def __init__(self, carries: Callable[[str, str], bool] | None) -> None:
        self._carries = carries
        self._known: dict[tuple[str, str], bool] = {}

    def __call__(self, a: str, b: str) -> bool:
        got = self._known.get((a, b))
        if got is None:
            got = self._known[(a, b)] = self._carries is not None and self._carries(a, b)
        return got


def _union_box(boxes: np.ndarray) -> np.ndarray:
    if len(boxes) == 0:  # no pieces: a box no query overlaps
        return np.array([np.inf, np.inf, np.inf, -np.inf, -np.inf, -np.inf])
    return np.concatenate([boxes[:, :3].min(axis=0), boxes[:, 3:].max(axis=0)])
