"""`PartsFactory`: the shared skeleton of every generator.

A generator lists its pieces once, as `parts(p, detail)`: with detail=False the cheap version
(plain boxes, low-poly circumscribed cylinders: never smaller than the detailed pieces) which
`placeholder` concatenates, with detail=True the detailed one which `create` boolean-unions into
a watertight mesh. Both are recentred by the SAME offset (computed from the cheap pieces'
bounding boxes), so the local-frame contract holds (origin at the bottom-centre of the bbox)
and placeholder and full mesh carry identical surfaces.
"""
from __future__ import annotations

from typing import Any, ClassVar

import numpy as np

from indoorgen.assets.protocol import Asset, AssetFactory, Joint, Param, Surface, box_surfaces
from indoorgen.assets.shapes.collision import clear_of, convex_pieces, free_space_above, hollowed
from indoorgen.assets.shapes.mesh import box_uv, concat, manifold_to_trimesh, union_links
from indoorgen.assets.shapes.primitives import Part
from indoorgen.model.tags import Semantics, Subpart

#: the objects things are put away in (their covered Interior surfaces get stowage boxes): storage
#: furniture, fridges, and dishwashers and microwaves (plates in the baskets, a bowl on the
#: turntable)
STOWING = frozenset({Semantics.Storage, Semantics.Fridge, Semantics.Dishwasher,
                     Semantics.Microwave})


def default_value(p: Param) -> Any:
    """The value a missing parameter takes: a range's midpoint, False, or the first choice."""
    if p.kind == "float":
        return (p.low + p.high) / 2
    if p.kind == "int":
        return int(round((p.low + p.high) / 2))
    if p.kind == "bool":
        return False
    return p.choices[0]


class PartsFactory(AssetFactory):
    """An `AssetFactory` built from a list of material-tagged `Part`s."""

    #: material slot names, in a stable order (face_slots index into this list)
    slots: ClassVar[list[str]] = ["body"]
    #: True when the whole `bottom` polygon rests on mesh (a plinth, a slab, a foot disc) rather
    #: than on legs; the tests then check points of it against the mesh
    solid_bottom: ClassVar[bool] = False
    #: names of `box_surfaces` entries not to emit (e.g. tables replace side_left/right)
    drop_box: ClassVar[tuple[str, ...]] = ()
    #: whether `create` is a closed (watertight) solid
    closed: ClassVar[bool] = True
    #: material slots whose parts are visual only, with no collision piece (a hanger's hook,
    #: whose hull would swallow the rail it hangs from)
    visual_slots: ClassVar[tuple[str, ...]] = ()

    def bottom_is_solid(self, params: dict[str, Any]) -> bool:
        """Whether the whole `bottom` polygon rests on mesh for these params."""
        return self.solid_bottom

    # ---- to implement
    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """The pieces for resolved params `p`: cheap (placeholder) ones, or detailed ones."""
        raise NotImplementedError

    def joints(self, p: dict[str, Any]) -> list[Joint]:
        """The articulations of these params, in the design frame (same frame as `parts`): one
        per moving link (door leaf, drawer, lid), its child being the link its parts are on."""
        return []

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """Surfaces beyond the bounding-box ones, in the design frame (same frame as `parts`).
        One named like a box surface ("top", "bottom") replaces it."""
        return []

    # ---- shared machinery
    def resolve(self, params: dict[str, Any] | None) -> dict[str, Any]:
        """Validated params with every missing one set to its default."""
        p = {k: default_value(v) for k, v in self.params.items()}
        p.update(self.validate_params(dict(params or {})))
        return p

    def _layout(self, p: dict[str, Any]) -> tuple[list[Part], np.ndarray, np.ndarray]:
        cheap = self.parts(p, False)
        lo = np.full(3, np.inf)
        hi = np.full(3, -np.inf)
        for part in cheap:
            bb = np.asarray(part.solid.bounding_box(), float)
            lo = np.minimum(lo, bb[:3])
            hi = np.maximum(hi, bb[3:])
        offset = np.array([-(lo[0] + hi[0]) / 2, -(lo[1] + hi[1]) / 2, -lo[2]])
        return cheap, offset, hi - lo

    def _surfaces(self, p: dict[str, Any], offset: np.ndarray, ext: np.ndarray) -> list[Surface]:
        extra = [s.transformed(np.eye(3), offset) for s in self.extra_surfaces(p)]
        names = {s.name for s in extra}
        base = [s for s in box_surfaces(float(ext[0]), float(ext[1]), float(ext[2]))
                if s.name not in names and s.name not in self.drop_box]
        return base + extra

    def _asset(self, p, mesh, face_slots, slots, offset, ext) -> Asset:
        mesh.apply_translation(offset)
        return Asset(mesh=mesh, surfaces=self._surfaces(p, offset, ext), face_slots=face_slots,
                     slots=slots, closed=self.closed)

    def placeholder(self, params: dict[str, Any], hollow: bool = True) -> Asset:
        """The cheap asset: its parts concatenated, each part's convex hull as a solid
        collision piece (the solver collides these, so an object inside another is caught) named
        by its link, and the joints (so the solver can keep each moving part's sweep free).
        With `hollow` False, the body is left solid where things are put away (`has_stowage`):
        the same mesh, surfaces and joints, built without the detailed parts."""
        p = self.resolve(params)
        cheap, offset, ext = self._layout(p)
        mesh, fs, slots = concat(cheap, self.slots)
        asset = self._asset(p, mesh, fs, slots, offset, ext)
        # hollow the cheap body where things are put away (a cupboard's shelves)
        rooms = self._stowage(p, float(ext[2] - offset[2])) if hollow else []
        pieces = self.colliding(hollowed(cheap, rooms) if rooms else cheap)
        asset.joints = [j.translated(offset) for j in self.joints(p)]
        asset.collision = [(link, manifold_to_trimesh(h.translate(tuple(offset))))
                           for link, h in convex_pieces(pieces, max_pieces=24 + 8 * len(rooms))]
        return asset

    def link_boxes(self, params: dict[str, Any]) -> dict[str, np.ndarray]:
        """The bounding box (2, 3: min, max corners) of each moving link's detailed parts, in the
        asset's frame at the closed pose: what a door, drawer or lid sweeps when it opens (the
        placeholder's pieces are all `base`), without building the whole asset."""
        p = self.resolve(params)
        _, offset, _ = self._layout(p)
        out: dict[str, np.ndarray] = {}
        for part in self.parts(p, True):
            if part.link == "base" or part.solid.is_empty():
                continue
            bb = np.asarray(part.solid.bounding_box(), float)
            box = np.array([bb[:3], bb[3:]]) + offset
            old = out.get(part.link)
            out[part.link] = box if old is None else np.array(
                [np.minimum(old[0], box[0]), np.maximum(old[1], box[1])])
        return out

    def has_stowage(self) -> bool:
        """Whether any of this generator's placeholders may be hollowed where things are put
        away (the costly part of building one: `_stowage` evaluates the detailed parts)."""
        return self.size_class != "small" and bool(self.tags & STOWING)

    def _stowage(self, p: dict[str, Any], top: float) -> list[list[float]]:
        """The open box (x0, y0, z0, x1, y1, z1, design frame) over each covered upward
        `Interior` surface (a shelf behind a door, a fridge shelf), up to the board above it:
        what the solver may fill, clear of every part of every link (a drawer's bin, a door's
        racks), so placeholders and simulators leave it free. Only `STOWING` objects have any
        (nothing is put in a shower; a bowl's inside is open above)."""
        if not self.has_stowage():
            return []
        inner = [s for s in self.extra_surfaces(p)
                 if s.subpart == Subpart.Interior and s.normal[2] > 0.9]
        if not inner:
            return []
        solids = [q.solid for q in self.parts(p, True) if not q.solid.is_empty()]
        out = []
        for s in inner:
            xy = s.corners()[:, :2]
            box = free_space_above(solids, (*xy.min(axis=0), *xy.max(axis=0)),
                                   float(s.origin[2]), top)
            if box is not None:  # from the surface itself: things stand on it 1 mm up
                box = clear_of([box[0], box[1], float(s.origin[2]), *box[3:]], solids)
            if box is not None:
                out.append(box)
        return out

    def create(self, params: dict[str, Any]) -> Asset:
        """The detailed asset: one watertight shell per link, UVs, joints and convex pieces."""
        p = self.resolve(params)
        _, offset, ext = self._layout(p)
        parts = self.parts(p, True)
        mesh, fs, slots, links, face_links = union_links(parts, self.slots)
        asset = self._asset(p, mesh, fs, slots, offset, ext)
        asset.links, asset.face_links = links, face_links
        asset.joints = [j.translated(offset) for j in self.joints(p)]
        asset.corner_uv = box_uv(asset.mesh.vertices, asset.mesh.faces)
        free = self._free_boxes(asset, parts, offset) + \
            self._stowage(p, float(ext[2] - offset[2]))
        asset.collision = [(link, manifold_to_trimesh(h.translate(tuple(offset))))
                           for link, h in convex_pieces(self.colliding(parts), decompose=True,
                                                        keep_free=free)]
        return asset

    def colliding(self, parts: list[Part]) -> list[Part]:
        """The parts that get collision pieces: all but those in `visual_slots`."""
        return [q for q in parts if q.slot not in self.visual_slots]

    @staticmethod
    def _free_boxes(asset: Asset, parts: list[Part], offset: np.ndarray) -> list[list[float]]:
        """Open space over each upward support surface below the object's top (a shelf, a
        cube-storage cell), in the parts' frame, reaching out through the front and the back
        (X: where shelves open, and what stands on them may overhang): simulators must find it
        empty, since the solver puts things there."""
        body = [p.solid for p in parts if p.link == "base" and not p.solid.is_empty()]
        top = float(asset.mesh.bounds[1][2])
        back = float(asset.mesh.bounds[0][0] - offset[0]) - 0.01
        front = float(asset.mesh.bounds[1][0] - offset[0]) + 0.01
        out = []
        for s in asset.surfaces:
            if s.subpart != Subpart.SupportSurface or s.normal[2] < 0.9 or \
                    s.origin[2] > top - 0.01:
                continue
            xy = s.corners()[:, :2] - offset[:2]
            box = free_space_above(body, (*xy.min(axis=0), *xy.max(axis=0)),
                                   float(s.origin[2] - offset[2]), top - float(offset[2]))
            if box is not None:
                out.append([min(box[0], back), *box[1:3], max(box[3], front), *box[4:]])
        return out
