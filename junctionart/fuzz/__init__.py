"""Property-based fuzzing of junctionart and xodrcheck: public Hypothesis strategies, properties and profiles.

Strategies (plural nouns, keyword bounds, arguments validated before anything is drawn):

* :func:`control_lines`, :func:`control_line_groups`, :func:`generator_params` - the generator's inputs, awkward ones
  included; :func:`invalid_control_line_files`, :func:`invalid_generator_params` - inputs it must refuse;
* :func:`opendrive_documents` - small valid OpenDRIVE files built without the generator;
* :func:`document_mutations`, :func:`damaged_documents`, :func:`defective_documents` - known defects and random
  damage to any OpenDRIVE file.

The properties (:mod:`junctionart.fuzz.properties`) and the strategies that feed them form the runs of
:mod:`junctionart.fuzz.campaign`, shared by the test suite (``tests/fuzz``, profile ``ci``) and ``python -m
junctionart.fuzz --minutes N [--profile long]``, which repeats every run until the time is up and prints figures.
Profiles, example budgets, the example database and the explicit regressions are in :mod:`junctionart.fuzz.profiles`.
"""

try:
    import hypothesis  # noqa: F401
except ImportError:  # pragma: no cover - the fuzz extra is missing
    raise ImportError(
        "junctionart.fuzz needs Hypothesis, which is not installed: pip install 'junctionart[fuzz]'"
    ) from None

from junctionart.fuzz.documents import document_specs, opendrive_documents
from junctionart.fuzz.mutations import (
    DAMAGE,
    DEFECTS,
    Mutation,
    damaged_documents,
    defective_documents,
    document_mutations,
)

__all__ = [
    "DAMAGE",
    "DEFECTS",
    "Mutation",
    "control_line_groups",
    "control_lines",
    "damaged_documents",
    "defective_documents",
    "document_mutations",
    "document_specs",
    "generator_params",
    "invalid_control_line_files",
    "invalid_generator_params",
    "opendrive_documents",
]


def __getattr__(name: str):
    # The generator's strategies import junctionart; load them only when asked for.
    if name in (
        "control_lines",
        "control_line_groups",
        "generator_params",
        "invalid_control_line_files",
        "invalid_generator_params",
    ):
        from junctionart.fuzz import generator

        return getattr(generator, name)
    raise AttributeError(name)
