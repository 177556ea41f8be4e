"""Read an input file safely: a regular file, not too large, UTF-8, TOML within limits.

Checks happen before the work, in this order, each with a message that names
the file (and the line or key where there is one):

1. the path is a regular file — a folder, a FIFO (which would block forever),
   a device such as ``/dev/zero`` (endless) or a socket is refused before it is
   opened for reading;
2. at most :func:`~epicyclic.limits.max_file_bytes` bytes (1 MiB by default);
3. UTF-8 text (a byte-order mark is skipped; NUL bytes mean a binary file);
4. arrays and tables nested at most :data:`~epicyclic.limits.MAX_NESTING`
   deep (found by a scan before :mod:`tomllib` runs, which would otherwise
   recurse until Python's stack ends);
5. valid TOML, every string at most :data:`~epicyclic.limits.MAX_STRING_CHARS`
   characters.

Examples
--------
>>> parse_toml('title = "a"\\nx = [[1, 2], [3]]', "t.toml")
{'title': 'a', 'x': [[1, 2], [3]]}
>>> parse_toml("x = " + "[" * 40 + "]" * 40, "t.toml")
Traceback (most recent call last):
...
epicyclic.io.source.InputFileError: t.toml: line 1, key 'x': arrays and tables are nested more than 16 levels deep; the train format needs at most 5 (see docs/limits.md).
"""

from __future__ import annotations

import os
import re
import stat
import tomllib
from pathlib import Path
from typing import Any

from ..errors import ModelError
from ..limits import MAX_NESTING, MAX_STRING_CHARS, MAX_TOML_VALUES, max_file_bytes

__all__ = ["InputFileError", "check_document", "decode_source", "expect_bytes", "parse_toml", "read_bytes", "read_source", "sniff"]


class InputFileError(ModelError):
    """A train description file that cannot be read or is invalid.

    Attributes
    ----------
    source : str
        The file (or ``"<string>"``).
    where : str
        The table, key or line, e.g. ``"[[planetary]] #1 'P1', key 'teeth'"``.
    """

    def __init__(self, message: str, source: str = "", where: str = ""):
        self.source = source
        self.where = where
        super().__init__(message)


def _size(n: int) -> str:
    return f"{n / 1048576:.3g} MiB ({n:,} bytes)" if n >= 1048576 else f"{n:,} bytes"


def expect_bytes(data: object, where: str) -> bytes:
    """``data`` as bytes (bytes, bytearray, memoryview), else a ModelError saying what to pass.

    >>> expect_bytes(bytearray(b"<model/>"), "is_rexs")
    b'<model/>'
    >>> expect_bytes("<model/>", "is_rexs")
    Traceback (most recent call last):
    ...
    epicyclic.errors.ModelError: is_rexs: data must be the file's bytes, got str; pass text.encode() or open(path, 'rb').read().
    """
    if isinstance(data, (bytes, bytearray, memoryview)):
        return bytes(data)
    from ..errors import ModelError

    raise ModelError(f"{where}: data must be the file's bytes, got {type(data).__name__}; pass text.encode() or "
                     "open(path, 'rb').read().")


def sniff(data: bytes) -> str | None:
    """The REXS container of a file's bytes: ``"zip"``, ``"xml"``, ``"json"``, or None (a TOML train file).

    By content, not by suffix: the zip signature ``PK``, else the first character that is not white
    space (a byte-order mark skipped): ``<`` is XML, ``{`` is JSON.  A TOML file starts with neither.

    Parameters
    ----------
    data : bytes
        The file's content (its first few kilobytes suffice).

    Returns
    -------
    str or None

    Examples
    --------
    >>> sniff(b'<?xml version="1.0"?><model/>'), sniff(b'  {"model": {}}'), sniff(b'title = "x"')
    ('xml', 'json', None)
    """
    data = expect_bytes(data, "sniff")
    if data.startswith((b"PK\x03\x04", b"PK\x05\x06")):  # an empty zip is a zip too
        return "zip"
    head = data[:4096].lstrip(b"\xef\xbb\xbf").lstrip(b" \t\r\n")
    if head.startswith(b"<"):
        return "xml"
    if head.startswith(b"{"):
        return "json"
    return None


def read_source(path: str | Path, max_bytes: int | None = None) -> str:
    """The text of the input file ``path``, checked (steps 1–3 of the module docstring).

    Parameters
    ----------
    path : str or Path
    max_bytes : int, optional
        Size limit in bytes; default :func:`epicyclic.limits.max_file_bytes`
        (1 MiB, or ``$EPICYCLIC_MAX_FILE_BYTES``).

    Raises
    ------
    InputFileError
        Missing, unreadable, not a regular file, too large, not UTF-8 text.
    """
    return decode_source(read_bytes(path, max_bytes), str(path), max_bytes)


def _head_is_rexs(path: str | Path, limit: int) -> bool:
    """Whether a regular file larger than ``limit`` starts like REXS (its first 4 KiB, read without blocking)."""
    try:
        info = os.stat(path)
        if not stat.S_ISREG(info.st_mode) or info.st_size <= limit:
            return False
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
        with os.fdopen(fd, "rb") as handle:
            return stat.S_ISREG(os.fstat(handle.fileno()).st_mode) and sniff(handle.read(4096)) is not None
    except OSError:
        return False  # the full read reports it


def read_bytes(path: str | Path, max_bytes: int | None = None, rexs_bytes: int | None = None) -> bytes:
    """The bytes of the input file ``path``, checked (steps 1–2 of the module docstring).

    Parameters
    ----------
    path : str or Path
        A regular file.
    max_bytes : int, optional
        Size limit in bytes; default :func:`epicyclic.limits.max_file_bytes`.
    rexs_bytes : int, optional
        A larger limit for a REXS file (:func:`sniff` of its first 4 KiB): REXS models are larger than
        train files (:func:`epicyclic.limits.max_rexs_bytes`).

    Raises
    ------
    InputFileError
        Missing, unreadable, not a regular file, too large.
    """
    limit = max_file_bytes() if max_bytes is None else max_bytes
    if rexs_bytes is not None and rexs_bytes > limit and _head_is_rexs(path, limit):
        limit = rexs_bytes
    name = str(path)

    def error(message: str) -> InputFileError:
        return InputFileError(f"{name}: {message}", name)

    try:
        info = os.stat(path)
    except FileNotFoundError:
        raise error("no such file; give the path of a .toml train description.") from None
    except OSError as exc:
        raise error(f"cannot read the file ({exc.strerror or exc}).") from None
    if stat.S_ISDIR(info.st_mode):
        raise error("is a folder, not a file; give the path of a .toml train description.")
    if not stat.S_ISREG(info.st_mode):
        kind = ("a FIFO (named pipe)" if stat.S_ISFIFO(info.st_mode) else
                "a device" if stat.S_ISCHR(info.st_mode) or stat.S_ISBLK(info.st_mode) else
                "a socket" if stat.S_ISSOCK(info.st_mode) else "not a regular file")
        raise error(f"is {kind}, not a regular file; save the train description to a file and give its path.")
    if info.st_size > limit:
        raise error(f"the file is {_size(info.st_size)}; at most {_size(limit)} are read (see docs/limits.md; "
                    f"raise the limit with EPICYCLIC_MAX_FILE_BYTES).")
    try:
        # O_NONBLOCK: should the path have been swapped for a FIFO since stat(), open() must not block.
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
        with os.fdopen(fd, "rb") as handle:
            if not stat.S_ISREG(os.fstat(handle.fileno()).st_mode):
                raise error("is not a regular file; save the train description to a file and give its path.")
            data = handle.read(limit + 1)
    except OSError as exc:
        raise error(f"cannot read the file ({exc.strerror or exc}).") from None
    if len(data) > limit:  # a file that grew, or one whose size stat() does not know
        raise error(f"the file is larger than {_size(limit)}, the most that is read (see docs/limits.md).")
    return data


def decode_source(data: bytes, name: str, max_bytes: int | None = None) -> str:
    """The bytes of an input file (read from disk, or uploaded to ``epicyclic serve``) as text.

    Checks steps 2–3 of the module docstring: the size limit, no NUL bytes,
    UTF-8 (a byte-order mark is skipped).

    Raises
    ------
    InputFileError
        Too large, a binary file, not UTF-8 text.
    """
    limit = max_file_bytes() if max_bytes is None else max_bytes
    if len(data) > limit:
        raise InputFileError(f"{name}: the file is {_size(len(data))}; at most {_size(limit)} are read (see "
                             "docs/limits.md; raise the limit with EPICYCLIC_MAX_FILE_BYTES).", name)
    if b"\x00" in data:
        raise InputFileError(f"{name}: cannot read the file: it contains NUL bytes (at byte {data.index(0)}), so it "
                             "is a binary file, not TOML text.", name)
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        line = data[: exc.start].count(b"\n") + 1
        raise InputFileError(f"{name}: cannot read the file: not UTF-8 text (byte 0x{data[exc.start]:02x} at line "
                             f"{line}); save it as UTF-8.", name) from None


# The nesting scan: one pass over the characters that matter ([ ] { } quotes #),
# each string and comment skipped as a whole, so the scan stays linear in the
# length of the text whatever it holds.  Malformed strings end the scan (tomllib
# then reports them).
_INTEREST = re.compile(r"[\[\]{}\"'#]")
_BASIC_REST = re.compile(r'(?:[^"\\\n]|\\.)*"')
_MULTI_BASIC_REST = re.compile(r'(?:[^\\]|\\.)*?"""', re.DOTALL)
_BREAKS = re.compile(r"[=,\n]")
_KEY = re.compile(r"[ \t]*([^=\n]{1,80}?)[ \t]*=")


def _check_nesting(text: str, source: str) -> None:
    depth, i, key, chain, items = 0, 0, "", 0, 0

    def too_deep(j: int, what: str) -> InputFileError:
        at = f"line {text.count(chr(10), 0, j) + 1}" + (f", key {key!r}" if key and depth else "")
        return InputFileError(f"{source}: {at}: {what} more than {MAX_NESTING} levels deep; the train format "
                           "needs at most 5 (see docs/limits.md).", source, at)

    def too_many(j: int) -> InputFileError:
        at = f"line {text.count(chr(10), 0, j) + 1}"
        return InputFileError(f"{source}: {at}: the file holds more than {MAX_TOML_VALUES:,} keys and values; "
                           "a train description needs a few hundred (see docs/limits.md).", source, at)

    def dotted(segment: str, chain: int, j: int) -> int:
        # parts of one dotted key (a.b."c".d): dots between two of '=', ',', newline
        pieces = _BREAKS.split(segment)
        chain += pieces[0].count(".")
        for piece in pieces[1:]:
            if chain > MAX_NESTING:
                break
            chain = piece.count(".")
        if chain > MAX_NESTING:
            raise too_deep(j, "a dotted key nests tables")
        return chain

    while (match := _INTEREST.search(text, i)) is not None:
        char, j = match.group(), match.start()
        if j > i:
            chain = dotted(text[i:j], chain, j)
            items += text.count("=", i, j) + text.count(",", i, j)
        items += char != "#"
        if items > MAX_TOML_VALUES:
            raise too_many(j)
        if char == "#":
            i = text.find("\n", j)
        elif char == "'" and text.startswith("\'\'\'", j):
            i = text.find("\'\'\'", j + 3) + 3 if text.find("\'\'\'", j + 3) >= 0 else -1
        elif char == "'":
            end, newline = text.find("'", j + 1), text.find("\n", j + 1)
            i = end + 1 if end >= 0 and (newline < 0 or end < newline) else newline
        elif char == '"':
            multi = text.startswith('"""', j)
            rest = (_MULTI_BASIC_REST if multi else _BASIC_REST).match(text, j + (3 if multi else 1))
            i = rest.end() if rest else (-1 if multi else text.find("\n", j))
        else:
            if char in "[{":
                if depth == 0:
                    found = _KEY.match(text, text.rfind("\n", 0, j) + 1, j)
                    key = found.group(1).strip() if found else ""
                depth += 1
                if depth > MAX_NESTING:
                    raise too_deep(j, "arrays and tables are nested")
            else:
                depth = max(depth - 1, 0)
            chain, i = 0, j + 1
        if i < 0:
            return
    dotted(text[i:], chain, len(text))
    if items + text.count("=", i) + text.count(",", i) > MAX_TOML_VALUES:
        raise too_many(len(text))


def _check_values(data: Any, source: str) -> None:
    """Depth at most MAX_NESTING (dotted keys nest too), every string and key at most
    MAX_STRING_CHARS long; iterative, so any depth is safe."""
    stack: list[tuple[Any, str, int]] = [(data, "", 0)]
    while stack:
        value, path, depth = stack.pop()
        if depth > MAX_NESTING:
            shown = path if len(path) <= 80 else path[:79] + "…"
            raise InputFileError(f"{source}: key {shown!r}: tables and arrays are nested more than {MAX_NESTING} "
                              "levels deep (see docs/limits.md).", source, shown)
        if isinstance(value, dict):
            items = list(value.items())
        elif isinstance(value, list):
            items = [(f"[{k}]", v) for k, v in enumerate(value)]
        else:
            items = []
        for key, item in items:
            where = f"{path}{key}" if key.startswith("[") else (f"{path}.{key}" if path else key)
            if len(key) > MAX_STRING_CHARS or isinstance(item, str) and len(item) > MAX_STRING_CHARS:
                long_what = f"a key of {len(key):,} characters" if len(key) > MAX_STRING_CHARS else \
                    f"a string of {len(item):,} characters"
                shown = where if len(where) <= 80 else where[:79] + "…"
                raise InputFileError(f"{source}: key {shown!r}: {long_what}; at most {MAX_STRING_CHARS:,} are "
                                  "accepted (see docs/limits.md).", source, shown)
            if isinstance(item, (dict, list)):
                stack.append((item, where, depth + 1))


def check_document(data: Any, source: str) -> None:
    """Check a parsed document (TOML, or a REXS file mapped onto the same structure) within the limits:
    nesting at most :data:`~epicyclic.limits.MAX_NESTING`, strings and keys at most
    :data:`~epicyclic.limits.MAX_STRING_CHARS` characters.

    Parameters
    ----------
    data : Any
        The document (tables, arrays, values).
    source : str
        The file, the start of every message.

    Raises
    ------
    InputFileError
        Nested too deeply, a string or key too long.
    """
    _check_values(data, source)


def parse_toml(text: str, source: str = "<string>") -> dict[str, Any]:
    """Parse ``text`` as TOML after the nesting check (steps 4–5 of the module docstring).

    Raises
    ------
    InputFileError
        Nested too deeply, not valid TOML, a string too long.
    """
    limit = max_file_bytes()
    if len(text) > limit:
        raise InputFileError(f"{source}: the text is {len(text):,} characters; at most {_size(limit)} are read "
                          "(see docs/limits.md).", source)
    text = text.removeprefix("\ufeff")
    _check_nesting(text, source)
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InputFileError(f"{source}: not valid TOML: {exc}. Check quotes, brackets and '=' signs.",
                          source) from None
    except RecursionError:  # the scan above should have caught it; never a traceback
        raise InputFileError(f"{source}: arrays and tables are nested too deeply (at most {MAX_NESTING} levels; see "
                          "docs/limits.md).", source) from None
    _check_values(data, source)
    return data
