"""Directories as tar bytes: a task's input travels to the worker, its outputs come back this way.

No shared file system is needed between the driver and the Ray workers. Unpacking uses tarfile's
`data` filter (no absolute paths, no `..`, no links leading out, no device files), so neither a
bundle nor a task's outputs can write outside the directory they are unpacked into.
"""

from __future__ import annotations

import io
import os
import stat
import tarfile
from dataclasses import dataclass
from pathlib import Path


class BundleError(Exception):
    """An input directory cannot be bundled (a link leading out of it, an unreadable file)."""


def _inside(root: Path, link: Path) -> bool:
    target = (link.parent / os.readlink(link)).resolve()
    return target == root or root in target.parents


def pack_input(root: Path) -> bytes:
    """The directory `root` as gzip'ed tar bytes: files, directories, and links that stay inside it.

    A link leading out of the directory is refused (BundleError): it would carry a file of the
    driver's machine that is not part of the task's input.
    """
    root = root.resolve()
    buffer = io.BytesIO()
    try:
        with tarfile.open(fileobj=buffer, mode="w:gz", compresslevel=1) as tar:
            for directory, dirs, files in os.walk(root):
                dirs.sort()
                for name in sorted(dirs) + sorted(files):
                    path = Path(directory) / name
                    mode = path.lstat().st_mode
                    if stat.S_ISLNK(mode) and not _inside(root, path):
                        raise BundleError(f"{path} is a link leading out of the input directory {root}")
                    if stat.S_ISLNK(mode) or stat.S_ISREG(mode) or stat.S_ISDIR(mode):
                        tar.add(path, arcname=str(path.relative_to(root)), recursive=False)
    except OSError as error:
        raise BundleError(f"cannot bundle {root}: {error}") from error
    return buffer.getvalue()


@dataclass(frozen=True)
class Packed:
    data: bytes
    files: int
    skipped: tuple[str, ...]


def pack_outputs(root: Path, budget_bytes: int) -> Packed:
    """The regular files under `root` (what a sandboxed command wrote) as tar bytes, at most `budget_bytes`.

    Links, pipes and devices are left out (a link could name a file of the worker's machine); files
    beyond the budget are left out and named in `skipped`.
    """
    buffer = io.BytesIO()
    files = 0
    skipped: list[str] = []
    total = 0
    with tarfile.open(fileobj=buffer, mode="w:gz", compresslevel=1) as tar:
        for directory, dirs, names in os.walk(root):
            dirs.sort()
            for name in sorted(names):
                path = Path(directory) / name
                relative = str(path.relative_to(root))
                info = path.lstat()
                if not stat.S_ISREG(info.st_mode):
                    skipped.append(f"{relative} (not a regular file)")
                    continue
                if total + info.st_size > budget_bytes:
                    skipped.append(f"{relative} ({info.st_size} bytes, over the output budget)")
                    continue
                total += info.st_size
                files += 1
                tar.add(path, arcname=relative, recursive=False)
    return Packed(buffer.getvalue(), files, tuple(skipped))


def unpack(data: bytes, into: Path) -> None:
    """Unpacks tar bytes into the directory `into` (created), refusing anything that would land outside it."""
    into.mkdir(parents=True, exist_ok=True)
    with tarfile.open(fileobj=io.BytesIO(data), mode="r:*") as tar:
        tar.extractall(into, filter="data")
