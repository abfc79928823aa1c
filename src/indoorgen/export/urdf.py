"""URDF export: `urdf/<object>.urdf` per object, `urdf/architecture.urdf`, and `scene.urdf`.

An object's URDF has its `base` link plus one child link per moving part, joined by revolute or
prismatic joints with limits (door leaves, drawers, appliance doors, lids). A child link's frame
sits at its joint's origin, so the joint turns about the link frame. Visual meshes are OBJ (+MTL
+ textures), collision geometry the asset's convex pieces (STL), inertials from the pieces with
mass from volume x density (`physics.link_inertials`).

`scene.urdf` holds everything in one robot whose root link is `world`: the architecture and
every object fixed to it at its pose (link names prefixed `<object>__`); an object fixed to
another's link (`ExportBundle.attachment`: a garment on a wardrobe's rail) is fixed to that link
instead. All paths are relative.

Door leaves are links of their own (`<door>__leaf`) on a revolute or prismatic joint to the
`architecture` link, with limits, effort, velocity, damping and friction. URDF has no initial
joint state, so a leaf's link is built where the scene stands it (open, shut) and that pose is
the joint's zero: the limits run from the shut pose (`-value`) to the fully open one
(`upper - value`).
"""
from __future__ import annotations

import logging
import os
from pathlib import Path
from xml.etree import ElementTree as ET

import numpy as np

from indoorgen.assets.protocol import Joint
from indoorgen.export.bundle import ArchElement, ExportBundle
from indoorgen.export.meshes import joint_frames
from indoorgen.export.obj import CollisionGeom, MeshFiles
from indoorgen.export.physics import (
    DOOR_DAMPING,
    JOINT_DAMPING,
    JOINT_EFFORT,
    JOINT_FRICTION,
    JOINT_VELOCITY,
    Inertial,
)

log = logging.getLogger(__name__)

URDF_DIR = "urdf"


def _f(v) -> str:
    return " ".join(f"{float(x):.6g}" for x in np.ravel(v))


def _origin(parent: ET.Element, xyz, rpy=(0.0, 0.0, 0.0)) -> None:
    ET.SubElement(parent, "origin", xyz=_f(xyz), rpy=_f(rpy))


def _link(robot: ET.Element, name: str, bundle: ExportBundle, files: MeshFiles, obj_name: str,
          link: str, frame: np.ndarray, inertial: Inertial | None, rel: str) -> None:
    """A <link> with inertial, visuals and collisions of one asset link; geometry is in the
    asset frame, shifted by -frame into the link frame. `rel` prefixes mesh paths. An object
    lying under others (a rug) is visual only, as in MJCF and USD: furniture stands on the
    floor through it."""
    el = ET.SubElement(robot, "link", name=name)
    if inertial is not None:
        _inertial(el, inertial, frame)
    for vf in files.visuals(obj_name):
        if vf.link != link:
            continue
        vis = ET.SubElement(el, "visual", name=f"{vf.link}_{vf.slot}")
        _origin(vis, -frame)
        geo = ET.SubElement(vis, "geometry")
        ET.SubElement(geo, "mesh", filename=rel + vf.path)
        mat = ET.SubElement(vis, "material", name=vf.material.key)
        r, g, b = files.textures.info(vf.material).mean_color
        ET.SubElement(mat, "color", rgba=f"{r:.4f} {g:.4f} {b:.4f} 1")
    if bundle.lies_under(bundle.scene.objects[obj_name]):
        return
    for k, (plink, geom) in enumerate(files.collisions(obj_name)):
        if plink == link:
            _collision(el, f"{link}_collision_{k}", geom, -frame, rel)


def _inertial(link: ET.Element, inertial: Inertial, frame: np.ndarray) -> None:
    """An <inertial> of `inertial` (asset or world coordinates) in a link frame at `frame`."""
    ine = ET.SubElement(link, "inertial")
    _origin(ine, inertial.com - frame)
    ET.SubElement(ine, "mass", value=f"{inertial.mass:.6g}")
    i = inertial.inertia
    ET.SubElement(ine, "inertia", ixx=f"{i[0, 0]:.6g}", ixy=f"{i[0, 1]:.6g}",
                  ixz=f"{i[0, 2]:.6g}", iyy=f"{i[1, 1]:.6g}", iyz=f"{i[1, 2]:.6g}",
                  izz=f"{i[2, 2]:.6g}")


def _collision(link: ET.Element, name: str, geom: CollisionGeom, offset: np.ndarray,
               rel: str) -> None:
    """A <collision>: a <box> primitive or an STL <mesh>, moved by `offset`."""
    col = ET.SubElement(link, "collision", name=name)
    geo = ET.SubElement(col, "geometry")
    if geom.is_box:
        _origin(col, np.asarray(geom.center) + offset)
        ET.SubElement(geo, "box", size=_f(geom.size))
    else:
        _origin(col, offset)
        ET.SubElement(geo, "mesh", filename=rel + geom.path)


def _joint(robot: ET.Element, name: str, j: Joint, origin: np.ndarray, links: tuple[str, str],
           limits: tuple[float, float], damping: float) -> None:
    """A revolute or prismatic <joint> between `links` (parent, child) at `origin` (in the
    parent's frame) along `j`'s axis, with `limits`, effort, velocity, damping and friction."""
    je = ET.SubElement(robot, "joint", name=name, type=j.kind)
    _origin(je, origin)
    ET.SubElement(je, "parent", link=links[0])
    ET.SubElement(je, "child", link=links[1])
    axis = np.asarray(j.axis, float)
    ET.SubElement(je, "axis", xyz=_f(axis / np.linalg.norm(axis)))
    ET.SubElement(je, "limit", lower=f"{limits[0]:.6g}", upper=f"{limits[1]:.6g}",
                  effort=f"{JOINT_EFFORT:g}", velocity=f"{JOINT_VELOCITY:g}")
    ET.SubElement(je, "dynamics", damping=f"{damping:g}", friction=f"{JOINT_FRICTION:g}")


def _object_links(robot: ET.Element, bundle: ExportBundle, files: MeshFiles, name: str,
                  prefix: str, rel: str) -> None:
    """Links and joints of one object into `robot` (link names `prefix + link`)."""
    asset = bundle.assets[name]
    frames = joint_frames(asset)
    inertials = bundle.inertials(name)
    for link in asset.links:
        _link(robot, prefix + link, bundle, files, name, link, frames[link],
              inertials.get(link), rel)
    for j in asset.joints:
        if j.child not in frames or j.parent not in frames:
            continue
        _joint(robot, prefix + j.name, j, frames[j.child] - frames[j.parent],
               (prefix + j.parent, prefix + j.child), (j.lower, j.upper), JOINT_DAMPING)


def _element_geometry(link: ET.Element, e: ArchElement, files: MeshFiles, offset: np.ndarray,
                      rel: str) -> None:
    """Visuals and collisions of architectural element `e` (world coordinates) moved by
    `offset` into `link`'s frame."""
    vis, col = files.architecture(e)
    for vf in vis:
        v = ET.SubElement(link, "visual", name=f"{'_'.join(e.path)}_{vf.slot}")
        _origin(v, offset)
        geo = ET.SubElement(v, "geometry")
        ET.SubElement(geo, "mesh", filename=rel + vf.path)
    for k, geom in enumerate(col):
        _collision(link, f"{'_'.join(e.path)}_collision_{k}", geom, offset, rel)


def _architecture_link(robot: ET.Element, name: str, bundle: ExportBundle, files: MeshFiles,
                       rel: str) -> None:
    """The static architecture as link `name`, and each door leaf as a link jointed to it."""
    el = ET.SubElement(robot, "link", name=name)
    for e in bundle.static_elements:
        _element_geometry(el, e, files, np.zeros(3), rel)
    for e in bundle.moving_elements:
        j = e.joint
        assert j is not None  # moving elements have joints
        origin = np.asarray(j.origin, float)
        lname = f"{e.parent}__leaf"
        link = ET.SubElement(robot, "link", name=lname)
        inertial = bundle.element_inertial(e)
        _inertial(link, inertial, origin)
        _element_geometry(link, e, files, -origin, rel)
        _joint(robot, f"{e.parent}__{j.name}", j, origin, (name, lname),
               (j.lower - e.joint_value, j.upper - e.joint_value), DOOR_DAMPING)


def _write(robot: ET.Element, path: Path) -> None:
    ET.indent(robot, "  ")
    path.write_text('<?xml version="1.0"?>\n' + ET.tostring(robot, encoding="unicode") + "\n")


def write_urdf(bundle: ExportBundle, root: Path, files: MeshFiles) -> list[Path]:
    """Write `urdf/<object>.urdf`, `urdf/architecture.urdf` and `scene.urdf` under `root`.
    Returns the files written (scene.urdf first)."""
    root = Path(root)
    udir = root / URDF_DIR
    udir.mkdir(parents=True, exist_ok=True)
    rel_u = Path(os.path.relpath(root, udir)).as_posix() + "/"
    written = []
    for obj in bundle.objects:
        robot = ET.Element("robot", name=obj.name)
        _object_links(robot, bundle, files, obj.name, "", rel_u)
        p = udir / f"{obj.name}.urdf"
        _write(robot, p)
        written.append(p)
    arch = ET.Element("robot", name="architecture")
    _architecture_link(arch, "architecture", bundle, files, rel_u)
    _write(arch, udir / "architecture.urdf")
    written.append(udir / "architecture.urdf")

    scene = ET.Element("robot", name="scene")
    ET.SubElement(scene, "link", name="world")
    _architecture_link(scene, "architecture", bundle, files, "")
    j = ET.SubElement(scene, "joint", name="world__architecture", type="fixed")
    ET.SubElement(j, "parent", link="world")
    ET.SubElement(j, "child", link="architecture")
    for obj in bundle.objects:
        prefix = f"{obj.name}__"
        _object_links(scene, bundle, files, obj.name, prefix, "")
        att = bundle.attachment(obj)
        if att is None:
            j = ET.SubElement(scene, "joint", name=f"world__{obj.name}", type="fixed")
            _origin(j, obj.pose.position, (0.0, 0.0, obj.pose.yaw))
            ET.SubElement(j, "parent", link="world")
        else:  # fixed to the link it hangs from, so it moves with it
            link = f"{att.parent}__{att.link}"
            j = ET.SubElement(scene, "joint", name=f"{link}__{obj.name}", type="fixed")
            frame = joint_frames(bundle.assets[att.parent])[att.link]
            _origin(j, att.position - frame, (0.0, 0.0, att.yaw))
            ET.SubElement(j, "parent", link=link)
        ET.SubElement(j, "child", link=prefix + "base")
    _write(scene, root / "scene.urdf")
    written.insert(0, root / "scene.urdf")
    return written
