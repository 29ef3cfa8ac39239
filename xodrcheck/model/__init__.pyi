"""The names of :mod:`xodrcheck.model` for type checkers: the package loads them lazily (see ``__init__.py``)."""

# ruff: noqa: F403
from xodrcheck.model.document import *
from xodrcheck.model.enums import *
from xodrcheck.model.facts import *
from xodrcheck.model.header import *
from xodrcheck.model.ids import *
from xodrcheck.model.junction_parts import *
from xodrcheck.model.junctions import *
from xodrcheck.model.lane_records import *
from xodrcheck.model.lanes import *
from xodrcheck.model.objects import *
from xodrcheck.model.planview import *
from xodrcheck.model.railroad import *
from xodrcheck.model.regulations import *
from xodrcheck.model.road_records import *
from xodrcheck.model.roads import *
from xodrcheck.model.signals import *
from xodrcheck.model.surface import *
