"""Write an output folder whole or not at all: build it in a temporary folder beside the
target, then rename it into place (an existing folder is replaced only after success)."""
from __future__ import annotations

import os
import shutil
import tempfile
from pathlib import Path

from flywheel.errors import InputError


def write_folder(target: Path, build) -> Path:
    """Call ``build(tmp_folder)`` to fill a fresh folder, then move it to ``target``.

    Raises InputError (one line) if the parent cannot be written or ``target`` is a file.
    """
    target = Path(target)
    parent = target.resolve().parent
    if target.exists() and not target.is_dir():
        raise InputError(f"--out {target}: exists and is not a folder")
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
