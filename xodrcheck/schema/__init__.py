"""Schema validation (S001): a document checked against the official OpenDRIVE XSD of its version.

:mod:`.validate` picks the schema and runs it; :mod:`.errata` corrects the official 1.8.1/1.9.0 XSDs; :mod:`.fast` and
:mod:`.plan` give a valid 1.8/1.9 file its verdict without the XSD 1.1 validator. The XSD files themselves are data of
the ``xodrcheck.schemas`` package.
"""
