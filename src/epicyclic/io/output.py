"""Write output files so that no file is ever lost.

* :func:`refuse_input` — an output path that is an input file (the same path,
  a symbolic link to it, or a hard link of it) is refused before any work.
* :func:`atomic_path` and :func:`write_atomic` — output is written to a
  temporary file in the target folder, flushed to disk and renamed over the
  target in one step (``os.replace``), so the target holds either the old
  content or the complete new one, never a truncated report.  A full disk or
  a missing permission raises :class:`OutputError` naming the path; the
  temporary file is removed.  The new file gets the permissions a plain
  ``open(path, "w")`` would give (``0o666`` less the umask), or keeps those of
  the file it replaces.

Examples
--------
>>> import tempfile, pathlib
>>> folder = pathlib.Path(tempfile.mkdtemp())
>>> write_atomic(folder / "report.md", "# report\\n").read_text()
'# report\\n'
>>> refuse_input(folder / "report.md", [folder / "report.md"])  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
epicyclic.io.output.OutputError: --out: ... is the input file; writing the output there would destroy it. Give another output path.
"""

from __future__ import annotations

import contextlib
import os
import stat
import tempfile
from collections.abc import Iterable, Iterator
from pathlib import Path

from ..errors import EpicyclicError

__all__ = ["OutputError", "refuse_input", "atomic_path", "write_atomic"]


class OutputError(EpicyclicError, OSError):
    """An output file that must not or cannot be written.

    Attributes
    ----------
    path : str
        The output path.
    """

    def __init__(self, message: str, path: str = ""):
        self.path = path
        super().__init__(message)

    def __str__(self) -> str:
        return str(self.args[0]) if self.args else ""


def _same_file(a: Path, b: Path) -> bool:
    try:
        if os.path.realpath(a) == os.path.realpath(b):
            return True
        return a.exists() and b.exists() and os.path.samefile(a, b)  # hard links: same device and inode
    except OSError:
        return False


def refuse_input(out: str | Path, inputs: Iterable[str | Path | None], option: str = "--out") -> None:
    """Raise :class:`OutputError` if ``out`` is (a link to, or a hard link of) one of ``inputs``.

    Also refuses an ``out`` that is an existing folder, or not a regular file
    (writing a report over a device or a FIFO is never meant).
    """
    out = Path(out)
    for given in inputs:
        if given is not None and _same_file(out, Path(given)):
            raise OutputError(f"{option}: {out} is the input file{'' if out == Path(given) else f' {given}'}; writing "
                              "the output there would destroy it. Give another output path.", str(out))
    if out.is_dir():
        raise OutputError(f"{option}: {out} is a folder; give a file name such as {out / 'report.html'}.", str(out))
    if out.exists() and not out.is_file():
        raise OutputError(f"{option}: {out} exists and is not a regular file (a device, FIFO or socket); give the "
                          "path of a file.", str(out))


def _mode_for(target: Path) -> int:
    try:
        return stat.S_IMODE(os.stat(target).st_mode)  # keep the mode of the file replaced
    except OSError:
        umask = os.umask(0)
        os.umask(umask)
        return 0o666 & ~umask


def _failed(exc: OSError, target: Path) -> OutputError:
    reason = exc.strerror or str(exc)
    return OutputError(f"cannot write {target}: {reason}. Nothing was written there; free space or choose "
                       "another path with --out.", str(target))


@contextlib.contextmanager
def atomic_path(target: str | Path) -> Iterator[Path]:
    """A temporary path beside ``target`` (same suffix) that becomes ``target`` on success.

    For libraries that write a file by name (matplotlib, Pillow): write to the
    yielded path; when the block ends without error the file is flushed and
    renamed over ``target``; on error it is removed and ``target`` is untouched.
    Folders above ``target`` are created.

    Raises
    ------
    OutputError
        The folder cannot be created or written, the disk is full.
    """
    target = Path(target)
    folder = target.parent
    try:
        folder.mkdir(parents=True, exist_ok=True)
        fd, name = tempfile.mkstemp(prefix=f".{target.name[:80]}.", suffix=f".tmp{target.suffix}", dir=folder)
        os.close(fd)
    except OSError as exc:
        raise _failed(exc, target) from None
    temporary = Path(name)
    try:
        yield temporary
        with open(temporary, "rb+") as handle:
            os.fsync(handle.fileno())
        os.chmod(temporary, _mode_for(target))
        os.replace(temporary, target)
    except OSError as exc:
        raise _failed(exc, target) from None
    finally:
        with contextlib.suppress(OSError):
            temporary.unlink()


def write_atomic(target: str | Path, data: str | bytes) -> Path:
    """Write ``data`` (text as UTF-8) to ``target`` atomically; return ``target``.

    Raises
    ------
    OutputError
        The file cannot be written (the message names the path); ``target``
        is left as it was.
    """
    target = Path(target)
    payload = data.encode("utf-8") if isinstance(data, str) else data
    with atomic_path(target) as temporary:
        try:
            with open(temporary, "wb") as handle:
                handle.write(payload)
                handle.flush()
                os.fsync(handle.fileno())
        except OSError as exc:
            raise _failed(exc, target) from None
    return target
