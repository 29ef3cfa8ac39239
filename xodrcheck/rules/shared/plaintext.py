"""Rule documentation as plain text for terminals and reports: the docstrings' reStructuredText markup taken out.

``xodrcheck rules`` prints rules this way; ``summary`` is the documentation's first sentence, whole.
"""

from __future__ import annotations

import re

_ROLE = re.compile(r":[a-z]+:`~?([^`<]*?)(?:\s*<[^>]*>)?`")
_LITERAL = re.compile(r"``(.+?)``", re.DOTALL)
_INTERPRETED = re.compile(r"(?<![`\w])`([^`]+)`(?![`\w])")
_LITERAL_BLOCK = re.compile(r"(\S)::$", re.MULTILINE)
_BARE_LITERAL_BLOCK = re.compile(r"^\s*::$\n?", re.MULTILINE)
_SENTENCE_END = re.compile(r"(?<!\be\.g)(?<!\bi\.e)(?<!\bvs)[.!?](?=\s|$)")


def _role(match: re.Match[str]) -> str:
    target = match.group(1).strip()
    if match.group(0).split("`")[1].startswith("~"):
        target = target.rsplit(".", 1)[-1]
    return target


def plain(text: str) -> str:
    """``text`` without reStructuredText markup: ``literal`` and `interpreted` become their text, :role:`~a.B` its
    last name, ``Passes::`` ends in one colon (its indented block stays as it is)."""
    text = _ROLE.sub(_role, text)
    text = _LITERAL.sub(r"\1", text)
    text = _INTERPRETED.sub(r"\1", text)
    text = _BARE_LITERAL_BLOCK.sub("", text)
    return _LITERAL_BLOCK.sub(r"\1:", text)


def summary(doc: str) -> str:
    """The first sentence of ``doc``'s first paragraph, whole and on one line, as plain text."""
    paragraph = plain(doc).strip().split("\n\n", 1)[0]
    one_line = " ".join(paragraph.split())
    end = _SENTENCE_END.search(one_line)
    return one_line if end is None else one_line[: end.end()]
