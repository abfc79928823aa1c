"""Newton benchmark: does an exported scene.usd stand still in NVIDIA's Newton engine (CPU)?

    python benchmarks/newton_usd.py SCENE.usdc [SCENE.usdc ...] [--seconds 1.0] [--dt 0.0016667]

Loads each stage with `newton.ModelBuilder.add_usd` (UsdPhysics rigid bodies, masses, convex
collision pieces, joints and their drives), simulates it on the CPU with the XPBD solver and
prints the load and simulation seconds, the bodies and joints loaded, the share of bodies whose
origin moves less than 2 cm in the simulated time and the bodies that moved most.

Needs `pip install newton newton-usd-schemas` (in the test extra; warp runs on the CPU). The
suite's cheap form is tests/export/usd/test_newton.py (a living room, 0.3 s); a home takes
minutes of CPU to simulate one second, so homes are measured here.
"""
from __future__ import annotations

import argparse
import time

import numpy as np

#: how far (m) a body may drift and still count as standing still
STILL = 0.02


def simulate(path: str, seconds: float, dt: float) -> dict:
    """Load `path` in Newton, simulate `seconds` at step `dt`; load/sim times and drifts."""
    import newton
    import warp as wp

    wp.config.quiet = True
    t0 = time.perf_counter()
    builder = newton.ModelBuilder()
    builder.add_usd(path)
    model = builder.finalize(device="cpu")
    t1 = time.perf_counter()
    solver = newton.solvers.SolverXPBD(model)
    s0, s1, control = model.state(), model.state(), model.control()
    newton.eval_fk(model, model.joint_q, model.joint_qd, s0)
    pipeline = newton.CollisionPipeline(model)
    contacts = pipeline.contacts()
    start = s0.body_q.numpy().copy()
    for _ in range(round(seconds / dt)):
        s0.clear_forces()
        pipeline.collide(s0, contacts)
        solver.step(s0, s1, control, contacts, dt)
        s0, s1 = s1, s0
    drift = np.linalg.norm(s0.body_q.numpy()[:, :3] - start[:, :3], axis=1)
    return {"load_s": t1 - t0, "sim_s": time.perf_counter() - t1, "bodies": model.body_count,
            "joints": model.joint_count, "drift": drift, "labels": list(model.body_label)}


def main() -> None:
    """Simulate each stage given and print its stability figures."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("stages", nargs="+")
    ap.add_argument("--seconds", type=float, default=1.0)
    ap.add_argument("--dt", type=float, default=1.0 / 600.0)
    ap.add_argument("--worst", type=int, default=8, help="bodies that moved most, listed")
    args = ap.parse_args()
    for path in args.stages:
        r = simulate(path, args.seconds, args.dt)
        d = r["drift"]
        still = float((d < STILL).mean()) if len(d) else 1.0
        print(f"{path}: load {r['load_s']:.1f} s, simulate {r['sim_s']:.1f} s; "
              f"{r['bodies']} bodies, {r['joints']} joints; "
              f"{still:.1%} within {STILL * 100:.0f} cm after {args.seconds:g} s")
        for i in np.argsort(-d)[:args.worst]:
            print(f"    {d[i]:.3f} m  {r['labels'][i]}")


if __name__ == "__main__":
    main()
