"""GitHub Actions workflow commands: ``::error file=PATH,line=N,title=CODE name::message [place] (basis)``.

Errors become ``::error``, warnings ``::warning``, infos ``::notice``; GitHub shows them as annotations on the
pull request. The message ends with the place and the basis, as a text line does. Values are escaped as the
workflow-command syntax requires.
"""

from __future__ import annotations

from collections.abc import Sequence

from xodrcheck.findings import Finding, Severity
from xodrcheck.report.text import where

COMMANDS = {Severity.ERROR: "error", Severity.WARNING: "warning", Severity.INFO: "notice"}


def _data(text: str) -> str:
    return text.replace("%", "%25").replace("\r", "%0D").replace("\n", "%0A")


def _property(text: str) -> str:
    return _data(text).replace(":", "%3A").replace(",", "%2C")


def command(path: str | None, f: Finding) -> str:
    props = [f"file={_property(path or '-')}"]
    if f.line:
        props.append(f"line={f.line}")
    props.append(f"title={_property(f'{f.code} {f.name}')}")
    return f"::{COMMANDS[f.severity]} {','.join(props)}::{_data(f'{f.message}{where(f)} ({f.basis})')}"


def render(reports: Sequence) -> str:
    return "".join(command(r.path, f) + "\n" for r in reports for f in r.findings)
