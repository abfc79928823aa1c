"""A rolling tool chest: a steel case of many shallow drawers, deeper towards the floor, on
casters, its top a work surface (front is +X; it stands against a wall)."""
from __future__ import annotations

from typing import Any

from indoorgen.assets.generators.storage._cases import (
    Case,
    CaseFactory,
    Row,
    back_surface,
    base_bottom,
    case_layout,
    top_surface,
)
from indoorgen.assets.protocol import Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.moving_parts import DoorJoint
from indoorgen.assets.shapes.primitives import Part
from indoorgen.model.tags import Semantics as S

#: the shallowest drawer a tool chest keeps (m): a row of spanners and screwdrivers
MIN_DRAWER = 0.07
#: how much deeper each drawer is than the one above it, as a share of the top one
DEEPER_BELOW = 0.35


@register
class ToolChest(CaseFactory):
    """A tool chest (roller cabinet): 4-8 rows of drawers, the top rows shallow and the bottom
    ones deep, one or two side by side, in a painted steel case on casters (short legs) with
    bar handles; every drawer slides out on its own prismatic joint; `top` is a support surface
    (a toolbox or a can of paint stands on it)."""

    name = "tool_chest"
    tags = frozenset({S.Object, S.Furniture, S.Storage, S.ToolChest})
    size_class = "large"
    material_choices = {
        "wood": {"painted_metal": 4.0, "brushed_steel": 1.0},
        "front": {"painted_metal": 4.0, "brushed_steel": 1.0},
        "back": {"painted_metal": 1.0},
        "metal": {"brushed_steel": 2.0, "chrome": 1.0},
    }
    params = {
        "width": Param(0.55, 1.05, doc="case Y extent (m)"),
        "depth": Param(0.42, 0.55, doc="case X extent, fronts excluded (m)"),
        "height": Param(0.75, 1.05, doc="overall height to the top's upper face (m)"),
        "board_thickness": Param(0.012, 0.02, doc="steel panel thickness, as modelled (m)"),
        "n_rows": Param(4, 8, kind="int",
                        doc=f"drawer rows (fewer if the top one would be < {MIN_DRAWER * 100:.0f} cm)"),
        "split_top": Param(kind="bool", doc="the top two rows have two drawers side by side"),
        "base_height": Param(0.08, 0.13, doc="caster height under the case (m)"),
        "top_overhang": Param(0.0, 0.015, doc="how far the top overhangs the front and sides (m)"),
    }

    def layout(self, p: dict[str, Any]) -> Case:
        """Graduated rows of drawers, the shallowest on top, as many as stay MIN_DRAWER deep."""
        W, D, H, t = p["width"], p["depth"], p["height"], p["board_thickness"]
        z_top = H - t
        inner = z_top - p["base_height"] - t
        n = int(p["n_rows"])
        while n > 2 and self._top_row(inner, n, t) < MIN_DRAWER:
            n -= 1
        weights = [1.0 + DEEPER_BELOW * (n - 1 - i) for i in range(n)]
        two = p["split_top"] and W - 2 * t >= 0.6
        rows = [Row("drawer", w, 2 if two and i >= n - 2 else 1) for i, w in enumerate(weights)]
        return case_layout(W, D, t, 0.006, p["base_height"], z_top, rows, overlay=True)

    @staticmethod
    def _top_row(inner: float, n: int, t: float) -> float:
        """The top row's height with `n` graduated rows in `inner` metres."""
        total = sum(1.0 + DEEPER_BELOW * (n - 1 - i) for i in range(n))
        return (inner - (n - 1) * t) / total

    def fronts(self, p: dict[str, Any]) -> list[tuple[list[Part], DoorJoint]]:
        """The drawers, with bar handles."""
        return super().fronts(_shared(p))

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """The case and its drawers, the top and the casters."""
        return self._topped_case(_shared(p), detail, p["base_height"], leg=0.05)

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The `top`, the footprint, the back and each drawer's floor (`drawer_<i>_floor`)."""
        W, D, H = p["width"], p["depth"], p["height"]
        floors = self.drawer_floors(self.layout(p))
        return [top_surface(D, W, H, p["top_overhang"]),
                base_bottom(D, W, "round_legs"),
                back_surface(W, p["base_height"], H, D)] + floors


def _shared(p: dict[str, Any]) -> dict[str, Any]:
    """The params with what every tool chest shares: bar handles and casters under the case."""
    return {**p, "handle": "bar", "base_style": "round_legs"}
