"""Rule layer-link-without-section: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture

RULE = "layer-link-without-section"


def test_permanent_section_runs_past_the_temporary_layers_start():
    found = findings(fixture(RULE, "fail.xodr"), RULE)
    assert sorted(f.lane for f in found) == [-2, -1]
    assert all("ends at s=60" in f.message and "start at 20" in f.message for f in found)


def test_a_layer_link_across_a_road_link_is_the_linked_roads():
    """Connecting road 10 starts at road 1's end, where road 1's temporary layer ends: its lane's predecessor on
    the temporary layer is road 1's lane, not a lane of its own layers."""
    from pathlib import Path

    from xodrcheck.check import check

    path = Path(__file__).parents[1] / "opendrive19" / "roadworks_junction.xodr"
    assert check(path, select=("L032",)).findings == ()
