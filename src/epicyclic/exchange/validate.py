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
    """
    if kind == "xml":
        import xmlschema

        schema = xmlschema.XMLSchema(str(SCHEMA_FOLDER / "rexs-schema.xsd"))
        return [str(error.reason or error)[:300] for _, error in zip(range(20), schema.iter_errors(text))]
    import jsonschema

    schema = json.loads((SCHEMA_FOLDER / "rexs-schema.json").read_text(encoding="utf-8"))
    validator = jsonschema.Draft7Validator(schema)
    return [f"{'/'.join(map(str, e.absolute_path))}: {e.message[:300]}"
            for _, e in zip(range(20), validator.iter_errors(json.loads(text)))]
