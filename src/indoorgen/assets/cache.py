"""Built assets and their collision BVHs, cached by (generator, params).

The solver asks for the same placeholder many times (resample, revert, re-add); building it and
its BVH once per distinct parameter set keeps the annealing step cheap.
"""
from __future__ import annotations

import json
from typing import Any

import fcl
import numpy as np
import shapely.geometry as sg
import trimesh

from indoorgen.assets.catalogue import get_factory
from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Asset


def params_key(generator: str, params: dict[str, Any]) -> tuple:
    """A hashable key for (generator, params): the params as sorted JSON."""
    return (generator, json.dumps(params, sort_keys=True, default=str))


def mesh_bvh(mesh: trimesh.Trimesh) -> fcl.BVHModel:
    """An fcl BVH of a trimesh (built once; objects share it and only change their transform)."""
    bvh = fcl.BVHModel()
    bvh.beginModel(len(mesh.vertices), len(mesh.faces))
    bvh.addSubModel(np.asarray(mesh.vertices, float), np.asarray(mesh.faces, np.int32))
    bvh.endModel()
    return bvh


def convex_shape(mesh: trimesh.Trimesh) -> fcl.Convex:
    """An fcl convex solid from a closed convex mesh. Unlike a BVH (a surface), a solid also
    collides with things entirely inside it."""
    faces = np.asarray(mesh.faces, np.int64)
    flat = np.hstack([np.full((len(faces), 1), 3), faces]).ravel()
    return fcl.Convex(np.asarray(mesh.vertices, float), len(faces), flat)


class AssetCache:
    """Placeholders, full assets and BVHs keyed by (generator, params)."""

    def __init__(self) -> None:
        self._placeholders: dict[tuple, Asset] = {}
        self._rough: dict[tuple, Asset] = {}
        self._full: dict[tuple, Asset] = {}
        self._hull: dict[tuple, np.ndarray] = {}
        self._convex: dict[tuple, list[fcl.Convex]] = {}
        self._boxes: dict[tuple, np.ndarray] = {}
        self.builds = 0

    def placeholder(self, generator: str, params: dict[str, Any]) -> Asset:
        """The generator's placeholder for these params (built once; counted in `builds`)."""
        key = params_key(generator, params)
        a = self._placeholders.get(key)
        if a is None:
            a = get_factory(generator).placeholder(params)
            self._placeholders[key] = a
            self.builds += 1
        return a

    def trial_placeholder(self, generator: str, params: dict[str, Any]) -> tuple[Asset, bool]:
        """The asset to try an object's poses with, and whether it is rough: the placeholder if
        built; else, where building it means hollowing the body where things are put away (the
        costly part: the detailed parts evaluated, and most poses an add tries are rejected), the
        rough placeholder, the same but with its body left solid (True: `State.collides` gives
        the object its placeholder once the rough pieces are found clear); else the placeholder,
        built."""
        key = params_key(generator, params)
        a = self._placeholders.get(key)
        if a is not None:
            return a, False
        fac = get_factory(generator)
        if not (isinstance(fac, PartsFactory) and fac.has_stowage()):
            return self.placeholder(generator, params), False
        rough = self._rough.get(key)
        if rough is None:
            rough = self._rough[key] = fac.placeholder(params, hollow=False)
        return rough, True

    def adopt_placeholder(self, generator: str, params: dict[str, Any], asset: Asset) -> Asset:
        """The cached placeholder for these params, or `asset` (built for them elsewhere, e.g.
        in a worker process) cached as it."""
        return self._placeholders.setdefault(params_key(generator, params), asset)

    def adopt_full(self, generator: str, params: dict[str, Any], asset: Asset) -> Asset:
        """The cached detailed asset for these params, or `asset` (built for them elsewhere)
        cached as it."""
        return self._full.setdefault(params_key(generator, params), asset)

    def full(self, generator: str, params: dict[str, Any]) -> Asset:
        """The generator's detailed asset for these params (built once)."""
        key = params_key(generator, params)
        a = self._full.get(key)
        if a is None:
            a = get_factory(generator).create(params)
            self._full[key] = a
        return a

    def hull_2d(self, generator: str, params: dict[str, Any]) -> np.ndarray:
        """The placeholder's plan-view outline (convex hull of its vertices, local XY)."""
        key = params_key(generator, params)
        h = self._hull.get(key)
        if h is None:  # (a rough placeholder has the same mesh)
            built = self._placeholders.get(key) or self._rough.get(key)
            pts = (built or self.placeholder(generator, params)).mesh.vertices[:, :2]
            h = np.asarray(sg.MultiPoint(pts).convex_hull.exterior.coords)[:-1]
            self._hull[key] = h
        return h

    def _pieces(self, generator: str, params: dict[str, Any], rough: bool
                ) -> list[tuple[str, trimesh.Trimesh]]:
        """The collision pieces of the placeholder, or of the rough one (`trial_placeholder`)."""
        if rough:
            return self._rough[params_key(generator, params)].collision
        return self.placeholder(generator, params).collision

    def placeholder_convex(self, generator: str, params: dict[str, Any], rough: bool = False
                           ) -> list[fcl.Convex]:
        """The placeholder's (or the rough placeholder's) convex collision pieces as fcl solids
        (built once, shared by every object with these params)."""
        key = (params_key(generator, params), rough)
        c = self._convex.get(key)
        if c is None:
            c = [convex_shape(m) for _, m in self._pieces(generator, params, rough)]
            self._convex[key] = c
        return c

    def placeholder_boxes(self, generator: str, params: dict[str, Any], rough: bool = False
                          ) -> np.ndarray:
        """Local bounding boxes (k, 2, 3) of the placeholder's (or the rough placeholder's)
        convex pieces, in the order of `placeholder_convex`."""
        key = (params_key(generator, params), rough)
        b = self._boxes.get(key)
        if b is None:
            pieces = self._pieces(generator, params, rough)
            b = np.array([m.bounds for _, m in pieces], float).reshape(-1, 2, 3)
            self._boxes[key] = b
        return b
