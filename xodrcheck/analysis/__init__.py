"""What a map is, beside whether it is right: summaries, measures and samples computed from the read document.

:mod:`.info` and :mod:`.elevation` (``xodrcheck info``), :mod:`.metrics` (junction metrics, ``xodrcheck metrics``),
:mod:`.sample` (points along every lane, ``xodrcheck sample``), :mod:`.snapshot` (map invariants and their differences,
``xodrcheck snapshot`` / ``diff``).
"""
