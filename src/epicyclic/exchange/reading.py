"""Read a REXS file into a train document: the one entry point of the train file reader for REXS.

:func:`load_rexs_document` reads the file within the REXS limits
(:mod:`epicyclic.exchange.container`) and maps it
(:mod:`epicyclic.exchange.mapping`); :func:`epicyclic.io.load_train_file`
calls it for every file whose content is REXS, so that every command that
reads a train file reads REXS.

Examples
--------
>>> doc = load_rexs_document("examples/rexs/FVA_Planetary_stage_-_Minus_gearing_1.1.rexs")
>>> doc.data["planetary"][0]["teeth"]
{'sun': 17, 'planet': 22, 'ring': 61}
>>> doc.ignored.split(",")[0]
'ignored: 11 shaft sections'

References
----------
REXS 1.x file formats (FVA GmbH, github.com/fva-net/rexs-api-java and
github.com/BearinxSimulationSuite/REXSapi, Apache-2.0).
"""

from __future__ import annotations

from pathlib import Path

from ..io.source import expect_bytes, read_bytes, sniff
from ..limits import max_rexs_bytes
from .container import read_model
from .mapping import RexsDocument, map_model

__all__ = ["is_rexs", "load_rexs_document", "loads_rexs_document"]


def is_rexs(data: bytes) -> bool:
    """Whether ``data`` (a file's first bytes or all of it) is REXS rather than a TOML train file.

    Parameters
    ----------
    data : bytes
    """
    return sniff(expect_bytes(data, "is_rexs")) is not None


def load_rexs_document(path: str | Path, max_bytes: int | None = None) -> RexsDocument:
    """The train document of the REXS file ``path`` (XML, JSON or zip, by content).

    Parameters
    ----------
    path : str or Path
    max_bytes : int, optional
        Size limit; default :func:`epicyclic.limits.max_rexs_bytes` (16 MiB).

    Returns
    -------
    RexsDocument

    Raises
    ------
    InputFileError
        The file cannot be read, is not REXS, is malformed, past a limit, or lacks what the train needs
        (the message names the file, the component id and name and the attribute).
    """
    data = read_bytes(path, max_rexs_bytes() if max_bytes is None else max_bytes)
    return loads_rexs_document(data, str(path))


def loads_rexs_document(data: bytes, source: str = "<bytes>") -> RexsDocument:
    """The train document of REXS ``data`` (the bytes of a file, e.g. an upload to ``epicyclic serve``).

    Parameters
    ----------
    data : bytes
    source : str, default "<bytes>"
        The file name, the start of every message.

    Returns
    -------
    RexsDocument
    """
    return map_model(read_model(expect_bytes(data, "loads_rexs_document"), source))
