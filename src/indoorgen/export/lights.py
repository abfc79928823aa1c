"""The lights of a scene, one source for every exporter: each lamp link's emissive faces (bulbs,
diffusers, LED faces, flames) become one sphere emitter of the same luminance.

An emitter sits at the area-weighted centre of its link's emissive faces, with the radius of the
sphere whose surface equals their area (kept between `MIN_RADIUS` and `MAX_RADIUS`), and glows
with `LUMINANCE` (cd/m^2, "nits": what a USD SphereLight's intensity is). Formats that take a
point light in candela (glTF's KHR_lights_punctual) get `Emitter.candela`: a sphere of radius r
and uniform luminance L shows a disc of area pi r^2 from every direction, so its luminous
intensity is I = L pi r^2 cd and its flux 4 pi I lm, the same light the sphere gives.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from indoorgen.assets.protocol import Asset
from indoorgen.export.bundle import EMISSIVE_SLOTS
from indoorgen.export.meshes import face_slot_names

#: luminance of every emitter (cd/m^2): a frosted bulb or an opal diffuser; the intensity USD's
#: SphereLights carry (export/usd/objects.py's LIGHT_INTENSITY, which should read it from here)
LUMINANCE = 8000.0
#: linear RGB colour of the light: a warm white of about 2700-3000 K
COLOR = (1.0, 0.88, 0.72)
#: radius range of an emitter's sphere (m): a candle flame up to a large ceiling diffuser
MIN_RADIUS = 0.005
MAX_RADIUS = 0.25


@dataclass(frozen=True)
class Emitter:
    """One light of an asset: on link `link`, centred at `centre` (asset frame, closed pose),
    a sphere of `radius` m around the link's emissive faces, whose total area is `area` m^2."""

    link: str
    index: int
    centre: np.ndarray
    radius: float
    area: float

    @property
    def candela(self) -> float:
        """Luminous intensity (cd) of the sphere seen as a point: `LUMINANCE` * pi r^2."""
        return LUMINANCE * math.pi * self.radius ** 2


def emitters(asset: Asset) -> list[Emitter]:
    """One `Emitter` per link of `asset` with emissive faces, in link order (`index` is the
    link's position, as USD names its lights `light_<index>`)."""
    slots = [i for i, s in enumerate(asset.slots) if s in EMISSIVE_SLOTS]
    if not slots:
        return []
    lit = np.nonzero(np.isin(face_slot_names(asset), slots))[0]
    if len(lit) == 0:
        return []
    areas = np.asarray(asset.mesh.area_faces)
    centres = np.asarray(asset.mesh.triangles_center)
    out = []
    for k, link in enumerate(asset.links):
        sel = np.intersect1d(lit, asset.link_faces(link))
        if len(sel) == 0:
            continue
        a = areas[sel]
        total = float(a.sum())
        centre = (centres[sel] * a[:, None]).sum(axis=0) / max(total, 1e-12)
        radius = float(np.clip(math.sqrt(total / (4 * math.pi)), MIN_RADIUS, MAX_RADIUS))
        out.append(Emitter(link, k, centre, radius, total))
    return out
