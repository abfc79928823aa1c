"""Physical properties shared by the simulator exporters: which collision piece is made of
which material, and each link's mass, centre of mass and inertia.

Mass is volume x density: each link's volume is its closed render shell's (the real amount of
material, so a hollow vase weighs what a vase weighs), its density the volume-weighted mean of
its convex pieces' materials (a piece takes the material slot of the render faces lying on
it). A render shell is often the outside of a hollow thing (a fridge's sheet-steel casing, a
sofa's padded fabric, a toilet's ceramic walls), so a link never weighs more than its surface
as a wall of its materials' usual thickness (`WALL`): per material, the lesser of its pieces'
solid mass and its render faces' area x wall x density (so a solid shower tray and the thin
panels standing on it are each capped by what they are, not by the other's allowance; a
material that owns no piece, such as a can's label, counts as its wall).
The centre of mass comes from the closed render shells (the real material: a lamp's heavy foot,
not its shade's hull weighed as a solid drum; a link's shell is one union of its parts, so it
is the material's centroid at one density); the inertia from the convex pieces, scaled to
that mass and moved to that centre (parallel axes), so it is always a physical tensor.
Per kind (`object_inertials`): a bathtub's walls are a thin shell (`WALL_OF_KIND`), a lamp's
shade a thin skin (`WALL_OF_SLOT`) and its foot carries a weight (`FOOT_BALLAST`), a food box
is full (`CONTENTS_DENSITY`).
"""
from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass

import numpy as np
import trimesh

from indoorgen.assets.materials import get_material
from indoorgen.assets.protocol import Asset
from indoorgen.export.meshes import face_slot_names
from indoorgen.model.tags import Semantics

#: wall thickness (m) of a hollow thing of each material family, so that area x wall x density
#: is its mass: appliance casings and furniture tubes 1 mm of steel, glassware and panes 4 mm,
#: vitreous china 8 mm, moulded plastic 3 mm, 30 mm stone worktops and trays (a slab up to
#: 2 x 15 mm stays solid), corrugated board 3 mm, a painting's canvas 2 mm. A board's two faces
#: are both rendered, so furniture board takes 10 mm a face (a 16-20 mm board: at 18 mm a face a
#: bed weighed 150-200 kg, a wardrobe 190); upholstery (fabric over foam and frame) 10 mm at the
#: fabric's density, leather (a hide over the same foam, twice a weave's density) 5 mm.
#: Materials things are made solid of (books, wax, soil, rubber) take `SOLID_WALL`: only blocks
#: over 10 cm thick are capped.
WALL = {"metal": 1.0e-3, "glass": 4e-3, "ceramic": 8e-3, "plastic": 3e-3, "wood": 10e-3,
        "fabric": 10e-3, "leather": 5e-3, "stone": 15e-3}
#: per-kind exceptions to `WALL` (by tag, then material family): a bathtub is a pressed-steel
#: or acrylic shell (retailers: 30-60 kg), not 8 mm of vitreous china (a 130 kg tub)
WALL_OF_KIND = {Semantics.Bathtub: {"ceramic": 3e-3}}
#: per-material exceptions to `WALL` (by material name; None: solid)
WALL_OF_MATERIAL = {"cardboard": 3e-3, "painting": 2e-3, "soil": None, "water": None,
                    "wax": None, "fruit_skin": None}
#: the wall of solid materials (m): half the thickness of a block still weighed as solid
SOLID_WALL = 0.05

#: per-slot exceptions to `wall_of` (by slot name): a lamp's shade is a 1 mm skin (stretched
#: linen, paper or blown glass on a wire frame) whatever its material: weighed as 15 mm of
#: upholstery fabric a shade was 3 kg, as solid paper 18 kg
WALL_OF_SLOT = {"shade": 1.0e-3}

#: the weight in a lamp's foot (kg, by kind): a cast-iron or steel plate, or a sand-filled
#: base, that keeps a tall light thing upright (retailers' sheets: table lamps 2-4 kg, desk
#: lamps 1.5-3 kg, floor lamps 4-9 kg in all). Without it a hollow lamp's mass sat in its
#: shade's height and lamps tipped over in MuJoCo and Newton (issue 12)
FOOT_BALLAST = {Semantics.TableLamp: 0.8, Semantics.DeskLamp: 0.8, Semantics.FloorLamp: 3.0}

#: what a full package's contents weigh (kg per m^3 of its closed shell, by kind): breakfast
#: cereal, pasta, rice and tea packed loose (a 4 L cereal box holds 0.4-0.5 kg)
CONTENTS_DENSITY = {Semantics.FoodBox: 110.0}

#: lightest link and smallest principal inertia written (kg, kg m^2): simulators reject zeros
MIN_MASS = 1e-3
MIN_INERTIA = 1e-7
#: products of inertia this small against the largest moment are dropped, the principal axes
#: taken as the body's own (a change of at most 1% of a moment). Near-zero products leave the
#: eigen-solver a rotation in general directions (any within a pair of nearly equal moments: a
#: round pot), and an engine that rebuilds the tensor from it in float32 finds it asymmetric
#: past its tolerance: Newton "corrected" a 28 kg potted plant of the suite's 2-storey home
AXES_SNAP = 0.01

# Joints of moving parts, shared by the simulator exporters (MJCF, URDF):
#: viscous damping of doors, drawers and lids (N m s/rad or N s/m): they stay where left
JOINT_DAMPING = 2.0
#: dry friction of doors, drawers and lids (N m or N): flaps stay shut under gravity
JOINT_FRICTION = 0.5
#: damping of a room door's hinge or slide (N m s/rad or N s/m): a heavy leaf swings slowly
DOOR_DAMPING = 5.0
#: rotor inertia added to every hinge and slide (kg m^2 or kg): light parts stay numerically
#: stable at the 2 ms step
JOINT_ARMATURE = 0.01
#: effort (N m or N) and velocity (rad/s or m/s) limits of every joint: a hand's push
JOINT_EFFORT, JOINT_VELOCITY = 50.0, 2.0


@dataclass
class Inertial:
    """Mass (kg), centre of mass (asset frame, m) and inertia tensor about it (kg m^2)."""

    mass: float
    com: np.ndarray
    inertia: np.ndarray

    def diagonalised(self) -> tuple[np.ndarray, np.ndarray]:
        """Principal moments (3,) and the rotation (3, 3) whose columns are the axes (the
        identity, with the tensor's diagonal, when its products are under `AXES_SNAP`)."""
        cached = self.__dict__.get("_diag")
        if cached is None:
            inertia = np.asarray(self.inertia, float)
            moments = np.diag(inertia)
            products = inertia - np.diag(moments)
            if np.abs(products).max() <= AXES_SNAP * np.abs(moments).max():
                w, v = moments.copy(), np.eye(3)
            else:
                w, v = np.linalg.eigh(inertia)
                if np.linalg.det(v) < 0:
                    v[:, 0] = -v[:, 0]
            cached = self.__dict__["_diag"] = (np.maximum(w, MIN_INERTIA), v)
        return cached


def density_of(material: str) -> float:
    """kg/m^3 of a registered material (1000 if unknown)."""
    try:
        return float(get_material(material).density)
    except Exception:
        return 1000.0


def wall_of(material: str, family_walls: Mapping[str, float] | None = None) -> float:
    """Wall thickness (m) a hollow thing of `material` has (`WALL`, or `family_walls` where it
    names the material's family; `SOLID_WALL` if solid)."""
    if material in WALL_OF_MATERIAL:
        return WALL_OF_MATERIAL[material] or SOLID_WALL
    try:
        family = get_material(material).family
    except Exception:
        return SOLID_WALL
    return {**WALL, **(family_walls or {})}.get(family, SOLID_WALL)


def wall_masses(asset: Asset, materials: Mapping[str, str]) -> dict[str, float]:
    """Each link's mass (kg) as a hollow wall: sum of its render faces' area x `wall_of` x
    density of the face's material (slot -> material name in `materials`)."""
    return {link: float(v.sum()) for link, v in slot_wall_masses(asset, materials).items()}


def slot_wall_masses(asset: Asset, materials: Mapping[str, str],
                     family_walls: Mapping[str, float] | None = None) -> dict[str, np.ndarray]:
    """Each link's mass (kg) as a hollow wall per material slot (an array indexed like
    `asset.slots`, at least one entry): its render faces' area x `wall_of` x density."""
    if len(asset.mesh.faces) == 0:
        return {}
    per_slot = np.array([(density_of(m) * WALL_OF_SLOT.get(slot, wall_of(m, family_walls)))
                         if (m := materials.get(slot)) else 1000.0 * SOLID_WALL
                         for slot in asset.slots] or [1000.0 * SOLID_WALL])
    fs = np.minimum(face_slot_names(asset), len(per_slot) - 1)
    per_face = np.asarray(asset.mesh.area_faces) * per_slot[fs]
    links = (np.zeros(len(fs), int) if asset.face_links is None
             else np.asarray(asset.face_links, int))
    names = asset.links if asset.face_links is not None else ["base"]
    sums = np.zeros((len(names), len(per_slot)))
    np.add.at(sums, (links, fs), per_face)
    return {link: sums[i] for i, link in enumerate(names)}


def piece_slots(asset: Asset) -> list[int]:
    """The material slot index of each collision piece: the slot covering the largest area of
    the render faces (of the piece's link) whose centroids lie in or on the piece."""
    fs = face_slot_names(asset)
    centroids = np.asarray(asset.mesh.triangles_center)
    areas = np.asarray(asset.mesh.area_faces)
    link_faces = {link: asset.link_faces(link) for link in asset.links}
    out = []
    for link, piece in asset.collision:
        faces = link_faces.get(link)
        if faces is None:
            faces = link_faces[link] = asset.link_faces(link)
        if len(faces) == 0 or len(piece.faces) == 0:
            out.append(0)
            continue
        tri = np.asarray(piece.vertices)[np.asarray(piece.faces)]
        lo = tri.reshape(-1, 3).min(axis=0) - 2e-3
        hi = tri.reshape(-1, 3).max(axis=0) + 2e-3
        c = centroids[faces]
        near = faces[np.all((c >= lo) & (c <= hi), axis=1)]
        if len(near) == 0:
            out.append(int(np.bincount(fs[faces], weights=areas[faces]).argmax()))
            continue
        n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
        n /= np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-18)
        d = np.einsum("ij,ij->i", n, tri[:, 0])
        inside = np.all(centroids[near] @ n.T - d <= 2e-3, axis=1)
        sel = near[inside] if inside.any() else near
        out.append(int(np.bincount(fs[sel], weights=areas[sel]).argmax()))
    return out


def volume_integrals(triangles: np.ndarray) -> np.ndarray:
    """Per-triangle contributions (T, 10) to the integrals over a closed solid of 1, x, y, z,
    x^2, y^2, z^2, xy, yz, zx (divergence theorem, Eberly's "Polyhedral Mass Properties"), so
    that any set of triangles forming closed shells sums to that solid's moments."""
    v0, v1, v2 = triangles[:, 0], triangles[:, 1], triangles[:, 2]
    d = np.cross(v1 - v0, v2 - v0)
    f1 = v0 + v1 + v2
    f2 = v0 * v0 + v1 * (v0 + v1) + v2 * f1
    f3 = v0 ** 3 + v0 * v0 * v1 + v0 * v1 * v1 + v1 ** 3 + v2 * f2
    g0, g1, g2 = f2 + v0 * (f1 + v0), f2 + v1 * (f1 + v1), f2 + v2 * (f1 + v2)
    nxt = [1, 2, 0]  # x -> y, y -> z, z -> x
    mixed = d * (v0[:, nxt] * g0 + v1[:, nxt] * g1 + v2[:, nxt] * g2)
    out = np.concatenate([d[:, :1] * f1[:, :1], d * f2, d * f3, mixed], axis=1)
    return out / np.array([6, 24, 24, 24, 60, 60, 60, 120, 120, 120], float)


def object_inertials(asset: Asset, materials: Mapping[str, str], tags: Iterable[str]
                     ) -> dict[str, Inertial]:
    """Inertial of every link of an object of `tags` (`link_inertials`): its kind's walls
    (`WALL_OF_KIND`), a lamp's foot carrying its weight (`FOOT_BALLAST`), a package full of
    what it holds (`CONTENTS_DENSITY`)."""
    kinds = set(tags)
    family_walls = {fam: w for tag, walls in WALL_OF_KIND.items() if tag in kinds
                    for fam, w in walls.items()}
    return link_inertials(asset, materials, family_walls=family_walls,
                          ballast=sum(kg for tag, kg in FOOT_BALLAST.items() if tag in kinds),
                          contents=sum(r for tag, r in CONTENTS_DENSITY.items() if tag in kinds))


def link_inertials(asset: Asset, materials: Mapping[str, str], *,
                   family_walls: Mapping[str, float] | None = None, ballast: float = 0.0,
                   contents: float = 0.0) -> dict[str, Inertial]:
    """Inertial of every link of `asset` whose slots are made of `materials` (slot -> material
    name; see module doc), walls per material family as `family_walls` says where it does,
    with `ballast` kg more in the root link's foot (`foot_weight`) and the root link filled
    with `contents` kg/m^3 (its closed shell's volume, at its centre of mass).

    All convex pieces' moments come from one vectorised pass over their triangles; a link's
    density-weighted moments are the sums over its pieces."""
    slots = piece_slots(asset)
    kept = [i for i, (_, piece) in enumerate(asset.collision) if len(piece.faces)]
    pieces = [asset.collision[i] for i in kept]
    slot_of = np.array([slots[i] for i in kept], int)
    rho = np.array([_slot_density(asset, materials, si) for si in slot_of])
    moments = np.zeros((len(pieces), 10))
    if pieces:
        tris = np.concatenate([np.asarray(p.vertices)[np.asarray(p.faces)] for _, p in pieces])
        owner = np.repeat(np.arange(len(pieces)), [len(p.faces) for _, p in pieces])
        per_tri = volume_integrals(tris)
        for k in range(10):
            moments[:, k] = np.bincount(owner, weights=per_tri[:, k], minlength=len(pieces))
        moments *= np.sign(moments[:, :1] + (moments[:, :1] == 0))  # inverted pieces
    shells = _shell_moments(asset)
    walls = slot_wall_masses(asset, materials, family_walls)
    out = {}
    for link in asset.links + [lk for lk, _ in pieces if lk not in asset.links]:
        sel = [i for i, (lk, _) in enumerate(pieces) if lk == link and moments[i, 0] > 1e-12]
        if not sel:
            out[link] = _placeholder_inertial(asset, link)
            continue
        out[link] = _link_inertial(moments[sel], rho[sel], slot_of[sel], shells.get(link),
                                   walls.get(link))
    root = asset.links[0] if asset.links else None
    if contents > 0 and root in out and root in shells:
        held = contents * shells[root][0]
        base = out[root]
        out[root] = Inertial(base.mass + held, base.com,
                             base.inertia * (base.mass + held) / base.mass)
    if ballast > 0 and root in out:
        out[root] = with_weight(out[root], *foot_weight(asset, ballast))
    return out


def foot_weight(asset: Asset, mass: float) -> tuple[float, np.ndarray, np.ndarray]:
    """A weight of `mass` kg in the asset's foot: a 1 cm plate filling its `bottom` surface
    (or its bounds' bottom), as (mass, centre, inertia about that centre)."""
    lo, hi = np.asarray(asset.mesh.bounds)
    try:
        bottom = asset.surface("bottom")
        c = bottom.polygon.centroid
        centre = bottom.to_world(np.array([[c.x, c.y]]))[0]
        radius = float(np.sqrt(bottom.polygon.area / np.pi))
    except (KeyError, ValueError):
        centre, radius = np.array([(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, lo[2]]), float(
            min(hi[:2] - lo[:2]) / 2)
    centre = np.array([centre[0], centre[1], lo[2] + 0.005])
    disc = mass * np.diag([radius ** 2 / 4, radius ** 2 / 4, radius ** 2 / 2])
    return mass, centre, disc


def with_weight(inertial: Inertial, mass: float, centre: np.ndarray, inertia: np.ndarray
                ) -> Inertial:
    """`inertial` with a rigid weight of `mass` at `centre` (its own `inertia` about it)
    added: the combined centre of mass, and both inertias moved there (parallel axes)."""
    total = inertial.mass + mass
    com = (inertial.mass * inertial.com + mass * centre) / total
    out = inertial.inertia + inertia
    for m, c in ((inertial.mass, inertial.com), (mass, centre)):
        d = c - com
        out = out + m * (float(d @ d) * np.eye(3) - np.outer(d, d))
    return Inertial(total, com, 0.5 * (out + out.T))


def _slot_density(asset: Asset, materials: Mapping[str, str], slot_index: int) -> float:
    """Density (kg/m^3) of the material of slot `slot_index` (1000 if it has none)."""
    slot = asset.slots[slot_index] if slot_index < len(asset.slots) else "body"
    material = materials.get(slot)
    return density_of(material) if material else 1000.0


def _shell_moments(asset: Asset) -> dict[str, tuple[float, np.ndarray]]:
    """Each link's render shell, for closed assets (whose links are closed shells): (enclosed
    volume, its centroid); empty otherwise. A link's shell is the union of its parts, so one
    surface often bounds several materials: the centroid is the material's at one density.
    Links whose shell encloses nothing, or whose centroid falls outside their bounds, are left
    out."""
    if not asset.closed or len(asset.mesh.faces) == 0:
        return {}
    tris = np.asarray(asset.mesh.triangles)
    per_tri = volume_integrals(tris)[:, :4]
    links = (np.zeros(len(tris), int) if asset.face_links is None
             else np.asarray(asset.face_links, int))
    out = {}
    for i, link in enumerate(asset.links if asset.face_links is not None else ["base"]):
        sel = links == i
        m = per_tri[sel].sum(axis=0)
        if not sel.any() or m[0] <= 1e-12:
            continue
        pts = tris[sel].reshape(-1, 3)
        com = m[1:4] / m[0]
        if np.all((com >= pts.min(axis=0)) & (com <= pts.max(axis=0))):
            out[link] = (float(m[0]), com)
    return out


def _placeholder_inertial(asset: Asset, link: str) -> Inertial:
    """A light box-shaped inertial for a link without collision pieces (its render bounds)."""
    faces = asset.link_faces(link)
    if len(faces):
        v = np.asarray(asset.mesh.vertices)[np.unique(np.asarray(asset.mesh.faces)[faces])]
        c, ext = (v.min(axis=0) + v.max(axis=0)) / 2, np.ptp(v, axis=0)
    else:
        c, ext = np.zeros(3), np.full(3, 0.05)
    m = MIN_MASS * 10
    box = m / 12.0 * np.diag([ext[1] ** 2 + ext[2] ** 2, ext[0] ** 2 + ext[2] ** 2,
                              ext[0] ** 2 + ext[1] ** 2])
    return Inertial(m, c, box + np.eye(3) * MIN_INERTIA)


def _link_inertial(moments: np.ndarray, rho: np.ndarray, slots: np.ndarray,
                   shell: tuple[float, np.ndarray] | None,
                   walls: np.ndarray | None) -> Inertial:
    """One link's inertial from its pieces' moments (P, 10), densities (P,) and slots (P,), its
    render shell (`_shell_moments`) and its per-slot masses as hollow walls (see module doc)."""
    vol_pieces = float(moments[:, 0].sum())
    piece_mass = rho * moments[:, 0]
    total, (x, y, z), (xx, yy, zz), (xy, yz, zx) = (
        float(piece_mass.sum()), rho @ moments[:, 1:4], rho @ moments[:, 4:7],
        rho @ moments[:, 7:10])
    com = np.array([x, y, z]) / total
    cx, cy, cz = com
    inertia = np.array([
        [yy + zz - total * (cy * cy + cz * cz), -(xy - total * cx * cy), -(zx - total * cz * cx)],
        [-(xy - total * cx * cy), xx + zz - total * (cx * cx + cz * cz), -(yz - total * cy * cz)],
        [-(zx - total * cz * cx), -(yz - total * cy * cz), xx + yy - total * (cx * cx + cy * cy)]])
    # mass: the shell's volume (the real material) at the pieces' mean density ...
    mass = total
    if shell is not None:
        mass = min(shell[0], vol_pieces) * total / vol_pieces
    # ... and never more than each material's pieces allow as a hollow wall
    if walls is not None:
        solid = np.bincount(slots, weights=piece_mass, minlength=len(walls))[:len(walls)]
        owned = np.bincount(slots, minlength=len(walls))[:len(walls)] > 0
        mass = min(mass, float(np.where(owned, np.minimum(solid, walls), walls).sum()))
    mass = max(mass, MIN_MASS)
    inertia *= mass / total
    if shell is not None:  # the pieces' inertia about the shell's centre (parallel axes)
        d = shell[1] - com
        inertia += mass * (float(d @ d) * np.eye(3) - np.outer(d, d))
        com = shell[1]
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


def matrix_to_quat(m: np.ndarray) -> np.ndarray:
    """Unit quaternion (w, x, y, z) of a 3x3 rotation."""
    h = np.eye(4)
    h[:3, :3] = m
    return np.asarray(trimesh.transformations.quaternion_from_matrix(h), float)
