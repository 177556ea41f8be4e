"""Validate REXS text against the official file schemas shipped with the package.

The schemas (``schema/rexs-schema.xsd``, ``schema/rexs-schema.json``, FVA GmbH,
Apache-2.0; see ``schema/NOTICE.md``) check the file layout — components,
attributes, relations, load spectra — not the meaning of attribute ids.  The
validators are :mod:`xmlschema` and :mod:`jsonschema` (the test extra).

References
----------
``rexs-schema.xsd``, ``rexs-schema.json`` (FVA GmbH 2020, github.com/BearinxSimulationSuite/REXSapi ``models/``).
"""

from __future__ import annotations

import json
from pathlib import Path

__all__ = ["SCHEMA_FOLDER", "validate_rexs"]

SCHEMA_FOLDER = Path(__file__).parent / "schema"


def validate_rexs(text: str, kind: str) -> list[str]:
    """The schema errors of REXS ``text`` (``kind`` ``"xml"`` or ``"json"``); ``[]`` when it is valid.

    A REXS 2.x document (``version="2.0.0"``) is checked against the FVA's file schema of the 2.0 API
    (``schema/rexs-file-2.0.xsd``); its JSON against ``rexs-schema.json`` with the version pattern widened
    to major.minor.patch (the only published REXS JSON schema pins ``major.minor``, older than 2.0.0).

    Parameters
    ----------
    text : str
        A REXS XML or JSON document.
    kind : str
        ``"xml"`` or ``"json"``.

    Returns
    -------
    list of str
        One message per violation (at most 20).

    Raises
    ------
    ImportError
        :mod:`xmlschema` or :mod:`jsonschema` is not installed (``pip install epicyclic[test]``).

    References
    ----------
    ``rexs-schema.xsd``, ``rexs-schema.json`` (REXSapi); ``rexs-file.xsd`` (fva-net/rexs-api-java, REXS 2.0.0).
    """
    if kind == "xml":
        import re

        import xmlschema

        head = re.search(r"<model\b[^>]*\bversion\s*=\s*[\"']([^\"']*)", text[:2000])
        name = "rexs-file-2.0.xsd" if head and head.group(1).startswith("2.") else "rexs-schema.xsd"
        schema = xmlschema.XMLSchema(str(SCHEMA_FOLDER / name))
        return [str(error.reason or error)[:300] for _, error in zip(range(20), schema.iter_errors(text))]
    import jsonschema

    document = json.loads(text)
    schema = json.loads((SCHEMA_FOLDER / "rexs-schema.json").read_text(encoding="utf-8"))
    version = document.get("model", {}).get("version") if isinstance(document, dict) else None
    if isinstance(version, str) and version.startswith("2."):
        schema["properties"]["model"]["properties"]["version"]["pattern"] = "^\\d+\\.\\d+\\.\\d+$"
    validator = jsonschema.Draft7Validator(schema)
    return [f"{'/'.join(map(str, e.absolute_path))}: {e.message[:300]}"
            for _, e in zip(range(20), validator.iter_errors(document))]
