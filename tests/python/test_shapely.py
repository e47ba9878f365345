# Shapely geometries as containers, elements and flow guides: the same as their rings.
import numpy as np
import pytest

import pak

try:
    from shapely.geometry import LineString, MultiPolygon, Point, Polygon, box
except ImportError:
    pytest.skip("shapely is not installed (scripts/install-deps.sh installs python3-shapely)",
                allow_module_level=True)


def rings_of(polygon):
    """A polygon's rings as arrays, without the repeated closing point."""
    return [np.asarray(polygon.exterior.coords)[:-1]] + [np.asarray(r.coords)[:-1] for r in polygon.interiors]


def test_a_polygon_with_a_hole_is_its_rings():
    disc = Point(0, 0).buffer(100).difference(Point(20, 10).buffer(25))
    assert len(pak.scene(disc).container) == 2  # the outer ring and the hole
    leaf = Polygon([(0, 0), (10, -3), (20, 0), (10, 3)])
    washer = Point(0, 0).buffer(5).difference(Point(0, 0).buffer(2))
    options = dict(seed=1, max_iterations=60, threads=1)
    shapely = pak.pack(disc, [leaf, washer], **options)
    arrays = pak.pack(rings_of(disc), [rings_of(leaf), rings_of(washer)], **options)
    assert shapely.to_svg() == arrays.to_svg()
    assert len(shapely) > 0


def test_a_multipolygon_is_one_element():
    pair = MultiPolygon([box(0, 0, 5, 5), box(7, 0, 12, 5)])
    result = pak.pack(Point(0, 0).buffer(60), [pair], seed=2, max_iterations=40, threads=1)
    assert len(result) > 0
    assert all(len(outline) == 2 for outline in result.outlines)  # both squares of each copy
    assert len(pak.elements(pair)) == 1


def test_flow_guides_as_linestrings():
    disc = Point(0, 0).buffer(100)
    leaf = Polygon([(0, 0), (10, -3), (20, 0), (10, 3)])
    guides = [LineString([(-100, -50), (100, 50)])]
    result = pak.flow(disc, [leaf, box(0, 0, 20, 4)], guides=guides, seed=2, count=12, iterations=1, threads=1)
    same = pak.flow(rings_of(disc), [rings_of(leaf), rings_of(box(0, 0, 20, 4))],
                    guides=[np.asarray(guides[0].coords)], seed=2, count=12, iterations=1, threads=1)
    assert len(result) > 0 and result.to_svg() == same.to_svg()


def test_other_geometries_raise_input_error():
    with pytest.raises(pak.InputError, match="must be a Polygon or a MultiPolygon, got a LineString"):
        pak.pack(LineString([(0, 0), (1, 1)]), [box(0, 0, 1, 1)])
    with pytest.raises(pak.InputError, match="element 0"):
        pak.pack(Point(0, 0).buffer(10), [Point(0, 0)])
