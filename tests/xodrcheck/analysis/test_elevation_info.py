"""``xodrcheck info``'s elevation summary: height range, steepest grade and z step at road links, exact."""

from __future__ import annotations

import json

import pytest

from xodrcheck.analysis.elevation import elevation_info
from xodrcheck.cli import main
from xodrcheck.reader import read

ROAD = """  <road name="" length="100.0" id="{id}" junction="-1">
    <link>{links}</link>
    <planView><geometry s="0.0" x="{x}" y="0.0" hdg="0.0" length="100.0"><line/></geometry></planView>
    <elevationProfile>{elevation}</elevationProfile>
    <lanes><laneSection s="0.0"><center><lane id="0" type="none" level="false"/></center>
      <right><lane id="-1" type="driving" level="false"><width sOffset="0.0" a="3.5" b="0.0" c="0.0" d="0.0"/></lane>
      </right></laneSection></lanes>
  </road>
"""
#: road 1 rises 3 m as 3 u^2 - 2 u^3 (steepest 4.5 % at s = 50), road 2 starts 0.25 m higher and stays level
ROAD1 = '<elevation s="0.0" a="1.0" b="0.0" c="0.0009" d="-0.000006"/>'
ROAD2 = '<elevation s="0.0" a="4.25" b="0.0" c="0.0" d="0.0"/>'


def _map(tmp_path, second=ROAD2):
    roads = ROAD.format(
        id="1", x=0.0, elevation=ROAD1, links='<successor elementType="road" elementId="2" contactPoint="start"/>'
    )
    roads += ROAD.format(
        id="2", x=100.0, elevation=second, links='<predecessor elementType="road" elementId="1" contactPoint="end"/>'
    )
    text = f'<?xml version="1.0"?>\n<OpenDRIVE><header revMajor="1" revMinor="8"/>\n{roads}</OpenDRIVE>\n'
    path = tmp_path / "m.xodr"
    path.write_text(text)
    return path


def test_range_grade_and_link_step_are_exact(tmp_path):
    e = elevation_info(read(_map(tmp_path)).document)
    assert (e.min_z, e.max_z) == pytest.approx((1.0, 4.25))
    assert e.max_grade == pytest.approx(0.045)
    assert e.max_link_step == pytest.approx(0.25) and e.links == 2


def test_roads_without_records_lie_at_zero_and_link_cleanly(tmp_path):
    e = elevation_info(read(_map(tmp_path, second='<elevation s="0.0" a="4.0" b="0.0" c="0.0" d="0.0"/>')).document)
    assert e.max_link_step == pytest.approx(0.0, abs=1e-12)


def test_info_prints_and_writes_it(tmp_path, capsys):
    path = _map(tmp_path)
    assert main(["info", str(path)]) == 0
    assert "max grade 4.50 %, largest z step at a road link 0.25 m (2 links)" in capsys.readouterr().out
    assert main(["info", "--format", "json", str(path)]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["elevation"]["max_link_step_m"] == pytest.approx(0.25) and data["elevation"]["links"] == 2
