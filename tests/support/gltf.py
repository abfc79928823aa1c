"""glTF files in tests: the Khronos glTF-Validator's report on a .glb (npm `gltf-validator`, run
by node through `gltf_validate.js`), a .glb's JSON, and its nodes' world placements."""
from __future__ import annotations

import json
import os
import shutil
import struct
import subprocess
from pathlib import Path

import numpy as np
import trimesh

#: the environment variable naming the installed `gltf-validator` package directory
VALIDATOR_ENV = "INDOORGEN_GLTF_VALIDATOR"
#: where `.ci/run` installs it (`npm install --prefix .ci-node gltf-validator`)
CI_VALIDATOR = Path(__file__).resolve().parents[2] / ".ci-node" / "node_modules" / "gltf-validator"
SCRIPT = Path(__file__).with_name("gltf_validate.js")


def validator() -> tuple[list[str] | None, str]:
    """(the command that validates a file, given its path appended; None when node or the
    validator is missing) and the reason it is missing."""
    node = shutil.which("node")
    if node is None:
        return None, "node is not installed (the glTF validator runs on node)"
    pkg = Path(os.environ.get(VALIDATOR_ENV) or CI_VALIDATOR)
    if not (pkg / "package.json").is_file():
        return None, (f"the glTF validator is not installed: npm install --prefix DIR "
                      f"gltf-validator, then {VALIDATOR_ENV}=DIR/node_modules/gltf-validator")
    return [node, str(SCRIPT), str(pkg)], ""


def validate(cmd: list[str], path: Path) -> dict:
    """The validator's report (its JSON as a dict) on the file at `path`."""
    out = subprocess.run([*cmd, str(path)], capture_output=True, text=True, timeout=600,
                         check=True)
    report: dict = json.loads(out.stdout)
    return report


def glb_json(path: Path) -> dict:
    """The JSON chunk of a binary glTF file."""
    data = Path(path).read_bytes()
    length, kind = struct.unpack("<II", data[12:20])
    assert kind == 0x4E4F534A, "the first chunk of a .glb is its JSON"
    tree: dict = json.loads(data[20:20 + length])
    return tree


def world_matrices(tree: dict) -> dict[int, np.ndarray]:
    """Node index -> its 4x4 world matrix, from the nodes' translation / rotation / scale /
    matrix and the scene's hierarchy."""
    nodes = tree["nodes"]
    out: dict[int, np.ndarray] = {}

    def local(n: dict) -> np.ndarray:
        if "matrix" in n:
            return np.asarray(n["matrix"], float).reshape(4, 4).T
        x, y, z, w = n.get("rotation", (0.0, 0.0, 0.0, 1.0))
        m = trimesh.transformations.quaternion_matrix([w, x, y, z])
        m[:3, :3] *= np.asarray(n.get("scale", (1.0, 1.0, 1.0)))
        m[:3, 3] = n.get("translation", (0.0, 0.0, 0.0))
        return m

    stack = [(i, np.eye(4)) for i in tree["scenes"][tree.get("scene", 0)]["nodes"]]
    while stack:
        i, parent = stack.pop()
        out[i] = parent @ local(nodes[i])
        stack.extend((c, out[i]) for c in nodes[i].get("children", []))
    return out
