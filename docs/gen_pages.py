"""Pages generated when the site is built (run by the mkdocs-gen-files plugin, see mkdocs.yml).

* ``reference/cli.md`` — the command-line reference, written by typer from the ``epicyclic`` app
  itself (``python -m typer epicyclic.cli.main utils docs``);
* ``reference/api/*.md`` — one page per sub-package or public module of ``epicyclic``, rendered by
  mkdocstrings from the docstrings, with ``SUMMARY.md`` for the navigation;
* ``validation.md`` — every published case of ``tests/published_cases.toml`` (and the published
  ratios of the transmission library) with source, value, tolerance and what we get, computed now.
"""

from __future__ import annotations

import ast
import html
import subprocess
import sys
from pathlib import Path

import mkdocs_gen_files

ROOT = Path(__file__).resolve().parents[1]
PACKAGE = ROOT / "src" / "epicyclic"
#: Modules that are no public API: the command line has its own reference; ``demo`` is a script.
NOT_API = {"cli", "demo", "__main__"}
#: Public modules inside a sub-package that its ``__init__`` does not re-export, documented on its page
#: (``from epicyclic.solver.batch import solve_batch``).
PUBLIC_SUBMODULES = {"epicyclic.solver": ("epicyclic.solver.batch", "epicyclic.solver.given_losses")}


# ---------------------------------------------------------------------- command line
def cli_reference() -> str:
    """Markdown of every command and option, from the typer app."""
    done = subprocess.run(
        [sys.executable, "-m", "typer", "epicyclic.cli.main", "utils", "docs", "--name", "epicyclic",
         "--title", "Command-line reference"],
        capture_output=True, text=True, cwd=ROOT, check=True, timeout=120,
    )
    intro = ("Generated from the `epicyclic` command itself when this site is built; "
             "`epicyclic COMMAND --help` prints the same. Exit codes: 0 success, 2 bad input (one paragraph "
             "on stderr naming the file and key), 1 internal error.\n\n")
    title, _, rest = done.stdout.partition("\n")
    return f"{title}\n\n{intro}{rest.lstrip()}"


# ---------------------------------------------------------------------- API reference
def _summary(path: Path) -> str:
    """First line of a module's docstring."""
    doc = ast.get_docstring(ast.parse(path.read_text(encoding="utf-8"))) or ""
    return doc.strip().splitlines()[0] if doc.strip() else ""


def api_modules() -> list[tuple[str, Path]]:
    """(dotted name, file) of the package, every sub-package and every public top-level module."""
    found = [("epicyclic", PACKAGE / "__init__.py")]
    for path in sorted(PACKAGE.iterdir()):
        name = path.stem
        if name.startswith("_") or name in NOT_API:
            continue
        if path.is_dir() and (path / "__init__.py").is_file():
            found.append((f"epicyclic.{name}", path / "__init__.py"))
        elif path.suffix == ".py":
            found.append((f"epicyclic.{name}", path))
    return found


def _shadowed(init: Path) -> list[str]:
    """Names that a package imports from a submodule of the same name (``from .solve import solve``).

    The submodule hides the name from the package's member list, so these get a directive of
    their own.
    """
    names = []
    for node in ast.parse(init.read_text(encoding="utf-8")).body:
        if isinstance(node, ast.ImportFrom) and node.level == 1 and node.module:
            names += [f"{node.module}.{a.name}" for a in node.names if a.name == node.module]
    return names


def _top_level_names() -> str:
    """The names ``epicyclic`` exports, each linked to where it is documented."""
    import epicyclic

    items = []
    for name in epicyclic.__all__:
        obj = getattr(epicyclic, name)
        module = getattr(obj, "__module__", "") or ""
        package = ".".join(module.split(".")[:2]) if module.startswith("epicyclic.") else ""
        if not package or isinstance(obj, str):
            items.append(f"`{name}`")
            continue
        shadowed = module == f"{package}.{name}"  # documented under its module's path
        items.append(f"[`{name}`][{module if shadowed else package}.{name}]")
    return "Names at the top level, each documented with its sub-package: " + ", ".join(items) + ".\n"


def api_pages() -> None:
    modules = api_modules()
    nav = ["* [Overview](index.md)"]
    rows = ["| module | what it holds |", "|---|---|"]
    options = "    options:\n      show_root_heading: false\n      show_submodules: false\n"
    for dotted, path in modules:
        page = f"{dotted}.md"
        nav.append(f"* [{dotted}]({page})")
        rows.append(f"| [`{dotted}`]({page}) | {_summary(path)} |")
        with mkdocs_gen_files.open(f"reference/api/{page}", "w") as out:
            if dotted == "epicyclic":
                out.write(f"# `epicyclic`\n\n::: epicyclic\n{options}      members: false\n\n{_top_level_names()}")
                continue
            out.write(f"# `{dotted}`\n\n::: {dotted}\n{options}")
            if path.name == "__init__.py":
                for name in _shadowed(path):
                    out.write(f"\n::: {dotted}.{name}\n")
            for module in PUBLIC_SUBMODULES.get(dotted, ()):
                out.write(f"\n::: {module}\n    options:\n      show_root_heading: true\n"
                          "      show_root_full_path: true\n      show_submodules: false\n")
        mkdocs_gen_files.set_edit_path(f"reference/api/{page}", path.relative_to(ROOT))
    with mkdocs_gen_files.open("reference/api/index.md", "w") as out:
        out.write("# API reference\n\nGenerated from the docstrings (numpydoc) when this site is built. "
                  "The package's folders are its architecture: model → solver → results → "
                  "io / report / plotting / command line. Core units: speed 1/min, torque N·m, power W.\n\n")
        out.write("\n".join(rows) + "\n")
    with mkdocs_gen_files.open("reference/api/SUMMARY.md", "w") as out:
        out.write("\n".join(nav) + "\n")


# ---------------------------------------------------------------------- validation
def _number(value: object, digits: int = 10) -> str:
    if value is None:
        return "—"
    if isinstance(value, (str, int)):
        return str(value)
    return f"{value:.{digits}g}"


def _cell(text: str) -> str:
    return html.escape(text, quote=False).replace("|", "\\|")


def validation_page() -> str:
    sys.path.insert(0, str(ROOT / "tests"))
    from published_cases import groups  # noqa: E402  (tests/published_cases.py)

    sections, total, agree, differ = [], 0, 0, 0
    for group in groups():
        values = group.compute()
        lines = [f"## {group.title}", "", f"**Source:** {group.source}  ", f"**Tolerance:** {group.tolerance_note}",
                 "", "| quantity | published | tolerance | we get | |", "|---|--:|--:|--:|:-:|"]
        notes = []
        for case, value in zip(group.cases, values):
            total += 1
            ok = case.within(value)
            agree += ok
            differ += bool(case.disagrees)
            unit = f" {case.unit}" if case.unit else ""
            where = f"<br><small>{_cell(case.where)}</small>" if case.where else ""
            published = f"`{case.formula}`" if case.formula else _cell(_number(case.published) + unit)
            tol = ("exact" if isinstance(case.published, str) or case.allowed == 0
                   else f"± {case.rel_tolerance:g} rel." if case.rel_tolerance is not None
                   else f"± {case.tolerance:g}")
            mark = "✓" if ok else ("differs¹" if case.disagrees else "✗")
            lines.append(f"| {_cell(case.quantity)}{where} | {published} | {tol} | {_cell(_number(value, 8) + unit)} "
                         f"| {mark} |")
            for text in (case.tolerance_note, case.note, case.disagrees):
                if text:
                    notes.append(f"* {case.quantity}: {text}")
        if notes:
            lines += ["", *notes]
        lines += ["", '??? note "How we compute it"', "", "    ```python",
                  *[f"    {line}" for line in group.setup.splitlines()],
                  *[f"    {case.compute}  # {case.quantity}" for case in group.cases], "    ```", ""]
        sections.append("\n".join(lines))
    head = f"""# Validation: published cases

Every published number that the test suite reproduces, with its source, the value as printed,
the tolerance and what epicyclic computes **now** (this page is computed when the site is built).
The cases live in one data file, `tests/published_cases.toml`; `tests/test_published_cases.py`
checks each within its tolerance, and the published transmission ratios come from
`epicyclic.transmission.library`, where they are kept with their sources. A *formula* in the
published column is the source's formula evaluated with its numbers.

**{total} cases, {agree} within tolerance, {differ} published values that we do not reproduce**
(¹ marked *differs*: a hand calculation in the test suite sides with our value; the reason is given
below the table).

"""
    return head + "\n".join(sections)


# ---------------------------------------------------------------------- main
with mkdocs_gen_files.open("reference/cli.md", "w") as _out:
    _out.write(cli_reference())
api_pages()
with mkdocs_gen_files.open("validation.md", "w") as _out:
    _out.write(validation_page())
