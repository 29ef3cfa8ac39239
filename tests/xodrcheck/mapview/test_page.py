"""The HTML page without a browser: self-contained, escaped, the DOM contract's attributes, the two commands."""

from __future__ import annotations

import json
import re
from dataclasses import dataclass, fields
from html.parser import HTMLParser
from pathlib import Path

import pytest

from tests.xodrcheck.rules.helpers import fixture
from xodrcheck.check import Report, check
from xodrcheck.cli import main
from xodrcheck.findings import Category, Finding, Severity
from xodrcheck.mapview.page import FilePage, json_script, render_page
from xodrcheck.report import render

BROKEN = fixture("road-link-target-missing", "fail.xodr")
CLEAN = fixture("link-not-reciprocal", "pass.xodr")


class Elements(HTMLParser):
    """Every start tag with its attributes, and the text of each script."""

    def __init__(self) -> None:
        super().__init__()
        self.tags: list[tuple[str, dict[str, str | None]]] = []
        self.scripts: list[str] = []
        self._in_script = False

    def handle_starttag(self, tag, attrs):
        self.tags.append((tag, dict(attrs)))
        self._in_script = tag == "script"
        if self._in_script:
            self.scripts.append("")

    def handle_endtag(self, tag):
        self._in_script = False

    def handle_data(self, data):
        if self._in_script:
            self.scripts[-1] += data


def parse(page: str) -> Elements:
    parser = Elements()
    parser.feed(page)
    return parser


def rows(page: Elements) -> list[dict[str, str | None]]:
    return [attrs for tag, attrs in page.tags if "xc-row" in (attrs.get("class") or "").split()]


def odd_finding(**where) -> Finding:
    return Finding(
        "R010", "road-link-target-missing", Category.REFERENCE, Severity.ERROR, 'a </script> "quoted" & <b>', **where
    )


def test_json_in_a_script_cannot_close_it():
    text = json_script({"m": "</script><script>alert(1)</script>", "a": "&"})
    assert "<" not in text and ">" not in text and "&" not in text
    assert json.loads(text) == {"m": "</script><script>alert(1)</script>", "a": "&"}


def test_page_is_self_contained_and_rows_follow_the_contract():
    findings = (odd_finding(road="7", lane=-2, section_s=0.0, s=1.5, x=10.0, y=-3.25, line=12), odd_finding())
    page_text = render_page([FilePage("a<b>.xodr", "1.7", findings, None, None)], "t")
    page = parse(page_text)
    assert not [a for _, a in page.tags if a.get("src") or (a.get("href") or "#").split("#")[0]]
    assert "http://" not in page_text.replace("http-equiv", "") and "https://" not in page_text
    csp = [a["content"] for t, a in page.tags if t == "meta" and a.get("http-equiv") == "Content-Security-Policy"]
    assert csp and "default-src 'none'" in csp[0]
    first, second = rows(page)
    assert (first["data-road"], first["data-lane"], first["data-section-s"], first["data-s"]) == (
        "7",
        "-2",
        "0.0",
        "1.5",
    )
    assert (first["data-x"], first["data-y"], first["data-line"], first["data-code"]) == ("10.0", "-3.25", "12", "R010")
    assert first["data-severity"] == "error" and first["data-category"] == "reference"
    assert all(second[k] == "" for k in ("data-road", "data-lane", "data-x", "data-y", "data-s"))
    assert "<b>" not in page_text.split("<body", 1)[1].split("<script", 1)[0]  # the message is escaped


def test_rule_uid_and_basis_are_data_attributes_and_a_tag(monkeypatch):
    """Issue 26: each row shows what the finding rests on, a UID by its rule name (the whole UID in the tooltip)."""
    uid = "asam.net:xodr:1.7.0:road.lane.link.zero_width_at_start"
    finding = odd_finding(road="1", rule_uid=uid, z=2.5, x=1, y=2)
    plain = odd_finding(road="1")
    page_text = render_page([FilePage("a.xodr", "1.7", (finding, plain), None, None)], "t")
    first, second = rows(parse(page_text))
    assert first["data-rule-uid"] == uid and first["data-basis"] == uid
    assert second["data-rule-uid"] == "" and second["data-basis"] == "plausibility"
    tags = [a for t, a in parse(page_text).tags if "xc-basis" in (a.get("class") or "")]
    assert [(a["class"], a["title"]) for a in tags] == [
        ("xc-basis annex-f", f"Annex F rule {uid}"),
        ("xc-basis plausibility", "the checker's own judgement: the standard does not state it"),
    ]
    assert ">road.lane.link.zero_width_at_start</span>" in page_text and ">plausibility</span>" in page_text
    assert "x 1.00, y 2.00, z 2.50" in page_text


def test_finding_fields_beyond_the_known_ones_become_data_attributes():
    """A field the page does not know by name (as rule_uid was, added to Finding after the page) reaches the row as a
    data-* attribute and in the row's text, without changing the page code."""

    @dataclass(frozen=True, slots=True)
    class LaterFinding(Finding):  # a Finding with a field added after the page was written
        review_note: str | None = None

    plain = odd_finding(road="1")
    finding = LaterFinding(**{f.name: getattr(plain, f.name) for f in fields(Finding)}, review_note="seen on site")
    page_text = render_page([FilePage("a.xodr", "1.7", (finding,), None, None)], "t")
    (row,) = rows(parse(page_text))
    assert row["data-review-note"] == "seen on site"
    assert "review note seen on site" in page_text


def test_rows_list_the_worst_first_and_docs_cover_every_code():
    reports = [check(BROKEN), check(CLEAN)]
    page = parse(render("html", reports))
    found = rows(page)
    assert len(found) == sum(len(r.findings) for r in reports)
    order = {"error": 0, "warning": 1, "info": 2}
    per_file = [found[: len(reports[0].findings)]]
    for group in per_file:
        ranks = [order[r["data-severity"]] for r in group]
        assert ranks == sorted(ranks)
    docs = json.loads(next(s for (t, a), s in zip(_scripts(page), page.scripts) if a.get("id") == "xc-rule-docs"))
    assert set(docs) == {r["data-code"] for r in found}
    for doc in docs.values():  # rendered (issue 26: the dialog showed ``literal`` and ``::``), with the basis
        prose = re.sub(r"<(pre|code)>.*?</\1>", "", doc["html"], flags=re.DOTALL)
        assert prose.startswith("<p>") and "``" not in prose and "::" not in prose
        assert doc["basis"]
    assert "<pre>&lt;" in docs["R010"]["html"] and "<code>" in docs["R010"]["html"]
    assert docs["R010"]["basis"].startswith("asam.net:xodr:")
    sections = [a for t, a in page.tags if t == "section"]
    assert [a["id"] for a in sections] == ["file-0", "file-1"]
    links = [a["href"] for t, a in page.tags if t == "a"]
    assert links == ["#file-0", "#file-1", "#xc-index", "#xc-index"]  # the index, then each file's way back


def _scripts(page: Elements):
    return [(t, a) for t, a in page.tags if t == "script"]


def test_a_report_of_bytes_has_no_map_but_its_findings():
    report = Report(None, "1.7", (odd_finding(road="1"),), ())
    page_text = render("html", [report])
    assert "xc-nomap" in page_text and len(rows(parse(page_text))) == 1


def test_check_format_html_writes_one_page(tmp_path: Path):
    out = tmp_path / "report.html"
    assert main(["check", str(BROKEN), "--format", "html", "-o", str(out)]) == 1
    page = parse(out.read_text(encoding="utf-8"))
    assert len(rows(page)) == len(check(BROKEN).findings)
    data = [s for (t, a), s in zip(_scripts(page), page.scripts) if a.get("class") == "xc-map-data"]
    assert len(data) == 1 and json.loads(data[0])["sections"]


def test_view_writes_a_map_without_findings(tmp_path: Path):
    out = tmp_path / "map.html"
    assert main(["view", str(CLEAN), "-o", str(out)]) == 0
    page = parse(out.read_text(encoding="utf-8"))
    assert not rows(page)
    assert any(a.get("class") == "xc-map-data" for t, a in _scripts(page))


@pytest.mark.parametrize(
    ("content", "code"),
    [
        (None, 2),
        (b"not xml at all", 2),
        (b'<?xml version="1.0"?><OpenDRIVE><header revMajor="1" revMinor="7"/></OpenDRIVE>', 1),
    ],
)
def test_view_exit_codes_and_no_file_without_a_map(tmp_path: Path, capsys, content, code):
    source = tmp_path / "in.xodr"
    if content is not None:
        source.write_bytes(content)
    out = tmp_path / "map.html"
    assert main(["view", str(source), "-o", str(out)]) == code
    err = capsys.readouterr().err
    assert err.count("\n") >= 1 and "Traceback" not in err
    assert not out.exists()
    assert not list(tmp_path.glob(".map.html.*"))


def test_view_to_an_unwritable_place_exits_2(tmp_path: Path, capsys):
    assert main(["view", str(CLEAN), "-o", str(tmp_path / "missing" / "map.html")]) == 2
    assert "cannot" in capsys.readouterr().err and not (tmp_path / "missing").exists()


def test_page_mentions_the_tool_version():
    page_text = render_page([FilePage("a.xodr", "1.7", (), None, None)], "t")
    assert re.search(r'<meta name="generator" content="xodrcheck [^"]+">', page_text)


def verdicts(page: Elements) -> list[tuple[str | None, str]]:
    return [(a.get("data-verdict"), t) for t, a in page.tags if "xc-verdict" in (a.get("class") or "").split()]


def test_the_page_says_pass_or_fail_on_top_and_per_file():
    one = parse(render("html", [check(BROKEN)]))
    assert verdicts(one) == [("FAIL", "span")]  # one file: the page's verdict is the file's
    text = render("html", [check(BROKEN), check(CLEAN)])
    assert verdicts(parse(text)) == [("FAIL", "span"), ("FAIL", "span"), ("PASS", "span")]
    assert "FAIL</span> 1 error of 1 rule in 1 of 2 files; 1 warning</span>" in text
    index = text.split('id="xc-index"', 1)[1].split("</nav>", 1)[0]
    assert index.count('class="xc-chip fail"') == 1 and index.count('class="xc-chip pass"') == 1
    assert verdicts(parse(render_page([FilePage("a.xodr", "1.7", None, None, None)], "t"))) == []  # a map alone


def test_info_markers_are_off_on_the_map_by_default():
    """Issue 26: a CARLA town's 1,534 info markers buried its junctions. The map's box draws them, unticked; the list's
    info box stays ticked."""
    infos = tuple(
        Finding("G901", "redundant-record", Category.GEOMETRY, Severity.INFO, "m", road="1", x=float(k), y=0.0)
        for k in range(3)
    )
    unplaced = Finding("G901", "redundant-record", Category.GEOMETRY, Severity.INFO, "m")
    data = {"bounds": [0, 0, 1, 1]}
    page = parse(render_page([FilePage("a.xodr", "1.7", (*infos, unplaced), data, None)], "t"))
    (box,) = [a for t, a in page.tags if a.get("data-tool") == "info-markers"]
    assert box["type"] == "checkbox" and "checked" not in box
    assert "info markers (3)</label>" in render_page([FilePage("a.xodr", "1.7", (*infos, unplaced), data, None)], "t")
    (listed,) = [a for t, a in page.tags if a.get("data-filter") == "severity" and a.get("value") == "info"]
    assert "checked" in listed
    errors = (odd_finding(x=1.0, y=2.0),)
    page = parse(render_page([FilePage("a.xodr", "1.7", errors, data, None)], "t"))
    assert not [a for t, a in page.tags if a.get("data-tool") == "info-markers"]  # no info on the map: no box
