"""The asset protocol: `Param`, `Surface`, `Joint`, `Asset` and `AssetFactory`.

A generator is an `AssetFactory` subclass registered by name (see `assets.registry`). It
documents every parameter as a `Param` (so sampling, validation and `assets list` come for free),
and builds two meshes from the same params: a cheap `placeholder` for the solver's collision
checks and a detailed `create` for export. Both carry the same named `Surface`s.

Local frame (DESIGN.md): metres, Z up, origin at the centre of the bottom face of the bounding
box, front facing +X.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, ClassVar

import numpy as np
import shapely
import shapely.geometry as sg
import trimesh
from numpy.typing import ArrayLike

from indoorgen.errors import ParameterError
from indoorgen.model.tags import Semantics, Subpart


@dataclass(frozen=True)
class Param:
    """One documented parameter: a float or int range, a boolean, or a choice among values."""

    low: float = 0.0
    high: float = 1.0
    kind: str = "float"  # "float" | "int" | "bool" | "choice"
    choices: tuple = ()
    doc: str = ""

    def sample(self, rng: np.random.Generator) -> Any:
        """Draw one value of this param from `rng` (uniform over the range or the choices)."""
        if self.kind == "float":
            return float(rng.uniform(self.low, self.high))
        if self.kind == "int":
            return int(rng.integers(int(self.low), int(self.high) + 1))
        if self.kind == "bool":
            return bool(rng.random() < 0.5)
        if self.kind == "choice":
            return self.choices[int(rng.integers(len(self.choices)))]
        raise ValueError(f"unknown Param kind {self.kind!r}")

    def check(self, name: str, value: Any) -> Any:
        """Return `value` converted to this param's type, or raise ParameterError."""
        try:
            if self.kind == "float":
                v = float(value)
                ok = self.low - 1e-9 <= v <= self.high + 1e-9
            elif self.kind == "int":
                v = int(value)
                ok = self.low <= v <= self.high
            elif self.kind == "bool":
                v = value if isinstance(value, bool) else str(value).lower() in ("1", "true", "yes")
                ok = True
            else:
                v = value
                ok = v in self.choices
        except (TypeError, ValueError, OverflowError):
            ok, v = False, value
        if not ok:
            raise ParameterError(f"parameter {name}={value!r} is invalid; valid: {self.describe()}")
        return v

    def describe(self) -> str:
        """The valid values in words, for error messages and `assets list`."""
        if self.kind in ("float", "int"):
            return f"{self.kind} in [{self.low}, {self.high}]"
        if self.kind == "bool":
            return "true or false"
        return "one of " + ", ".join(map(str, self.choices))


@dataclass
class Surface:
    """A named planar patch of an asset: a polygon in the plane through `origin` with unit
    `normal`, expressed in 2D coordinates along `u` and `v = normal x u`."""

    name: str
    subpart: Subpart
    origin: np.ndarray
    normal: np.ndarray
    u: np.ndarray
    polygon: sg.Polygon
    #: the link the surface moves with (a drawer's floor: its drawer), "base" for the body
    link: str = "base"

    @property
    def v(self) -> np.ndarray:
        """The polygon's second axis, normal x u (computed once and cached)."""
        v = self.__dict__.get("_v")
        if v is None:
            n, u = self.normal, self.u
            v = self.__dict__["_v"] = np.array([n[1] * u[2] - n[2] * u[1],
                                                n[2] * u[0] - n[0] * u[2],
                                                n[0] * u[1] - n[1] * u[0]])
        return v

    @staticmethod
    def rect(name: str, subpart: Subpart, center: ArrayLike, normal: ArrayLike, u: ArrayLike,
             half_u: float, half_v: float) -> Surface:
        """A rectangle centred on `center`, extending +-half_u along u and +-half_v along v."""
        return Surface(name, subpart, np.asarray(center, float), _unit(normal), _unit(u),
                       shapely.box(-half_u, -half_v, half_u, half_v))

    def to_world(self, xy: np.ndarray) -> np.ndarray:
        """Map 2D polygon coordinates (N,2) to 3D points in the asset frame."""
        xy = np.atleast_2d(np.asarray(xy, float))
        return self.origin + xy[:, :1] * self.u + xy[:, 1:2] * self.v

    def corners(self) -> np.ndarray:
        """The polygon's exterior vertices in 3D (asset frame); of its convex hull when it comes
        in pieces (a counter split by a sink bowl nearly its full width)."""
        outline = self.polygon if isinstance(self.polygon, shapely.Polygon) else \
            self.polygon.convex_hull
        return self.to_world(np.asarray(outline.exterior.coords)[:-1])

    def transformed(self, rotation: np.ndarray, translation: np.ndarray) -> Surface:
        """This surface rotated, then translated (the polygon itself is unchanged)."""
        return Surface(self.name, self.subpart, rotation @ self.origin + translation,
                       rotation @ self.normal, rotation @ self.u, self.polygon, self.link)


@dataclass
class Joint:
    """An articulation: link `child` moves relative to link `parent`, turning about (revolute) or
    sliding along (prismatic) `axis` through `origin`, both in the asset frame at the closed pose.
    Joint values run from `lower` to `upper` (radians or metres); 0 is the pose the mesh is built
    in (door shut, drawer in)."""

    name: str
    kind: str  # "revolute" | "prismatic"
    axis: np.ndarray
    origin: np.ndarray
    lower: float
    upper: float
    child: str
    parent: str = "base"

    def transform(self, value: float) -> np.ndarray:
        """4x4 transform of the child link at joint value `value`."""
        axis = np.asarray(self.axis, float) / np.linalg.norm(self.axis)
        m = np.eye(4)
        if self.kind == "prismatic":
            m[:3, 3] = axis * value
            return m
        rot = trimesh.transformations.rotation_matrix(value, axis, np.asarray(self.origin, float))
        return rot

    def translated(self, offset: np.ndarray) -> Joint:
        """This joint with its origin moved by `offset` (when an asset is recentred)."""
        return Joint(self.name, self.kind, np.asarray(self.axis, float),
                     np.asarray(self.origin, float) + offset, self.lower, self.upper,
                     self.child, self.parent)


@dataclass
class Asset:
    """A built object: its mesh, named surfaces, material slot per face, and its articulation.

    The mesh is the concatenation of one closed shell per link ("base" first); `face_links`
    says which link each face belongs to and `joints` how the links move. `corner_uv` holds a
    texture coordinate per face corner (F, 3, 2), in metres, so tileable materials map at true
    scale. `collision` lists convex pieces (link name, mesh) for simulators, which never collide
    with the render mesh."""

    mesh: trimesh.Trimesh
    surfaces: list[Surface]
    face_slots: np.ndarray | None = None
    slots: list[str] = field(default_factory=lambda: ["body"])
    joints: list[Joint] = field(default_factory=list)
    closed: bool = True
    links: list[str] = field(default_factory=lambda: ["base"])
    face_links: np.ndarray | None = None
    corner_uv: np.ndarray | None = None
    collision: list[tuple[str, trimesh.Trimesh]] = field(default_factory=list)

    def surface(self, name: str) -> Surface:
        """The surface called `name`, or KeyError listing the surfaces there are."""
        for s in self.surfaces:
            if s.name == name:
                return s
        raise KeyError(f"no surface named {name!r}; have {[s.name for s in self.surfaces]}")

    def surfaces_of(self, subpart: Subpart) -> list[Surface]:
        """Every surface with the role `subpart`."""
        return [s for s in self.surfaces if s.subpart == subpart]

    @property
    def extents(self) -> np.ndarray:
        """The mesh's bounding-box size (x, y, z)."""
        return self.mesh.bounds[1] - self.mesh.bounds[0]

    def link_faces(self, link: str) -> np.ndarray:
        """Indices of the faces of `link`."""
        if self.face_links is None:
            return np.arange(len(self.mesh.faces)) if link == "base" else np.zeros(0, int)
        return np.nonzero(self.face_links == self.links.index(link))[0]

    def link_mesh(self, link: str) -> trimesh.Trimesh:
        """The closed shell of one link, in the asset frame at the closed pose."""
        shell = self.mesh.submesh([self.link_faces(link)], append=True, repair=False)
        assert isinstance(shell, trimesh.Trimesh)  # append=True joins the pieces into one mesh
        return shell

    def posed(self, values: dict[str, float]) -> trimesh.Trimesh:
        """The whole mesh with joints set to `values` (joint name -> value; missing: 0).
        Chained joints (a link whose parent is not the base) compose parent-first."""
        mesh = self.mesh.copy()
        if not self.joints or self.face_links is None:
            return mesh
        by_child = {j.child: j for j in self.joints}
        verts = mesh.vertices.copy()
        for li, link in enumerate(self.links):
            m, cur = np.eye(4), link
            while cur in by_child:
                j = by_child[cur]
                m = j.transform(values.get(j.name, 0.0)) @ m
                cur = j.parent
            if np.allclose(m, np.eye(4)):
                continue
            idx = np.unique(mesh.faces[self.face_links == li])
            verts[idx] = trimesh.transform_points(self.mesh.vertices[idx], m)
        mesh.vertices = verts
        return mesh


def _unit(v) -> np.ndarray:
    v = np.asarray(v, float)
    return v / np.linalg.norm(v)


def box_surfaces(depth: float, width: float, height: float, *, front: bool = True,
                 back: bool = True, top: bool = True, sides: bool = True) -> list[Surface]:
    """The standard outer surfaces of an object whose bounding box is depth (X) x width (Y) x
    height (Z), in the local frame: bottom, top, back, front and both sides."""
    d2, w2, h2 = depth / 2, width / 2, height / 2
    out = [Surface.rect("bottom", Subpart.Bottom, (0, 0, 0), (0, 0, -1), (1, 0, 0), d2, w2)]
    if top:
        out.append(Surface.rect("top", Subpart.Top, (0, 0, height), (0, 0, 1), (1, 0, 0), d2, w2))
    if back:
        out.append(Surface.rect("back", Subpart.Back, (-d2, 0, h2), (-1, 0, 0), (0, 1, 0), w2, h2))
    if front:
        out.append(Surface.rect("front", Subpart.Front, (d2, 0, h2), (1, 0, 0), (0, 1, 0), w2, h2))
    if sides:
        out.append(Surface.rect("side_left", Subpart.Side, (0, w2, h2), (0, 1, 0), (1, 0, 0), d2, h2))
        out.append(Surface.rect("side_right", Subpart.Side, (0, -w2, h2), (0, -1, 0), (1, 0, 0), d2, h2))
    return out


class AssetFactory:
    """Base class of every generator. Subclasses set `name`, `tags`, `params` and implement
    `placeholder` and `create`; most never override `sample_params`."""

    name: ClassVar[str] = ""
    tags: ClassVar[frozenset[Semantics]] = frozenset()
    params: ClassVar[dict[str, Param]] = {}
    #: "large" (floor furniture), "medium" (wall / beside furniture) or "small" (on objects);
    #: informational: stages are decided by relations in the constraint program.
    size_class: ClassVar[str] = "large"
    #: weighted material choices per slot ({"legs": {"oak": 2, "brushed_steel": 1}}), overriding
    #: the material library's defaults for slots of the same name
    material_choices: ClassVar[dict[str, dict[str, float]]] = {}
    #: relative weight of this generator when the solver draws one for a tag set (`solver/moves`
    #: `add`): how common the kind is among its peers (a home holds one or two table clocks)
    frequency: ClassVar[float] = 1.0

    def sample_params(self, rng: np.random.Generator) -> dict[str, Any]:
        """Draw every documented parameter from its range (in sorted-name order, for stability)."""
        return {k: self.params[k].sample(rng) for k in sorted(self.params)}

    def validate_params(self, overrides: dict[str, Any]) -> dict[str, Any]:
        """Check user overrides against the documented params; raise ParameterError if bad."""
        out = {}
        for k, v in overrides.items():
            if k not in self.params:
                raise ParameterError(f"{self.name} has no parameter {k!r}; valid: "
                                     + ", ".join(sorted(self.params)))
            out[k] = self.params[k].check(k, v)
        return out

    def placeholder(self, params: dict[str, Any]) -> Asset:
        """The cheap asset the solver collides: every part containing the detailed one."""
        raise NotImplementedError

    def create(self, params: dict[str, Any]) -> Asset:
        """The detailed asset for export: watertight shells, UVs, joints, collision pieces."""
        raise NotImplementedError
