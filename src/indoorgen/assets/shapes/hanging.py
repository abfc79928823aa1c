"""What hanging rails and the things hung from them share: the rail's radius, the `Rail` surface
a piece of furniture declares along a rail's top, and a hanger's hook around it."""
from __future__ import annotations

import manifold3d as m3d

from indoorgen.assets.protocol import Surface
from indoorgen.assets.shapes.primitives import rod, torus
from indoorgen.model.tags import Subpart

#: a clothes rail's radius (m): a 25 mm wardrobe tube, the common closet rod
RAIL_RADIUS = 0.0125
#: the Rail surface's half-width across the rail (m): a hook's centre sits within it
RAIL_HALF_WIDTH = 0.001
#: a hook's free play around the rail (m): its inside's radius is the rail's and this much
HOOK_PLAY = 0.005
#: how far the hook's arc is centred under the rail's axis (m): hung (its `hook` surface the
#: solver's 1 mm contact gap over the rail's top), its inside is ~3 mm over the rail's top and
#: clears the rail by 2 mm or more all round, polygon facets and the rail's width included
HOOK_DROP = 0.003


def rail_surface(name: str, x: float, y0: float, y1: float, z_axis: float) -> Surface:
    """The `Rail` surface along the top of a rail running along Y from y0 to y1 at (x, z_axis):
    upward, u along the rail (what hangs from it turns across it, its front along u)."""
    return Surface.rect(name, Subpart.Rail, (x, (y0 + y1) / 2, z_axis + RAIL_RADIUS), (0, 0, 1),
                        (0, 1, 0), (y1 - y0) / 2, RAIL_HALF_WIDTH)


def hook(wire: float, stem_bottom: float) -> m3d.Manifold:
    """A hanger's hook in its YZ plane, the rail running along X through (0, 0, -RAIL_RADIUS)
    (so the rail's top, where the hook rests, is z = 0): an arc over the rail, clear of it, and
    a stem down its +Y side to `stem_bottom` (z < 0)."""
    major = RAIL_RADIUS + HOOK_PLAY + wire
    zc = -RAIL_RADIUS - HOOK_DROP
    arc = torus(major, wire, sections=24, tube_sections=8).rotate((0.0, 90.0, 0.0))
    arc = arc.trim_by_plane((0.0, 0.0, 1.0), 0.0).translate((0.0, 0.0, zc))
    stem = rod((0.0, major, zc + 0.001), (0.0, major, stem_bottom), wire, 8)
    return arc + stem
