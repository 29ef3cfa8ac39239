"""The official OpenDRIVE XML schemas 1.1 to 1.9.0, and corrected copies of 1.8.1 and 1.9.0 (see NOTICE.md), shipped
as package data ``xodrcheck.schemas``."""
