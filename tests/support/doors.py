"""Room doors in tests: each door opening's centre and wall normal, and whether a ray through
it, square to the wall, hits a mesh (a door leaf) at a given height."""
from __future__ import annotations

import numpy as np
import trimesh

from indoorgen.architecture.solidify import Architecture
from indoorgen.architecture.walls import door_frame, entrance_frame

#: heights above the floor the rays run at (m): a robot's base, its body, a person's head
RAY_HEIGHTS = (0.3, 1.0, 1.8)


def door_openings(arch: Architecture) -> dict[str, tuple[np.ndarray, np.ndarray, float]]:
    """Door name -> (opening centre on the wall's centre line (2,), unit wall normal (2,),
    floor elevation) of every door and the entrance of `arch`."""
    out = {}
    for storey in arch.floorplan.storeys:
        for d in storey.doors:
            f = door_frame(storey, d, arch.walls)
            out[d.name] = (np.asarray(f.center, float), np.asarray(f.n, float), storey.elevation)
        if arch.floorplan.entrance is not None and storey.level == 0:
            f = entrance_frame(storey, arch.floorplan.entrance, arch.walls)
            out["entrance"] = (np.asarray(f.center, float), np.asarray(f.n, float),
                               storey.elevation)
    return out


def blocked_heights(mesh: trimesh.Trimesh, centre: np.ndarray, normal: np.ndarray,
                    elevation: float, reach: float = 1.5) -> list[float]:
    """The heights of `RAY_HEIGHTS` at which a ray through the opening's `centre` along the
    wall `normal`, from `reach` before the wall to `reach` beyond it, hits `mesh`."""
    n = np.array([normal[0], normal[1], 0.0])
    origins = np.array([[centre[0], centre[1], elevation + h] for h in RAY_HEIGHTS]) - reach * n
    locs, rays, _ = mesh.ray.intersects_location(origins, np.tile(n, (len(origins), 1)))
    hit = {int(r) for r, p in zip(rays, locs, strict=True)
           if np.dot(p - origins[int(r)], n) <= 2 * reach}
    return [RAY_HEIGHTS[r] for r in sorted(hit)]
