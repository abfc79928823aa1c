"""Doors, windows, stairs and railings of a home from the asset catalogue.

The catalogue's architecture generators (interior_door, exterior_door, window, staircase,
stair_railing) share one frame (see `assets.shapes.architectural`): the wall is the YZ plane
centred on x=0, +X the side a door swings into or the room side of a window, the opening's
width along Y, its bottom at z=0; a straight staircase climbs toward +X, centred on the origin;
a railing runs along Y. Each fixture here samples the generator's free parameters from its own
seed, pins the ones the plan fixes (width, height, wall thickness, rise, run), and places the
asset on the plan's wall, flight or opening. `None` comes back when a generator is missing or
rejects the plan's values, and the caller falls back to the simple parametric solids.

A door's leaf is kept apart from its frame (`Fixture.leaf`, `leaf_collision`, `joint`, all in
world coordinates at the shut pose), so the home's exporters make it an articulated body.
"""
from __future__ import annotations

import logging
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import trimesh

from indoorgen.architecture.doors import placed_joint
from indoorgen.assets import get_factory
from indoorgen.assets.protocol import Joint
from indoorgen.assets.shapes.architectural import opening_size
from indoorgen.errors import IndoorGenError
from indoorgen.rng import stream

log = logging.getLogger(__name__)


@dataclass
class Fixture:
    """A placed catalogue asset: generator, params, its mesh in world coordinates."""

    generator: str
    params: dict[str, Any]
    mesh: trimesh.Trimesh
    opening: tuple[float, float] | None = None  # the rough opening (width, height) it needs
    #: the asset's own convex collision pieces, placed like `mesh` (what simulators collide)
    collision: list[trimesh.Trimesh] = field(default_factory=list)
    #: a door's moving leaf: its mesh and convex pieces (shut, world coordinates; `mesh` and
    #: `collision` then hold the frame alone) and its joint in world coordinates
    leaf: trimesh.Trimesh | None = None
    leaf_collision: list[trimesh.Trimesh] = field(default_factory=list)
    joint: Joint | None = None


def _build(generator: str, seed: int, path: tuple, fixed: dict[str, Any]):
    """Sample `generator`'s params from (seed, path), pin `fixed`, check and build; None if the
    generator does not exist or rejects the values."""
    try:
        f = get_factory(generator)
        params = f.sample_params(stream(seed, "architecture", *path))
        params.update(fixed)
        params = {k: f.params[k].check(k, v) if k in f.params else v for k, v in params.items()}
        return f, params, f.create(params)
    except IndoorGenError as e:
        log.debug("catalogue %s unusable for %s: %s", generator, path, e)
        return None


def _placement(x_axis: np.ndarray, origin: np.ndarray) -> np.ndarray:
    """The 4x4 transform turning local +X onto `x_axis` (2D, horizontal), origin to `origin`."""
    m = np.eye(4)
    c, s = float(x_axis[0]), float(x_axis[1])
    m[:2, :2] = [[c, -s], [s, c]]
    m[:3, 3] = origin
    return m


def _placed(mesh: trimesh.Trimesh, m: np.ndarray) -> trimesh.Trimesh:
    out = mesh.copy()
    out.apply_transform(m)
    return out


def _fixture(generator: str, params: dict, asset, x_axis: np.ndarray, origin: np.ndarray,
             opening: tuple[float, float] | None = None) -> Fixture:
    """`asset` placed with its local +X rotated onto `x_axis` (2D, horizontal) and its origin
    moved to `origin`; its collision pieces go along."""
    m = _placement(x_axis, origin)
    return Fixture(generator, params, _placed(asset.mesh, m), opening,
                   [_placed(piece, m) for _, piece in asset.collision])


def _door_fixture(generator: str, params: dict, asset, x_axis: np.ndarray, origin: np.ndarray,
                  opening: tuple[float, float]) -> Fixture:
    """A door set placed like `_fixture`, its leaf (the child of its one joint) kept apart from
    the frame; a door without a joint stays one piece."""
    if len(asset.joints) != 1:
        return _fixture(generator, params, asset, x_axis, origin, opening)
    joint = asset.joints[0]
    m = _placement(x_axis, origin)
    frame = [_placed(p, m) for link, p in asset.collision if link != joint.child]
    leaf = [_placed(p, m) for link, p in asset.collision if link == joint.child]
    return Fixture(generator, params, _placed(asset.link_mesh(joint.parent), m), opening, frame,
                   _placed(asset.link_mesh(joint.child), m), leaf, placed_joint(joint, m))


def door(seed: int, name: str, exterior: bool, center, into: np.ndarray, width: float,
         height: float, wall: float, elevation: float) -> Fixture | None:
    """A door leaf with frame and casings in the wall at `center`, swinging towards `into`."""
    gen = "exterior_door" if exterior else "interior_door"
    fixed: dict[str, Any] = {"width": width, "height": height, "wall_thickness": wall}
    if exterior:
        fixed["sidelites"] = "none"
    got = _build(gen, seed, ("door", name), fixed)
    if got is None:
        return None
    f, params, asset = got
    c = np.asarray(center, float)
    return _door_fixture(gen, params, asset, into, np.array([c[0], c[1], elevation]),
                         opening_size(params))


def window(seed: int, name: str, center, inward: np.ndarray, width: float, height: float,
           sill: float, wall: float, elevation: float) -> Fixture | None:
    """A window in an exterior wall, its room side towards `inward`, bottom at the sill."""
    got = _build("window", seed, ("window", name),
                 {"width": width, "height": height, "wall_thickness": wall})
    if got is None:
        return None
    f, params, asset = got
    c = np.asarray(center, float)
    return _fixture("window", params, asset, inward,
                    np.array([c[0], c[1], elevation + sill]), opening_size(params))


def stair(seed: int, name: str, polygon, rise: float, elevation: float) -> Fixture | None:
    """A straight catalogue staircase on a flight footprint [bl, br, tr, tl] climbing `rise`."""
    p = np.asarray(polygon, float)
    up = p[3] - p[0]
    run = float(np.linalg.norm(up))
    width = float(np.linalg.norm(p[1] - p[0]))
    n = max(2, int(round(rise / 0.18)))
    got = _build("staircase", seed, ("stair", name),
                 {"style": "straight", "total_rise": rise, "riser_target": rise / n,
                  "going": run / (n - 1), "width": width})
    if got is None:
        return None
    f, params, asset = got
    centre = p.mean(axis=0)
    return _fixture("staircase", params, asset, up / run,
                    np.array([centre[0], centre[1], elevation]))


def railing(seed: int, name: str, a, b, elevation: float) -> Fixture | None:
    """A balustrade from a to b (its local Y along a->b)."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    length = float(np.linalg.norm(b - a))
    got = _build("stair_railing", seed, ("railing", name), {"length": length})
    if got is None:
        return None
    f, params, asset = got
    along = (b - a) / length
    x_axis = np.array([along[1], -along[0]])  # local +X is right of +Y
    mid = (a + b) / 2
    return _fixture("stair_railing", params, asset, x_axis,
                    np.array([mid[0], mid[1], elevation]))

