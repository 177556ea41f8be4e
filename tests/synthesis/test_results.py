"""The result object renders itself: table, markdown, HTML, JSON, CSV, train files, figures."""

from __future__ import annotations

import json

import pytest

from epicyclic.synthesis import SynthesisError, synthesize


@pytest.fixture(scope="module")
def result():
    return synthesize([2.46, 1.46, 1.0, -2.18], sets=2, elements={"brakes": 2, "clutches": 2, "engaged": 2},
                      constraints={"tolerance": 0.01, "top": 3}, workers=1, processes=False)


def test_renderings(result):
    assert len(result.top) == 3 and result.best is result[0]
    text = result.table()
    assert "schedule" in text and "candidates from" in text
    assert result.markdown().startswith("| rank |")
    assert result._repr_html_().startswith("<table>")
    data = json.loads(result.to_json())
    assert len(data["candidates"]) == 3 and data["candidates"][0]["rank"] == 1
    assert data["stats"]["candidates"] == len(result)
    assert result.to_csv().count("\n") == 4
    assert repr(result).startswith("<SynthesisResult")


def test_lever_plot_and_errors(result):
    import matplotlib.pyplot as plt

    fig = result.plot(kind="lever")
    assert len(fig.axes) >= 2 and "lever diagram" in fig._suptitle.get_text()
    plt.close(fig)
    fig = result.plot()  # the speed chart across gears
    assert fig.axes
    plt.close(fig)
    with pytest.raises(SynthesisError, match="rank must lie"):
        result.plot(rank=99)
    with pytest.raises(SynthesisError, match="no gear 'X'"):
        result.plot(gear="X")
    with pytest.raises(SynthesisError, match="kind must be"):
        result.plot(kind="pie")


def test_candidates_dropped_by_the_sizing_are_said():
    from epicyclic.synthesis import SynthesisSpec
    from epicyclic.synthesis.results import SynthesisResult

    spec = SynthesisSpec.create([2.46, 1.46, 1.0, -2.18], 2, {"brakes": 2, "clutches": 2}, {"input_torque": 1e6})
    stats = {"candidates": 0, "architectures": 10, "mechanisms": 2, "screened": 3, "fitted": 3, "tasks": 1,
             "workers": 1, "seconds": 0.1, "rejected_sizing": 3}
    text = SynthesisResult(spec, (), stats).table()
    assert "3 dropped: a set no ISO 54 module up to 50 mm carries at 1e+06 N·m" in text
