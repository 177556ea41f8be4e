"""Resumable searches: the finished tasks of a search, kept in a checkpoint file written atomically.

A long search (``--checkpoint FILE`` / ``synthesize(..., checkpoint=path)``)
records every finished task's result; started again with the same file it
loads them and runs only the tasks still missing, so an interrupted search
(Ctrl-C, a lost cluster, the time limit) loses at most the tasks that were
running.  The file is replaced atomically (written beside it, then renamed:
an interruption while writing leaves the previous checkpoint whole), at most
once a second and at the end.

It holds a *fingerprint* of everything that decides the tasks' results (the
spec's targets, sets, elements, bounds, search and sizing values, the task
split and the package version): a checkpoint of another search is refused
rather than mixed in.  It is a pickle read by a restricted unpickler that
builds only epicyclic's own value objects and plain Python values, never an
arbitrary callable from the file.

References
----------
Python documentation, "pickle — Restricting globals"; POSIX rename(2) (atomic replacement).
"""

from __future__ import annotations

import hashlib
import io
import pickle
import time
from collections.abc import Sequence
from dataclasses import fields
from pathlib import Path
from typing import Any

from .spec import SynthesisError, SynthesisSpec

__all__ = ["Checkpoint", "fingerprint", "log_task", "logged_tasks"]

_FORMAT = "epicyclic synthesis checkpoint"
#: Spec fields that do not change what the tasks return (only what is shown, or when the search stops).
_PRESENTATION = {"top", "title", "source", "time_limit", "weights", "module", "max_architectures"}
_BUILTINS = {"dict", "list", "tuple", "set", "frozenset", "int", "float", "str", "bool", "complex", "bytes",
             "NoneType", "getattr"}


def fingerprint(spec: SynthesisSpec, tasks: Sequence[Any]) -> str:
    """SHA-256 of what decides the tasks' results: spec values, the split into tasks, the version.

    Parameters
    ----------
    spec : SynthesisSpec
    tasks : sequence of Task
        From :func:`~epicyclic.synthesis.search.plan`.
    """
    from .. import __version__

    values = tuple((f.name, getattr(spec, f.name)) for f in fields(spec) if f.name not in _PRESENTATION)
    split = tuple((t.engaged, tuple(m.members + (int(m.free_input),) for m in t.mechanisms)) for t in tasks)
    return hashlib.sha256(repr((__version__, values, split)).encode()).hexdigest()


class _Restricted(pickle.Unpickler):
    def find_class(self, module: str, name: str) -> Any:
        if module == "epicyclic" or module.startswith("epicyclic."):
            return super().find_class(module, name)
        if module == "builtins" and name in _BUILTINS:
            return super().find_class(module, name)
        if module in ("numpy", "numpy.core.multiarray", "numpy._core.multiarray") and name in ("scalar", "dtype"):
            return super().find_class(module, name)
        if module == "copyreg" and name == "_reconstructor":
            return super().find_class(module, name)
        raise pickle.UnpicklingError(f"{module}.{name} is not part of a synthesis checkpoint")


class Checkpoint:
    """The finished tasks of one search, loaded from and saved to ``path``.

    Parameters
    ----------
    path : str or Path
        The checkpoint file (need not exist yet).
    key : str
        The search's :func:`fingerprint`.
    interval : float, default 1.0
        Seconds between writes while tasks finish (:meth:`save` with ``force`` always writes).

    Raises
    ------
    SynthesisError
        The file is not a checkpoint, or one of another search.
    """

    def __init__(self, path: str | Path, key: str, interval: float = 1.0):
        self.path, self.key, self.interval = Path(path), key, interval
        self.done: dict[int, Any] = {}
        self._written = 0.0
        if self.path.exists():
            self.done = self._load()

    def _load(self) -> dict[int, Any]:
        try:
            data = _Restricted(io.BytesIO(self.path.read_bytes())).load()
        except (OSError, pickle.UnpicklingError, EOFError, AttributeError, ImportError, ValueError, TypeError) as exc:
            raise SynthesisError(f"--checkpoint: {self.path} is not a synthesis checkpoint ({exc}); give another "
                                 "path, or remove the file to start the search afresh.") from None
        if not isinstance(data, dict) or data.get("format") != _FORMAT:
            raise SynthesisError(f"--checkpoint: {self.path} is not a synthesis checkpoint; give another path, or "
                                 "remove the file to start the search afresh.")
        if data.get("fingerprint") != self.key:
            raise SynthesisError(f"--checkpoint: {self.path} belongs to another search (other targets, bounds, "
                                 "elements or version); give another path, or remove it to start this search "
                                 "afresh.")
        done = data.get("done", {})
        return {int(k): v for k, v in done.items()}

    def add(self, index: int, result: Any) -> None:
        """Record a finished task and write the file if ``interval`` has passed.

        Parameters
        ----------
        index : int
            The task's position in the plan.
        result : TaskResult
        """
        self.done[index] = result
        self.save()

    def save(self, force: bool = False) -> None:
        """Write the checkpoint atomically (now if ``force``, else at most once per ``interval``).

        Parameters
        ----------
        force : bool, default False
        """
        from ..io.output import write_atomic

        now = time.monotonic()
        if not force and now - self._written < self.interval:
            return
        payload = pickle.dumps({"format": _FORMAT, "fingerprint": self.key, "done": self.done},
                               protocol=pickle.HIGHEST_PROTOCOL)
        write_atomic(self.path, payload)
        self._written = now


def log_task(path: str | Path, index: int, result: Any) -> None:
    """Append one finished task to a task log: a record per task, each written at once, none rewritten.

    Unlike a :class:`Checkpoint` (the whole file rewritten at most once a second), every task is on
    disk as soon as it finishes: a search whose process is stopped (the page's Cancel) keeps every
    task it finished.

    Parameters
    ----------
    path : str or Path
    index : int
        The task's position in the plan.
    result : TaskResult
    """
    record = pickle.dumps((int(index), result), protocol=pickle.HIGHEST_PROTOCOL)
    with open(path, "ab") as file:
        file.write(record)
        file.flush()


def logged_tasks(path: str | Path) -> dict[int, Any]:
    """The tasks of a task log (:func:`log_task`): index → TaskResult; a record cut short is left out.

    Read with the restricted unpickler of the checkpoints (epicyclic's own value objects only).

    Parameters
    ----------
    path : str or Path
    """
    path = Path(path)
    data = path.read_bytes() if path.exists() else b""
    stream, done = io.BytesIO(data), {}
    while stream.tell() < len(data):
        try:
            index, result = _Restricted(stream).load()
        except (pickle.UnpicklingError, EOFError, AttributeError, ImportError, ValueError, TypeError):
            break  # the last record, cut short by a stopped writer
        done[int(index)] = result
    return done
