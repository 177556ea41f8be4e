"""Griffe extension: the reStructuredText bits of numpydoc docstrings, as Markdown for mkdocstrings.

The docstrings follow numpydoc, which lives in reStructuredText; mkdocstrings renders Markdown.
Four constructs differ, and this extension rewrites them before rendering (the source stays
numpydoc, so ``help()`` and Sphinx read it as before):

* roles such as ``:func:`solve``` or ``:class:`~epicyclic.model.Teeth``` become inline code;
* ``.. math::`` (one line or an indented block) becomes a display formula (pymdownx.arithmatex);
* simple tables (``=====  =====`` rules) become pipe tables;
* doctest blocks outside the Examples section become ``pycon`` code blocks.
"""

from __future__ import annotations

import re
from typing import Any

import griffe

_ROLE = re.compile(r":(?:py:)?(?:func|class|mod|data|meth|attr|exc|obj|const|term|ref):`(~?)([^`]+)`")
_RULE = re.compile(r"^(\s*)(=+)(\s+=+)+\s*$")


def _role(match: re.Match[str]) -> str:
    short, target = match.groups()
    target = target.split("<")[-1].rstrip(">").strip() if "<" in target else target
    return f"`{target.rsplit('.', 1)[-1] if short else target}`"


def _columns(rule: str) -> list[tuple[int, int]]:
    return [(m.start(), m.end()) for m in re.finditer(r"=+", rule)]


def _tables(lines: list[str]) -> list[str]:
    out: list[str] = []
    i = 0
    while i < len(lines):
        if not _RULE.match(lines[i]):
            out.append(lines[i])
            i += 1
            continue
        indent = _RULE.match(lines[i]).group(1)
        spans = _columns(lines[i])
        rows, rules, j = [], 1, i + 1
        while j < len(lines) and rules < 3:
            if _RULE.match(lines[j]):
                rules += 1
            elif lines[j].strip():
                cells = []
                for k, (start, _) in enumerate(spans):
                    end = spans[k + 1][0] if k + 1 < len(spans) else None
                    cells.append(lines[j][start:end].strip())
                rows.append(cells)
            j += 1
        if not rows:
            out.append(lines[i])
            i += 1
            continue
        out.append("")
        out.append(indent + "| " + " | ".join(rows[0]) + " |")
        out.append(indent + "|" + "---|" * len(spans))
        out.extend(indent + "| " + " | ".join(c.replace("|", "\\|") for c in row) + " |" for row in rows[1:])
        out.append("")
        i = j
    return out


def _math(lines: list[str]) -> list[str]:
    out: list[str] = []
    i = 0
    while i < len(lines):
        match = re.match(r"^(\s*)\.\. math::\s*(.*)$", lines[i])
        if not match:
            out.append(lines[i])
            i += 1
            continue
        indent, first = match.groups()
        body = [first] if first.strip() else []
        i += 1
        while i < len(lines) and (not lines[i].strip() or len(lines[i]) - len(lines[i].lstrip()) > len(indent)):
            if lines[i].strip():
                body.append(lines[i].strip())
            elif body and i + 1 < len(lines) and lines[i + 1].strip() and \
                    len(lines[i + 1]) - len(lines[i + 1].lstrip()) <= len(indent):
                break
            i += 1
        out += ["", f"{indent}$$", *(f"{indent}{b}" for b in body), f"{indent}$$", ""]
    return out


def _doctests(lines: list[str]) -> list[str]:
    out: list[str] = []
    in_examples = False
    i = 0
    while i < len(lines):
        line = lines[i]
        if i + 1 < len(lines) and re.match(r"^\s*-{3,}\s*$", lines[i + 1]) and line.strip():
            in_examples = line.strip() == "Examples"
        if in_examples or not line.lstrip().startswith(">>>"):
            out.append(line)
            i += 1
            continue
        indent = line[: len(line) - len(line.lstrip())]
        block = []
        while i < len(lines) and lines[i].strip():
            block.append(lines[i])
            i += 1
        out += [f"{indent}```pycon", *block, f"{indent}```"]
    return out


def to_markdown(text: str) -> str:
    """Rewrite the reStructuredText constructs of a numpydoc docstring as Markdown."""
    text = _ROLE.sub(_role, text)
    lines = _doctests(_math(_tables(text.splitlines())))
    return "\n".join(lines)


class RstToMarkdown(griffe.Extension):
    """Rewrite every docstring as its object is loaded."""

    def on_instance(self, *, obj: griffe.Object, **kwargs: Any) -> None:
        if obj.docstring is not None:
            obj.docstring.value = to_markdown(obj.docstring.value)
