"""A storage rack: the freestanding steel shelving of garages, cellars and utility rooms, four
steel posts holding 3-6 boards, each shelf a support surface (front is +X; it stands
against a wall)."""
from __future__ import annotations

from typing import Any

from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.primitives import OVERLAP, Part, box_between
from indoorgen.assets.shapes.surfaces import support_rect
from indoorgen.model.tags import Semantics as S

#: the least clear height between a rack's shelves (m): a storage box or a can of paint
MIN_CLEAR = 0.28
#: the lowest shelf's height above the floor (m)
FIRST_SHELF = 0.12
#: a shelf's steel edge beam's height (m)
BEAM = 0.035
#: how far the beams stand inside the posts' faces, and the top shelf below their tops (m):
#: no face of one lies in another's plane
SET_IN = 0.004


@register
class StorageRack(PartsFactory):
    """Boltless steel shelving: four steel posts and 3-6 shelves of chipboard or wire mesh
    on edge beams, evenly spaced from just above the floor to the top; every shelf's upper face
    is a support surface `shelf_<i>` (the top one also named `top`)."""

    name = "storage_rack"
    tags = frozenset({S.Object, S.Furniture, S.Storage, S.Shelf, S.StorageRack})
    size_class = "large"
    slots = ["metal", "wood"]
    material_choices = {
        "metal": {"galvanized_steel": 3.0, "painted_metal": 2.0, "brushed_steel": 0.5},
        "wood": {"plywood": 3.0, "painted_metal": 1.0},
    }
    params = {
        "width": Param(0.75, 1.5, doc="Y extent (m)"),
        "depth": Param(0.3, 0.6, doc="X extent (m)"),
        "height": Param(1.5, 2.0, doc="height of the posts (m)"),
        "n_shelves": Param(3, 6, kind="int",
                           doc=f"shelves (fewer if they would stand < {MIN_CLEAR * 100:.0f} cm apart)"),
        "upright": Param(0.03, 0.045, doc="the posts' square section (m)"),
        "board_thickness": Param(0.008, 0.018, doc="shelf board thickness (m)"),
    }

    def _levels(self, p) -> list[float]:
        """The upper faces of the shelves, bottom first; the top one just under the posts' tops."""
        H, t = p["height"], p["board_thickness"]
        n = int(p["n_shelves"])
        while n > 2 and (H - FIRST_SHELF) / (n - 1) - t - BEAM < MIN_CLEAR:
            n -= 1
        step = (H - SET_IN - FIRST_SHELF) / (n - 1)
        return [FIRST_SHELF + i * step for i in range(n)]

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """The posts, and each shelf's board on its frame of edge beams."""
        W, D, H, u, t = p["width"], p["depth"], p["height"], p["upright"], p["board_thickness"]
        d2, w2 = D / 2, W / 2
        out: list[Part] = []
        for sx in (-1, 1):  # square steel posts at the corners
            for sy in (-1, 1):
                xs, ys = _span(sx * d2, sx * (d2 - u)), _span(sy * w2, sy * (w2 - u))
                out.append(Part(box_between((xs[0], ys[0], 0.0), (xs[1], ys[1], H)), "metal"))
        for zt in self._levels(p):
            out.append(Part(box_between((-d2 + u / 2, -w2 + u - OVERLAP, zt - t),
                                        (d2 - u / 2, w2 - u + OVERLAP, zt)), "wood"))
            for s in (-1, 1):  # front and back edge beams under the board, bolted to the posts
                xb = _span(s * (d2 - SET_IN), s * (d2 - u + SET_IN))
                out.append(Part(box_between((xb[0], -w2 + SET_IN, zt - t - BEAM),
                                            (xb[1], w2 - SET_IN, zt - t + OVERLAP)), "metal"))
        return out

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """Each shelf's upper face (`shelf_<i>`, bottom first) and the top shelf as `top`."""
        W, D, u = p["width"], p["depth"], p["upright"]
        levels = self._levels(p)
        hx, hy = D / 2 - u - 0.01, W / 2 - u - 0.01
        out = [support_rect(f"shelf_{i}", (0, 0, z), hx, hy) for i, z in enumerate(levels[:-1])]
        out.append(support_rect("top", (0, 0, levels[-1]), hx, hy))
        return out


def _span(a: float, b: float) -> tuple[float, float]:
    """(low, high) of two coordinates."""
    return min(a, b), max(a, b)
