"""Stage 3: intersections (incident points, connection lanes, lane links) with repair instead of discarding."""

from .layout import build
from .model import ConnectionPlan, JunctionPlan, Layout, RoadPlan

__all__ = ["ConnectionPlan", "JunctionPlan", "Layout", "RoadPlan", "build"]
