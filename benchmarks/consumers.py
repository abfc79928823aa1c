"""Consumers benchmark: how the simulator exports behave in the engines users run.

    python benchmarks/consumers.py [--rooms 2] [--homes1 2] [--homes2 1] [--cache DIR]
                                   [--preset default] [--seconds 2]

For living rooms (seeds 0..rooms-1) and 1- and 2-storey homes (seeds 0..N-1) it writes the MJCF
and URDF exports and prints, per scene and then per kind (median and p90 over seeds):
- MuJoCo: seconds to compile `scene.xml` (or the compile error), and stability: the share of
  free bodies that moved < 2 cm in `--seconds` s under gravity and the largest drift (issue 12's
  bar: >= 99 % and none > 10 cm);
- PyBullet: seconds to load `scene.urdf`, then the same drift with every object URDF loaded as
  a free body at its pose (objects hanging on walls fixed, what a drawer or rail holds welded
  to it) on the fixed architecture, and the
  joints that penetrate another body (> 1 cm) when opened to either limit;
- with `--validators`, the Khronos glTF-Validator's errors on `scene.glb` (when node and the npm
  `gltf-validator` are installed, the package directory in `INDOORGEN_GLTF_VALIDATOR`, as
  `.ci/run` installs it) and NVIDIA's Omniverse asset validator's errors and failures on
  `scene.usdc` (issue 12's bar: none of either);
- Newton, when `import newton` works: load seconds and drift from `scene.usd` over 1 s
  (benchmarks/newton_usd.py's XPBD stepping; issue 12's bar: >= 99 % within 2 cm).
`--cache DIR` keeps each generated scene.json there and re-exports it on later runs (so before
and after an exporter change compare the same scenes).
"""
from __future__ import annotations

import argparse
import json
import logging
import math
import os
import shutil
import statistics
import subprocess
import tempfile
import time
from pathlib import Path

import mujoco
import numpy as np
import pybullet as pb

from indoorgen import GenerateConfig, HomeConfig, generate, generate_home
from indoorgen.export import write_formats
from indoorgen.export.bundle import ExportBundle, bundle_from_generated, bundle_from_scene
from indoorgen.export.stability import simulate, stability
from indoorgen.model.scene import Scene

#: Newton's simulated time and step (s): issue 12's bar is a second
NEWTON_SECONDS, NEWTON_DT = 1.0, 1.0 / 600.0
#: the environment variable naming the npm `gltf-validator` package directory, and the script
#: that runs it on one file (the suite's own)
GLTF_VALIDATOR_ENV = "INDOORGEN_GLTF_VALIDATOR"
GLTF_SCRIPT = Path(__file__).resolve().parents[1] / "tests" / "support" / "gltf_validate.js"
#: deepest a joint's part may reach into another body at a limit before it counts (m)
PENETRATION = 0.01


def scene_bundle(kind: str, seed: int, preset: str, cache: Path | None) -> ExportBundle:
    """The export bundle of one scene, generated (or read back from `cache`)."""
    path = cache / f"{kind}_{seed}.json" if cache else None
    if path is not None and path.exists():
        return bundle_from_scene(Scene.from_json(json.loads(path.read_text())))
    if kind == "living_room":
        gen = generate(seed, GenerateConfig(room_type="living_room", preset=preset))
    else:
        gen = generate_home(seed, HomeConfig(floors=int(kind[-1]), preset=preset))
    if path is not None:
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(gen.scene.dumps())
    return bundle_from_generated(gen)


def mujoco_figures(d: Path, seconds: float) -> dict:
    """Compile seconds and drift of `scene.xml` in MuJoCo."""
    t = time.perf_counter()
    try:
        mujoco.MjModel.from_xml_path(str(d / "scene.xml"))
    except Exception as e:  # reported: a refused file is a result
        return {"mj_error": str(e).splitlines()[0][:160]}
    out: dict = {"mj_load_s": time.perf_counter() - t}
    st = stability(simulate(d / "scene.xml", seconds))
    out.update(mj_free=st.free, mj_still=st.under_2cm, mj_max=st.max_m, mj_worst=st.worst)
    return out


def _quat(yaw: float) -> list[float]:
    return [0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2)]


def bullet_figures(bundle: ExportBundle, d: Path, seconds: float) -> dict:
    """PyBullet: scene.urdf load seconds; free-body drift; joints penetrating at a limit."""
    cid = pb.connect(pb.DIRECT)
    try:
        t = time.perf_counter()
        pb.loadURDF(str(d / "scene.urdf"), useFixedBase=True, physicsClientId=cid)
        out: dict = {"pb_load_s": time.perf_counter() - t}
        pb.resetSimulation(physicsClientId=cid)
        pb.setGravity(0, 0, -9.81, physicsClientId=cid)
        pb.loadURDF(str(d / "urdf" / "architecture.urdf"), useFixedBase=True,
                    physicsClientId=cid)
        bodies = {}
        for obj in bundle.objects:
            fixed = bundle.is_fixed(obj) or bundle.lies_under(obj)  # rugs: welded, as in MJCF
            bodies[obj.name] = (pb.loadURDF(
                str(d / "urdf" / f"{obj.name}.urdf"), obj.pose.position, _quat(obj.pose.yaw),
                useFixedBase=fixed, physicsClientId=cid), fixed)
        contents = {(bodies[a.parent][0], bodies[o.name][0]) for o in bundle.objects
                    if (a := bundle.attachment(o)) is not None and a.parent in bodies}
        out["pb_bad_joints"], out["pb_joints"] = _limit_penetrations(bodies, cid, contents)
        held = _hold_attached(bundle, bodies, cid)
        names = [n for n, (_, fixed) in bodies.items() if not fixed and n not in held]
        free = [bodies[n][0] for n in names]
        p0 = np.array([pb.getBasePositionAndOrientation(b, physicsClientId=cid)[0]
                       for b in free]).reshape(-1, 3)
        for _ in range(int(seconds * 240)):
            pb.stepSimulation(physicsClientId=cid)
        p1 = np.array([pb.getBasePositionAndOrientation(b, physicsClientId=cid)[0]
                       for b in free]).reshape(-1, 3)
        moved = np.linalg.norm(p1 - p0, axis=1)
        out.update(pb_free=len(free), pb_still=float((moved < 0.02).mean()) if len(free) else 1.0,
                   pb_max=float(moved.max()) if len(free) else 0.0,
                   pb_worst=[(names[i], float(moved[i])) for i in np.argsort(-moved)[:3]])
        return out
    finally:
        pb.disconnect(cid)


def _hold_attached(bundle: ExportBundle, bodies: dict, cid: int) -> set[str]:
    """Weld what lies in a drawer or hangs from a rail to its holder's link, clear of the
    holder's pieces, as every simulator export does (loaded free, folded clothes inside a
    dresser burst out of its carcass and flung what stood on it 0.9 m); their names."""
    held = set()
    for obj in bundle.objects:
        att = bundle.attachment(obj)
        if att is None or att.parent not in bodies or bodies[obj.name][1]:
            continue
        holder, body = bodies[att.parent][0], bodies[obj.name][0]
        links = {pb.getJointInfo(holder, j, physicsClientId=cid)[12].decode(): j
                 for j in range(pb.getNumJoints(holder, physicsClientId=cid))}
        for link in [-1, *links.values()]:
            pb.setCollisionFilterPair(holder, body, link, -1, 0, physicsClientId=cid)
        link = links.get(att.link, -1)
        state = (pb.getLinkState(holder, link, physicsClientId=cid)[0:2] if link >= 0 else
                 pb.getBasePositionAndOrientation(holder, physicsClientId=cid))
        pos, orn = pb.getBasePositionAndOrientation(body, physicsClientId=cid)
        inv = pb.invertTransform(*state)
        local = pb.multiplyTransforms(*inv, pos, orn)
        pb.createConstraint(holder, link, body, -1, pb.JOINT_FIXED, [0, 0, 0], local[0], [0, 0, 0],
                            local[1], physicsClientId=cid)
        held.add(obj.name)
    return held


def _limit_penetrations(bodies: dict, cid: int, contents: set[tuple[int, int]]
                        ) -> tuple[int, int]:
    """(joints whose part penetrates another body by > PENETRATION at a limit, joints); a
    body's `contents` (holder, held pairs: the clothes in a drawer, which move with it) are
    not the other bodies it may meet."""
    bad = total = 0
    others = [b for b, _ in bodies.values()]
    for b, _ in bodies.values():
        for j in range(pb.getNumJoints(b, physicsClientId=cid)):
            info = pb.getJointInfo(b, j, physicsClientId=cid)
            if info[2] not in (pb.JOINT_REVOLUTE, pb.JOINT_PRISMATIC):
                continue
            total += 1
            deepest = 0.0
            for q in (info[8], info[9]):
                pb.resetJointState(b, j, q, physicsClientId=cid)
                for o in others:
                    if o == b or (b, o) in contents:
                        continue
                    pts = pb.getClosestPoints(b, o, 0.0, linkIndexA=j, physicsClientId=cid)
                    deepest = min([deepest, *[p[8] for p in pts]])
            pb.resetJointState(b, j, 0.0, physicsClientId=cid)
            bad += deepest < -PENETRATION
    return bad, total


def newton_figures(d: Path) -> dict:
    """Newton (if installed): load seconds and drift of scene.usd's bodies over issue 12's
    second, stepped as benchmarks/newton_usd.py and the suite's Newton test step it (XPBD)."""
    try:
        from newton_usd import simulate
    except ImportError:
        return {}
    try:
        r = simulate(str(d / "scene.usdc"), NEWTON_SECONDS, NEWTON_DT)
    except ImportError:
        return {}
    except Exception as e:  # reported: an engine refusing the file is a result
        return {"nt_error": f"{type(e).__name__}: {e}"[:160]}
    moved = r["drift"]
    return {"nt_load_s": r["load_s"], "nt_bodies": len(moved),
            "nt_still": float((moved < 0.02).mean()), "nt_max": float(moved.max())}


def validator_figures(d: Path) -> dict:
    """The glTF validator's error count on scene.glb (when it is installed) and the asset
    validator's error and failure counts on scene.usdc, with the first few."""
    out: dict = {}
    pkg = os.environ.get(GLTF_VALIDATOR_ENV)
    node = shutil.which("node")
    if pkg and node:
        run = subprocess.run([node, str(GLTF_SCRIPT), pkg, str(d / "scene.glb")],
                             capture_output=True, text=True, timeout=900, check=True)
        issues = json.loads(run.stdout)["issues"]
        out["gltf_errors"] = int(issues["numErrors"])
        out["gltf_first"] = [m["code"] for m in issues["messages"] if m["severity"] == 0][:3]
    try:
        import omni.asset_validator as av
    except ImportError:
        return out
    logging.getLogger("omni.asset_validator").setLevel(logging.WARNING)
    found = list(av.ValidationEngine(init_rules=True).validate(str(d / "scene.usdc")).issues())
    bad = [i for i in found if i.severity in (av.IssueSeverity.ERROR, av.IssueSeverity.FAILURE)]
    out["oav_bad"] = len(bad)
    out["oav_first"] = [i.rule.__name__ if i.rule else i.message[:60] for i in bad[:3]]
    return out


def run_one(kind: str, seed: int, args) -> dict:
    """Every figure of one scene."""
    bundle = scene_bundle(kind, seed, args.preset, args.cache)
    fmts = "mjcf,urdf" + (",usd" if args.newton or args.validators else "") + (
        ",glb" if args.validators else "")
    with tempfile.TemporaryDirectory() as tmp:
        d = Path(tmp)
        write_formats(bundle, d, fmts, texture_resolution=16)
        out = {"kind": kind, "seed": seed, **mujoco_figures(d, args.seconds)}
        if args.bullet:
            out.update(bullet_figures(bundle, d, args.seconds))
        if args.newton:
            out.update(newton_figures(d))
        if args.validators:
            out.update(validator_figures(d))
    return out


def _stat(xs: list[float]) -> str:
    if not xs:
        return "-"
    return f"{statistics.median(xs):.3g} / {float(np.percentile(xs, 90)):.3g}"


def _total(xs: list[int | None]) -> str:
    """The sum of the counts measured ('-' when none was)."""
    got = [x for x in xs if x is not None]
    return str(sum(got)) if got else "-"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rooms", type=int, default=2, help="living rooms (seeds 0..N-1)")
    ap.add_argument("--homes1", type=int, default=2, help="1-storey homes (seeds 0..N-1)")
    ap.add_argument("--homes2", type=int, default=1, help="2-storey homes (seeds 0..N-1)")
    ap.add_argument("--preset", default="default")
    ap.add_argument("--seconds", type=float, default=2.0)
    ap.add_argument("--cache", type=Path, default=None)
    ap.add_argument("--no-bullet", dest="bullet", action="store_false")
    ap.add_argument("--newton", action="store_true", help="also Newton from the USD")
    ap.add_argument("--validators", action="store_true",
                    help="also the glTF validator on scene.glb and the asset validator on USD")
    args = ap.parse_args()
    rows = []
    jobs = ([("living_room", s) for s in range(args.rooms)]
            + [("home1", s) for s in range(args.homes1)]
            + [("home2", s) for s in range(args.homes2)])
    for kind, seed in jobs:
        r = run_one(kind, seed, args)
        rows.append(r)
        worst = ", ".join(f"{n} {m * 100:.1f} cm" for n, m in r.get("mj_worst", []))
        mj = (f"MJ error: {r['mj_error']}" if "mj_error" in r else
              f"MJ {r['mj_load_s']:.2f} s {r['mj_free']} free {100 * r['mj_still']:.1f}% "
              f"max {100 * r['mj_max']:.1f} cm ({worst})")
        pb_ = (f" | PB {r['pb_load_s']:.2f} s {100 * r['pb_still']:.1f}% "
               f"max {100 * r['pb_max']:.1f} cm ("
               + ", ".join(f"{n} {m * 100:.1f} cm" for n, m in r.get("pb_worst", []))
               + f"), {r['pb_bad_joints']}/{r['pb_joints']} joints penetrate"
               if "pb_load_s" in r else "")
        nt = (f" | NT {r.get('nt_error') or ''}{r.get('nt_load_s', 0):.2f} s "
              f"{100 * r.get('nt_still', 0):.1f}% max {100 * r.get('nt_max', 0):.1f} cm"
              if args.newton else "")
        va = (f" | glTF errors {r.get('gltf_errors', '-')} {r.get('gltf_first', '')}"
              f" | USD errors+failures {r.get('oav_bad', '-')} {r.get('oav_first', '')}"
              if args.validators else "")
        print(f"{kind:11s} {seed:3d}  {mj}{pb_}{nt}{va}", flush=True)
    print("\nkind         n  compiled  MJ load s  MJ % still  MJ max cm  pass  PB load s  "
          "PB % still  PB max cm  joints penetrating  NT % still  NT pass  glTF errors  "
          "USD errors+failures  (median / p90; errors summed)")
    for kind in dict.fromkeys(k for k, _ in jobs):
        rs = [r for r in rows if r["kind"] == kind]
        ok = [r for r in rs if "mj_error" not in r]
        passes = sum(r["mj_still"] >= 0.99 and r["mj_max"] <= 0.10 for r in ok)
        pbr = [r for r in rs if "pb_load_s" in r]
        ntr = [r for r in rs if "nt_still" in r]
        print(f"{kind:11s} {len(rs):2d}  {len(ok):4d}  {_stat([r['mj_load_s'] for r in ok]):>14s}"
              f"  {_stat([100 * r['mj_still'] for r in ok]):>12s}"
              f"  {_stat([100 * r['mj_max'] for r in ok]):>12s}  {passes:3d}"
              f"  {_stat([r['pb_load_s'] for r in pbr]):>12s}"
              f"  {_stat([100 * r['pb_still'] for r in pbr]):>12s}"
              f"  {_stat([100 * r['pb_max'] for r in pbr]):>12s}"
              f"  {sum(r['pb_bad_joints'] for r in pbr)}/{sum(r['pb_joints'] for r in pbr)}"
              f"  {_stat([100 * r['nt_still'] for r in ntr]):>12s}"
              f"  {sum(r['nt_still'] >= 0.99 for r in ntr)}/{len(ntr)}"
              f"  {_total([r.get('gltf_errors') for r in rs]):>11s}"
              f"  {_total([r.get('oav_bad') for r in rs]):>19s}")


if __name__ == "__main__":
    main()
