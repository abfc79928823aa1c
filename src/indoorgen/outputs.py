"""Writing outputs so that a killed run leaves either the whole result or nothing.

Everything is written to a temporary sibling of the target (same directory, so the final rename
is atomic on one filesystem) and renamed into place only when complete. A directory indoorgen
writes records which of its entries are indoorgen's (`RECORD`); nothing else in it is ever
replaced or deleted, so a user's own files beside a scene survive a rewrite.
"""
from __future__ import annotations

import contextlib
import fcntl
import json
import os
import re
import shutil
import tempfile
from collections.abc import Iterable, Iterator
from pathlib import Path

from indoorgen.errors import OutputError

#: the record of which entries of an output directory indoorgen wrote (so it never replaces or
#: removes anything else there)
RECORD = ".indoorgen-outputs.json"
#: files every scene or floorplan directory holds: found in a directory but not recorded as
#: indoorgen's, they make a write there fail before any work rather than after it
SCENE_FILES = frozenset({"scene.json", "floorplan.json", "report.json", "plan.png"})
#: the help of every command's --overwrite
OVERWRITE_HELP = ("write into a non-empty directory indoorgen did not write, beside its files "
                  "(none of them is replaced or removed)")
#: the start of the empty directory that checks a parent is writable, before `<pid>-`
PROBE_PREFIX = ".indoorgen-probe-"
#: the names of a run's temporary and old directories after `.<out name>.`
_STALE = re.compile(r"(?P<kind>tmp|old)-(?P<pid>[0-9]+)(-.*)?")


def check_writable(out: Path, directory: bool = True, *, replacing: bool = True,
                   overwrite: bool = False) -> None:
    """Raise OutputError now, before any work, if `out` (a directory, or a file when
    `directory` is False) cannot be created or written: a non-empty directory indoorgen did not
    write (unless `overwrite`: then indoorgen writes beside its files), one another run is
    writing, or, for a directory to be `replacing`, one holding scene files indoorgen did not
    write."""
    out = Path(out)
    if directory and Path.cwd().resolve().is_relative_to(out.resolve()):
        raise OutputError(f"{str(out)!r} is the current directory or holds it; indoorgen writes a "
                          "scene into a directory of its own: give a new name such as scene_0")
    if directory and out.exists() and not out.is_dir():
        raise OutputError(f"{out} exists and is not a directory")
    if not directory and out.is_dir():
        raise OutputError(f"{out} is a directory; give a file name")
    if directory and replacing and out.is_dir():
        ours = written_by_indoorgen(out)
        foreign = sorted(p.name for p in out.iterdir() if p.name in SCENE_FILES and p.name not in ours)
        if foreign:
            raise OutputError(f"{out} holds {', '.join(foreign)}, which indoorgen did not write; "
                              "move them or choose another output directory")
    if directory and out.is_dir() and not overwrite and not (out / RECORD).is_file() and \
            any(out.iterdir()):
        raise OutputError(f"{out} is not empty and indoorgen did not write it; give --overwrite "
                          "to write beside its files (none of them is replaced or removed), or "
                          "choose another output directory")
    parent = out.resolve().parent
    probe = parent
    while not probe.exists():
        probe = probe.parent
    if not probe.is_dir() or not os.access(probe, os.W_OK | os.X_OK):
        raise OutputError(f"cannot write to {out}: {probe} is not a writable directory")
    try:  # permissions can say yes where the filesystem says no (root, /proc, read-only mounts)
        tempfile.TemporaryDirectory(prefix=f"{PROBE_PREFIX}{os.getpid()}-", dir=probe).cleanup()
    except OSError as e:
        raise OutputError(f"cannot write to {out}: {probe} is not writable ({e.strerror})") from None
    if directory and out.resolve().parent.is_dir():
        with output_lock(out):  # another run writing there fails now, not after its work
            pass


@contextlib.contextmanager
def atomic_dir(out: Path, *, merge: bool = False, drop: Iterable[str] = (),
               overwrite: bool = False) -> Iterator[Path]:
    """Yield a fresh temporary directory; on success its entries replace `out`'s, on any error
    it is removed and `out` is left as it was.

    Only entries indoorgen wrote are ever replaced or dropped: every other entry of `out` (the
    user's files) is carried over into the new directory. `merge` keeps indoorgen's earlier
    entries too unless rewritten (an export adding a format beside the others); otherwise the
    result holds exactly what was written now plus the user's files; `drop` names earlier
    entries of indoorgen's that a merge must not keep (now stale). If something written now
    would overwrite a user's entry of the same name, OutputError is raised and nothing changes.
    A non-empty `out` indoorgen did not write is refused unless `overwrite`; a second run
    writing `out` at the same time is refused (`output_lock`).
    """
    out = Path(out)
    check_writable(out, replacing=not merge, overwrite=overwrite)
    parent = out.resolve().parent
    parent.mkdir(parents=True, exist_ok=True)
    with output_lock(out):
        clean_stale(out)
        try:
            tmp = Path(tempfile.mkdtemp(prefix=f".{out.name}.tmp-{os.getpid()}-", dir=parent))
        except OSError as e:
            raise OutputError(f"cannot write to {out}: {e.strerror}") from None
        try:
            yield tmp
            _swap_in(tmp, out, merge, frozenset(drop))
        except BaseException:
            shutil.rmtree(tmp, ignore_errors=True)
            raise


@contextlib.contextmanager
def output_lock(out: Path) -> Iterator[None]:
    """Hold the lock on writing `out` (fcntl on its sibling `.NAME.lock`, removed on release);
    OutputError at once if another run holds it."""
    path = Path(out).resolve().parent / f".{Path(out).name}.lock"
    while True:
        try:
            fd = os.open(path, os.O_RDWR | os.O_CREAT, 0o644)
        except OSError as e:
            raise OutputError(f"cannot write to {out}: {e.strerror}") from None
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            os.close(fd)
            raise OutputError(f"another indoorgen run is writing {out} (it holds {path.name}); "
                              "wait for it to finish or choose another output directory") from None
        try:  # the run that held it may have removed it meanwhile: lock the file in place
            if os.fstat(fd).st_ino == os.stat(path).st_ino:
                break
        except FileNotFoundError:
            pass
        os.close(fd)
    try:
        yield
    finally:
        path.unlink(missing_ok=True)
        os.close(fd)


def written_by_indoorgen(directory: Path) -> set[str]:
    """The entries of `directory` indoorgen wrote (from its record there; empty if none)."""
    try:
        data = json.loads((Path(directory) / RECORD).read_text())
        return {str(e) for e in data["entries"]} if isinstance(data.get("entries"), list) else set()
    except (OSError, ValueError, AttributeError):
        return set()


def _write_record(directory: Path, entries: set[str]) -> None:
    """Record which of `directory`'s entries indoorgen wrote."""
    (directory / RECORD).write_text(json.dumps({"written_by": "indoorgen",
                                                "entries": sorted(entries)}, indent=1) + "\n")


def _swap_in(tmp: Path, out: Path, merge: bool, drop: frozenset[str]) -> None:
    """Put the finished `tmp` in `out`'s place, carrying over the entries of `out` to keep."""
    new = {p.name for p in tmp.iterdir()}
    if not out.exists():
        _write_record(tmp, new)
        tmp.rename(out)
        return
    ours = written_by_indoorgen(out)
    old_entries = {p.name for p in out.iterdir()} - {RECORD}
    clash = sorted((old_entries & new) - ours)
    if clash:
        raise OutputError(f"{out} holds {', '.join(clash[:5])}, which indoorgen did not write; "
                          "move them or choose another output directory")
    keep = {e for e in old_entries - new if (merge and e not in drop) or e not in ours}
    _write_record(tmp, new | (keep & ours))
    old = out.with_name(f".{out.name}.old-{os.getpid()}")
    out.rename(old)
    tmp.rename(out)
    for e in sorted(keep):
        (old / e).rename(out / e)
    shutil.rmtree(old, ignore_errors=True)


def clean_stale(out: Path) -> None:
    """Remove what killed runs left beside `out`: their temporary directories, and their
    half-swapped old directories after moving any entry indoorgen did not write back into
    `out`. Only directories named by this module for a process that no longer runs are
    touched."""
    parent = Path(out).resolve().parent
    if not parent.is_dir():
        return
    for p in parent.glob(f"{PROBE_PREFIX}*-*"):  # a writability probe a kill left behind
        pid = p.name[len(PROBE_PREFIX):].split("-")[0]
        if pid.isdigit() and p.is_dir() and not _alive(int(pid)):
            with contextlib.suppress(OSError):
                p.rmdir()  # only ever empty: a probe holds nothing
    for p in parent.glob(f".{Path(out).name}.*-*"):
        m = _STALE.fullmatch(p.name[len(Path(out).name) + 2:])
        if m is None or not p.is_dir() or _alive(int(m["pid"])):
            continue
        if m["kind"] == "old" and Path(out).is_dir():
            ours = written_by_indoorgen(p)
            for e in p.iterdir():
                if e.name != RECORD and e.name not in ours and not (Path(out) / e.name).exists():
                    e.rename(Path(out) / e.name)
            if any(e.name not in ours | {RECORD} for e in p.iterdir()):
                continue  # the user's files with nowhere to go: left for them to see
        shutil.rmtree(p, ignore_errors=True)


def _alive(pid: int) -> bool:
    """Whether process `pid` still runs (on this machine)."""
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


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
