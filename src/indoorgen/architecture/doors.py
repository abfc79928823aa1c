"""Room doors as articulated objects: the states a home's door leaves stand in, and their joints
in world coordinates.

A door leaf turns about (or slides along) one joint whose value is 0 when the door is shut and
`upper` when it stands fully open (see `assets.protocol.Joint`). A home's doors are all `open`
(each leaf at `OPEN_ANGLE`, or its own limit if that is smaller, so the opening is clear), all
`closed`, or `random` (each door open or shut, drawn from the seed's own stream
`rng.stream(seed, "doors", name)`). The values are recorded per door in scene.json, so a
re-export stands every leaf where it stood.
"""
from __future__ import annotations

import math
from collections.abc import Mapping

import numpy as np
import trimesh

from indoorgen.assets.protocol import Joint
from indoorgen.errors import ConfigError
from indoorgen.rng import stream

#: the door states `--doors` accepts
DOOR_MODES = ("open", "closed", "random")
#: how far an open hinged leaf stands (rad): square to its wall, the opening clear
OPEN_ANGLE = math.pi / 2
#: a joint value at or below this (rad or m) counts as shut
SHUT = 1e-6


def check_door_mode(mode: str) -> str:
    """`mode` if it is one of `DOOR_MODES`, else ConfigError naming it and the valid ones."""
    if mode not in DOOR_MODES:
        raise ConfigError(f"doors {mode!r} is not a door state; valid: {', '.join(DOOR_MODES)}")
    return mode


def open_value(joint: Joint) -> float:
    """The joint value of a fully open leaf: `OPEN_ANGLE` for a hinge (or its upper limit if
    smaller), the full travel for a slide."""
    if joint.kind == "revolute":
        return float(min(OPEN_ANGLE, joint.upper))
    return float(joint.upper)


def door_value(doors: str | Mapping[str, float], seed: int | None, name: str,
               joint: Joint) -> float:
    """The joint value door `name` stands at: from a recorded map of values (a door missing
    from it is shut), or by mode (`DOOR_MODES`); `random` draws from (seed, "doors", name)."""
    if not isinstance(doors, str):
        return float(np.clip(float(doors.get(name, 0.0)), joint.lower, joint.upper))
    mode = check_door_mode(doors)
    if mode == "open":
        return open_value(joint)
    if mode == "closed":
        return 0.0
    rng = stream(0 if seed is None else seed, "doors", name)
    return open_value(joint) if rng.random() < 0.5 else 0.0


def placed_joint(joint: Joint, m: np.ndarray) -> Joint:
    """`joint` moved by the rigid transform `m` (4x4): axis rotated, origin transformed."""
    return Joint(joint.name, joint.kind, m[:3, :3] @ np.asarray(joint.axis, float),
                 m[:3, :3] @ np.asarray(joint.origin, float) + m[:3, 3], joint.lower,
                 joint.upper, joint.child, joint.parent)


def posed(mesh: trimesh.Trimesh, joint: Joint, value: float) -> trimesh.Trimesh:
    """A copy of `mesh` (its link at the shut pose) with `joint` set to `value`."""
    out = mesh.copy()
    if value != 0.0:
        out.apply_transform(joint.transform(value))
    return out
