"""Output files are never lost (epicyclic.io.output and the commands that write files)."""

from __future__ import annotations

import errno
import os
import stat
from pathlib import Path

import matplotlib
import pytest
from typer.testing import CliRunner

from epicyclic.cli.main import app
from epicyclic.io.output import OutputError, atomic_path, refuse_input, write_atomic

matplotlib.use("Agg")

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "brandenberger_1952.toml"
TRANSMISSION = Path(__file__).resolve().parents[2] / "examples" / "simpson_c4_3speed.toml"
runner = CliRunner()


def no_temporaries(folder: Path) -> bool:
    return not [p for p in folder.iterdir() if ".tmp" in p.name]


def full_disk(monkeypatch):
    def fsync(fd):
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(os, "fsync", fsync)


def test_write_atomic_replaces_whole_files_and_keeps_the_mode(tmp_path):
    target = tmp_path / "r.txt"
    target.write_text("old")
    target.chmod(0o640)
    write_atomic(target, "new")
    assert target.read_text() == "new" and stat.S_IMODE(target.stat().st_mode) == 0o640
    assert no_temporaries(tmp_path)


def test_a_new_file_gets_the_mode_of_a_plain_open(tmp_path):
    umask = os.umask(0o022)
    try:
        written = write_atomic(tmp_path / "deep" / "new.md", "x")
    finally:
        os.umask(umask)
    assert stat.S_IMODE(written.stat().st_mode) == 0o644


def test_a_full_disk_leaves_the_old_file_and_names_the_path(tmp_path, monkeypatch):
    target = tmp_path / "r.txt"
    target.write_text("old report")
    full_disk(monkeypatch)
    with pytest.raises(OutputError, match=rf"cannot write {target}: No space left on device"):
        write_atomic(target, "new report")
    assert target.read_text() == "old report" and no_temporaries(tmp_path)


def test_atomic_path_removes_the_temporary_file_when_the_writer_fails(tmp_path):
    target = tmp_path / "figure.png"
    with pytest.raises(RuntimeError):
        with atomic_path(target) as temporary:
            assert temporary.suffix == ".png" and temporary.parent == tmp_path
            temporary.write_bytes(b"half a pic")
            raise RuntimeError("drawing failed")
    assert not target.exists() and no_temporaries(tmp_path)


def test_refuse_input_sees_links_and_other_spellings(tmp_path):
    source = tmp_path / "t.toml"
    source.write_text("x")
    (tmp_path / "soft.toml").symlink_to(source)
    os.link(source, tmp_path / "hard.toml")
    (tmp_path / "sub").mkdir()
    for out in (source, tmp_path / "soft.toml", tmp_path / "hard.toml", tmp_path / "sub" / ".." / "t.toml"):
        with pytest.raises(OutputError, match="is the input file"):
            refuse_input(out, [source])
    refuse_input(tmp_path / "other.toml", [source])  # a different file is fine


@pytest.mark.parametrize(
    "args",
    [
        ["analyze", "{in}", "-f", "json", "--out", "{in}"],
        ["explain", "{in}", "--out", "{in}"],
        ["analyze", "{in}", "--out", "{link}"],
    ],
)
def test_out_equal_to_the_input_leaves_the_input_intact(tmp_path, args):
    source = tmp_path / "t.toml"
    source.write_bytes(EXAMPLE.read_bytes())
    (tmp_path / "link.toml").symlink_to(source)
    result = runner.invoke(app, [a.format(**{"in": source, "link": tmp_path / "link.toml"}) for a in args])
    assert result.exit_code == 2 and "is the input file" in result.stderr
    assert source.read_bytes() == EXAMPLE.read_bytes()


def test_gears_out_equal_to_the_input_leaves_it_intact(tmp_path):
    source = tmp_path / "c4.toml"
    source.write_bytes(TRANSMISSION.read_bytes())
    result = runner.invoke(app, ["gears", str(source), "-o", str(source)])
    assert result.exit_code == 2 and source.read_bytes() == TRANSMISSION.read_bytes()


@pytest.mark.parametrize(
    "args, name",
    [
        (["analyze", str(EXAMPLE), "-f", "html", "--out", "{out}"], "report.html"),
        (["explain", str(EXAMPLE), "--out", "{out}"], "worked.txt"),
        (["gears", str(TRANSMISSION), "--out", "{out}"], "gears.md"),
        (["modes", "--i0", "-2", "--out", "{out}"], "modes.txt"),
        (["plot", str(EXAMPLE), "--out", "{out}"], "speed.svg"),
        (["animate", str(EXAMPLE), "--out", "{out}"], "anim.svg"),
    ],
)
def test_a_full_disk_exits_2_names_the_path_and_keeps_the_old_file(tmp_path, monkeypatch, args, name):
    target = tmp_path / name
    target.write_text("previous content")
    full_disk(monkeypatch)
    result = runner.invoke(app, [a.format(out=target) for a in args])
    assert result.exit_code == 2, result.output
    assert str(target) in result.stderr and "No space left on device" in result.stderr
    assert len(result.stderr.splitlines()) == 1
    assert target.read_text() == "previous content" and no_temporaries(tmp_path)


def test_plot_and_animate_write_complete_files_atomically(tmp_path):
    for args, out in ((["plot", str(EXAMPLE), "-k", "power"], tmp_path / "p.png"),
                      (["animate", str(EXAMPLE)], tmp_path / "a.html")):
        result = runner.invoke(app, [*args, "--out", str(out)])
        assert result.exit_code == 0, result.output
        assert out.stat().st_size > 1000 and no_temporaries(tmp_path)


def test_an_interrupted_command_exits_130_and_leaves_no_file(tmp_path):
    import signal
    import subprocess
    import sys
    import time

    out = tmp_path / "movie.gif"
    process = subprocess.Popen([sys.executable, "-c", "from epicyclic.cli.main import main; main()", "animate",
                                str(EXAMPLE), "--frames", "240", "--out", str(out)],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                               # as from a terminal: Python installs its Ctrl-C handler only when SIGINT is not
                               # ignored at start, and a test run before this one (a Dask or server test) may
                               # leave SIGINT ignored in this process, which the child would inherit
                               preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    deadline = time.monotonic() + 20
    while not list(tmp_path.iterdir()) and time.monotonic() < deadline:  # the temporary file: drawing has begun
        time.sleep(0.05)
    process.send_signal(signal.SIGINT)
    _, err = process.communicate(timeout=30)
    assert process.returncode == 130 and "Traceback" not in err
    assert not out.exists() and no_temporaries(tmp_path)
