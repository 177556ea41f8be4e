"""``epicyclic convert IN -o OUT``: REXS → TOML, TOML → REXS (XML, JSON or zipped), by OUT's suffix.

See :mod:`epicyclic.exchange.convert`.  Exit codes: 0, 2 bad input (also an
output that is the input, or an unknown suffix), 1 internal error.
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Optional

import typer

from ._common import guarded, say

__all__ = ["convert"]


@guarded
def convert(
    file: Annotated[Path, typer.Argument(help="Train description: TOML, or REXS (.rexs XML, .rexsj JSON, .rexsz).")],
    out: Annotated[Path, typer.Option("--out", "-o", help="The file to write: .toml, .rexs (REXS XML), .rexsj "
                                                          "(REXS JSON) or .rexsz (zipped XML).")],
    rexs_version: Annotated[Optional[str], typer.Option(
        "--rexs-version", help="REXS version to write: 1.7 (default) or 2.0.0 (2.0).")] = None,
) -> None:
    """Convert a train file between TOML and REXS (the gearbox exchange format of KISSsoft, FVA-Workbench...).

    REXS → TOML writes a commented train file naming the REXS component of every element; TOML → REXS
    writes REXS 1.7 (or 2.0.0 with --rexs-version 2.0) that validates against the official schema and reads
    back to the same train.
    """
    from ..exchange.convert import convert as run

    say(run(file, out, rexs_version=rexs_version))
