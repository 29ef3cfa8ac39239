"""Rule documentation rendered as HTML and Markdown (issue 26: the HTML report showed ````t * k```` and ``::``)."""

from __future__ import annotations

import re

import pytest

from xodrcheck.rules import load_rules
from xodrcheck.rules.shared.docformat import blocks, html, markdown

DOC = """A lane's ``width`` is below ``t * k`` for :class:`~xodrcheck.config.Tolerances` and `x`, *really*.

It goes on
over two lines < 3 & more.

* ``pRange="arcLength"``: an error,
  said over two lines.
* the other: a warning.

Passes (an arc)::

    <geometry s="0">
      <arc curvature="0.02"/>
    </geometry>

    <second/>

Fails:

::

    <bad/>
"""


def test_blocks_are_paragraphs_lists_and_literal_blocks():
    assert blocks(DOC) == [
        ("p", "A lane's ``width`` is below ``t * k`` for :class:`~xodrcheck.config.Tolerances` and `x`, *really*."),
        ("p", "It goes on over two lines < 3 & more."),
        ("ul", ('``pRange="arcLength"``: an error, said over two lines.', "the other: a warning.")),
        ("p", "Passes (an arc):"),
        ("pre", '<geometry s="0">\n  <arc curvature="0.02"/>\n</geometry>\n\n<second/>'),
        ("p", "Fails:"),
        ("pre", "<bad/>"),
    ]


def test_html_escapes_text_and_marks_up_only_the_subset():
    page = html(DOC)
    assert page.startswith(
        "<p>A lane's <code>width</code> is below <code>t * k</code> for <code>Tolerances</code> and <code>x</code>, "
        "<em>really</em>.</p>\n<p>It goes on over two lines &lt; 3 &amp; more.</p>"
    )
    assert '<li><code>pRange="arcLength"</code>: an error, said over two lines.</li>' in page
    pre = '<pre>&lt;geometry s="0"&gt;\n  &lt;arc curvature="0.02"/&gt;\n&lt;/geometry&gt;\n\n&lt;second/&gt;</pre>'
    assert pre in page
    assert "<p>Passes (an arc):</p>" in page and "<p>Fails:</p>\n<pre>&lt;bad/&gt;</pre>" in page
    assert "``" not in page and "::" not in page


def test_markdown_fences_literal_blocks_and_escapes_text():
    text = markdown(DOC)
    assert text.startswith("A lane's `width` is below `t * k` for `Tolerances` and `x`, *really*.\n\n")
    assert "over two lines \\< 3 & more." in text
    assert '* `pRange="arcLength"`: an error, said over two lines.\n* the other: a warning.' in text
    assert '```xml\n<geometry s="0">\n  <arc curvature="0.02"/>\n</geometry>\n\n<second/>\n```' in text
    assert markdown("a ``x`y`` b") == "a `` x`y `` b\n"


@pytest.mark.parametrize("code", sorted(load_rules()))
def test_every_rule_renders_without_raw_markup(code):
    """Outside literal blocks and code, no rule's help shows ``, ::, or a :role:`...` once rendered."""
    page = html(load_rules()[code].doc)
    prose = re.sub(r"<(pre|code)>.*?</\1>", "", page, flags=re.DOTALL)
    assert "``" not in prose and "::" not in prose and not re.search(r":[a-z]+:`", prose), prose
    assert prose.count("<p>") >= 1
