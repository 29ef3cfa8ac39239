"""The official OpenDRIVE XML schemas 1.1 to 1.8.1 (see NOTICE.md), shipped as package data ``xodrcheck.schemas``."""
