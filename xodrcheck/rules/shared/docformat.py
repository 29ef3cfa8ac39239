"""Rule documentation as HTML (the HTML report's rule help) and Markdown (SARIF's ``help.markdown``).

The rules' docstrings use a small part of reStructuredText, and only that part is read: paragraphs, a paragraph ending
in ``::`` followed by an indented literal block (``Passes::``; a bare ``::`` paragraph only opens the block), ``*`` or
``-`` bullet lists, and inline ``literal``, `interpreted`, :role:`~a.Target` and *emphasis*. Anything else is text.
:mod:`xodrcheck.rules.shared.plaintext` gives the same documentation as plain text for terminals.
"""

from __future__ import annotations

import inspect
import re
import textwrap
from html import escape

__all__ = ["blocks", "html", "markdown"]

#: ``("p", text)``, ``("pre", text)`` or ``("ul", items)``; texts still carry their inline markup.
Block = tuple[str, str | tuple[str, ...]]

_BULLET = re.compile(r"^([*-])\s+")
_INLINE = re.compile(
    r"``(?P<lit>.+?)``"
    r"|:(?P<role>[a-z]+):`(?P<target>[^`]+)`"
    r"|(?<![`\w])`(?P<interp>[^`]+)`(?![`\w])"
    r"|(?<![*\w])\*(?P<em>[^*\s](?:[^*]*[^*\s])?)\*(?![*\w])",
    re.DOTALL,
)
_MARKDOWN_SPECIAL = re.compile(r"([\\`*_<>\[\]#|])")


def _indent(line: str) -> int:
    return len(line) - len(line.lstrip())


def _literal(lines: list[str], i: int, floor: int) -> tuple[str | None, int]:
    """The literal block from line ``i`` on (lines indented deeper than ``floor``, blank lines within), dedented."""
    start = i
    while i < len(lines) and lines[i].strip() == "":
        i += 1
    body: list[str] = []
    while i < len(lines) and (lines[i].strip() == "" or _indent(lines[i]) > floor):
        body.append(lines[i])
        i += 1
    while body and body[-1].strip() == "":
        body.pop()
    if not body:
        return None, start
    return textwrap.dedent("\n".join(body)), i


def _paragraph_end(text: str) -> tuple[str, bool]:
    """A paragraph's text without its ``::``, and whether it opens a literal block."""
    if not text.endswith("::"):
        return text, False
    if text == "::":
        return "", True
    return (text[:-3] if text.endswith(" ::") else text[:-1]), True


def blocks(doc: str) -> list[Block]:
    """The documentation as blocks: paragraphs and list items joined onto one line, literal blocks as written."""
    lines = inspect.cleandoc(doc).splitlines()
    out: list[Block] = []
    i = 0
    while i < len(lines):
        if not lines[i].strip():
            i += 1
            continue
        floor = _indent(lines[i])
        if _BULLET.match(lines[i].strip()):
            items: list[str] = []
            while i < len(lines):
                stripped = lines[i].strip()
                if not stripped:
                    nxt = next((k for k in range(i, len(lines)) if lines[k].strip()), len(lines))
                    if nxt < len(lines) and _indent(lines[nxt]) == floor and _BULLET.match(lines[nxt].strip()):
                        i = nxt
                        continue
                    break
                if _indent(lines[i]) == floor and _BULLET.match(stripped):
                    items.append(_BULLET.sub("", stripped))
                elif _indent(lines[i]) > floor and items:
                    items[-1] += " " + stripped
                else:
                    break
                i += 1
            out.append(("ul", tuple(items)))
            continue
        para: list[str] = []
        while i < len(lines) and lines[i].strip() and not (para and _BULLET.match(lines[i].strip())):
            para.append(lines[i].strip())
            i += 1
        text, opens = _paragraph_end(" ".join(para))
        if text:
            out.append(("p", text))
        if opens:
            literal, i = _literal(lines, i, floor)
            if literal is not None:
                out.append(("pre", literal))
    return out


def _role_target(target: str) -> str:
    target = re.sub(r"\s*<[^>]*>$", "", target).strip()
    return target[1:].rsplit(".", 1)[-1] if target.startswith("~") else target


def _inline(text: str, code, em, plain) -> str:
    parts, at = [], 0
    for m in _INLINE.finditer(text):
        parts.append(plain(text[at : m.start()]))
        if m["lit"] is not None:
            parts.append(code(m["lit"]))
        elif m["role"] is not None:
            parts.append(code(_role_target(m["target"])))
        elif m["interp"] is not None:
            parts.append(code(m["interp"]))
        else:
            parts.append(em(m["em"]))
        at = m.end()
    parts.append(plain(text[at:]))
    return "".join(parts)


def _text(text: str) -> str:
    return escape(text, quote=False)


def _html_inline(text: str) -> str:
    return _inline(text, lambda t: f"<code>{_text(t)}</code>", lambda t: f"<em>{_text(t)}</em>", _text)


def html(doc: str) -> str:
    """The documentation as HTML: ``<p>``, ``<pre>`` and ``<ul>`` blocks, ``<code>`` and ``<em>`` inline; every
    character of the text is escaped."""
    out = []
    for kind, value in blocks(doc):
        if kind == "pre":
            out.append(f"<pre>{_text(str(value))}</pre>")
        elif kind == "ul":
            out.append("<ul>" + "".join(f"<li>{_html_inline(item)}</li>" for item in value) + "</ul>")
        else:
            out.append(f"<p>{_html_inline(str(value))}</p>")
    return "\n".join(out)


def _md_code(text: str) -> str:
    fence = "``" if "`" in text else "`"
    pad = " " if fence == "``" else ""
    return f"{fence}{pad}{text}{pad}{fence}"


def _md_inline(text: str) -> str:
    return _inline(text, _md_code, lambda t: f"*{t}*", lambda t: _MARKDOWN_SPECIAL.sub(r"\\\1", t))


def markdown(doc: str) -> str:
    """The documentation as (GitHub-flavoured) Markdown: paragraphs, fenced code blocks (``xml`` where the block is
    XML) and bullet lists."""
    out = []
    for kind, value in blocks(doc):
        if kind == "pre":
            lang = "xml" if str(value).lstrip().startswith("<") else ""
            out.append(f"```{lang}\n{value}\n```")
        elif kind == "ul":
            out.append("\n".join(f"* {_md_inline(item)}" for item in value))
        else:
            out.append(_md_inline(str(value)))
    return "\n\n".join(out) + "\n"
