"""Maps the graph tests read: the README's T junction and the rule fixtures."""

from __future__ import annotations

from pathlib import Path

from xodrcheck.model import Document
from xodrcheck.reader import read

REPO = Path(__file__).resolve().parents[3]
FIXTURES = REPO / "tests" / "xodrcheck" / "rules" / "fixtures"
T_JUNCTION = REPO / "examples" / "t-junction.xodr"
#: Road 1 enters a loop (road 2, back into itself through connecting road 11); connecting road 12 leads out to road 3.
LOOP = FIXTURES / "lanes-trapped" / "pass.xodr"
TRAP = FIXTURES / "lanes-trapped" / "fail.xodr"


def document(path: Path) -> Document:
    result = read(path)
    assert result.document is not None
    return result.document
