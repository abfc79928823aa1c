"""A batch's directory: the append-only `manifest.jsonl` (one line per finished attempt, flushed
and fsync'd, so a crash loses no finished line), `batch.json` (the options the scenes were made
with, so a resume cannot mix configurations), and the cleaning of what killed attempts left.

    DIR/batch.json        {"indoorgen_version", "generate": the generate options, ...}
    DIR/manifest.jsonl    one record per attempt (`jobs.record`)
    DIR/scenes/<seed>/    each scene, written by `outputs.atomic_dir` and renamed into place
"""
from __future__ import annotations

import fcntl
import json
import os
import re
import shutil
from collections.abc import Iterable, Mapping
from pathlib import Path
from typing import Any, TextIO

from indoorgen import __version__
from indoorgen.errors import BatchConfigError
from indoorgen.outputs import atomic_file, clean_stale

MANIFEST = "manifest.jsonl"
BATCH_JSON = "batch.json"
SCENES = "scenes"
#: a temporary or old directory `outputs.atomic_dir` made for a scene (`.<seed>.tmp-<pid>-...`)
_SCENE_LEFTOVER = re.compile(r"\.(?P<seed>[0-9]+)\.(tmp|old)-(?P<pid>[0-9]+)(-.*)?")
#: a scene's writer lock (`outputs.output_lock`), left behind when its writer was killed
_SCENE_LOCK = re.compile(r"\.(?P<seed>[0-9]+)\.lock")


class Manifest:
    """The manifest open for appending: each record is one JSON line, flushed and fsync'd."""

    def __init__(self, directory: Path) -> None:
        """Open `directory`'s manifest for appending, first cutting off a line a crash left
        half-written (so the next record starts on a line of its own)."""
        self.path = Path(directory) / MANIFEST
        _drop_partial_line(self.path)
        self._file: TextIO = open(self.path, "a", encoding="utf-8")  # noqa: SIM115 (held open)

    def append(self, rec: Mapping[str, Any]) -> None:
        """Write one record as a line and make it durable before returning."""
        self._file.write(json.dumps(rec, sort_keys=True) + "\n")
        self._file.flush()
        os.fsync(self._file.fileno())

    def close(self) -> None:
        """Close the file."""
        self._file.close()

    def __enter__(self) -> Manifest:
        """Use as a context manager that closes the file."""
        return self

    def __exit__(self, *exc: object) -> None:
        """Close the file."""
        self.close()


def read_manifest(directory: Path) -> list[dict[str, Any]]:
    """Every complete record of `directory`'s manifest, in order (a half-written last line, left
    by a crash, is skipped)."""
    path = Path(directory) / MANIFEST
    if not path.is_file():
        return []
    out = []
    for line in path.read_text(encoding="utf-8").splitlines():
        try:
            rec = json.loads(line)
        except ValueError:
            continue
        if isinstance(rec, dict) and isinstance(rec.get("seed"), int):
            out.append(rec)
    return out


def latest(records: Iterable[Mapping[str, Any]]) -> dict[int, dict[str, Any]]:
    """Each seed's last record (a retried seed's earlier attempts stay in the manifest)."""
    return {int(r["seed"]): dict(r) for r in records}


def seeds_to_run(seeds: Iterable[int], directory: Path, *, retry_failed: bool) -> list[int]:
    """The seeds of `seeds` still to generate: those never attempted, those whose scene went
    missing, and with `retry_failed` those whose last attempt failed or timed out."""
    last = latest(read_manifest(directory))
    todo = []
    for s in seeds:
        rec = last.get(s)
        if rec is None or (rec["status"] == "ok" and not (scenes_dir(directory) / str(s)).is_dir()) \
                or (retry_failed and rec["status"] != "ok"):
            todo.append(s)
    return todo


def scenes_dir(directory: Path) -> Path:
    """The directory holding a batch's scenes."""
    return Path(directory) / SCENES


def check_batch_dir(directory: Path, settings: Mapping[str, Any], *, force: bool) -> None:
    """Refuse, before any work, a directory that is not a batch's, or one whose batch.json was
    written by another indoorgen version or with other generate options (unless `force`)."""
    directory = Path(directory)
    path = directory / BATCH_JSON
    if directory.is_dir() and not path.is_file() and any(directory.iterdir()) and not force:
        raise BatchConfigError(f"{directory} is not empty and holds no {BATCH_JSON}: it is not a "
                               "batch's directory; choose another, or give --force to add to it")
    new = {"indoorgen_version": __version__, **settings}
    if directory.exists() and not directory.is_dir():
        raise BatchConfigError(f"{directory} exists and is not a directory")
    if path.is_file() and not force:
        try:
            old = json.loads(path.read_text())
        except ValueError:
            raise BatchConfigError(f"{path} does not parse; give --force to replace it") from None
        if old.get("indoorgen_version") != __version__:
            raise BatchConfigError(f"{directory} was written by indoorgen "
                                   f"{old.get('indoorgen_version')} and this is {__version__}; "
                                   "choose another directory, or give --force to add to it")
        diff = sorted(k for k in set(old.get("generate", {})) | set(new.get("generate", {}))
                      if old.get("generate", {}).get(k) != new.get("generate", {}).get(k))
        if diff:
            was = ", ".join(f"{k}={old.get('generate', {}).get(k)!r}" for k in diff[:3])
            raise BatchConfigError(f"{directory} was made with other generate options ({was}); "
                                   "give the same options, choose another directory, or give "
                                   "--force to mix them")


def write_batch_json(directory: Path, settings: Mapping[str, Any]) -> None:
    """Write the batch's batch.json: indoorgen's version and the `settings` (generate options)."""
    with atomic_file(Path(directory) / BATCH_JSON) as tmp:
        tmp.write_text(json.dumps({"indoorgen_version": __version__, **settings}, indent=1,
                                  sort_keys=True) + "\n")


def clean_leftovers(directory: Path) -> list[str]:
    """Remove what killed attempts left in a batch's scenes directory: their temporary and
    half-swapped directories (`outputs.clean_stale`, which touches only those of dead processes)
    and their unheld scene locks. Returns the names removed."""
    scenes = scenes_dir(directory)
    if not scenes.is_dir():
        return []
    removed = []
    for p in sorted(scenes.iterdir()):
        if (m := _SCENE_LEFTOVER.fullmatch(p.name)) is not None:
            if m[2] == "tmp" and _zombie(int(m["pid"])):  # killed, not yet reaped: as dead
                shutil.rmtree(p, ignore_errors=True)
            clean_stale(scenes / m["seed"])
            if not p.exists():
                removed.append(p.name)
        elif _SCENE_LOCK.fullmatch(p.name) and _unheld(p):
            p.unlink(missing_ok=True)
            removed.append(p.name)
    return removed


def _zombie(pid: int) -> bool:
    """Whether process `pid` has exited but not been reaped (its parent was killed too and no
    init process has collected it yet): what it wrote is as dead as its writer."""
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().rsplit(")", 1)[1].split()[0] == "Z"
    except (OSError, IndexError):
        return False


def _unheld(lock: Path) -> bool:
    """Whether no process holds the fcntl lock on `lock`."""
    try:
        fd = os.open(lock, os.O_RDWR)
    except OSError:
        return False
    try:
        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except BlockingIOError:
        return False
    finally:
        os.close(fd)
    return True


def _drop_partial_line(path: Path) -> None:
    """Cut `path` back to its last complete line (a crash may have left half of one)."""
    if not path.is_file():
        return
    with open(path, "rb+") as f:
        data = f.read()
        if data and not data.endswith(b"\n"):
            f.truncate(data.rfind(b"\n") + 1)
