from pathlib import Path

import numpy as np
import pytest

from junctionart import controllines
from junctionart.errors import InputError
from junctionart.params import Params

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


@pytest.mark.parametrize("size", [(500, 500), (1000, 300), (300, 1500), (2000, 2000)])
@pytest.mark.parametrize("seed", [0, 1, 2])
def test_automatic_lines_stay_inside_both_dimensions(size, seed):
    W, H = size
    cl = controllines.automatic(Params(width=W, height=H), np.random.default_rng(seed))
    pts = np.array([p for ln in cl.lines for p in ln.points])
    assert pts[:, 0].min() >= 0 and pts[:, 0].max() <= W
    assert pts[:, 1].min() >= 0 and pts[:, 1].max() <= H
    # the height is used, not just respected: the top line is within one spacing (plus the 200 m gap) of the top
    assert pts[:, 1].max() >= H - 420 or len(cl.lines) == 2
    assert len(cl.lines) >= 2 and cl.pairs == tuple((i, i + 1) for i in range(len(cl.lines) - 1))


def test_automatic_line_count_is_honoured():
    cl = controllines.automatic(Params(width=1000, height=5000, n_lines=4), np.random.default_rng(0))
    assert len(cl.lines) == 4


def test_json_lines_pairs_groups_lanes():
    data = {
        "lines": [
            {"id": "a", "points": [[0, 0], [100, 0], [200, 50]], "group": 1, "lanes": [2, 1]},
            {"id": "b", "points": [[0, 100], [200, 100]], "group": 1},
            {"id": "c", "points": [[0, 300], [200, 300]], "group": 2, "lanes": {"forward": 0, "backward": 3}},
        ],
        "pairs": [["a", "b"]],
    }
    cl = controllines.parse(data)
    assert [ln.id for ln in cl.lines] == ["a", "b", "c"]
    assert cl.pairs == ((0, 1),)
    assert cl.lines[0].lanes == (2, 1) and cl.lines[2].lanes == (0, 3) and cl.lines[1].lanes is None
    assert cl.groups == (1, 2)
    assert cl.lines[0].length == pytest.approx(100 + np.hypot(100, 50))
    assert cl.lines[0].point_at(150) == pytest.approx((100 + 50 * 100 / np.hypot(100, 50), 50 * 50 / np.hypot(100, 50)))


def test_default_pairs_are_consecutive_lines_of_a_group():
    data = {
        "lines": [
            {"id": k, "points": [[0, y], [100, y]], "group": g}
            for k, y, g in (("a", 0, 0), ("b", 100, 0), ("c", 200, 0), ("d", 500, 1), ("e", 600, 1))
        ]
    }
    assert controllines.parse(data).pairs == ((0, 1), (1, 2), (3, 4))


def test_geojson_features():
    cl = controllines.load(EXAMPLES / "three_groups.geojson")
    assert len(cl.lines) == 6 and cl.groups == (0, 1, 2)
    assert cl.pairs == ((0, 1), (2, 3), (4, 5))
    assert cl.lines[5].lanes == (3, 0)
    assert len(cl.lines[2].points) == 3  # a sequence of segments joined at their endpoints


@pytest.mark.parametrize("name", ["a_shape.json", "three_groups.geojson", "grid.json"])
def test_examples_load(name):
    cl = controllines.load(EXAMPLES / name)
    assert len(cl.lines) >= 3 and cl.pairs


@pytest.mark.parametrize(
    "content, words",
    [
        ("{not json", ["not valid JSON", "line 1"]),
        ("[1, 2]", ["expected a JSON object"]),
        ('{"lines": [{"id": "a", "points": [[0, 0], [1, 1]]}]}', ["at least 2 control lines"]),
        (
            '{"lines": [{"id": "a", "points": [[0, 0]]}, {"id": "b", "points": [[0, 9], [9, 9]]}]}',
            ["line 0", "at least 2 points"],
        ),
        (
            '{"lines": [{"id": "a", "points": [[0, 0], [5, "x"]]}, {"id": "b", "points": [[0, 9], [9, 9]]}]}',
            ["point 1"],
        ),
        (
            '{"lines": [{"id": "a", "points": [[0, 0], [50, 0]]}, {"id": "a", "points": [[0, 9], [9, 9]]}]}',
            ["'a' is used twice"],
        ),
        (
            '{"lines": [{"id": "a", "points": [[0, 0], [50, 0]], "lanes": [0, 0]}, {"id": "b", "points": [[0, 9], [9, 9]]}]}',  # noqa: E501
            ["0 in both"],
        ),
        (
            '{"lines": [{"id": "a", "points": [[0, 0], [50, 0]], "lanes": [4, 1]}, {"id": "b", "points": [[0, 9], [9, 9]]}]}',  # noqa: E501
            ["[0, 3]"],
        ),
        (
            '{"lines": [{"id": "a", "points": [[0, 0], [50, 0]]}, {"id": "b", "points": [[0, 9], [9, 9]]}], "pairs": [["a", "z"]]}',  # noqa: E501
            ["pair", "'z'"],
        ),
        (
            '{"type": "FeatureCollection", "features": [{"type": "Feature", "geometry": {"type": "Point", "coordinates": [0, 0]}}]}',  # noqa: E501
            ["LineString"],
        ),
        (
            '{"lines": [{"id": "a", "points": [[0, 0], [400, 0]]}, {"id": "b", "points": [[0, 0], [400, 0]]}]}',
            ["'a' and 'b'", "overlap along 400.0 m"],
        ),
        (
            '{"lines": [{"id": "a", "points": [[0, 0], [400, 0]]}, {"id": "b", "points": [[200, 0], [600, 0]]}]}',
            ["overlap along 200.0 m"],
        ),
    ],
)
def test_bad_files_name_the_file_and_the_problem(tmp_path, content, words):
    f = tmp_path / "lines.json"
    f.write_text(content)
    with pytest.raises(InputError) as err:
        controllines.load(f)
    assert str(f) in str(err.value)
    for w in words:
        assert w in str(err.value)


def test_missing_file(tmp_path):
    with pytest.raises(InputError, match="cannot read"):
        controllines.load(tmp_path / "none.json")


def test_projection_onto_a_polyline():
    ln = controllines.ControlLine("x", ((0.0, 0.0), (100.0, 0.0), (100.0, 100.0)))
    assert ln.project((50.0, 10.0)) == pytest.approx(50.0)
    assert ln.project((120.0, 60.0)) == pytest.approx(160.0)
