"""The lights of a scene, one source for every exporter: each lamp link's emissive faces (bulbs,
diffusers, LED faces, flames) become one sphere emitter, and the fixture's household flux
(`FIXTURE_LUMENS`) is shared among its emitters.

An emitter sits at the area-weighted centre of its link's emissive faces, with the radius of the
sphere whose surface equals their area (kept between `MIN_RADIUS` and `MAX_RADIUS`), and gives out
`Emitter.lumens`. USD writes it as a normalized SphereLight (flux = pi x intensity lm, whatever its
radius); glTF's KHR_lights_punctual as a point light of `Emitter.candela` (an isotropic source of
flux F has intensity F / 4 pi cd).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from indoorgen.assets.protocol import Asset
from indoorgen.export.bundle import EMISSIVE_SLOTS
from indoorgen.export.meshes import face_slot_names

#: luminous flux (lm) of each light fixture, shared among its lit links: household LED lamps
#: (a ceiling lamp 1200 lm, about a 100 W incandescent bulb; a reading lamp 450 lm, 40 W); a
#: candle flame 12 lm (one candela)
FIXTURE_LUMENS = {"ceiling_light": 1200.0, "pendant_light": 800.0, "floor_lamp": 1000.0,
                  "table_lamp": 450.0, "desk_lamp": 450.0, "wall_sconce": 400.0,
                  "candle": 12.0}
#: flux (lm) of any other object with emissive faces
DEFAULT_LUMENS = 450.0
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
    lumens: float

    @property
    def candela(self) -> float:
        """Luminous intensity (cd) of the emitter seen as an isotropic point: lumens / 4 pi."""
        return self.lumens / (4 * math.pi)


def emissive_faces(asset: Asset) -> np.ndarray:
    """Whether each face of `asset` glows (an emissive slot: bulbs, diffusers, flames)."""
    slots = [i for i, s in enumerate(asset.slots) if s in EMISSIVE_SLOTS]
    return np.isin(face_slot_names(asset), slots)


def emitters(asset: Asset, generator: str = "") -> list[Emitter]:
    """One `Emitter` per link of `asset` with emissive faces, in link order (`index` is the
    link's position, as USD names its lights `light_<index>`), sharing the flux of a
    `generator` fixture."""
    lit = np.nonzero(emissive_faces(asset))[0]
    if len(lit) == 0:
        return []
    areas = np.asarray(asset.mesh.area_faces)
    centres = np.asarray(asset.mesh.triangles_center)
    found = []
    for k, link in enumerate(asset.links):
        sel = np.intersect1d(lit, asset.link_faces(link))
        if len(sel):
            found.append((k, link, sel))
    lumens = FIXTURE_LUMENS.get(generator, DEFAULT_LUMENS) / max(len(found), 1)
    out = []
    for k, link, sel in found:
        a = areas[sel]
        total = float(a.sum())
        centre = (centres[sel] * a[:, None]).sum(axis=0) / max(total, 1e-12)
        radius = float(np.clip(math.sqrt(total / (4 * math.pi)), MIN_RADIUS, MAX_RADIUS))
        out.append(Emitter(link, k, centre, radius, total, lumens))
    return out
