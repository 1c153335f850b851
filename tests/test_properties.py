"""Property-based tests of the site readers (hypothesis): whatever a file holds — malformed
JSON structures, odd numbers, broken CSV and WKT — reading it gives a Site or an
InputError with a message, never another exception; and a site that reads plans."""

from __future__ import annotations

import json
import math
import string

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import planner
from planner.errors import InputError
from planner.siteio import read_site

ODD_NUMBERS = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True),
    st.floats(min_value=-1e3, max_value=1e3),
    st.sampled_from([0.0, -0.0, 1e300, -1e300, 5e-324, 1e-9, 500000.0, 5400000.0]),
    st.integers(min_value=-(10**20), max_value=10**20),
)
JSON_SCALARS = st.one_of(
    st.none(), st.booleans(), ODD_NUMBERS, st.text(max_size=12), st.just("<script>")
)
JSON_ANY = st.recursive(
    JSON_SCALARS,
    lambda children: st.one_of(
        st.lists(children, max_size=4), st.dictionaries(st.text(max_size=8), children, max_size=4)
    ),
    max_leaves=12,
)
NEAR = st.floats(min_value=-60.0, max_value=60.0, allow_nan=False)


@st.composite
def ring(draw):
    """A ring near (500000, 5400000): mostly sensible, sometimes degenerate or odd."""
    n = draw(st.integers(min_value=0, max_value=7))
    pts = [[500000 + draw(NEAR), 5400000 + draw(NEAR)] for _ in range(n)]
    if pts and draw(st.booleans()):
        pts.append(list(pts[0]))
    if draw(st.integers(0, 9)) == 0:
        pts = [[draw(ODD_NUMBERS), draw(ODD_NUMBERS)] for _ in range(n)]
    return pts


@st.composite
def feature(draw):
    kind = draw(
        st.sampled_from(["Polygon", "Polygon", "MultiPolygon", "Point", "LineString", None])
    )
    coords = [draw(ring())]
    if kind == "MultiPolygon":
        coords = [coords, [draw(ring())]]
    elif kind == "Point":
        coords = [draw(ODD_NUMBERS), draw(ODD_NUMBERS)]
    elif kind == "LineString":
        coords = coords[0]
    props = draw(
        st.one_of(
            st.fixed_dictionaries(
                {},
                optional={
                    "height": st.one_of(ODD_NUMBERS, JSON_SCALARS),
                    "role": st.sampled_from(["building", "obstacle", "no-go", "boundary", "x"]),
                    "id": JSON_SCALARS,
                    "plan": JSON_SCALARS,
                },
            ),
            JSON_ANY,
        )
    )
    geometry = None if kind is None else {"type": kind, "coordinates": coords}
    return {"type": "Feature", "properties": props, "geometry": geometry}


@st.composite
def geojson_text(draw):
    if draw(st.integers(0, 7)) == 0:
        return json.dumps(draw(JSON_ANY), allow_nan=True)
    doc = {"type": "FeatureCollection", "features": draw(st.lists(feature(), max_size=4))}
    if draw(st.booleans()):
        doc["crs"] = {"type": "name", "properties": {"name": draw(st.text(max_size=20))}}
    return json.dumps(doc, allow_nan=True)


CSV_CELLS = st.one_of(
    st.text(alphabet=string.printable, max_size=8), ODD_NUMBERS.map(str), st.just("")
)


@st.composite
def csv_text(draw):
    header = draw(
        st.one_of(
            st.just(["id", "x", "y", "height"]),
            st.just(["id", "x", "y", "ring", "part", "height", "role"]),
            st.lists(st.sampled_from(["id", "x", "y", "height", "ring", "junk"]), max_size=6),
        )
    )
    rows = []
    for _ in range(draw(st.integers(0, 9))):
        row = []
        for col in header:
            if col in ("x", "y") and draw(st.booleans()):
                base = 500000 if col == "x" else 5400000
                row.append(str(base + draw(NEAR)))
            elif col in ("ring", "part"):
                row.append(str(draw(st.integers(-1, 2))))
            else:
                row.append(draw(CSV_CELLS).replace(",", ";").replace("\n", " "))
        rows.append(",".join(row))
    return "\n".join([",".join(header), *rows]) + "\n"


@st.composite
def wkt_text(draw):
    lines = []
    for _ in range(draw(st.integers(0, 4))):
        pts = draw(ring())
        body = ", ".join(f"{x} {y}" for x, y in pts)
        head = draw(st.sampled_from(["POLYGON ((", "POLYGON (", "MULTIPOLYGON (((", "POINT ("]))
        tail = draw(st.sampled_from(["))", ")", ")))", ""]))
        extra = draw(
            st.sampled_from(
                [
                    "",
                    "; height=12",
                    "; height=abc",
                    "; role=obstacle",
                    "; height=",
                    "; =",
                    "; id=<b>",
                ]
            )
        )
        lines.append(head + body + tail + extra)
    return "\n".join(lines)


def _read_or_refuse(tmp_path_factory, suffix: str, text: str):
    path = tmp_path_factory.mktemp("site") / f"site{suffix}"
    path.write_text(text, encoding="utf-8", errors="surrogatepass")
    try:
        return read_site(path, default_height_m=None)
    except InputError as exc:
        assert str(exc).strip(), "an InputError must say what was wrong"
        return None


COMMON = settings(
    max_examples=150, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)


@COMMON
@given(text=geojson_text())
def test_geojson_reads_or_is_refused_with_a_message(tmp_path_factory, text):
    _read_or_refuse(tmp_path_factory, ".geojson", text)


@COMMON
@given(text=csv_text())
def test_csv_reads_or_is_refused_with_a_message(tmp_path_factory, text):
    _read_or_refuse(tmp_path_factory, ".csv", text)


@COMMON
@given(text=wkt_text())
def test_wkt_reads_or_is_refused_with_a_message(tmp_path_factory, text):
    _read_or_refuse(tmp_path_factory, ".wkt", text)


@COMMON
@given(raw=st.binary(max_size=300), suffix=st.sampled_from([".geojson", ".csv", ".wkt"]))
def test_arbitrary_bytes_are_refused_or_read(tmp_path_factory, raw, suffix):
    path = tmp_path_factory.mktemp("site") / f"site{suffix}"
    path.write_bytes(raw)
    try:
        read_site(path)
    except InputError:
        pass


@st.composite
def small_site(draw):
    """A valid small site: one to three rectangles, apart, of plausible heights."""
    feats = []
    for i in range(draw(st.integers(1, 3))):
        w = draw(st.floats(3, 25))
        d = draw(st.floats(3, 25))
        x0, y0 = 500000 + 40.0 * i, 5400000 + draw(st.floats(-5, 5))
        h = draw(st.floats(1, 30))
        ring = [[x0, y0], [x0 + w, y0], [x0 + w, y0 + d], [x0, y0 + d], [x0, y0]]
        feats.append(
            {
                "type": "Feature",
                "properties": {"id": f"b{i}", "height": h},
                "geometry": {"type": "Polygon", "coordinates": [ring]},
            }
        )
    return json.dumps({"type": "FeatureCollection", "features": feats})


@settings(
    max_examples=12, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
@given(text=small_site(), strict=st.floats(0.5, 8))
def test_a_site_that_reads_plans_completely(tmp_path_factory, text, strict):
    site = _read_or_refuse(tmp_path_factory, ".geojson", text)
    assert site is not None
    p = planner.plan(
        site,
        None,
        planner.Requirements(max_xy_mm=strict, max_z_mm=strict),
        planner.PlanSettings(sample_spacing_m=4, sample_height_step_m=4, grid_m=3),
    )
    assert len(p.coverage) > 0
    unmet = p.unmet
    assert (unmet["reason"] != "").all()  # every unmet sample says why
    met = p.scanned[p.scanned["meets"]]
    assert (met["m_x_mm"] <= strict * (1 + 1e-9)).all() and (
        met["m_z_mm"] <= strict * (1 + 1e-9)
    ).all()
    assert all(math.isfinite(v) for v in p.stations[["x", "y"]].to_numpy().ravel())


@settings(
    max_examples=5, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
@given(text=st.one_of(small_site(), geojson_text()))
def test_generated_sites_through_the_command_line(tmp_path_factory, text):
    """Generated sites end to end: exit 0/1 with a complete plan, or 2 with nothing."""
    from sites import run_cli as run

    folder = tmp_path_factory.mktemp("cli")
    path = folder / "site.geojson"
    path.write_text(text)
    out = folder / "out"
    code, _, err = run("plan", str(path), "--out", str(out), "--sample-spacing-m", "4", "-q")
    assert code in (0, 1, 2) and "Traceback" not in err
    if code == 2:
        assert not out.exists() and err.startswith("planner: error:")
    else:
        assert {p.name for p in out.iterdir()} >= {"stations.csv", "coverage.csv", "summary.txt"}
