"""MJCF export (`scene.xml`) for MuJoCo.

- The architecture: static geoms in the world body (convex pieces for collision, textured
  visual meshes).
- Every movable object: a body at its pose with a `freejoint`; articulated parts as child
  bodies with `hinge` / `slide` joints (limits, damping and friction loss so flaps and doors
  stay shut under gravity until pushed).
- Objects hanging from walls or ceilings: bodies welded to the world (no joint); rugs too, with
  no collision geoms (furniture legs stand on the floor through their pile).
- Objects fixed to another's link (`ExportBundle.attachment`: a garment hung from a wardrobe's
  rail): a body inside that link's body, welded to it (no joint), so it moves with it.
- Door leaves: a body each in the world with a `hinge` / `slide` joint (range from shut, 0, to
  fully open; `ref` the value the leaf stands at, so the model starts where the scene stands
  it); the leaf's contacts with the static architecture are excluded (its range keeps it
  clear of frame and walls).
- Collision: one mesh geom per convex piece (MuJoCo hulls every mesh anyway); visual: textured
  mesh geoms that never collide (contype = conaffinity = 0, group 2).
- Inertials are written explicitly (mass from volume x density), and contacts between the
  links of one object are excluded.

Mesh and texture files are shared with the URDF export (`obj.MeshFiles`) and referenced by
paths relative to scene.xml.
"""
from __future__ import annotations

import logging
import math
from pathlib import Path
from xml.etree import ElementTree as ET

import numpy as np

from indoorgen.assets.protocol import Joint
from indoorgen.export.bundle import EMISSIVE_SLOTS, ArchElement, ExportBundle
from indoorgen.export.meshes import joint_frames
from indoorgen.export.obj import CollisionGeom, MeshFiles
from indoorgen.export.physics import (
    DOOR_DAMPING,
    JOINT_ARMATURE,
    JOINT_DAMPING,
    JOINT_FRICTION,
    Inertial,
    matrix_to_quat,
)
from indoorgen.model.scene import SceneObject

log = logging.getLogger(__name__)

TIMESTEP = 0.002
FRICTION = "0.9 0.02 0.001"
#: fewest vertices of a mesh MuJoCo accepts
MIN_MESH_VERTICES = 4
#: contact stiffness (time constant s, damping ratio): 5 steps, so a piece that starts a few mm
#: inside another (a headboard under a window sill, a box in a tight shelf cell) is eased out
#: instead of kicked out (2 steps, MuJoCo's stiffest, threw a bed and what lay on it 10-14 cm)
SOLREF = f"{5 * TIMESTEP:g} 1"


def _f(v) -> str:
    return " ".join(f"{float(x):.6g}" for x in np.ravel(v))


class _Assets:
    """The <asset> section: meshes, textures and materials, each added once."""

    def __init__(self, root: ET.Element, files: MeshFiles) -> None:
        self.el = ET.SubElement(root, "asset")
        self.files = files
        self._names: set[str] = set()

    def mesh(self, path: str, visual: bool = False) -> str:
        """The asset name of a mesh file. Visual meshes are open surfaces (one material's faces),
        so MuJoCo must treat them as shells when it measures them; inertia comes from the
        explicit <inertial> elements anyway."""
        name = path.removeprefix("meshes/").replace("/", "__").rsplit(".", 1)[0]
        if name not in self._names:
            attrs = {"name": name, "file": path}
            if visual:
                attrs["inertia"] = "shell"
            ET.SubElement(self.el, "mesh", attrs)
            self._names.add(name)
        return name

    def material(self, ref, emissive: bool = False) -> str:
        name = f"mat_{ref.key}" + ("_emissive" if emissive else "")
        if name in self._names:
            return name
        info = self.files.textures.info(ref)
        attrs = {"name": name, "specular": f"{0.5 * (1 - info.mean_roughness):.3f}",
                 "shininess": f"{0.8 * (1 - info.mean_roughness):.3f}",
                 "reflectance": f"{0.2 * info.metallic_value:.3f}"}
        rel = self.files.textures.relpath(ref, "base_color", self.files.root)
        if rel:
            tex = f"tex_{ref.key}"
            if tex not in self._names:
                ET.SubElement(self.el, "texture", name=tex, type="2d", file=rel)
                self._names.add(tex)
            attrs["texture"] = tex
            attrs["rgba"] = f"1 1 1 {info.opacity:.3f}"
        else:
            r, g, b = info.mean_color
            attrs["rgba"] = f"{r:.4f} {g:.4f} {b:.4f} {info.opacity:.3f}"
        if emissive:
            attrs["emission"] = "1"
        ET.SubElement(self.el, "material", attrs)
        self._names.add(name)
        return name


def _inertial(body: ET.Element, inertial: Inertial, frame: np.ndarray) -> None:
    moments, axes = inertial.diagonalised()
    q = matrix_to_quat(axes)
    ET.SubElement(body, "inertial", pos=_f(inertial.com - frame), quat=_f(q),
                  mass=f"{inertial.mass:.6g}", diaginertia=_f(moments))


def _collision_geom(assets: _Assets, geom: CollisionGeom, offset: np.ndarray) -> ET.Element:
    """A collision <geom>: a box (half sizes) or a convex mesh, moved by `offset`."""
    if geom.is_box:
        return ET.Element("geom", {"class": "collision", "type": "box",
                                   "size": _f(np.asarray(geom.size) / 2),
                                   "pos": _f(np.asarray(geom.center) + offset)})
    return ET.Element("geom", {"class": "collision", "mesh": assets.mesh(geom.path),
                               "pos": _f(offset)})


def _joint(body: ET.Element, name: str, j: Joint, damping: float,
           ref: float | None = None) -> None:
    """A hinge or slide <joint> of `j` at `body`'s origin: limited to its range, damped, with
    dry friction; `ref`, when given, the joint value the body is authored at."""
    axis = np.asarray(j.axis, float)
    attrs = {"name": name, "type": "slide" if j.kind == "prismatic" else "hinge",
             "axis": _f(axis / np.linalg.norm(axis)), "pos": "0 0 0",
             "range": f"{j.lower:.6g} {j.upper:.6g}", "limited": "true"}
    if ref is not None:
        attrs["ref"] = f"{ref:.6g}"
    attrs.update(damping=f"{damping:g}", frictionloss=f"{JOINT_FRICTION:g}",
                 armature=f"{JOINT_ARMATURE:g}")
    ET.SubElement(body, "joint", attrs)


def _geoms(body: ET.Element, assets: _Assets, files: MeshFiles, name: str, link: str,
           frame: np.ndarray, collide: bool = True) -> None:
    pos = _f(-frame)
    for vf in files.visuals(name):
        # a mesh of fewer than 4 vertices (a one-triangle label) is refused by MuJoCo
        if vf.link == link and vf.vertices >= MIN_MESH_VERTICES:
            ET.SubElement(body, "geom", {"class": "visual", "mesh": assets.mesh(vf.path, True),
                                         "material": assets.material(
                                             vf.material, vf.slot in EMISSIVE_SLOTS),
                                         "pos": pos})
    for plink, geom in files.collisions(name) if collide else ():
        if plink == link:
            body.append(_collision_geom(assets, geom, -frame))


def _object_body(world: ET.Element, assets: _Assets, bundle: ExportBundle, files: MeshFiles,
                 name: str) -> list[str]:
    """The body tree of object `name`; returns its body names (for contact exclusion)."""
    obj = bundle.scene.objects[name]
    asset = bundle.assets[name]
    frames = joint_frames(asset)
    inertials = bundle.inertials(name)
    container, position, yaw = _body_frame(world, bundle, obj)
    base = ET.SubElement(container, "body", name=name, pos=_f(position),
                         quat=_f([math.cos(yaw / 2), 0.0, 0.0, math.sin(yaw / 2)]))
    if container is not world:  # welded to the link it hangs from: its mass goes along
        _inertial(base, inertials["base"], frames["base"])
    elif not bundle.is_fixed(obj):
        ET.SubElement(base, "freejoint", name=f"{name}__free")
        _inertial(base, inertials["base"], frames["base"])
    _geoms(base, assets, files, name, "base", frames["base"], not bundle.lies_under(obj))
    bodies = {"base": base}
    names = [name]
    pending = list(asset.joints)
    while pending:
        progressed = False
        for j in list(pending):
            if j.parent not in bodies:
                continue
            pending.remove(j)
            progressed = True
            bname = f"{name}__{j.child}"
            b = ET.SubElement(bodies[j.parent], "body", name=bname,
                              pos=_f(frames[j.child] - frames[j.parent]))
            _joint(b, f"{name}__{j.name}", j, JOINT_DAMPING)
            _inertial(b, inertials[j.child], frames[j.child])
            _geoms(b, assets, files, name, j.child, frames[j.child])
            bodies[j.child] = b
            names.append(bname)
        if not progressed:
            log.warning("MJCF: object %r has joints whose parent link is missing: %s", name,
                        [j.name for j in pending])
            break
    return names


def _body_frame(world: ET.Element, bundle: ExportBundle, obj: SceneObject
                ) -> tuple[ET.Element, np.ndarray, float]:
    """Where `obj`'s body goes: inside the body of the link it is fixed to (`attachment`), at
    its pose in that link's frame, or in the world at its pose."""
    att = bundle.attachment(obj)
    if att is not None:
        link = att.parent if att.link == "base" else f"{att.parent}__{att.link}"
        body = world.find(f".//body[@name='{link}']")
        if body is not None:
            frame = joint_frames(bundle.assets[att.parent])[att.link]
            return body, att.position - frame, att.yaw
    return world, np.asarray(obj.pose.position, float), obj.pose.yaw


def _element_geoms(body: ET.Element, assets: _Assets, files: MeshFiles, el: ArchElement,
                   offset: np.ndarray) -> None:
    """Visual and collision geoms of architectural element `el` (world coordinates) moved by
    `offset` into `body`'s frame."""
    vis_files, col_files = files.architecture(el)
    for vf in vis_files:
        ET.SubElement(body, "geom", {"class": "visual", "mesh": assets.mesh(vf.path, True),
                                     "material": assets.material(vf.material),
                                     "pos": _f(offset)})
    for geom in col_files:
        body.append(_collision_geom(assets, geom, offset))


def _leaf_body(world: ET.Element, assets: _Assets, bundle: ExportBundle, files: MeshFiles,
               el: ArchElement) -> str:
    """A door leaf's body on its joint, framed at the joint's origin; returns its name."""
    j = el.joint
    assert j is not None  # moving elements have joints
    origin = np.asarray(j.origin, float)
    name = f"{el.parent}__leaf"
    body = ET.SubElement(world, "body", name=name, pos=_f(origin))
    _joint(body, f"{el.parent}__{j.name}", j, DOOR_DAMPING, el.joint_value)
    _inertial(body, bundle.element_inertial(el), origin)
    _element_geoms(body, assets, files, el, -origin)
    return name


def build_mjcf(bundle: ExportBundle, files: MeshFiles) -> ET.Element:
    """The <mujoco> element of `bundle` (mesh files written through `files`)."""
    root = ET.Element("mujoco", model=f"indoorgen_{bundle.scene.seed}")
    ET.SubElement(root, "compiler", angle="radian", autolimits="true", inertiafromgeom="false")
    ET.SubElement(root, "option", timestep=f"{TIMESTEP:g}", gravity="0 0 -9.81",
                  integrator="implicitfast", cone="elliptic")
    ET.SubElement(root, "size", memory="256M")
    default = ET.SubElement(root, "default")
    vis = ET.SubElement(default, "default", {"class": "visual"})
    ET.SubElement(vis, "geom", type="mesh", contype="0", conaffinity="0", group="2",
                  density="0")
    col = ET.SubElement(default, "default", {"class": "collision"})
    ET.SubElement(col, "geom", type="mesh", group="3", density="0", friction=FRICTION,
                  rgba="0.5 0.5 0.5 0.3", solref=SOLREF)
    assets = _Assets(root, files)
    world = ET.SubElement(root, "worldbody")
    ET.SubElement(world, "light", name="sun", directional="true", pos="0 0 10",
                  dir="0.2 0.3 -1", diffuse="0.6 0.6 0.6")
    for el in bundle.static_elements:
        _element_geoms(world, assets, files, el, np.zeros(3))
    contact = ET.Element("contact")
    for el in bundle.moving_elements:
        leaf = _leaf_body(world, assets, bundle, files, el)
        ET.SubElement(contact, "exclude", body1="world", body2=leaf)
    bodies: dict[str, list[str]] = {}
    # objects fixed to another's link go in after it, inside its body
    for obj in sorted(bundle.objects, key=lambda o: bundle.attachment(o) is not None):
        names = bodies[obj.name] = _object_body(world, assets, bundle, files, obj.name)
        att = bundle.attachment(obj)
        if att is not None:
            names = names + bodies.get(att.parent, [])
        for i, a in enumerate(names):
            for b in names[i + 1:]:
                ET.SubElement(contact, "exclude", body1=a, body2=b)
    if len(contact):
        root.append(contact)
    return root


def write_mjcf(bundle: ExportBundle, root: Path, files: MeshFiles) -> Path:
    """Write `scene.xml` under `root`; returns its path."""
    el = build_mjcf(bundle, files)
    ET.indent(el, "  ")
    path = Path(root) / "scene.xml"
    path.write_text(ET.tostring(el, encoding="unicode") + "\n")
    return path
