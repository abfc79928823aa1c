"""Running the `indoorgen` command line in a subprocess, for tests of what it prints."""
from __future__ import annotations

import subprocess
import sys

CLI = [sys.executable, "-m", "indoorgen.cli"]


def run(*args, cwd=None):
    """`indoorgen <args>` in `cwd`; the completed process (stdout, stderr as text)."""
    return subprocess.run(CLI + list(args), capture_output=True, text=True, cwd=cwd, timeout=600)
