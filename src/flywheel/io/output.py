"""Atomic writers: an output folder or a file is written whole or not at all, nothing outside
the folder is ever touched, and nothing the program did not write there is ever deleted.

An output folder is built in a temporary folder beside the target (``.NAME.tmp-PID-XXXX``),
then put in place. The folder carries a manifest (``.flywheel-manifest.json``): every file
flywheel wrote there with its SHA-256, and a *seal*.

**Which files are flywheel's.** A file is flywheel's to replace or remove only if all hold:

* the folder's manifest is flywheel's and *sealed*: its ``seal`` is the SHA-256 of a fixed
  label, the kind of folder and the list of files with their hashes (:func:`_seal`). A
  manifest written by hand, edited, or written by an older flywheel (no seal) fails; the
  folder still counts as an output folder (flywheel writes into it), but nothing the manifest
  lists is replaced or removed: those files are the user's (a note says so). The seal holds
  no secret and nothing of the folder's identity (its name, its inode), so the manifest stays
  byte-identical for the same input wherever it is written; it cannot tell a verbatim copy of
  a genuine manifest from the original — but then every file it lets flywheel replace or
  remove holds, byte for byte, what flywheel wrote (the hash below), and no hand-made list,
  edit or stale format passes it;
* the file is listed there with a path inside the folder, and every folder on the way to it is
  a real folder (never a symbolic link: flywheel never descends through a link in an output
  folder);
* it is a regular file (not a link) whose SHA-256 now equals the recorded one (else the user
  edited it: it is kept as ``NAME.edited`` if this run writes that name, left in place if not).

Anything else standing where this run writes — a file of the user's, a link (moved, never
followed) — is kept as ``NAME.user`` (said once on stderr); a real folder standing where a file
goes is refused in one line before anything changes. A non-empty folder without a manifest of
flywheel's is the user's folder: refused in one line (``out_not_ours``). ``--out`` may be a
symbolic link to a folder: the files go into the folder it points to, the link stays a link.

**All or nothing.** A new target is the built folder renamed into place (one atomic step). Into
an existing folder the files are swapped by a journal: every step (move an old file aside into
a hidden backup inside the temporary folder, move a new file in, make or remove a folder) is
planned and checked first, written to ``.flywheel-journal.json`` in the temporary folder, then
done; if a step fails, the done steps are undone in reverse order and the folder is exactly as
before. Ctrl-C and SIGTERM are held off during the swap (the CLI turns them into exceptions
otherwise). A run killed with SIGKILL leaves its temporary folder, named with its pid: the next
run into the same place finds it, undoes the swap its journal describes (the folder as before
the killed run, said in a note), and removes it. The journal is removed once the last step is
done: a temporary folder without a journal holds nothing of the user's.
"""
from __future__ import annotations

import hashlib
import json
import os
import re
import shutil
import stat
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

from flywheel.errors import InputError, Notice

MANIFEST = ".flywheel-manifest.json"
JOURNAL = ".flywheel-journal.json"
BACKUP = ".flywheel-backup"             # inside a temporary folder: the old files during a swap
_PID = ".flywheel-writer-pid"          # temporaries of flywheel before 2026-11 held their pid here
_WRITTEN_BY = "flywheel"
_FORMAT = 2
_SEAL_LABEL = "flywheel output manifest 2"
_MANIFEST_MAX = 64 << 20               # a manifest larger than this is nobody's list of outputs


def cannot_write(option: str, path, exc: OSError) -> Notice:
    """The error of a file or folder the system refuses to write (``exc.strerror``, the
    system's own words; its errno lets a renderer say them in another language)."""
    return Notice.of(
        "run_cannot_write", "{option} {path}: cannot be written ({reason})", option=option,
        path=str(path), reason=exc.strerror, errno=exc.errno)


def _sha256_fd(fd: int) -> str:
    h = hashlib.sha256()
    while chunk := os.read(fd, 1 << 20):
        h.update(chunk)
    return h.hexdigest()


def _sha256(path: Path) -> str:
    """SHA-256 of a regular file, the link itself never followed (OSError if ``path`` is a
    link or not a regular file)."""
    fd = os.open(path, os.O_RDONLY | getattr(os, "O_NOFOLLOW", 0))
    try:
        if not stat.S_ISREG(os.fstat(fd).st_mode):
            raise IsADirectoryError(f"{path}: not a regular file")
        return _sha256_fd(fd)
    finally:
        os.close(fd)


def _files(folder: Path) -> list[str]:
    """Relative POSIX paths of every regular file below ``folder``, sorted (links are not
    followed)."""
    out = []
    for root, dirs, names in os.walk(folder):
        rel = Path(root).relative_to(folder)
        out += [(rel / n).as_posix() for n in names
                if stat.S_ISREG(os.lstat(os.path.join(root, n)).st_mode)]
    return sorted(out)


def _seal(kind: str, files: dict[str, str]) -> str:
    """The manifest's seal: SHA-256 of the label, the kind and the files with their hashes."""
    body = json.dumps(files, sort_keys=True, ensure_ascii=True, separators=(",", ":"))
    return hashlib.sha256(f"{_SEAL_LABEL}\n{kind}\n{body}".encode()).hexdigest()


def _manifest_text(kind: str, files: dict[str, str]) -> str:
    return json.dumps({"written_by": _WRITTEN_BY, "format": _FORMAT, "kind": kind,
                       "files": files, "seal": _seal(kind, files)},
                      indent=1, sort_keys=True) + "\n"


@dataclass(frozen=True)
class _Earlier:
    """What a folder holds of an earlier run: relative path → SHA-256 as written, trusted (a
    sealed manifest) or not (then none of its files is flywheel's to replace or remove)."""

    files: dict[str, str]
    trusted: bool = True


def _read_manifest(folder: Path, kind: str) -> _Earlier | None:
    """The manifest of ``folder`` if it is flywheel's and of this kind (None: it has none, or
    it is a link, not JSON, or another kind's); trusted only if its seal holds."""
    from flywheel.io.jsonfile import read_json

    try:                                    # a link, a folder, too large, too deep: not one
        doc = read_json(folder / MANIFEST, follow_links=False, max_bytes=_MANIFEST_MAX)
    except (OSError, ValueError):
        return None
    if not (isinstance(doc, dict) and doc.get("written_by") == _WRITTEN_BY
            and doc.get("kind") == kind and isinstance(doc.get("files"), dict)):
        return None
    files = doc["files"]
    trusted = (doc.get("format") == _FORMAT and isinstance(doc.get("seal"), str)
               and all(isinstance(k, str) and isinstance(v, str) for k, v in files.items())
               and doc["seal"] == _seal(kind, files)
               and all(_inside(k) for k in files))
    return _Earlier({k: v for k, v in files.items() if isinstance(k, str)
                     and isinstance(v, str) and _inside(k)} if trusted else {}, trusted)


def _inside(rel: str) -> bool:
    """True if ``rel`` is a plain relative path below a folder (no absolute path, no ``..``,
    no ``.``, no empty part: a manifest cannot reach outside its folder)."""
    parts = rel.split("/")
    return bool(rel) and not rel.startswith("/") and "\\" not in rel and "\0" not in rel \
        and all(p not in ("", ".", "..") for p in parts)


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


def _tmp_pid(d: Path, name: str) -> int | None:
    """The pid of the writer of a temporary folder ``.NAME.tmp-PID-XXXX`` (or of an older
    ``.NAME.tmp-XXXX`` holding a pid file); None if it is not flywheel's."""
    m = re.fullmatch(rf"\.{re.escape(name)}\.tmp-(\d+)-[A-Za-z0-9_]+", d.name)
    if m:
        return int(m.group(1))
    try:
        return int((d / _PID).read_text(encoding="ascii").strip())
    except (OSError, ValueError):
        return None


_CHANGED = "a path changed since"
_NOT_A_JOURNAL = "its journal is not one flywheel wrote"


def _restore_failed(target: Path, tmp: Path, exc: OSError | None,
                    why: str = _CHANGED) -> InputError:
    reason = exc.strerror if exc is not None and exc.strerror else why
    return InputError(Notice.of(
        "out_restore_failed", "--out {target}: a run killed while replacing its files left the "
        "earlier files in {tmp}, and they cannot be put back ({reason}); move them back by hand "
        "or give another folder", target=str(target), tmp=str(tmp), reason=reason,
        errno=getattr(exc, "errno", None)))


def remove_stale_temporaries(parent: Path, name: str, notes: list | None = None,
                             shown: Path | None = None) -> list[Path]:
    """Remove the temporary folders ``.NAME.tmp-*`` in ``parent`` whose writer is no longer
    running (a run killed with SIGKILL leaves one); one killed while swapping its files into
    ``parent/NAME`` first has that swap undone (its journal). Returns those removed. A folder
    that is not flywheel's (no pid in its name or pid file) is left alone; one whose swap
    cannot be undone is kept (it holds the user's earlier files) and refused (naming the target
    as ``shown``, by default ``parent/name``)."""
    shown = shown if shown is not None else parent / name
    removed = []
    try:
        candidates = sorted(parent.glob(f".{glob_escape(name)}.tmp-*"))
    except OSError:
        return removed
    for d in candidates:
        try:
            if not stat.S_ISDIR(os.lstat(d).st_mode):
                continue
        except OSError:
            continue
        pid = _tmp_pid(d, name)
        if pid is None or pid == os.getpid() or _pid_alive(pid):
            continue
        journal = d / JOURNAL
        if os.path.lexists(journal):
            try:
                doc = json.loads(journal.read_text(encoding="utf-8"))
                steps = [tuple(s) for s in doc["steps"]]
            except (OSError, ValueError, KeyError, TypeError):
                steps = None
            if steps is None or doc.get("target") != name or not _valid_steps(steps):
                raise _restore_failed(shown, d, None, _NOT_A_JOURNAL)
            bad = _undo(parent / name, d, steps)
            if bad is not None:
                raise _restore_failed(shown, d, bad if isinstance(bad, OSError) else None)
            journal.unlink()
            if notes is not None:
                notes.append(Notice.of(
                    "out_restored", "{target}: put back as it was before a run that was killed "
                    "while replacing its files", target=str(shown)))
        shutil.rmtree(d, ignore_errors=True)
        removed.append(d)
    return removed


def glob_escape(name: str) -> str:
    """``name`` with glob's special characters taken literally."""
    return re.sub(r"([*?\[])", r"[\1]", name)


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


def _real_target(target: Path) -> Path:
    """The folder the files go to: ``target`` itself, or the folder a symbolic link ``target``
    points to (the link stays)."""
    return Path(os.path.realpath(target)) if os.path.islink(target) else \
        Path(os.path.abspath(target))


def write_folder(target: Path, build, marker: str, kind: str = "output",
                 notes: list[str] | None = None) -> Path:
    """Call ``build(tmp_folder)`` to fill a fresh folder, then put its files at ``target``.

    ``marker`` names the main document of the folder (summary.json, answers.json; kept for
    the callers, no longer used to recognise a folder); ``kind`` ("output", "variants",
    "task2", …) is recorded in the manifest, so one kind never replaces another. What a rerun
    removed, kept aside or put back is appended to ``notes`` (one Notice each, for stderr).
    Raises InputError (one line) if the parent cannot be written, a part of the path is a file,
    ``target`` is a non-empty folder flywheel did not write, or a folder of the user's stands
    where a file goes; then nothing has changed.
    """
    del marker
    target = Path(target)
    notes = notes if notes is not None else []
    try:                                    # a name too long for the system: no stat at all
        a_file = next((p for p in (target, *target.parents) if p.exists() and not p.is_dir()),
                      None)
    except OSError as exc:
        raise InputError(cannot_write("--out", target, exc)) from None
    if a_file is not None:
        raise InputError(Notice.of(
            "out_is_a_file", "--out {target}: {file} is a file, not a folder", target=str(target),
            file=str(a_file)))
    real = _real_target(target)
    parent = real.parent
    try:
        parent.mkdir(parents=True, exist_ok=True)
        remove_stale_temporaries(parent, real.name, notes, target)
        exists = real.is_dir()
        nonempty = exists and any(real.iterdir())
    except OSError as exc:
        raise InputError(cannot_write("--out", target, exc)) from None
    earlier: _Earlier | None = None
    if nonempty:
        earlier = _read_manifest(real, kind)
        if earlier is None:
            raise InputError(Notice.of(
                "out_not_ours", "--out {target}: the folder exists, is not empty and is not an "
                "earlier {folder_kind} folder of flywheel (no {manifest}); give a new or empty "
                "folder (in {article} {folder_kind} folder a rerun replaces only the files "
                "flywheel wrote)", target=str(target), folder_kind=kind, manifest=MANIFEST,
                article='an' if kind[0] in 'aeiou' else 'a'))
    elif exists:
        earlier = _Earlier({})              # an empty folder (or a link to one): swapped into
    tmp = None
    try:
        with _signals_held():               # a Ctrl-C right after it is made: still removed
            tmp = Path(tempfile.mkdtemp(prefix=f".{real.name}.tmp-{os.getpid()}-", dir=parent))
        build(tmp)
        new = {rel: _sha256(tmp / rel) for rel in _files(tmp)}
        (tmp / MANIFEST).write_text(_manifest_text(kind, new), encoding="utf-8")
        if earlier is None:
            os.chmod(tmp, 0o755)
            with _signals_held():           # Ctrl-C now: the old folder stays as it was
                os.replace(tmp, real)       # a new name: nothing there to replace
            return target
        plan = _plan(real, tmp, earlier, new, target)
        with _signals_held():
            _swap(real, tmp, plan.steps)
        _say(plan, earlier, target, notes)
    except OSError as exc:
        raise InputError(cannot_write("--out", target, exc)) from None
    finally:                                # a journal left: the earlier files are in it
        if tmp is not None and os.path.isdir(tmp) and not os.path.lexists(tmp / JOURNAL):
            shutil.rmtree(tmp, ignore_errors=True)
    return target


# -- the swap into an existing folder ----------------------------------------------------------

@dataclass
class _Plan:
    """The steps of a swap (``("mv", SRC, DST)``, ``("mkdir", D)``, ``("rmdir", D)``, each
    path ``[place, rel]`` with place "out" or "tmp") and what to say about it."""

    steps: list = field(default_factory=list)
    edited: list = field(default_factory=list)
    users: list = field(default_factory=list)
    removed: list = field(default_factory=list)


def _kind_on_disk(path: Path) -> str:
    try:
        m = os.lstat(path).st_mode
    except FileNotFoundError:
        return "missing"
    if stat.S_ISDIR(m):
        return "dir"
    if stat.S_ISREG(m):
        return "file"
    return "link" if stat.S_ISLNK(m) else "other"


def _plan(out: Path, tmp: Path, earlier: _Earlier, new: dict[str, str], target: Path) -> _Plan:
    """Check every path the swap touches and list its steps; raises InputError (nothing done
    yet) if a folder of the user's stands where a file goes."""
    plan = _Plan()
    overlay: dict[str, str] = {}            # rel → its kind after the steps planned so far
    made: set[str] = set()                  # the folders the plan makes (empty on disk)

    def kind(rel: str) -> str:
        if rel in overlay:
            return overlay[rel]
        parts = rel.split("/")
        for i in range(1, len(parts)):      # below a folder moved away or made: nothing yet
            up = "/".join(parts[:i])
            if overlay.get(up) == "missing" or up in made:
                return "missing"
        return _kind_on_disk(out / rel)

    def reachable(rel: str) -> bool:        # every folder on the way a real folder, no link
        parts = rel.split("/")
        return all(kind("/".join(parts[:i])) == "dir" for i in range(1, len(parts)))

    own: dict[str, str] = {}                # rel in the manifest → "own" | "edited"
    for rel, sha in earlier.files.items():
        if reachable(rel) and kind(rel) == "file":
            try:
                own[rel] = "own" if _sha256(out / rel) == sha else "edited"
            except OSError:
                pass

    def aside(rel: str, suffix: str) -> str:
        cand, n = rel + suffix, 2
        while kind(cand) != "missing" or cand in new:
            cand, n = f"{rel}{suffix}-{n}", n + 1
        plan.steps.append(("mv", ["out", rel], ["out", cand]))
        overlay[rel], overlay[cand] = "missing", "file"
        return cand

    def clear(rel: str) -> None:            # whatever stands at rel (not a real folder) goes
        how = own.get(rel) if rel in earlier.files else None
        if how == "own":
            backup = tmp / BACKUP / rel
            backup.parent.mkdir(parents=True, exist_ok=True)
            plan.steps.append(("mv", ["out", rel], ["tmp", f"{BACKUP}/{rel}"]))
            overlay[rel] = "missing"
        elif how == "edited":
            plan.edited.append(f"{rel} → {aside(rel, '.edited')}")
        else:
            plan.users.append(f"{rel} → {aside(rel, '.user')}")

    for rel in sorted(new):
        parts = rel.split("/")
        for i in range(1, len(parts)):      # the folders on the way: real folders, made if need be
            d = "/".join(parts[:i])
            k = kind(d)
            if k == "dir":
                continue
            if k != "missing":              # a file or a link where a folder goes: kept aside
                clear(d)
            plan.steps.append(("mkdir", ["out", d]))
            overlay[d] = "dir"
            made.add(d)
        k = kind(rel)
        if k == "dir":                      # a real folder where a file goes: the user's
            raise InputError(Notice.of(
                "run_out_folder_in_the_way", "--out {target}: {rel} is a folder, where flywheel "
                "writes a file", target=str(target), rel=rel))
        if k != "missing":
            clear(rel)
        plan.steps.append(("mv", ["tmp", rel], ["out", rel], new[rel]))
        overlay[rel] = "file"
    for rel in sorted(set(earlier.files) - set(new)):
        if own.get(rel) == "own" and kind(rel) == "file":
            clear(rel)
            plan.removed.append(rel)
            parts = rel.split("/")          # a folder flywheel made and emptied: gone too
            for i in range(len(parts) - 1, 0, -1):
                d = "/".join(parts[:i])
                if kind(d) != "dir" or _children(out, d, overlay):
                    break
                plan.steps.append(("rmdir", ["out", d]))
                overlay[d] = "missing"
    if kind(MANIFEST) != "missing":        # the old manifest (a regular file: it was read)
        (tmp / BACKUP).mkdir(exist_ok=True)
        plan.steps.append(("mv", ["out", MANIFEST], ["tmp", f"{BACKUP}/{MANIFEST}"]))
    plan.steps.append(("mv", ["tmp", MANIFEST], ["out", MANIFEST],
                       _sha256(tmp / MANIFEST)))
    return plan


def _children(out: Path, d: str, overlay: dict[str, str]) -> set[str]:
    """The names in folder ``d`` after the planned steps."""
    names = set(os.listdir(out / d))
    for rel, k in overlay.items():
        head, _, name = rel.rpartition("/")
        if head == d:
            (names.discard if k == "missing" else names.add)(name)
    return names


def _path(out: Path, tmp: Path, where) -> Path:
    place, rel = where
    return (out if place == "out" else tmp) / rel


def _reachable_on_disk(out: Path, tmp: Path, where) -> bool:
    """No link and no non-folder on the way from ``out`` (or ``tmp``) to ``where``."""
    place, rel = where
    base = out if place == "out" else tmp
    parts = rel.split("/")
    return all(_kind_on_disk(base.joinpath(*parts[:i])) == "dir" for i in range(1, len(parts)))


def _do(out: Path, tmp: Path, step) -> None:
    """One step of a swap, never through a link and never over something there."""
    op = step[0]
    ends = step[1:3] if op == "mv" else step[1:2]
    if not all(_reachable_on_disk(out, tmp, w) for w in ends):
        raise NotADirectoryError(20, "Not a directory", str(_path(out, tmp, ends[-1])))
    if op == "mv":
        src, dst = _path(out, tmp, step[1]), _path(out, tmp, step[2])
        if os.path.lexists(dst):            # changed since the plan: never replace it
            raise FileExistsError(17, "File exists", str(dst))
        os.replace(src, dst)
    elif op == "mkdir":
        os.mkdir(_path(out, tmp, step[1]))
    elif op == "rmdir":
        os.rmdir(_path(out, tmp, step[1]))


def _undo(out: Path, tmp: Path, steps) -> OSError | bool | None:
    """Undo ``steps`` in reverse, each only if it was done (by what is on disk), never through
    a link: an old file moved into the backup goes back (if its place is taken, the backup is
    kept: a failure), a file moved aside gets its name back, a new file goes back into the
    temporary only if it is still the very file flywheel moved (its SHA-256), a made folder is
    removed if empty. Returns None if all is undone, else the first OSError (or True)."""
    bad: OSError | bool | None = None
    for step in reversed(steps):
        try:
            op = step[0]
            ends = step[1:3] if op == "mv" else step[1:2]
            if not all(_reachable_on_disk(out, tmp, w) for w in ends):
                bad = bad or True
                continue
            if op == "mv":
                src, dst = _path(out, tmp, step[1]), _path(out, tmp, step[2])
                if not os.path.lexists(dst):
                    continue                # not done
                if os.path.lexists(src):    # its place is taken since: a backup stays
                    if step[2][0] == "tmp":
                        bad = bad or True
                    continue
                if len(step) > 3 and _kind_on_disk(dst) == "file" and _sha256(dst) != step[3]:
                    continue                # not the file flywheel put there: left alone
                os.replace(dst, src)
            else:
                d = _path(out, tmp, step[1])
                if op == "mkdir" and _kind_on_disk(d) == "dir" and not os.listdir(d):
                    os.rmdir(d)
                elif op == "rmdir" and not os.path.lexists(d):
                    os.mkdir(d)
        except OSError as exc:
            bad = bad or exc
    return bad


def _valid_steps(steps) -> bool:
    """A journal's steps as :func:`_plan` makes them (every path inside its folder)."""
    def where(w) -> bool:
        return (isinstance(w, (list, tuple)) and len(w) == 2 and w[0] in ("out", "tmp")
                and isinstance(w[1], str) and _inside(w[1]))

    for st in steps:
        if not (isinstance(st, (list, tuple)) and st):
            return False
        if st[0] == "mv":
            if not (len(st) in (3, 4) and where(st[1]) and where(st[2])
                    and (len(st) == 3 or isinstance(st[3], str))):
                return False
        elif st[0] in ("mkdir", "rmdir"):
            if not (len(st) == 2 and where(st[1])):
                return False
        else:
            return False
    return True


def _swap(out: Path, tmp: Path, steps) -> None:
    """Do ``steps`` all or none (journalled in ``tmp``); on a failure the done steps are
    undone and the error raised (if they cannot be undone, the temporary folder is kept with
    its journal, for the next run to undo, and the error names it)."""
    part = tmp / (JOURNAL + ".part")
    part.write_text(json.dumps({"target": out.name, "steps": steps}, ensure_ascii=False),
                    encoding="utf-8")
    os.replace(part, tmp / JOURNAL)         # from here on the next run can undo the swap
    done = 0
    try:
        for step in steps:
            _do(out, tmp, step)
            done += 1
    except BaseException as exc:
        bad = _undo(out, tmp, steps[:done + 1])
        if bad is not None:                 # keep the backup: the next run puts it back
            raise _restore_failed(out, tmp, bad if isinstance(bad, OSError) else
                                  exc if isinstance(exc, OSError) else None) from None
        (tmp / JOURNAL).unlink()
        raise
    (tmp / JOURNAL).unlink()                # the swap is whole: the backup can go


def _say(plan: _Plan, earlier: _Earlier, target: Path, notes: list) -> None:
    if not earlier.trusted:
        notes.append(Notice.of(
            "out_manifest_untrusted", "{target}: its {manifest} is not the one flywheel wrote for "
            "this folder (edited, written by hand or by an older flywheel): the files it lists "
            "are treated as yours, none is replaced or removed", target=str(target),
            manifest=MANIFEST))
    if plan.edited:
        notes.append(Notice.of(
            "out_kept", "{target}: kept the files you edited since the earlier run: {files}",
            target=str(target), files=", ".join(plan.edited)))
    if plan.users:
        files = _summarise(plan.users)
        notes.append(Notice.of(
            "out_user_kept", "{target}: kept your files where this run writes its own: {files}",
            target=str(target), files=files))
    if plan.removed:
        notes.append(Notice.of(
            "out_removed", "{target}: removed {n} file(s) of the earlier run that this run does "
            "not write: {files}", target=str(target), n=len(plan.removed),
            files=_summarise(plan.removed)))


def _summarise(names: list[str], n: int = 4) -> str:
    return ", ".join(names[:n]) + (f" and {len(names) - n} more" if len(names) > n else "")


# -- one file ------------------------------------------------------------------------------------

def write_file(path: Path, text, option: str = "--out", expected: str = "a file name") -> Path:
    """Write ``text`` (UTF-8; a str, or an iterable of str pieces written one after another,
    so a streamed report is never held whole) to ``path`` as :func:`write_file_with` does."""
    pieces = (text,) if isinstance(text, str) else text

    def write(tmp: Path) -> None:
        with open(tmp, "w", encoding="utf-8", newline="") as f:
            for piece in pieces:
                f.write(piece)

    return write_file_with(path, write, option, expected)


def write_file_with(path: Path, writer, option: str = "--out", expected: str = "a file name",
                    failed=None, make_folder: bool = True) -> Path:
    """Let ``writer(tmp)`` write a file whole or not at all: ``tmp`` is a temporary file beside
    ``path`` (``.NAME.tmp-PID-XXXX`` ending in ``path``'s suffix, so a writer that picks its
    format by the suffix, like matplotlib's savefig, picks the same), renamed into place once
    ``writer`` returns; a symbolic link ``path`` stays a link (the file it points to is
    written). If ``writer`` raises, the temporary is removed, the old file is untouched and
    the exception goes on (an OSError as InputError: ``failed(exc)``, the error naming
    ``path``, not the temporary; by default :func:`cannot_write` naming ``option``). Temporaries of killed writers are removed.
    InputError naming ``option`` if ``path`` is a folder. A missing folder of ``path`` is made
    unless ``make_folder`` is false (then it is the OSError of a missing folder)."""
    path = Path(path)
    try:
        is_dir = path.is_dir()
    except OSError as exc:                  # a name too long for the system
        raise InputError(cannot_write(option, path, exc)) from None
    if is_dir:
        raise InputError(Notice.of(
            "option_is_a_folder", "{option} {path}: is a folder, expected {expected}",
            option=option, path=str(path), expected=expected))
    real = Path(os.path.realpath(path)) if os.path.islink(path) else path
    tmp = None
    try:
        if make_folder:
            real.parent.mkdir(parents=True, exist_ok=True)
        _remove_stale_files(real.parent, real.name)
        fd, tmp = tempfile.mkstemp(prefix=f".{real.name}.tmp-{os.getpid()}-",
                                   suffix=_suffix(real), dir=real.parent)
        os.close(fd)
        writer(Path(tmp))
        os.chmod(tmp, 0o644)
        os.replace(tmp, real)
    except OSError as exc:
        if tmp is not None and os.path.lexists(tmp):
            os.unlink(tmp)
        if failed is None:
            raise InputError(cannot_write(option, path, exc)) from None
        if exc.errno is not None:           # the user's path in it, not the temporary's
            exc = type(exc)(exc.errno, exc.strerror, str(path))
        raise InputError(failed(exc)) from None
    except BaseException:
        if tmp is not None and os.path.lexists(tmp):
            os.unlink(tmp)
        raise
    return path


def _suffix(path: Path) -> str:
    """The suffix a temporary of ``path`` ends in (letters and digits only, else none)."""
    return path.suffix if re.fullmatch(r"\.[A-Za-z0-9]{1,16}", path.suffix) else ""


def _remove_stale_files(parent: Path, name: str) -> None:
    """Remove the temporary files ``.NAME.tmp-PID-XXXX`` (or ``...-XXXX.SUFFIX``, NAME's own
    suffix) of writers no longer running."""
    try:
        for p in parent.glob(f".{glob_escape(name)}.tmp-*"):
            m = re.fullmatch(rf"\.{re.escape(name)}\.tmp-(\d+)-[A-Za-z0-9_]+"
                             rf"(?:{re.escape(_suffix(Path(name)))})?", p.name)
            if m and int(m.group(1)) != os.getpid() and not _pid_alive(int(m.group(1))) \
                    and stat.S_ISREG(os.lstat(p).st_mode):
                p.unlink()
    except OSError:
        pass
