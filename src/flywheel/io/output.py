"""Atomic writers: an output folder or a file is written whole or not at all, and nothing the
program did not write is ever deleted.

An output folder is built in a temporary folder beside the target, then moved into place. The
folder carries a manifest (``.flywheel-manifest.json``: every file flywheel wrote there, with
its SHA-256), so a rerun knows exactly which files are its own:

* a new or empty target: the built folder is renamed into place (one atomic step);
* an earlier output folder (it has a manifest): each new file replaces its old self, files of
  the earlier run that this run does not write are removed (and said so), a file of the earlier
  run that the user has edited since is kept under ``NAME.edited`` (said so), and every file
  that is not in the manifest — the user's own — is left alone;
* anything else non-empty is refused in one line.

A temporary folder is removed when the run fails or is interrupted (Ctrl-C, SIGTERM: the CLI
turns both into exceptions), and one left behind by a killed run (SIGKILL) is found and removed
by the next run into the same place (it holds the pid of its writer, no longer alive).
"""
from __future__ import annotations

import hashlib
import json
import os
import shutil
import tempfile
from dataclasses import dataclass
from pathlib import Path

from flywheel.errors import InputError, Notice

MANIFEST = ".flywheel-manifest.json"
_PID = ".flywheel-writer-pid"          # inside a temporary folder while it is being built
_WRITTEN_BY = "flywheel"


def cannot_write(option: str, path, exc: OSError) -> Notice:
    """The error of a file or folder the system refuses to write (``exc.strerror``, the
    system's own words; its errno lets a renderer say them in another language)."""
    return Notice.of(
        "run_cannot_write", "{option} {path}: cannot be written ({reason})", option=option,
        path=str(path), reason=exc.strerror, errno=exc.errno)


def _sha256(path: Path) -> str:
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for chunk in iter(lambda: f.read(1 << 20), b""):
            h.update(chunk)
    return h.hexdigest()


def _files(folder: Path) -> list[str]:
    """Relative POSIX paths of every file below ``folder``, sorted."""
    return sorted(p.relative_to(folder).as_posix() for p in folder.rglob("*") if p.is_file())


@dataclass(frozen=True)
class _Earlier:
    """What a folder holds of an earlier run: relative path → SHA-256 as written (empty for a
    folder written before manifests existed: then no file is removed, only overwritten)."""

    files: dict[str, str]


def _read_manifest(target: Path, kind: str) -> _Earlier | None:
    p = target / MANIFEST
    if not p.is_file():
        return None
    try:
        doc = json.loads(p.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    if not (isinstance(doc, dict) and doc.get("written_by") == _WRITTEN_BY
            and doc.get("kind") == kind and isinstance(doc.get("files"), dict)):
        return None
    files = {k: v for k, v in doc["files"].items()
             if isinstance(k, str) and isinstance(v, str) and _inside(target, k)}
    return _Earlier(files)


def _inside(folder: Path, rel: str) -> bool:
    """True if ``rel`` names a path inside ``folder`` (a manifest cannot reach outside it)."""
    p = Path(rel)
    return not p.is_absolute() and ".." not in p.parts and bool(p.parts)


def _legacy(target: Path, marker: str, kind: str) -> bool:
    """A folder written before manifests existed: its marker is a document flywheel wrote
    (summary.json with "results" and "units"; answers.json with "variants" and "answers")."""
    keys = {"output": ("results", "units"), "variants": ("variants", "answers")}.get(kind, ())
    try:
        doc = json.loads((target / marker).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return False
    return isinstance(doc, dict) and bool(keys) and all(k in doc for k in keys)


def _pid_alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    except OSError:
        return False
    return True


def remove_stale_temporaries(parent: Path, name: str) -> list[Path]:
    """Remove the temporary folders ``.NAME.tmp-*`` in ``parent`` whose writer is no longer
    running (a run killed with SIGKILL leaves one); returns those removed. A folder without
    flywheel's pid file is not ours and is left alone."""
    removed = []
    try:
        candidates = sorted(parent.glob(f".{name}.tmp-*"))
    except OSError:
        return removed
    for d in candidates:
        pid_file = d / _PID
        if not (d.is_dir() and pid_file.is_file()):
            continue
        try:
            pid = int(pid_file.read_text(encoding="ascii").strip())
        except (OSError, ValueError):
            continue
        if pid != os.getpid() and not _pid_alive(pid):
            shutil.rmtree(d, ignore_errors=True)
            removed.append(d)
    return removed


def _backup_name(path: Path) -> Path:
    cand = path.with_name(path.name + ".edited")
    n = 2
    while cand.exists():
        cand = path.with_name(f"{path.name}.edited-{n}")
        n += 1
    return cand


class _signals_held:
    """Ctrl-C and SIGTERM held off while a built folder is moved into place: one that came
    before is acted on first (the old folder stays, the temporary is removed), one that comes
    during the move is acted on right after it (the new folder is whole)."""

    _SIGNALS = ("SIGINT", "SIGTERM")

    def __enter__(self):
        import signal

        self._held = {getattr(signal, n) for n in self._SIGNALS if hasattr(signal, n)}
        self._old = None
        if hasattr(signal, "pthread_sigmask"):
            self._old = signal.pthread_sigmask(signal.SIG_BLOCK, self._held)
            if signal.sigpending() & self._held:    # it came while building: act on it now
                signal.pthread_sigmask(signal.SIG_SETMASK, self._old)
                self._old = None
                _deliver_pending()
        return self

    def __exit__(self, *exc):
        import signal

        if self._old is not None:
            signal.pthread_sigmask(signal.SIG_SETMASK, self._old)
        return False


def _deliver_pending() -> None:
    """Give Python a bytecode boundary to run a signal handler that became due."""
    for _ in range(3):
        pass


def write_folder(target: Path, build, marker: str, kind: str = "output",
                 notes: list[str] | None = None) -> Path:
    """Call ``build(tmp_folder)`` to fill a fresh folder, then put its files at ``target``.

    ``marker`` names the main document of the folder (summary.json, answers.json), used to
    recognise a folder written before manifests existed; ``kind`` ("output", "variants") is
    recorded in the manifest, so one kind never replaces another. What a rerun removed or kept
    aside is appended to ``notes`` (one line each, for stderr). Raises InputError (one line) if
    the parent cannot be written, a part of the path is a file, or ``target`` is a non-empty
    folder flywheel did not write.
    """
    target = Path(target)
    try:                                    # a name too long for the system: no stat at all
        a_file = next((p for p in (target, *target.parents) if p.exists() and not p.is_dir()),
                      None)
    except OSError as exc:
        raise InputError(cannot_write("--out", target, exc)) from None
    if a_file is not None:
        raise InputError(Notice.of(
            "out_is_a_file", "--out {target}: {file} is a file, not a folder", target=str(target),
            file=str(a_file)))
    earlier: _Earlier | None = None
    if target.is_dir() and any(target.iterdir()):
        earlier = _read_manifest(target, kind)
        if earlier is None and _legacy(target, marker, kind):
            earlier = _Earlier({})
        if earlier is None:
            raise InputError(Notice(
                f"--out {target}: the folder exists, is not empty and is not an earlier {kind} "
                f"folder of flywheel (no {MANIFEST}); give a new or empty folder (in "
                f"{'an' if kind[0] in 'aeiou' else 'a'} {kind} folder a rerun replaces only the "
                f"files flywheel wrote)", "out_not_ours",
                target=str(target), folder_kind=kind, manifest=MANIFEST))
    parent = target.resolve().parent
    try:
        parent.mkdir(parents=True, exist_ok=True)
        remove_stale_temporaries(parent, target.name)
        tmp = Path(tempfile.mkdtemp(prefix=f".{target.name}.tmp-", dir=parent))
    except OSError as exc:
        raise InputError(cannot_write("--out", target, exc)) from None
    try:
        (tmp / _PID).write_text(str(os.getpid()), encoding="ascii")
        build(tmp)
        (tmp / _PID).unlink()
        new = {rel: _sha256(tmp / rel) for rel in _files(tmp)}
        manifest = json.dumps({"written_by": _WRITTEN_BY, "kind": kind,
                               "files": new}, indent=1, sort_keys=True) + "\n"
        with _signals_held():               # Ctrl-C now: the old folder stays as it was
            if earlier is None:
                (tmp / MANIFEST).write_text(manifest, encoding="utf-8")
                os.chmod(tmp, 0o755)
                if target.is_dir():
                    os.rmdir(target)        # empty (checked above)
                os.rename(tmp, target)
            else:
                _merge(tmp, target, earlier, new, manifest, notes)
                shutil.rmtree(tmp, ignore_errors=True)
    except OSError as exc:
        shutil.rmtree(tmp, ignore_errors=True)
        raise InputError(cannot_write("--out", target, exc)) from None
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
    return target


def _merge(tmp: Path, target: Path, earlier: _Earlier, new: dict[str, str], manifest: str,
           notes: list[str] | None) -> None:
    """Move the new files into an earlier output folder: only flywheel's own files change."""
    notes = notes if notes is not None else []
    edited, removed = [], []
    for rel, sha in earlier.files.items():
        p = target / rel
        if p.is_file() and _sha256(p) != sha:
            aside = _backup_name(p)
            os.replace(p, aside)
            edited.append(f"{rel} → {aside.name}")
    for rel in new:
        dst = target / rel
        dst.parent.mkdir(parents=True, exist_ok=True)
        if dst.is_dir():
            raise InputError(Notice.of(
                "run_out_folder_in_the_way", "--out {target}: {rel} is a folder, where flywheel "
                "writes a file", target=str(target), rel=rel))
        os.replace(tmp / rel, dst)
    for rel in sorted(set(earlier.files) - set(new)):
        p = target / rel
        if p.is_file() and _sha256(p) == earlier.files[rel]:
            p.unlink()
            removed.append(rel)
            d = p.parent                    # a folder flywheel made and emptied: gone too
            while d != target and d.is_dir() and not any(d.iterdir()):
                d.rmdir()
                d = d.parent
    write_file(target / MANIFEST, manifest)
    if edited:
        notes.append(Notice.of(
            "out_kept", "{target}: kept the files you edited since the earlier run: {files}",
            target=str(target), files=", ".join(edited)))
    if removed:
        notes.append(Notice.of(
            "out_removed", "{target}: removed {n} file(s) of the earlier run that this run does "
            "not write: {files}", target=str(target), n=len(removed), files=_summarise(removed)))


def _summarise(names: list[str], n: int = 4) -> str:
    return ", ".join(names[:n]) + (f" and {len(names) - n} more" if len(names) > n else "")


def write_file(path: Path, text: str, option: str = "--out", expected: str = "a file name") -> Path:
    """Write ``text`` (UTF-8) to ``path`` whole or not at all: a temporary file beside it,
    renamed into place. Raises InputError naming ``option`` if ``path`` is a folder or cannot
    be written."""
    path = Path(path)
    try:
        is_dir = path.is_dir()
    except OSError as exc:                  # a name too long for the system
        raise InputError(cannot_write(option, path, exc)) from None
    if is_dir:
        raise InputError(Notice.of(
            "option_is_a_folder", "{option} {path}: is a folder, expected {expected}",
            option=option, path=str(path), expected=expected))
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
        raise InputError(cannot_write(option, path, exc)) from None
    except BaseException:
        if tmp is not None and os.path.exists(tmp):
            os.unlink(tmp)
        raise
    return path
