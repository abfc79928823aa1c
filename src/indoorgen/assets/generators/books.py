"""Books: a single hardback standing upright (spine facing +X, out of a shelf; thickness along Y),
a stack lying flat, and a row of upright books with the last one leaning.

The groups are made of `Book`'s detailed hardback (covers, spine, recessed page block) moved into
place; neighbours sink 1 mm into each other so the group unions into one shell. Per-book sizes,
spines and jitter come from a `layout` variant number, so a group stays reproducible from its
params.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import manifold3d as m3d
import numpy as np
import shapely.affinity as sa
import shapely.geometry as sg

from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.primitives import SMALL_OVERLAP, Part, box, box_between
from indoorgen.assets.shapes.surfaces import support_polygon
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart


@register
class Book(PartsFactory):
    """A hardback: two covers and a spine (flat or rounded) around a page block that is recessed
    at the top and fore-edge and flush at the bottom (so the whole footprint rests)."""

    name = "book"
    tags = frozenset({S.Object, S.SmallObject, S.Book})
    size_class = "small"
    slots = ["cover", "pages"]
    solid_bottom = True
    params = {
        "height": Param(0.18, 0.30, doc="Z extent (m)"),
        "depth": Param(0.12, 0.22, doc="X extent: page width (m)"),
        "thickness": Param(0.015, 0.06, doc="Y extent (m)"),
        "cover_thickness": Param(0.0015, 0.004, doc="board thickness (m)"),
        "page_inset": Param(0.002, 0.005, doc="how far pages sit inside the covers (m)"),
        "spine_style": Param(kind="choice", choices=("flat", "rounded"), doc="spine shape"),
    }

    def _spine_bulge(self, p) -> float:
        return min(0.006, p["thickness"] * 0.15) if p["spine_style"] == "rounded" else 0.0

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """Covers, spine (flat or rounded) and page block; the placeholder is one box."""
        H, D, T = p["height"], p["depth"], p["thickness"]
        ct, pi = p["cover_thickness"], p["page_inset"]
        if not detail:
            return [Part(box((D, T, H), (0, 0, H / 2)), "cover")]
        a = self._spine_bulge(p)
        xs = D / 2 - a  # back face of the spine's flat part / base of the bulge
        out = []
        for s in (-1, 1):
            out.append(Part(box_between((-D / 2, min(s * T / 2, s * (T / 2 - ct)), 0.0),
                                        (xs, max(s * T / 2, s * (T / 2 - ct)), H)), "cover"))
        out.append(Part(box_between((xs - ct, -T / 2 + SMALL_OVERLAP, 0.0), (xs, T / 2 - SMALL_OVERLAP, H)),
                        "cover"))
        if a > 0:
            cyl = m3d.Manifold.cylinder(H, 1.0, -1.0, 32).scale((a, T / 2, 1.0)).translate((xs, 0.0, 0.0))
            out.append(Part(cyl, "cover"))
        out.append(Part(box_between((-D / 2 + pi, -T / 2 + ct - SMALL_OVERLAP, 0.0),
                                    (xs - ct + SMALL_OVERLAP, T / 2 - ct + SMALL_OVERLAP, H - pi)), "pages"))
        return out

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The footprint of the covers and spine (pages are flush with it) as the bottom."""
        D, T = p["depth"], p["thickness"]
        a = self._spine_bulge(p)
        poly = sg.box(-D / 2, -T / 2, D / 2 - a, T / 2)
        if a > 0:
            ang = np.arange(32) * 2 * np.pi / 32
            ell = sg.Polygon(np.c_[D / 2 - a + a * np.cos(ang), T / 2 * np.sin(ang)])
            poly = poly.union(ell).buffer(-0.0003, join_style="mitre")
        return [support_polygon("bottom", (0, 0, 0), poly, subpart=Subpart.Bottom, up=False)]


#: how far neighbouring books sink into each other (m)
SINK = 0.001


SPINES = ("flat", "rounded", "mixed")


@dataclass(frozen=True)
class _Spec:
    """One book: its Book params and where it goes (yaw in degrees, offset in metres)."""

    params: dict[str, Any]
    yaw: float = 0.0
    offset: tuple[float, float] = (0.0, 0.0)


def _book_params(rng: np.random.Generator, height: float, depth: float, thickness: float,
                 variation: float, spine: str) -> dict[str, Any]:
    """A book's params near the given size (each dimension within +-variation)."""
    k = 1 + variation * rng.uniform(-1, 1, 3)
    if spine == "mixed":
        spine = ("flat", "rounded")[int(rng.integers(2))]
    return {"height": float(np.clip(height * k[0], 0.12, 0.34)),
            "depth": float(np.clip(depth * k[1], 0.09, 0.25)),
            "thickness": float(np.clip(thickness * k[2], 0.01, 0.065)),
            "cover_thickness": float(rng.uniform(0.0015, 0.003)),
            "page_inset": float(rng.uniform(0.002, 0.004)), "spine_style": spine}


def _book(bp: dict[str, Any], detail: bool) -> list[Part]:
    """An upright book's parts (spine +X, thickness along Y, z from 0 to its height)."""
    return Book().parts(bp, detail)


def _moved(parts: list[Part], fn) -> list[Part]:
    return [Part(fn(q.solid), q.slot) for q in parts]


class _Books(PartsFactory):
    """Shared declaration of the book groups."""

    size_class = "small"
    slots = ["cover", "pages"]  # as Book's (the material library dresses them as books)
    tags = frozenset({S.Object, S.SmallObject, S.Decor, S.Book})


@register
class BookStack(_Books):
    """2-6 hardbacks lying flat in a stack, spines towards +X, each turned and shifted a little
    (largest at the bottom, or in any order); the top book's cover is a support surface."""

    name = "book_stack"
    params = {
        "n_books": Param(2, 6, kind="int", doc="number of books"),
        "height": Param(0.16, 0.3, doc="typical book height (its long edge, along Y) (m)"),
        "depth": Param(0.11, 0.22, doc="typical page width (along X) (m)"),
        "thickness": Param(0.012, 0.05, doc="typical book thickness (m)"),
        "size_variation": Param(0.0, 0.25, doc="spread of each dimension between books"),
        "max_rotation": Param(0.0, 15.0, doc="largest turn of a book about Z (degrees)"),
        "max_offset": Param(0.0, 0.02, doc="largest shift of a book's centre (m)"),
        "spine_style": Param(kind="choice", choices=SPINES, doc="flat, rounded or mixed spines"),
        "largest_bottom": Param(kind="bool", doc="order the books largest at the bottom"),
        "layout": Param(0, 999, kind="int", doc="which sizes and jitter (a variant number)"),
    }

    def _specs(self, p) -> list[_Spec]:
        rng = np.random.default_rng(int(p["layout"]))
        books = [_book_params(rng, p["height"], p["depth"], p["thickness"], p["size_variation"],
                              p["spine_style"]) for _ in range(int(p["n_books"]))]
        if p["largest_bottom"]:
            books.sort(key=lambda b: -b["height"] * b["depth"])
        out = []
        for i, bp in enumerate(books):
            yaw = float(rng.uniform(-1, 1) * p["max_rotation"]) if i else 0.0
            off = tuple((rng.uniform(-1, 1, 2) * p["max_offset"]).tolist()) if i else (0.0, 0.0)
            out.append(_Spec(bp, yaw, off))
        return out

    def _bases(self, specs: list[_Spec]) -> list[float]:
        """The height of each book's underside."""
        z, out = 0.0, []
        for s in specs:
            out.append(z)
            z += s.params["thickness"] - SINK
        return out

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """Each book of the stack, laid flat, turned and shifted onto the one below."""
        specs = self._specs(p)
        out = []
        for s, z in zip(specs, self._bases(specs), strict=True):
            H, T = s.params["height"], s.params["thickness"]

            def place(m: m3d.Manifold, H=H, T=T, s=s, z=z) -> m3d.Manifold:
                m = m.rotate((90.0, 0.0, 0.0)).translate((0.0, H / 2, T / 2))
                return m.rotate((0.0, 0.0, s.yaw)).translate((s.offset[0], s.offset[1], z))
            out += _moved(_book(s.params, detail), place)
        return out

    def _cover(self, s: _Spec, margin: float, with_spine: bool = False) -> sg.Polygon:
        """The footprint of a book's flat cover (with a rounded spine's bulge if `with_spine`),
        shrunk by `margin`, turned and shifted like the book."""
        bp = s.params
        rounded = bp["spine_style"] == "rounded" and not with_spine
        cut = min(0.006, bp["thickness"] * 0.15) if rounded else 0.0
        d2, h2 = bp["depth"] / 2, bp["height"] / 2
        poly = sg.box(-d2 + margin, -h2 + margin, d2 - cut - margin, h2 - margin)
        return sa.translate(sa.rotate(poly, s.yaw, origin=(0, 0)), *s.offset)

    def bottom_is_solid(self, params: dict[str, Any]) -> bool:
        """A flat-spined bottom book rests on its whole cover; a rounded spine lifts its edge."""
        return self._specs(self.resolve(params))[0].params["spine_style"] == "flat"

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The top book's cover (`top`) and the bottom book's cover (`bottom`)."""
        specs = self._specs(p)
        top = self._bases(specs)[-1] + specs[-1].params["thickness"]
        return [support_polygon("top", (0, 0, top), self._cover(specs[-1], 0.003)),
                support_polygon("bottom", (0, 0, 0), self._cover(specs[0], 0.0003, with_spine=True),
                                subpart=Subpart.Bottom, up=False)]


@register
class LeaningBooks(_Books):
    """A row of 1-4 upright books, spines flush towards +X, and one more at the +Y end leaning
    back against them (resting on its bottom edge, its cover against the last one's top
    corner, or its top corner against the last one's cover if it is the shorter)."""

    name = "leaning_books"
    params = {
        "n_books": Param(2, 5, kind="int", doc="number of books, the leaning one included"),
        "height": Param(0.18, 0.3, doc="typical book height (m)"),
        "depth": Param(0.12, 0.22, doc="typical page width (along X) (m)"),
        "thickness": Param(0.015, 0.05, doc="typical book thickness (m)"),
        "size_variation": Param(0.0, 0.2, doc="spread of each dimension between books"),
        "lean_angle": Param(10.0, 35.0, doc="tilt of the leaning book (degrees)"),
        "spine_style": Param(kind="choice", choices=SPINES, doc="flat, rounded or mixed spines"),
        "layout": Param(0, 999, kind="int", doc="which sizes (a variant number)"),
    }

    def _books(self, p) -> list[dict[str, Any]]:
        rng = np.random.default_rng(int(p["layout"]))
        return [_book_params(rng, p["height"], p["depth"], p["thickness"], p["size_variation"],
                             p["spine_style"]) for _ in range(int(p["n_books"]))]

    def _lean(self, p, books) -> tuple[float, float]:
        """(y of the leaning book's pivot edge, its tilt in radians)."""
        th = math.radians(p["lean_angle"])
        last, lean = books[-2], books[-1]
        y1 = sum(b["thickness"] - SINK for b in books[:-1]) + SINK
        h1, h2 = last["height"], lean["height"]
        # its cover rests on the last book's top corner, or its top corner on the last one's cover
        yp = y1 + h1 * math.tan(th) if h2 * math.cos(th) >= h1 else y1 + h2 * math.sin(th)
        return yp - 0.0015, th

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """The upright books side by side, then the last one leaning back against them."""
        books = self._books(p)
        front = max(b["depth"] for b in books) / 2
        out, y = [], 0.0
        for bp in books[:-1]:
            dx, dy = front - bp["depth"] / 2, y + bp["thickness"] / 2
            out += _moved(_book(bp, detail), lambda m, dx=dx, dy=dy: m.translate((dx, dy, 0.0)))
            y += bp["thickness"] - SINK
        bp = books[-1]
        yp, th = self._lean(p, books)
        dx = front - bp["depth"] / 2

        def lean(m: m3d.Manifold) -> m3d.Manifold:
            m = m.translate((0.0, bp["thickness"] / 2, 0.0)).rotate((math.degrees(th), 0.0, 0.0))
            return m.translate((dx, yp, 0.0))
        return out + _moved(_book(bp, detail), lean)
