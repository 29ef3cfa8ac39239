"""Quality-diversity search over the intersection genome (``junctionart search``, issue 13)."""
