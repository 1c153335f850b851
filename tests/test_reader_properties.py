"""A property of the city-model readers (issue 71): any model file — a valid one, or one
broken anywhere in its structure or numbers — is read into a site or refused with an
InputError (exit 2, a message naming the file and the fault); never another exception
(exit 3). Read as the command reads a file (:func:`planner.cityio.read_city_model`)."""

from __future__ import annotations

import copy
import json

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from planner.cityio import read_city_model
from planner.errors import InputError
from planner.synthetic3d import lod2_town

BASE = lod2_town(2, seed=0)

#: Values a field may be broken into.
JUNK = st.one_of(
    st.none(),
    st.booleans(),
    st.integers(min_value=-(2**63), max_value=2**63),
    st.floats(allow_nan=True, allow_infinity=True),
    st.text(max_size=8),
    st.lists(st.integers(min_value=-5, max_value=5), max_size=4),
    st.just({}),
    st.just([[[]]]),
)


def _paths(node, prefix=()):
    """Every path (keys and indices) into a JSON value, breadth limited."""
    yield prefix
    if isinstance(node, dict):
        for k, v in list(node.items())[:12]:
            yield from _paths(v, (*prefix, k))
    elif isinstance(node, list):
        for i, v in enumerate(node[:6]):
            yield from _paths(v, (*prefix, i))


PATHS = [p for p in _paths(BASE) if p]


def _set(doc, path, value):
    node = doc
    for k in path[:-1]:
        node = node[k]
    node[path[-1]] = value


@settings(
    max_examples=60,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large],
)
@given(st.lists(st.tuples(st.sampled_from(PATHS), JUNK), min_size=1, max_size=3))
def test_a_broken_cityjson_is_read_or_refused_never_a_crash(tmp_path_factory, edits):
    doc = copy.deepcopy(BASE)
    for path, value in edits:
        try:
            _set(doc, path, value)
        except (KeyError, IndexError, TypeError):  # an earlier edit removed the way there
            continue
    path = tmp_path_factory.mktemp("fuzz") / "fuzzed.city.json"
    path.write_text(json.dumps(doc, allow_nan=True))
    try:
        site = read_city_model(path)
    except InputError as exc:
        assert "fuzzed" in str(exc)  # the file named, with its fault
    else:
        assert site.planned


GML = b"""<?xml version="1.0"?>
<core:CityModel xmlns:core="http://www.opengis.net/citygml/2.0"
 xmlns:bldg="http://www.opengis.net/citygml/building/2.0" xmlns:gml="http://www.opengis.net/gml">
 <core:cityObjectMember><bldg:Building gml:id="B1">
  <bldg:boundedBy><bldg:WallSurface><bldg:lod2MultiSurface><gml:MultiSurface>
   <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing>
    <gml:posList srsDimension="3">POS</gml:posList>
   </gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
  </gml:MultiSurface></bldg:lod2MultiSurface></bldg:WallSurface></bldg:boundedBy>
 </bldg:Building></core:cityObjectMember>
</core:CityModel>"""


@settings(max_examples=60, deadline=None)
@given(
    st.lists(
        st.one_of(
            st.floats(allow_nan=True, allow_infinity=True, width=32),
            st.sampled_from(["x", "", "1e400", "-0", "NaN"]),
        ),
        max_size=20,
    )
)
def test_a_citygml_poslist_of_anything_is_read_or_refused_never_a_crash(tmp_path_factory, values):
    text = " ".join(str(v) for v in values).encode()
    path = tmp_path_factory.mktemp("fuzz") / "fuzzed.gml"
    path.write_bytes(GML.replace(b"POS", text))
    try:
        read_city_model(path)
    except InputError as exc:
        assert "fuzzed.gml" in str(exc)
