"""Physical properties shared by the simulator exporters: which collision piece is made of
which material, and each link's mass, centre of mass and inertia.

Mass is volume x density: each link's volume is its closed render shell's (the real amount of
material, so a hollow vase weighs what a vase weighs), its density the volume-weighted mean of
its convex pieces' materials (a piece takes the material slot of the render faces lying on
it). The centre of mass and inertia come from the convex pieces, scaled to that mass.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..assets.base import Asset
from .bundle import MatRef
from .meshes import face_slot_names

#: lightest link and smallest principal inertia written (kg, kg m^2): simulators reject zeros
MIN_MASS = 1e-3
MIN_INERTIA = 1e-7


@dataclass
class Inertial:
    """Mass (kg), centre of mass (asset frame, m) and inertia tensor about it (kg m^2)."""

    mass: float
    com: np.ndarray
    inertia: np.ndarray

    def diagonalised(self) -> tuple[np.ndarray, np.ndarray]:
        """Principal moments (3,) and the rotation (3, 3) whose columns are the axes."""
        cached = self.__dict__.get("_diag")
        if cached is None:
            w, v = np.linalg.eigh(self.inertia)
            if np.linalg.det(v) < 0:
                v[:, 0] = -v[:, 0]
            cached = self.__dict__["_diag"] = (np.maximum(w, MIN_INERTIA), v)
        return cached


def density_of(material: str) -> float:
    """kg/m^3 of a registered material (1000 if unknown)."""
    from ..assets.materials import get_material
    try:
        return float(get_material(material).density)
    except Exception:
        return 1000.0


def piece_slots(asset: Asset) -> list[int]:
    """The material slot index of each collision piece: the slot covering the largest area of
    the render faces (of the piece's link) whose centroids lie in or on the piece."""
    fs = face_slot_names(asset)
    centroids = np.asarray(asset.mesh.triangles_center)
    areas = np.asarray(asset.mesh.area_faces)
    out = []
    for link, piece in asset.collision:
        faces = asset.link_faces(link)
        if len(faces) == 0 or len(piece.faces) == 0:
            out.append(0)
            continue
        lo, hi = np.asarray(piece.bounds) + [[-2e-3], [2e-3]]
        c = centroids[faces]
        near = faces[np.all((c >= lo) & (c <= hi), axis=1)]
        if len(near) == 0:
            out.append(int(np.bincount(fs[faces], weights=areas[faces]).argmax()))
            continue
        tri = np.asarray(piece.vertices)[np.asarray(piece.faces)]
        n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
        n /= np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-18)
        d = np.einsum("ij,ij->i", n, tri[:, 0])
        inside = np.all(centroids[near] @ n.T - d <= 2e-3, axis=1)
        sel = near[inside] if inside.any() else near
        out.append(int(np.bincount(fs[sel], weights=areas[sel]).argmax()))
    return out


def link_inertials(asset: Asset, materials: dict[str, MatRef]) -> dict[str, Inertial]:
    """Inertial of every link of `asset` with slot materials `materials` (see module doc)."""
    slots = piece_slots(asset)
    by_link: dict[str, list[tuple]] = {link: [] for link in asset.links}
    for (link, piece), si in zip(asset.collision, slots):
        slot = asset.slots[si] if si < len(asset.slots) else "body"
        ref = materials.get(slot)
        rho = density_of(ref.name) if ref else 1000.0
        by_link.setdefault(link, []).append((piece, rho))
    out = {}
    for link, items in by_link.items():
        out[link] = _link_inertial(asset, link, items)
    return out


def _link_inertial(asset: Asset, link: str, items: list[tuple]) -> Inertial:
    shell = asset.link_mesh(link) if len(asset.link_faces(link)) else None
    masses, coms, tensors, vol_pieces, rho_vol = [], [], [], 0.0, 0.0
    for piece, rho in items:
        v = abs(float(piece.volume))
        if v <= 1e-12:
            continue
        props = piece.mass_properties  # density 1
        masses.append(v * rho)
        coms.append(np.asarray(props["center_mass"], float))
        tensors.append(np.asarray(props["inertia"], float) * rho * np.sign(piece.volume or 1))
        vol_pieces += v
        rho_vol += v * rho
    if not masses:
        if shell is not None and len(shell.faces):
            c = np.asarray(shell.bounds).mean(axis=0)
            ext = np.ptp(np.asarray(shell.vertices), axis=0) if len(shell.vertices) else np.ones(3)
        else:
            c, ext = np.zeros(3), np.full(3, 0.05)
        m = MIN_MASS * 10
        box = m / 12.0 * np.diag([ext[1] ** 2 + ext[2] ** 2, ext[0] ** 2 + ext[2] ** 2,
                                  ext[0] ** 2 + ext[1] ** 2])
        return Inertial(m, c, box + np.eye(3) * MIN_INERTIA)
    masses = np.asarray(masses)
    coms = np.asarray(coms)
    total = masses.sum()
    com = (masses[:, None] * coms).sum(axis=0) / total
    inertia = np.zeros((3, 3))
    for m, c, t in zip(masses, coms, tensors):
        r = c - com
        inertia += t + m * (np.dot(r, r) * np.eye(3) - np.outer(r, r))
    # mass: the shell's volume (the real material) at the pieces' mean density
    rho = rho_vol / vol_pieces
    volume = vol_pieces
    if shell is not None and asset.closed and shell.is_volume:
        volume = min(abs(float(shell.volume)), vol_pieces)
    mass = max(volume * rho, MIN_MASS)
    inertia *= mass / total
    inertia = 0.5 * (inertia + inertia.T) + np.eye(3) * MIN_INERTIA
    return Inertial(mass, com, inertia)


def quat_between(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Unit quaternion (w, x, y, z) rotating unit vector a onto unit vector b."""
    a = np.asarray(a, float) / np.linalg.norm(a)
    b = np.asarray(b, float) / np.linalg.norm(b)
    c = float(np.dot(a, b))
    if c < -1 + 1e-9:  # opposite: half turn about any axis perpendicular to a
        axis = np.cross(a, [1.0, 0.0, 0.0])
        if np.linalg.norm(axis) < 1e-6:
            axis = np.cross(a, [0.0, 1.0, 0.0])
        axis /= np.linalg.norm(axis)
        return np.array([0.0, *axis])
    v = np.cross(a, b)
    q = np.array([1.0 + c, *v])
    return q / np.linalg.norm(q)


def quat_to_matrix(q: np.ndarray) -> np.ndarray:
    """3x3 rotation of unit quaternion (w, x, y, z)."""
    w, x, y, z = q
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def matrix_to_quat(m: np.ndarray) -> np.ndarray:
    """Unit quaternion (w, x, y, z) of a 3x3 rotation."""
    import trimesh
    h = np.eye(4)
    h[:3, :3] = m
    return np.asarray(trimesh.transformations.quaternion_from_matrix(h), float)
