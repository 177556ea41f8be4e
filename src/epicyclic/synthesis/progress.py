"""The progress of a search: tasks done of all and the time left, on stderr.

On a terminal one line is rewritten in place (a bar of the done share); elsewhere (a log, CI) a line is
written every 10 %.  The time left is the time per task finished so far times the tasks left (tasks
resumed from a checkpoint do not count for the rate).

>>> import io
>>> out = io.StringIO()
>>> line = ProgressLine(stream=out, interactive=False, clock=iter([0.0, 2.0, 4.0]).__next__)
>>> line(0, 4); line(2, 4)
>>> print(out.getvalue().strip())
synthesize: 0/4 tasks (0 %)
synthesize: 2/4 tasks (50 %), about 2 s left
"""

from __future__ import annotations

import sys
import time
from collections.abc import Callable
from typing import TextIO

from .estimate import duration

__all__ = ["ProgressLine"]

_BAR = 20


class ProgressLine:
    """A ``progress(done, total)`` callback that shows the search's progress on a stream.

    Parameters
    ----------
    label : str, default "synthesize"
        The line's first word.
    stream : file, optional
        Default ``sys.stderr``.
    interactive : bool, optional
        Rewrite one line with a bar (a terminal); default: whether ``stream`` is a terminal.
    clock : callable, optional
        Seconds (default :func:`time.monotonic`).
    """

    def __init__(self, label: str = "synthesize", stream: TextIO | None = None, interactive: bool | None = None,
                 clock: Callable[[], float] = time.monotonic):
        self.label, self.stream, self.clock = label, stream or sys.stderr, clock
        self.interactive = self.stream.isatty() if interactive is None else interactive
        self.start = clock()
        self.first: int | None = None
        self.last = -1

    def __call__(self, done: int, total: int) -> None:
        if self.first is None:
            self.first = done
        percent = 100 * done // max(total, 1)
        ran = done - self.first
        left = f", about {duration((self.clock() - self.start) / ran * (total - done))} left" \
            if 0 < ran and done < total else ""
        text = f"{self.label}: {done}/{total} tasks ({percent} %){left}"
        if self.interactive:
            filled = _BAR * done // max(total, 1)
            bar = "#" * filled + "-" * (_BAR - filled)
            self.stream.write(f"\r[{bar}] {text}   " + ("\n" if done >= total else ""))
            self.stream.flush()
        elif percent // 10 != self.last // 10 or done >= total:
            self.stream.write(text + "\n")
        self.last = percent
