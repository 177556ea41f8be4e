"""``epicyclic convert IN -o OUT``: REXS → TOML and TOML (or REXS) → REXS.

The output format follows the suffix of OUT: ``.toml`` a commented train file
(:mod:`~epicyclic.exchange.toml_writer`), ``.rexs`` REXS 1.7 XML, ``.rexsj``
REXS 1.7 JSON, ``.rexsz`` the XML zipped.  The input is read as every command
reads a train file (by content: TOML or REXS in any container).  The output
never replaces the input (:func:`~epicyclic.io.output.refuse_input`) and is
written atomically (:func:`~epicyclic.io.output.write_atomic`): a failed
conversion leaves nothing half-written.

References
----------
REXS file formats (FVA GmbH, github.com/BearinxSimulationSuite/REXSapi, Apache-2.0).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import io
import zipfile
from pathlib import Path

from ..errors import ModelError

__all__ = ["OUTPUT_SUFFIXES", "convert", "rexs_text", "toml_text"]

OUTPUT_SUFFIXES = (".toml", ".rexs", ".rexsj", ".rexsz")


def _cases_lines(document) -> list[str]:
    lines = []
    if len(document.load_cases) > 1:
        lines.append(f"Load spectrum: {len(document.load_cases)} load cases; the first is [operating_point] "
                     "(epicyclic.io.load_train_file(path).load_cases holds all):")
        for case in document.load_cases:
            op = case.operating_point
            values = ", ".join(f"{k} {v}" for group in ("speeds", "torques", "powers")
                               for k, v in op.get(group, {}).items())
            share = f", {100 * case.duration_fraction:g} % of the time" if case.duration_fraction is not None else ""
            oil = f", oil {case.lubricant_temperature:g} degC" if case.lubricant_temperature is not None else ""
            lines.append(f"  load case {case.id}: {values}{share}{oil}")
    if document.materials:
        lines.append("Gear materials (REXS material_designation): " + ", ".join(
            f"{gear} {material}" for gear, material in document.materials.items()))
    if document.lubricant:
        lub = document.lubricant
        given = ", ".join(f"{k} = {v:g}" if isinstance(v, float) else f"{k} = {v}" for k, v in lub.items())
        lines.append(f"Lubricant as given (mm^2/s, kg/dm^3, degC): {given}; [lubricant] viscosity is the dynamic "
                     "viscosity at the temperature (Ubbelohde-Walther, ASTM D341).")
    return lines


def _expect_train_file(train_file, where: str) -> None:
    """A ModelError unless ``train_file`` is a read train file (it has a source and maybe a REXS document)."""
    if not (hasattr(train_file, "exchange") and hasattr(train_file, "source")):
        raise ModelError(f"{where}: train_file must be a train file read by epicyclic.io.load_train_file(path), "
                         f"got {type(train_file).__name__}.")


def toml_text(train_file) -> str:
    """The train file as commented TOML text (a REXS file's origins, load cases and ignored parts in comments).

    Parameters
    ----------
    train_file : TrainFile
        Read by :func:`epicyclic.io.load_train_file` (a REXS file's has :attr:`~TrainFile.exchange`).

    Returns
    -------
    str
    """
    from .toml_writer import document_toml

    _expect_train_file(train_file, "toml_text")
    document = train_file.exchange
    if document is None:
        from ..io.source import parse_toml, read_source

        return document_toml(parse_toml(read_source(train_file.source), train_file.source))
    header = [f"Converted by epicyclic convert from {Path(document.source).name} (REXS {document.version}, "
              f"{document.container}, written by {document.application or 'an unknown program'}).",
              "Each element and shaft names the REXS component it came from; lengths in mm, angles in degrees."]
    if document.ignored:
        header.append(document.ignored + " (not used by the train model).")
    header += [f"Note: {note}." for note in document.notes]
    return document_toml(document.data, document.origins, header, _cases_lines(document))


@dataclass(frozen=True)
class DutyLoadCase:
    """A ``[[duty_cycle.case]]`` as a REXS ``load_case``: its operating point, time share and gear."""

    point: Any
    duration_fraction: float
    gear: str | None = None
    lubricant_temperature: float | None = None
    from_duty_cycle: bool = True

    def to_operating_point(self):
        """The case's operating point."""
        return self.point


def duty_load_cases(train_file) -> tuple[DutyLoadCase, ...]:
    """The cases of the file's ``[duty_cycle]`` as REXS load cases (() without one or with one case).

    Parameters
    ----------
    train_file : TrainFile

    Returns
    -------
    tuple of DutyLoadCase
    """
    duty = train_file.duty_cycle
    if duty is None or len(duty) < 2:
        return ()
    return tuple(DutyLoadCase(c.operating_point, float(share), c.gear) for c, share in zip(duty.cases, duty.shares))


def rexs_text(train_file, kind: str = "xml", date: str | None = None, document=None,
              rexs_version: str | None = None) -> str:
    """The train file as REXS text (1.7 unless ``rexs_version`` says 2.0.0): ``kind`` ``"xml"`` or ``"json"``.

    Parameters
    ----------
    train_file : TrainFile
    kind : str, default "xml"
    date : str, optional
        The file's date (ISO 8601 with offset); default now.
    document : mapping, optional
        The parsed TOML the train file was read from (default: read again from its source, or a REXS
        file's mapped document).
    rexs_version : str, optional
        ``"1.7"`` or ``"2.0.0"`` (``"2.0"`` is the same); default
        :data:`~epicyclic.exchange.versions.DEFAULT_WRITE_VERSION`.

    Returns
    -------
    str
    """
    from .. import __version__
    from .versions import DEFAULT_WRITE_VERSION, check_write_version
    from .writing import build_rexs

    _expect_train_file(train_file, "rexs_text")
    if kind not in ("xml", "json"):
        raise ModelError(f"rexs_text: kind must be 'xml' or 'json', got {kind!r:.40}.")
    mapped = train_file.exchange
    if document is not None:
        data, cases = document, ()
    elif mapped is None:
        from ..io.source import parse_toml, read_source

        data = parse_toml(read_source(train_file.source), train_file.source)
        cases = duty_load_cases(train_file)
    else:
        data, cases = mapped.data, mapped.load_cases if len(mapped.load_cases) > 1 else ()
    version = check_write_version(DEFAULT_WRITE_VERSION if rexs_version is None else rexs_version)
    builder = build_rexs(train_file, data, cases, application_version=__version__, date=date)
    return builder.xml(version) if kind == "xml" else builder.json(version)


def convert(source: str | Path, target: str | Path, date: str | None = None, rexs_version: str | None = None) -> str:
    """Convert the train file ``source`` (TOML or REXS) to ``target`` (format by its suffix).

    Parameters
    ----------
    source : str or Path
    target : str or Path
        Ends ``.toml``, ``.rexs``, ``.rexsj`` or ``.rexsz``.
    date : str, optional
        The REXS file's date; default now.
    rexs_version : str, optional
        The REXS version written: ``"1.7"`` or ``"2.0.0"`` (default
        :data:`~epicyclic.exchange.versions.DEFAULT_WRITE_VERSION`); refused for a TOML target.

    Returns
    -------
    str
        One line: what was written.

    Raises
    ------
    ModelError
        An unknown output suffix, or the output is the input.
    EpicyclicError
        The input cannot be read (every message names the file and key or component).
    OutputError
        The output cannot be written.
    """
    from ..io import load_train_file
    from ..io.output import refuse_input, write_atomic

    target = Path(target)
    suffix = target.suffix.lower()
    if suffix not in OUTPUT_SUFFIXES:
        raise ModelError(f"--out: {str(target)[:80]!r} ends in {suffix or 'no suffix'!r}; give a .toml, .rexs (REXS "
                         "XML), .rexsj (REXS JSON) or .rexsz (zipped REXS) file.")
    refuse_input(target, [source])
    from .versions import DEFAULT_WRITE_VERSION, check_write_version

    version = check_write_version(DEFAULT_WRITE_VERSION if rexs_version is None else rexs_version)
    if rexs_version is not None and suffix == ".toml":
        raise ModelError(f"--rexs-version: {str(target)[:80]!r} is a TOML train file; the REXS version applies to "
                         ".rexs, .rexsj and .rexsz outputs.")
    train_file = load_train_file(source)
    if suffix == ".toml":
        data: str | bytes = toml_text(train_file)
        what = "a TOML train file"
    elif suffix == ".rexsz":
        buffer = io.BytesIO()
        with zipfile.ZipFile(buffer, "w", zipfile.ZIP_DEFLATED) as archive:
            archive.writestr("model.rexs", rexs_text(train_file, "xml", date, rexs_version=version))
        data, what = buffer.getvalue(), f"zipped REXS {version} XML"
    else:
        data = rexs_text(train_file, "xml" if suffix == ".rexs" else "json", date, rexs_version=version)
        what = f"REXS {version} " + ("XML" if suffix == ".rexs" else "JSON")
    write_atomic(target, data)
    note = f"; {train_file.exchange.ignored}" if train_file.exchange is not None and train_file.exchange.ignored else ""
    return f"wrote {target} ({what}) from {source}{note}"
