"""Element names of outline points and skeleton vertices (13.2, 13.4): a module of their own, so that a rule module
can key its tables by them without loading the dataclasses of :mod:`.model` (which re-exports them).
"""

#: Element names of outline points, in the order :attr:`xodrcheck.objects.model.Outline.kind` reports them.
CORNER_ROAD, CORNER_LOCAL, CURVE_LOCAL = "cornerRoad", "cornerLocal", "curveLocal"
#: Element names of skeleton vertices.
VERTEX_ROAD, VERTEX_LOCAL = "vertexRoad", "vertexLocal"
