"""Exact road geometry, vectorised with numpy: plan-view elements and reference lines, cubic profiles, lane borders
and lane lines of every lane section (:mod:`~xodrcheck.geometry.lanes` per road, :mod:`~xodrcheck.geometry.batch` for
many sections at once, the one evaluation both use), and their adaptive sampling."""
