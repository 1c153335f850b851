"""Files and folders written whole or not at all.

* :func:`write_bytes_atomic` — one file: written to a temporary file beside it, flushed to
  disk, then renamed over the old one. Readers see the old file or the new one.
* :func:`replace_folder_files` — a set of files that belong together (a plan's files):
  written into a new folder beside the target folder, which is then exchanged with it in
  one step (``renameat2(RENAME_EXCHANGE)`` on Linux; two renames elsewhere). Readers see
  the old set or the new set, never a mix. Files and folders of the user's own in the
  target folder are carried over (hard links, or copies where links are impossible;
  folders re-created), so they are in the folder at every moment.

Temporaries carry the writer's process id; a writer killed outright (SIGKILL, a power cut)
leaves them behind, and the next write into the same place recovers them: the user's own
entries are put back, the rest removed. Any other exception (including the ``SystemExit``
the command line raises on SIGTERM/SIGHUP, and ``KeyboardInterrupt``) removes the
temporaries on its way out.

:func:`fault_point` marks every step that changes the disk: the tests kill the process or
raise an ``OSError`` there (``TLS_PLANNER_FAULT_AT``) to prove the all-old-or-all-new
property at each one.
"""

from __future__ import annotations

import contextlib
import ctypes
import errno
import os
import secrets
import shutil
import signal
from collections.abc import Iterable, Mapping
from pathlib import Path

from planner.errors import InputError

__all__ = [
    "FAULT_ENV",
    "check_inputs_kept",
    "check_output_file",
    "check_output_folder",
    "fault_point",
    "replace_folder_files",
    "write_bytes_atomic",
    "write_text_atomic",
]

#: Test hook: ``N`` or ``N:ACTION`` makes the N-th write point of this process act —
#: ACTION is a signal (``KILL``, the default, ``TERM``, ``INT``) sent to the process, or an
#: errno name (``ENOSPC``, ``EROFS``…) raised as an ``OSError``.
FAULT_ENV = "TLS_PLANNER_FAULT_AT"
_TMP = ".tls-planner-"
_points = 0


def fault_point(what: str) -> None:
    """A step that changes the disk (see :data:`FAULT_ENV`); a no-op unless the hook is set."""
    spec = os.environ.get(FAULT_ENV)
    if not spec:
        return
    global _points
    _points += 1
    n, _, action = spec.partition(":")
    if _points != int(n):
        return
    action = action or "KILL"
    if hasattr(signal, f"SIG{action}"):
        os.kill(os.getpid(), getattr(signal, f"SIG{action}"))
        return
    code = getattr(errno, action)
    raise OSError(code, os.strerror(code), what)


def _fsync_dir(folder: Path) -> None:
    with contextlib.suppress(OSError):
        fd = os.open(folder, os.O_RDONLY)
        try:
            os.fsync(fd)
        finally:
            os.close(fd)


def _alive(pid: int) -> bool:
    if pid == os.getpid():
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


def _pid_of(name: str) -> int | None:
    """The writer's pid in a temporary's name (``….<kind>-<pid>-<random>``)."""
    try:
        return int(name.rsplit("-", 2)[-2])
    except (ValueError, IndexError):
        return None


def check_output_file(path: str | Path) -> Path:
    """Where a single output file may go, checked before any work: a non-empty path, not
    a folder, in a folder that exists."""
    if str(path) == "":
        raise InputError("the output path is empty; name a file")
    p = Path(path)
    _check_no_dangling_link(p)
    if p.is_dir():
        raise InputError(f"{str(p)!r} is a folder; name a file to write")
    _check_parent(p, create=False)
    return p


def check_output_folder(folder: str | Path) -> Path:
    """Where a folder of files (a plan's, the figures') may go, checked before any work (a
    plan can take minutes): a non-empty path, not a file, under folders that are folders
    and can be written in (the missing ones are made when the files are written)."""
    if str(folder) == "":
        raise InputError("the output folder is empty; name a folder (e.g. --out plan)")
    target = Path(folder)
    _check_no_dangling_link(target)
    if target.exists() and not target.is_dir():
        raise InputError(f"{str(target)!r} exists and is not a folder; choose another --out")
    if target.is_dir() and os.path.ismount(target):
        raise InputError(
            f"{str(target)!r} is a mount point; a plan replaces its folder as a whole, which "
            f"a mount point cannot be: give a folder inside it (e.g. --out {target}/plan)"
        )
    if target.is_dir():
        _check_no_mount_point(target)
    try:
        above = target.resolve().parent
    except (OSError, RuntimeError) as exc:  # RuntimeError: a loop of symbolic links
        raise InputError(
            f"{str(target)!r} cannot be followed ({exc}); choose another --out"
        ) from None
    while not above.exists():
        above = above.parent
    if not above.is_dir():
        raise InputError(f"{str(above)!r} is not a folder; choose another --out")
    if not os.access(above, os.W_OK | os.X_OK):
        raise InputError(f"the folder {str(above)!r} cannot be written in; choose another --out")
    return target


def check_inputs_kept(outputs: Iterable[str | Path], inputs: Iterable[str | Path | None]) -> None:
    """Refuse to write over an input: an output path that is one of the files read (the
    user's ``zones.csv`` given to ``--zones`` from inside the plan's folder, which the
    plan's own ``zones.csv`` would replace)."""

    def resolved(path: str | Path) -> Path | None:
        try:
            return Path(path).resolve()
        except (OSError, RuntimeError, ValueError):  # a loop of links, a NUL: not a file read
            return None

    files = {resolved(given): given for given in inputs if given is not None and str(given)}
    files.pop(None, None)
    for out in outputs:
        hit = files.get(resolved(out))
        if hit is not None:
            raise InputError(
                f"the input {str(hit)!r} is where the output {Path(out).name} is written, "
                "and would be lost; move the input out of the way or choose another --out"
            )


def _check_no_dangling_link(p: Path) -> None:
    """A symbolic link on the way to ``p`` that points nowhere is refused: writing through it
    would create the tree it names, somewhere the user did not choose."""
    for q in (p, *p.parents):
        if not q.is_symlink():
            continue
        try:
            q.resolve(strict=True)
        except FileNotFoundError:
            raise InputError(
                f"{str(q)!r} is a symbolic link to {os.readlink(q)!r}, which does not exist; "
                "fix the link or choose another output path"
            ) from None
        except (OSError, RuntimeError) as exc:  # a loop of links
            raise InputError(
                f"{str(q)!r} cannot be followed ({exc}); choose another output path"
            ) from None


def _check_no_mount_point(folder: Path) -> None:
    """A plan's folder is exchanged as a whole, and the user's entries travel with it; a
    filesystem mounted inside cannot travel (it would be left under a temporary name), so
    it is refused before any work."""
    for root, dirs, _ in os.walk(folder):
        for d in dirs:
            if os.path.ismount(os.path.join(root, d)):
                raise InputError(
                    f"{os.path.join(root, d)!r} is a mount point inside the output folder; a "
                    "plan replaces its folder as a whole, which a mounted filesystem cannot "
                    "follow: unmount it or choose another --out"
                )


def _check_parent(p: Path, create: bool) -> None:
    if str(p) in ("", ".") and p.name == "":
        raise InputError("the output path is empty; name a file or folder")
    parent = p.parent
    if parent.is_dir():
        return
    if parent.exists():
        raise InputError(f"{str(parent)!r} is not a folder; choose another output path")
    if not create:
        raise InputError(
            f"the folder {str(parent)!r} does not exist; create it first or choose another path"
        )
    try:
        parent.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise InputError(f"cannot create the folder {str(parent)!r}: {exc.strerror}") from None


# -- one file -----------------------------------------------------------------------------
def write_bytes_atomic(path: str | Path, data: bytes, *, create_parents: bool = True) -> Path:
    """Write ``data`` to ``path`` via a temporary file in the same folder and a rename.

    A failure part-way (an error, a signal, a full disk) leaves any existing file untouched
    and no temporary behind; a kill leaves a temporary the next write removes.
    """
    p = Path(path)
    if str(path) == "":
        raise InputError("the output path is empty; name a file")
    if p.is_dir():
        raise InputError(f"{str(p)!r} is a folder; name a file to write")
    _check_parent(p, create_parents)
    _remove_stale(p.parent, f".{p.name}.")
    tmp = p.parent / f".{p.name}.tmp-{os.getpid()}-{secrets.token_hex(4)}"
    try:
        fault_point(f"create {tmp.name}")
        with open(tmp, "xb") as fh:
            fh.write(data)
            fault_point(f"write {tmp.name}")
            fh.flush()
            os.fsync(fh.fileno())
        os.chmod(tmp, _mode_for(p))
        fault_point(f"rename {tmp.name} to {p.name}")
        os.replace(tmp, p)
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise
    _fsync_dir(p.parent)
    return p


def _remove_stale(folder: Path, prefix: str) -> None:
    """Remove temporary files ``prefix…tmp-<pid>-…`` of writers that are gone."""
    with contextlib.suppress(OSError):
        for entry in folder.iterdir():
            name = entry.name
            if name.startswith(prefix) and ".tmp-" in name:
                pid = _pid_of(name)
                if pid is not None and not _alive(pid):
                    entry.unlink(missing_ok=True)


def _mode_for(p: Path) -> int:
    """Keep an existing file's permissions; a new file gets the usual 0666 less the umask
    (``mkstemp`` would leave it readable by its owner only)."""
    try:
        return p.stat().st_mode & 0o777
    except FileNotFoundError:
        umask = os.umask(0)
        os.umask(umask)
        return 0o666 & ~umask


def write_text_atomic(path: str | Path, text: str, *, create_parents: bool = True) -> Path:
    """UTF-8 text variant of :func:`write_bytes_atomic`."""
    return write_bytes_atomic(path, text.encode("utf-8"), create_parents=create_parents)


# -- a set of files -----------------------------------------------------------------------
def _exchange(a: Path, b: Path) -> bool:
    """Swap two paths in one step (Linux ``renameat2``); False where unsupported."""
    try:
        libc = ctypes.CDLL(None, use_errno=True)
        renameat2 = libc.renameat2
    except (OSError, AttributeError):
        return False
    at_fdcwd, rename_exchange = -100, 2
    rc = renameat2(at_fdcwd, os.fsencode(a), at_fdcwd, os.fsencode(b), rename_exchange)
    if rc == 0:
        return True
    code = ctypes.get_errno()
    if code in (errno.ENOSYS, errno.EINVAL, errno.ENOTSUP):
        return False
    raise OSError(code, os.strerror(code), str(b))


def _replicate(src: Path, dst: Path) -> None:
    """``dst`` made a copy of the user's entry ``src`` sharing its data: hard-linked files
    (copies where links are impossible), re-created folders and symbolic links."""
    if src.is_symlink():
        os.symlink(os.readlink(src), dst)
    elif src.is_dir():
        os.mkdir(dst)
        shutil.copystat(src, dst)
        for child in sorted(src.iterdir()):
            _replicate(child, dst / child.name)
    else:
        try:
            os.link(src, dst)
        except OSError:
            shutil.copy2(src, dst)


def _carry_over(src: Path, dst: Path, owned: set[str]) -> None:
    """Move what is the user's in ``src`` (entries not ``owned``) into ``dst``, folders
    merged entry by entry. An entry already in ``dst`` as the same file (a hard link made
    earlier) is left; a different one (changed meanwhile) is kept beside it under a
    ``.kept-N`` name — nothing of the user's is lost."""
    for entry in sorted(src.iterdir()):
        if entry.name in owned:
            continue
        there = dst / entry.name
        if entry.is_dir() and not entry.is_symlink() and there.is_dir() and not there.is_symlink():
            _carry_over(entry, there, set())
            continue
        if there.exists() or there.is_symlink():
            with contextlib.suppress(OSError):
                if os.path.samefile(entry, there):
                    continue
            n = 1
            while (dst / f"{entry.name}.kept-{n}").exists():
                n += 1
            there = dst / f"{entry.name}.kept-{n}"
        fault_point(f"move {entry.name}")
        os.rename(entry, there)


def _recover(folder: Path, owned: set[str]) -> None:
    """Finish what killed writers left beside ``folder``: the user's entries go back into it,
    the rest is removed."""
    prefix = f"{_TMP}{folder.name}."
    try:
        stale = sorted(
            e
            for e in folder.parent.iterdir()
            if e.name.startswith(prefix) and e.is_dir() and not _alive(_pid_of(e.name) or 0)
        )
    except OSError:
        return
    for entry in stale:
        if not folder.exists():
            # killed between the two renames of the fallback: the entry is a whole plan
            os.rename(entry, folder)
            continue
        _carry_over(entry, folder, owned)
        shutil.rmtree(entry, ignore_errors=True)


def replace_folder_files(
    folder: str | Path, files: Mapping[str, bytes], *, owned: Iterable[str] = ()
) -> list[Path]:
    """Make ``folder`` hold exactly ``files`` — plus the user's own entries — in one step.

    ``owned`` names every file this kind of folder may hold from an earlier run (so an old
    file that the new set lacks is not carried over as if it were the user's). The folder
    and its parents are created if missing.
    """
    target = check_output_folder(folder)
    _check_parent(target.resolve(), create=True)
    target = target.resolve()
    owned_names = set(owned) | set(files)
    _recover(target, owned_names)
    new = target.parent / f"{_TMP}{target.name}.new-{os.getpid()}-{secrets.token_hex(4)}"
    fault_point("create the new folder")
    os.mkdir(new)
    try:
        for name, data in files.items():
            fault_point(f"write {name}")
            with open(new / name, "xb") as fh:
                fh.write(data)
                fh.flush()
                os.fsync(fh.fileno())
        _fsync_dir(new)
        if not target.exists():
            fault_point("rename the new folder into place")
            os.rename(new, target)
            _fsync_dir(target.parent)
            return [target / name for name in files]
        os.chmod(new, target.stat().st_mode & 0o7777)
        for entry in sorted(target.iterdir()):  # the user's entries travel with the folder
            if entry.name not in owned_names:
                fault_point(f"link {entry.name}")
                _replicate(entry, new / entry.name)
        fault_point("exchange the folders")
        if not _exchange(new, target):
            old = target.parent / f"{_TMP}{target.name}.old-{os.getpid()}-{secrets.token_hex(4)}"
            os.rename(target, old)
            fault_point("rename the new folder into place")
            os.rename(new, target)
            new = old
        _fsync_dir(target.parent)
    except BaseException:
        if new.exists() and target.is_dir():
            with contextlib.suppress(OSError):
                _carry_over(new, target, owned_names)
            shutil.rmtree(new, ignore_errors=True)
        raise
    # the new set is in place: tidying up is best effort (what it leaves, the next write
    # into this folder recovers — the user's entries back in, the rest removed); a signal
    # arriving meanwhile still finds it done before the process ends
    try:
        with contextlib.suppress(OSError):
            _carry_over(new, target, owned_names)  # what the user changed meanwhile
            fault_point("remove the old folder")
            shutil.rmtree(new)
    except BaseException:
        with contextlib.suppress(OSError):
            _carry_over(new, target, owned_names)
        shutil.rmtree(new, ignore_errors=True)
        raise
    return [target / name for name in files]
