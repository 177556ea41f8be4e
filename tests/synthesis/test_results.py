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


def test_candidate_files_are_the_ones_written_and_the_table_takes_an_action(result, tmp_path):
    paths = result.write_toml(tmp_path)
    assert [p.read_text(encoding="utf-8") for p in paths] == [result.candidate_toml(k) for k in (1, 2, 3)]
    with pytest.raises(SynthesisError, match="rank must lie in"):
        result.candidate_toml(0)
    table = result.html(lambda rank: f"<button>{rank}</button>", "open")
    assert table.count("<button>") == 3 and "<th>open</th>" in table and result._repr_html_() == result.html()


@pytest.mark.parametrize("title", ['a "quoted" title', "two\nlines [x]", "control \x7f\x1b and \\ ü"])
def test_a_candidate_file_holds_any_title(title):
    """The title is a TOML string (escaped), on one line in the comment: the file always reads back."""
    import tomllib

    from epicyclic.io import loads_train_file

    found = synthesize([2.46, 1.46, 1.0, -2.18], sets=2, elements={"brakes": 2, "clutches": 2, "engaged": 2},
                       constraints={"top": 1, "title": title}, workers=1, announce=False)
    text = found.candidate_toml(1)
    assert tomllib.loads(text)["title"] == f"{title}, candidate 1"
    assert loads_train_file(text).title.endswith("candidate 1")  # it reads (control characters dropped from the title)


def test_candidates_dropped_by_the_sizing_are_said():
    from epicyclic.synthesis import SynthesisSpec
    from epicyclic.synthesis.results import SynthesisResult

    spec = SynthesisSpec.create([2.46, 1.46, 1.0, -2.18], 2, {"brakes": 2, "clutches": 2}, {"input_torque": 1e6})
    stats = {"candidates": 0, "architectures": 10, "mechanisms": 2, "screened": 3, "fitted": 3, "tasks": 1,
             "workers": 1, "seconds": 0.1, "rejected_sizing": 3}
    text = SynthesisResult(spec, (), stats).table()
    assert "3 dropped: a set no ISO 54 module up to 50 mm carries at 1e+06 N·m" in text
