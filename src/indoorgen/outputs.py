"""Writing outputs so that a killed run leaves either the whole result or nothing.

Everything is written to a temporary sibling of the target (same directory, so the final rename
is atomic on one filesystem) and renamed into place only when complete.
"""
from __future__ import annotations

import contextlib
import os
import shutil
import tempfile
from collections.abc import Iterator
from pathlib import Path

from indoorgen.errors import OutputError


def check_writable(out: Path, directory: bool = True) -> None:
    """Raise OutputError now, before any work, if `out` (a directory, or a file when
    `directory` is False) cannot be created or replaced."""
    out = Path(out)
    if directory and out.exists() and not out.is_dir():
        raise OutputError(f"{out} exists and is not a directory")
    if not directory and out.is_dir():
        raise OutputError(f"{out} is a directory; give a file name")
    parent = out.resolve().parent
    probe = parent
    while not probe.exists():
        probe = probe.parent
    if not probe.is_dir() or not os.access(probe, os.W_OK | os.X_OK):
        raise OutputError(f"cannot write to {out}: {probe} is not a writable directory")
    try:  # permissions can say yes where the filesystem says no (root, /proc, read-only mounts)
        tempfile.TemporaryDirectory(prefix=".indoorgen-probe-", dir=probe).cleanup()
    except OSError as e:
        raise OutputError(f"cannot write to {out}: {probe} is not writable ({e.strerror})") from None


@contextlib.contextmanager
def atomic_dir(out: Path) -> Iterator[Path]:
    """Yield a fresh temporary directory; on success it replaces `out` (a directory), on any
    error it is removed and `out` is left as it was."""
    out = Path(out)
    check_writable(out)
    out.resolve().parent.mkdir(parents=True, exist_ok=True)
    try:
        tmp = Path(tempfile.mkdtemp(prefix=f".{out.name}.tmp-", dir=out.resolve().parent))
    except OSError as e:
        raise OutputError(f"cannot write to {out}: {e.strerror}") from None
    try:
        yield tmp
        if out.exists():
            old = out.with_name(f".{out.name}.old-{os.getpid()}")
            out.rename(old)
            tmp.rename(out)
            shutil.rmtree(old, ignore_errors=True)
        else:
            tmp.rename(out)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise


@contextlib.contextmanager
def atomic_file(out: Path) -> Iterator[Path]:
    """Yield a temporary file path (same suffix as `out`) that replaces `out` on success."""
    out = Path(out)
    check_writable(out, directory=False)
    out.resolve().parent.mkdir(parents=True, exist_ok=True)
    fd, name = tempfile.mkstemp(prefix=f".{out.stem}.tmp-", suffix=out.suffix,
                                dir=out.resolve().parent)
    os.close(fd)
    tmp = Path(name)
    try:
        yield tmp
        os.chmod(tmp, 0o666 & ~_umask())  # mkstemp makes 0600; give it a normal file's mode
        os.replace(tmp, out)
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise


def _umask() -> int:
    """The process umask (read by setting and restoring it)."""
    mask = os.umask(0o022)
    os.umask(mask)
    return mask
