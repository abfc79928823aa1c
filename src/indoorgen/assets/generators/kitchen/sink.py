"""The kitchen sink: a sink base unit (a base cabinet's carcass, plinth and doors) under a
countertop with one or two steel basins hollowed into it and a faucet behind. Front faces +X.
"""
from __future__ import annotations

from typing import Any

import manifold3d as m3d
import shapely.geometry as sg

from indoorgen.assets.generators.kitchen._parts import Unit, counter_params, countertop, run_parts
from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.primitives import Part, box_between, cylinder, lathe, rod, torus
from indoorgen.assets.shapes.surfaces import bottom_rect, support_polygon
from indoorgen.model.polygons import largest_polygon
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart

#: carcass board thickness of the sink base (that of the base cabinets' units)
BOARD = 0.018
#: how far the plinth of the sink base is set back (m)
TOE_KICK_DEPTH = 0.06


def rounded_rect_prism(x0: float, x1: float, y0: float, y1: float, z0: float, z1: float,
                       radius: float, segments: int = 6) -> m3d.Manifold:
    """A vertical prism over the rectangle x0..x1, y0..y1 with rounded vertical edges."""
    r = min(radius, 0.49 * min(x1 - x0, y1 - y0))
    if r < 1e-4:
        return box_between((x0, y0, z0), (x1, y1, z1))
    cs = m3d.CrossSection.square((x1 - x0 - 2 * r, y1 - y0 - 2 * r), True).offset(
        r, m3d.JoinType.Round, 2.0, 4 * segments)
    return m3d.Manifold.extrude(cs, z1 - z0).translate(((x0 + x1) / 2, (y0 + y1) / 2, z0))


@register
class KitchenSink(PartsFactory):
    """A kitchen sink base unit: a base cabinet's carcass (no top board, no shelf: the basins
    hang there) on a recessed plinth with a pair of overlay doors, under a countertop at base
    cabinet height with one or two basins (undermounted below the cut-out, or dropped in with a
    rim on the countertop) hollowed out of rounded steel blocks, drains, and a faucet behind the
    basin (gooseneck or angular spout; single lever or two cross handles). The countertop
    around the basin is the `top` support surface, the carcass bottom `interior_0`."""

    name = "kitchen_sink"
    tags = frozenset({S.Object, S.KitchenSink, S.Countertop})
    size_class = "large"
    slots = ["wood", "front", "metal", "countertop"]
    solid_bottom = True
    params = {
        "width": Param(0.6, 1.2, doc="Y extent (m)"),
        **counter_params(),
        "bowls": Param(kind="choice", choices=("single", "double"), doc="one or two basins"),
        "bowl_depth": Param(0.16, 0.24, doc="basin depth below the countertop (m)"),
        "bowl_width_frac": Param(0.7, 1.0, doc="basin Y extent / the most the carcass holds"),
        "mount": Param(kind="choice", choices=("undermount", "drop_in"),
                       doc="basin under the cut-out or dropped in with a rim"),
        "faucet": Param(kind="choice", choices=("gooseneck", "angular"), doc="spout shape"),
        "faucet_handles": Param(kind="choice", choices=("lever", "cross"),
                                doc="one side lever or two cross handles"),
        "faucet_height": Param(0.22, 0.4, doc="faucet height above the countertop (m)"),
    }

    WALL = 0.008
    RIM = 0.03
    CORNER = 0.025

    def _cabinet(self, p) -> tuple[dict[str, Any], list[Unit]]:
        """The params `run_parts` reads and the one doors-only unit."""
        W = p["width"]
        return dict(p, toe_kick_depth=TOE_KICK_DEPTH), [Unit(-W / 2, W / 2, "doors")]

    def _sink_layout(self, p) -> dict[str, Any]:
        W, D, H = p["width"], p["depth"], p["height"]
        zb = H - p["countertop_thickness"]
        # the basin block and its flange stay inside the carcass, clear of the doors
        room = W - 2 * (BOARD + 0.005 + self.WALL + self.RIM)
        bw = room * p["bowl_width_frac"]
        bx0, bx1 = -D / 2 + 0.14, D / 2 - 0.02 - self.WALL - self.RIM
        if p["bowls"] == "double":
            gap = 0.04
            wa = (bw - gap) * 0.55
            cav = [(-bw / 2, -bw / 2 + wa), (-bw / 2 + wa + gap, bw / 2)]
        else:
            cav = [(-bw / 2, bw / 2)]
        xf = (-D / 2 + bx0) / 2
        return dict(z0=zb - p["bowl_depth"], zb=zb, zt=H, bw=bw, bx0=bx0, bx1=bx1, cav=cav,
                    xf=xf, yf=0.0)

    def _faucet(self, p, L, solids: bool = True) -> tuple[list[m3d.Manifold], tuple[tuple, tuple]]:
        """The faucet solids (none unless `solids`: placeholders only need the box) and their
        bounding box ((x0, y0, z0), (x1, y1, z1))."""
        xf, yf, zt = L["xf"], L["yf"], L["zt"] - 0.001
        fh = p["faucet_height"]
        r = 0.014
        reach = min(max((L["bx0"] + L["bx1"]) / 2 - xf, 0.12), 0.3) * 0.75
        out: list[m3d.Manifold] = []

        def add(make) -> None:
            if solids:
                out.append(make())

        add(lambda: cylinder(0.03, 0.014, (xf, yf, zt), 24))
        lo, hi = [xf - 0.03, yf - 0.03, zt], [xf + 0.03, yf + 0.03, zt + fh]
        if p["faucet"] == "gooseneck":
            R = reach / 2
            zc = zt + fh - R - r
            add(lambda: rod((xf, yf, zt), (xf, yf, zc + 0.001), r, 16))
            add(lambda: torus(R, r, sections=24, tube_sections=12).rotate((90.0, 0.0, 0.0))
                .trim_by_plane((0.0, 0.0, 1.0), 0.0).translate((xf + R, yf, zc)))
            xs = xf + 2 * R
            add(lambda: rod((xs, yf, zc - 0.05), (xs, yf, zc + 0.001), r, 16))
            add(lambda: cylinder(r * 1.15, 0.02, (xs, yf, zc - 0.06), 16))
            lo[2], hi[0] = zt, xs + r * 1.15
        else:
            zc = zt + fh - r
            add(lambda: rod((xf, yf, zt), (xf, yf, zc + r), r, 16))
            xs = xf + reach
            add(lambda: rod((xf, yf, zc), (xs + r, yf, zc), r, 16))
            add(lambda: rod((xs, yf, zc - 0.06), (xs, yf, zc), r, 16))
            add(lambda: cylinder(r * 1.15, 0.015, (xs, yf, zc - 0.07), 16))
            hi[0] = xs + r * 1.15
        if p["faucet_handles"] == "lever":
            zl = zt + min(0.08, 0.3 * fh)
            add(lambda: rod((xf, yf, zl), (xf, yf + 0.045, zl), 0.013, 16))
            add(lambda: rod((xf, yf + 0.04, zl), (xf - 0.035, yf + 0.04, zl + 0.06), 0.005, 8))
            lo[0] = min(lo[0], xf - 0.04)
            hi[1] = max(hi[1], yf + 0.053)
        else:
            for s in (-1, 1):
                yh = yf + s * 0.09
                if solids:
                    out += [cylinder(0.02, 0.045, (xf, yh, zt), 16),
                            rod((xf - 0.025, yh, zt + 0.04), (xf + 0.025, yh, zt + 0.04), 0.005, 8),
                            rod((xf, yh - 0.025, zt + 0.04), (xf, yh + 0.025, zt + 0.04), 0.005, 8)]
            lo[1], hi[1] = yf - 0.115, yf + 0.115
        return out, (tuple(lo), tuple(hi))

    def parts(self, p, detail):
        """The sink base's solids: detailed, or the blocks of its placeholder."""
        W, D = p["width"], p["depth"]
        q, units = self._cabinet(p)
        L = self._sink_layout(p)
        z0, zb, zt, bx0, bx1 = L["z0"], L["zb"], L["zt"], L["bx0"], L["bx1"]
        w, rc, R = self.WALL, self.CORNER, self.RIM
        drop = p["mount"] == "drop_in"
        # outer block of the basin, its rim (drop-in) and the countertop's cut-out
        oy0, oy1 = L["cav"][0][0] - w, L["cav"][-1][1] + w
        ox0, ox1 = bx0 - w, bx1 + w
        out, _, _ = run_parts(q, units, detail, False, n_shelves=0)
        slab = countertop(p, -D / 2, D / 2 + p["overhang"], -W / 2, W / 2, detail)
        faucet, (flo, fhi) = self._faucet(p, L, detail)
        if not detail:  # the basin hangs inside the carcass block
            out += [slab, Part(box_between(flo, fhi), "metal")]
            if drop:
                out.append(Part(box_between((ox0 - R, oy0 - R, zt - 0.001),
                                            (ox1 + R, oy1 + R, zt + 0.006)), "metal"))
            return out
        cavities = [rounded_rect_prism(bx0, bx1, ya, yb, z0 + w, zt + 0.02, rc) for ya, yb in L["cav"]]
        if drop:
            block = rounded_rect_prism(ox0, ox1, oy0, oy1, z0, zt - 0.001, rc + w)
            rim = rounded_rect_prism(ox0 - R, ox1 + R, oy0 - R, oy1 + R, zt - 0.001, zt + 0.006,
                                     rc + w + R)
            hole = rounded_rect_prism(ox0 + 0.001, ox1 - 0.001, oy0 + 0.001, oy1 - 0.001, zb - 0.01,
                                      zt + 0.01, rc + w)
            basin = m3d.Manifold.batch_boolean([block, rim], m3d.OpType.Add)
        else:
            basin = rounded_rect_prism(ox0 - R, ox1 + R, oy0 - R, oy1 + R, z0, zb + 0.001, rc + w + R)
            hole = m3d.Manifold.batch_boolean(
                [rounded_rect_prism(bx0, bx1, ya, yb, zb - 0.01, zt + 0.01, rc) for ya, yb in L["cav"]],
                m3d.OpType.Add)
        basin = m3d.Manifold.batch_boolean([basin] + cavities, m3d.OpType.Subtract)
        out += [Part(slab.solid - hole, "countertop"), Part(basin, "metal")]
        for ya, yb in L["cav"]:  # drain: a flange ring with a recessed strainer
            c = ((bx0 + bx1) / 2, (ya + yb) / 2)
            drain = lathe([(0.0, w - 0.001), (0.045, w - 0.001), (0.045, w + 0.002), (0.035, w + 0.002),
                           (0.03, w - 0.0005), (0.0, w - 0.0005)], 32).translate((c[0], c[1], z0))
            out.append(Part(drain, "metal"))
        out += [Part(f, "metal") for f in faucet]
        return out

    def joints(self, p):
        """The sink base's joints, one per door."""
        q, units = self._cabinet(p)
        return run_parts(q, units, False, False, n_shelves=0)[1]

    def extra_surfaces(self, p):
        """The sink base's surfaces besides its bounding box's: top (the countertop around the
        basin and faucet), bottom, back (the carcass and countertop, not the air beside the
        faucet), interior_0 (the carcass bottom under the basin)."""
        W, D, H = p["width"], p["depth"], p["height"]
        q, units = self._cabinet(p)
        L = self._sink_layout(p)
        w = self.WALL
        ox0, ox1 = L["bx0"] - w, L["bx1"] + w
        oy0, oy1 = L["cav"][0][0] - w, L["cav"][-1][1] + w
        R = self.RIM + 0.005 if p["mount"] == "drop_in" else 0.005
        top = sg.box(-D / 2 + 0.01, -W / 2 + 0.02, D / 2 + p["overhang"] - 0.02, W / 2 - 0.02)
        top = top.difference(sg.box(ox0 - R, oy0 - R, ox1 + R, oy1 + R))
        _, (flo, fhi) = self._faucet(p, L, False)
        top = top.difference(sg.box(flo[0] - 0.005, flo[1] - 0.005, fhi[0] + 0.005, fhi[1] + 0.005))
        kd = TOE_KICK_DEPTH
        # a basin nearly as wide as the unit cuts the counter in two: things stand on the
        # larger strip (the one behind, with the faucet, or before it)
        top = largest_polygon(top)
        return [support_polygon("top", (0, 0, L["zt"]), top),
                bottom_rect((-kd / 2, 0, 0), (D - kd) / 2, W / 2 - 0.01),
                Surface.rect("back", Subpart.Back, (-D / 2, 0, H / 2), (-1, 0, 0), (0, 1, 0), W / 2, H / 2),
                *run_parts(q, units, False, False, n_shelves=0)[2]]
