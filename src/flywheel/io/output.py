"""Atomic writers: an output folder or a file is written whole or not at all (built in a
temporary beside the target, then renamed into place; what was there is replaced only after
success)."""
from __future__ import annotations

import os
import shutil
import tempfile
from pathlib import Path

from flywheel.errors import InputError


def write_folder(target: Path, build, marker: str, kind: str = "output") -> Path:
    """Call ``build(tmp_folder)`` to fill a fresh folder, then move it to ``target``.

    An existing ``target`` is replaced whole, so it must be empty or an earlier folder of the
    same kind, recognised by its ``marker`` file (summary.json, answers.json): a user's folder
    given by mistake is never deleted. Raises InputError (one line) if the parent cannot be
    written, a part of the path is a file, or ``target`` is someone else's folder.
    """
    target = Path(target)
    for p in (target, *target.parents):
        if p.exists() and not p.is_dir():
            raise InputError(f"--out {target}: {p} is a file, not a folder")
    if target.is_dir() and any(target.iterdir()) and not (target / marker).is_file():
        raise InputError(f"--out {target}: the folder exists, is not empty and is not an earlier "
                         f"{kind} folder (no {marker}); give a new or empty folder (an {kind} "
                         f"folder is replaced whole)")
    parent = target.resolve().parent
    try:
        parent.mkdir(parents=True, exist_ok=True)
        tmp = Path(tempfile.mkdtemp(prefix=f".{target.name}.tmp-", dir=parent))
    except OSError as exc:
        raise InputError(f"--out {target}: cannot be written ({exc.strerror})") from None
    try:
        build(tmp)
        os.chmod(tmp, 0o755)
        if target.exists():
            old = Path(tempfile.mkdtemp(prefix=f".{target.name}.old-", dir=parent))
            os.rmdir(old)
            os.rename(target, old)
            os.rename(tmp, target)
            shutil.rmtree(old, ignore_errors=True)
        else:
            os.rename(tmp, target)
    except OSError as exc:
        shutil.rmtree(tmp, ignore_errors=True)
        raise InputError(f"--out {target}: cannot be written ({exc.strerror})") from None
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
    return target


def write_file(path: Path, text: str, option: str = "--out", expected: str = "a file name") -> Path:
    """Write ``text`` (UTF-8) to ``path`` whole or not at all: a temporary file beside it,
    renamed into place. Raises InputError naming ``option`` if ``path`` is a folder or cannot
    be written."""
    path = Path(path)
    if path.is_dir():
        raise InputError(f"{option} {path}: is a folder, expected {expected}")
    tmp = None
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", dir=path.parent)
        with os.fdopen(fd, "w", encoding="utf-8", newline="") as f:
            f.write(text)
        os.chmod(tmp, 0o644)
        os.replace(tmp, path)
    except OSError as exc:
        if tmp is not None and os.path.exists(tmp):
            os.unlink(tmp)
        raise InputError(f"{option} {path}: cannot be written ({exc.strerror})") from None
    return path
