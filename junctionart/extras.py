"""Optional dependencies, loaded where a command needs them, with one clear line when they are missing.

matplotlib (figures: ``junctionart render``, the ERA's figures) is the extra ``figures``; the generator and the
checker never need it.
"""

from __future__ import annotations

from types import ModuleType

from .errors import MissingDependency


def pyplot(purpose: str) -> ModuleType:
    """``matplotlib.pyplot`` on the non-interactive Agg backend, or :class:`MissingDependency` naming ``purpose``."""
    try:
        import matplotlib
    except ImportError:
        raise MissingDependency(
            f"{purpose} draws with matplotlib, which is not installed: pip install 'junctionart[figures]'"
        ) from None
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt
