"""The example list of the page and what opening an example or a file of one's own says (issue 30)."""

from __future__ import annotations

import re

from epicyclic.web.examples import bundled_examples


def opened_example(html: str) -> str:
    """The bundled example a workspace says it shows (empty: a file of one's own)."""
    match = re.search(r'<input type="hidden" id="opened-example" value="([^"]*)">', html)
    assert match, "no opened-example in the answer"
    return match.group(1)


def test_the_list_has_the_ten_speed_the_rated_sets_and_the_rexs_models():
    examples = bundled_examples()
    assert "ford_10r80_10speed" in examples  # examples/transmissions/
    assert {"simple_set", "simple_set_duty_cycle"} <= set(examples)  # examples/rating/
    rexs = [e for e in examples.values() if e.rexs]
    assert {e.file_name for e in rexs} == {"FVA_Planetary_stage_-_Minus_gearing_1.1.rexs",
                                            "FVA-Industriegetriebe_2stufig_1-4.rexs"}
    assert len({e.title for e in examples.values()}) == len(examples)  # every entry tells itself apart


def test_a_rexs_example_opens_as_convert_writes_it(client, examples):
    key = "FVA_Planetary_stage_-_Minus_gearing_1.1"
    answer = client.post("/example", data={"example": key})
    assert answer.status_code == 200, answer.text[:400]
    assert opened_example(answer.text) == key
    assert "[[planetary]]" in answer.text


def test_an_own_file_named_like_an_example_is_no_example(client, examples):
    """Issue 30: an uploaded, edited ``zf_8hp70_8speed.toml`` is the user's file: the page must not put
    ``?example=zf_8hp70_8speed`` in its address (a reload would show the bundled 8HP)."""
    text = examples["zf_8hp70_8speed"].text.replace("title = ", "title = \"mine\"\n# ", 1)
    answer = client.post("/upload", files={"file": ("zf_8hp70_8speed.toml", text.encode(), "text/plain")})
    assert answer.status_code == 200, answer.text[:400]
    assert opened_example(answer.text) == ""
    assert opened_example(client.post("/example", data={"example": "zf_8hp70_8speed"}).text) == "zf_8hp70_8speed"


def test_an_unreadable_upload_keeps_the_open_file(client):
    """Issue 30: a malformed .rexs leaves the workspace (editor, form, tabs) as it is: its message goes above
    the results (htmx HX-Retarget), not in place of the workspace."""
    bad = b'<?xml version="1.0"?><model applicationId="x" version="1.4"><components><component'
    answer = client.post("/upload", files={"file": ("broken.rexs", bad, "application/xml")})
    assert answer.status_code == 422
    assert answer.headers["hx-retarget"] == "#results" and answer.headers["hx-reswap"] == "afterbegin"
    assert "broken.rexs" in answer.text and "was not opened" in answer.text
    assert "<textarea" not in answer.text and 'class="columns"' not in answer.text
    nul = client.post("/upload", files={"file": ("nul.toml", b"title = 'a'\x00", "text/plain")})
    assert nul.status_code == 422 and nul.headers["hx-retarget"] == "#results"


def test_a_file_address_keeps_its_operating_point_to_itself(client):
    """Issue 30: ``?file=`` with the file's operating point, opened where the browser does not keep the file:
    the example shown instead must not get the file's shafts (``unknown shaft 'Sonnenwelle [34]'``); the page
    names the file it lacks."""
    page = client.get('/?file=FVA.rexs&gear=1&op=[["Sonnenwelle [34]","drive","1500","torque","1"]]').text
    restore = page.split('id="restore"', 1)[1].split("</div>", 1)[0]
    assert "Sonnenwelle" not in restore and 'name="gear" value=""' in restore
    assert '<b class="name">FVA.rexs</b>' in page
    shared = client.get('/?example=simpson_c4_3speed&gear=2&op=[["in","drive","2500 1/min","torque","100 N*m"]]')
    assert 'value="2500 1/min"' in shared.text  # an example's own address keeps its operating point
