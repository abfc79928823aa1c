"""The suite's own scheduling: tests marked with one `xdist_group` run on one worker, so the shared
homes (tests/conftest.py) are built once per run, not once per worker."""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

GROUPED = '''
import os
import pytest

@pytest.mark.xdist_group("homes")
@pytest.mark.parametrize("i", range(6))
def test_grouped(i):
    with open(os.environ["WORKERS_LOG"], "a") as log:
        log.write(os.environ["PYTEST_XDIST_WORKER"] + "\\n")

@pytest.mark.parametrize("i", range(6))
def test_free(i):
    pass
'''


def test_one_xdist_group_runs_on_one_worker(tmp_path: Path) -> None:
    """Six grouped tests under `-n 2 --dist loadgroup` (the suite's own options) share a worker."""
    (tmp_path / "test_grouped.py").write_text(GROUPED)
    log = tmp_path / "workers.log"
    run = subprocess.run(
        [sys.executable, "-m", "pytest", "-p", "no:cacheprovider", "-n", "2",
         "--dist", "loadgroup", "-q", str(tmp_path / "test_grouped.py")],
        cwd=tmp_path, env={**_env(), "WORKERS_LOG": str(log)},
        capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stdout + run.stderr
    workers = log.read_text().split()
    assert len(workers) == 6
    assert len(set(workers)) == 1, f"one xdist_group ran on workers {sorted(set(workers))}"


def _env() -> dict[str, str]:
    """The current environment without pytest's own variables (so the inner run is a fresh one)."""
    return {k: v for k, v in os.environ.items() if not k.startswith("PYTEST_")}
