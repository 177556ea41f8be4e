"""The search's progress line (issue 30: `synthesize()` from Python showed no progress for minutes)."""

from __future__ import annotations

import io

from epicyclic.synthesis import SynthesisSpec, synthesize_spec
from epicyclic.synthesis.progress import ProgressLine

SPEC = SynthesisSpec.create([2.46, 1.46, 1.0, -2.18], 2, {"brakes": 2, "clutches": 2, "engaged": 2},
                            {"tolerance": 0.01})


def test_a_log_gets_a_line_every_ten_percent_with_the_time_left():
    out = io.StringIO()
    clock = iter(float(t) for t in range(100)).__next__
    line = ProgressLine(stream=out, interactive=False, clock=clock)
    for done in range(0, 41):
        line(done, 40)
    lines = out.getvalue().splitlines()
    assert lines[0] == "synthesize: 0/40 tasks (0 %)" and lines[-1] == "synthesize: 40/40 tasks (100 %)"
    assert len(lines) == 11  # 0, 10, ..., 100 %
    # one task per clock tick: 4 ticks for 4 tasks, 36 left → about 36 s
    assert lines[1] == "synthesize: 4/40 tasks (10 %), about 36 s left"


def test_a_terminal_gets_one_line_with_a_bar():
    out = io.StringIO()
    line = ProgressLine(stream=out, interactive=True, clock=iter([0.0, 1.0, 2.0, 3.0]).__next__)
    line(0, 2), line(1, 2), line(2, 2)
    text = out.getvalue()
    assert text.count("\n") == 1 and text.endswith("\n") and "\r[##########----------] synthesize: 1/2" in text


def test_tasks_resumed_from_a_checkpoint_do_not_count_for_the_rate():
    out = io.StringIO()
    line = ProgressLine(stream=out, interactive=False, clock=iter([0.0, 10.0]).__next__)
    line(80, 100), line(90, 100)  # 10 tasks in 10 s (not 90): 10 left → 10 s
    assert out.getvalue().splitlines()[-1] == "synthesize: 90/100 tasks (90 %), about 10 s left"


def test_the_python_call_shows_progress_when_asked(capsys):
    result = synthesize_spec(SPEC, workers=1, processes=False, progress=True, announce=False)
    err = capsys.readouterr().err
    total = result.stats["tasks"]
    assert f"synthesize: {total}/{total} tasks (100 %)" in err and len(result) > 0
    synthesize_spec(SPEC, workers=1, processes=False, progress=False, announce=False)
    assert capsys.readouterr().err == ""
