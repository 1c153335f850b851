"""Hostile input, round two: each promise, an example of each way it was broken, and a
property-based test generating more of its kind.

1. Nothing is fetched and nothing outside the input is read (GIS files pinned to their
   format and driver; the session's loopback sentinel, ``conftest.sentinel``, sees no call).
2. Nothing is dropped silently (a shapefile's tables disagreeing).
3. A bad number is exit 2 naming its range, never 3 (:mod:`planner.ranges`).
4. ``--scheduler`` fails fast and clearly.
5. Units: a CRS in feet is refused, not planned as metres.
6. User strings never become live content (:mod:`planner.text`).
7. ``--out`` never loses or leaves anything.
8. Budgets hold for every part of the work (the timed cases are in
   ``benchmarks/hostile_budgets.py``; here what makes them hold).
9. ``planner serve``'s numbers (its static paths: ``test_serve.py``).
"""

from __future__ import annotations

import json
import socket
import struct
import threading
import time
import xml.etree.ElementTree as ET
import zipfile
from pathlib import Path

import numpy as np
import pytest
import shapely
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from shapely.geometry import box
from sites import run_cli

import planner
from planner import gdalio
from planner.errors import InputError
from planner.pipeline.documents.export import OWNED_FILES
from planner.pipeline.inputs.requirements import PlanSettings, Requirements, field_specs
from planner.ranges import RANGES, Range, check_number
from planner.synthetic import densified
from planner.text import printable

FAST = ["--sample-spacing-m", "5", "--sample-height-step-m", "4", "--grid-m", "4", "-q"]
PROPERTY = settings(
    max_examples=40,
    deadline=None,
    suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow],
)
X0, Y0 = 500000.0, 5400000.0


def _site(ids=("hut",), crs="EPSG:25832", size=(20.0, 15.0)) -> str:
    feats = [
        {
            "type": "Feature",
            "properties": {"id": ident, "height": 9},
            "geometry": shapely.geometry.mapping(
                box(X0 + 40 * k, Y0, X0 + 40 * k + size[0], Y0 + size[1])
            ),
        }
        for k, ident in enumerate(ids)
    ]
    doc = {"type": "FeatureCollection", "features": feats}
    if crs:
        doc["crs"] = {"type": "name", "properties": {"name": crs}}
    return json.dumps(doc)


def _vrt(source: str) -> str:
    return (
        f'<OGRVRTDataSource><OGRVRTLayer name="b"><SrcDataSource>{source}</SrcDataSource>'
        "</OGRVRTLayer></OGRVRTDataSource>"
    )


# -- 1. nothing fetched, nothing outside the input read ------------------------------------
def _hostile_gis(kind: str, url: str, tmp: Path) -> tuple[str, bytes]:
    remote = _vrt(f"/vsicurl/{url}/x.geojson").encode()
    gml = (
        b'<?xml version="1.0"?><ogr:FeatureCollection xmlns:ogr="http://ogr.maptools.org/" '
        b'xmlns:gml="http://www.opengis.net/gml"><gml:featureMember><ogr:b><ogr:geometryProperty>'
        b"<gml:Polygon><gml:outerBoundaryIs><gml:LinearRing><gml:coordinates>0,0 10,0 10,10 0,0"
        b"</gml:coordinates></gml:LinearRing></gml:outerBoundaryIs></gml:Polygon>"
        b"</ogr:geometryProperty></ogr:b></gml:featureMember></ogr:FeatureCollection>"
    )
    return {
        "vrt-url.gpkg": ("site.gpkg", remote),
        "vrt-url.kml": ("site.kml", remote),
        "vrt-url.shp": ("site.shp", remote),
        "wfs.gpkg": (
            "site.gpkg",
            f"<OGRWFSDataSource><URL>{url}/wfs</URL></OGRWFSDataSource>".encode(),
        ),
        "vrt-local.gpkg": ("site.gpkg", _vrt("CSV:/etc/hostname").encode()),
        "gml.gpkg": ("site.gpkg", gml),
        "gml.kml": ("site.kml", gml),
    }[kind]


@pytest.mark.parametrize(
    ("kind", "message"),
    [
        ("vrt-url.gpkg", "has the extension .gpkg but is not a GeoPackage (it is an XML document)"),
        ("vrt-url.kml", "is not a KML file (its root element is 'OGRVRTDataSource'"),
        ("vrt-url.shp", "has the extension .shp but is not a Shapefile"),
        ("wfs.gpkg", "is not a GeoPackage"),
        ("vrt-local.gpkg", "is not a GeoPackage"),
        ("gml.gpkg", "is not a GeoPackage"),
        ("gml.kml", "its root element is 'FeatureCollection'"),
    ],
)
def test_a_gis_file_that_is_really_another_format_is_refused_unread(
    tmp_path, sentinel, kind, message
):
    name, data = _hostile_gis(kind, sentinel.url, tmp_path)
    folder = tmp_path / "in"
    folder.mkdir()
    (folder / name).write_bytes(data)
    if name.endswith(".shp"):  # its side-cars, so that only the content is wrong
        (folder / "site.shx").write_bytes(b"\0" * 100)
        (folder / "site.dbf").write_bytes(b"\x03" + b"\0" * 31)
    before = sorted(p.name for p in folder.iterdir())
    calls = len(sentinel.calls)
    code, _, err = run_cli("plan", str(folder / name), "--out", str(tmp_path / "p"), *FAST)
    assert code == 2 and message in err, err
    assert "Traceback" not in err and not (tmp_path / "p").exists()
    assert sorted(p.name for p in folder.iterdir()) == before  # no .gfs, no .aux.xml
    assert len(sentinel.calls) == calls  # nothing fetched


def test_a_kmz_holding_a_virtual_dataset_is_refused(tmp_path, sentinel):
    path = tmp_path / "site.kmz"
    with zipfile.ZipFile(path, "w") as zf:
        zf.writestr("doc.kml", _vrt(f"/vsicurl/{sentinel.url}/x.geojson"))
    with pytest.raises(InputError, match="root element is 'OGRVRTDataSource'"):
        planner.read_site(path)


def test_real_gis_files_still_open_by_their_own_driver(tmp_path):
    """Negative control: a GeoPackage and a KMZ written by GDAL pass the pin."""
    import pyogrio.raw

    gpkg = tmp_path / "site.gpkg"
    geom = np.array([shapely.to_wkb(box(X0, Y0, X0 + 20, Y0 + 15))], dtype=object)
    pyogrio.raw.write(
        gpkg, geom, [np.array([9.0])], fields=["height"], geometry_type="Polygon",
        crs="EPSG:25832", driver="GPKG", layer="buildings",
    )  # fmt: skip
    assert gdalio.layers(gpkg, "GeoPackage") == ["buildings"]
    kml = (
        '<?xml version="1.0"?><kml xmlns="http://www.opengis.net/kml/2.2"><Document><Placemark>'
        "<name>A</name><Polygon><outerBoundaryIs><LinearRing><coordinates>11,48 11.0003,48 "
        "11.0003,48.0002 11,48.0002 11,48</coordinates></LinearRing></outerBoundaryIs>"
        "</Polygon></Placemark></Document></kml>"
    )
    kmz = tmp_path / "site.kmz"
    with zipfile.ZipFile(kmz, "w") as zf:
        zf.writestr("doc.kml", kml)
    site = planner.read_site(kmz, default_height_m=9)
    assert [b.id for b in site.buildings] == ["A"]


_OTHER_CONTENT = st.one_of(
    st.builds(
        lambda tag: f"<{tag}><x/></{tag}>".encode(),
        st.from_regex(r"[A-Za-z]{1,12}", fullmatch=True),
    ),
    st.builds(lambda s: json.dumps({"type": s}).encode(), st.text(max_size=20)),
    st.builds(lambda b: b"SQLite format 3\x00" + b, st.binary(min_size=60, max_size=120)),
    st.binary(min_size=1, max_size=300),
)


@PROPERTY
@given(
    content=_OTHER_CONTENT,
    kind=st.sampled_from(["GeoPackage", "KML", "KMZ", "Shapefile"]),
    member=st.sampled_from(["doc.kml", "files/a.xml"]),
)
def test_nothing_but_its_own_format_passes_the_pin(tmp_path, content, kind, member):
    """Whatever bytes stand under a GIS extension, they pass the pin only if they are that
    format (an XML root other than kml, JSON, an SQLite database that is no GeoPackage,
    random bytes; as a KMZ's member too, its .kml or another XML): else InputError, and
    GDAL never sees them. A shapefile's side-cars are there and agree, so only its content
    is wrong."""
    if content.lstrip().startswith(b"<kml"):
        return
    path = (
        tmp_path
        / {"GeoPackage": "a.gpkg", "KML": "a.kml", "KMZ": "a.kmz", "Shapefile": "a.shp"}[kind]
    )
    path.write_bytes(content)
    if kind == "Shapefile":
        (tmp_path / "a.shx").write_bytes(b"\0" * 100)  # no shape …
        (tmp_path / "a.dbf").write_bytes(b"\x03" + b"\0" * 31)  # … and no record
    if kind == "KMZ":
        kml = b'<kml xmlns="http://www.opengis.net/kml/2.2"><Document/></kml>'
        with zipfile.ZipFile(path, "w") as zf:
            zf.writestr("doc.kml" if member != "doc.kml" else "other.kml", kml)
            body = (
                content if content.lstrip()[:1] == b"<" or member == "doc.kml" else b"<" + content
            )
            zf.writestr(member, body)
    with pytest.raises(InputError):
        gdalio.check_signature(path, kind)


@pytest.mark.parametrize(
    ("name", "data", "message"),
    [
        (
            "doctype.kml",
            b'<?xml version="1.0"?><!DOCTYPE kml [<!ENTITY a "b">]><kml/>',
            "no document type",
        ),
        (
            "comment.kml",
            b'<?xml version="1.0"?><!-- <kml --><!DOCTYPE kml [<!ENTITY a "b">]><kml/>',
            "no document type",
        ),
        (
            "utf16.kml",
            '<?xml version="1.0" encoding="UTF-16"?><!DOCTYPE kml><kml/>'.encode("utf-16"),
            "no document type",
        ),
        ("encoding.kml", b'<?xml version="1.0" encoding="x-nope"?><kml/>', "not well-formed XML"),
    ],
)
def test_a_kml_declaring_a_document_type_or_an_unknown_encoding_is_refused(
    tmp_path, name, data, message
):
    (tmp_path / name).write_bytes(data)
    with pytest.raises(InputError, match=message):
        planner.read_site(tmp_path / name)


def _zip_bytes(flag_bits: int = 0, method: int | None = None, offset: int | None = None) -> bytes:
    """A KMZ whose central directory says something its entry is not."""
    import io

    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w") as zf:
        zf.writestr("doc.kml", '<kml xmlns="http://www.opengis.net/kml/2.2"><Document/></kml>')
    data = bytearray(buf.getvalue())
    cd = data.rfind(b"PK\x01\x02")
    if flag_bits:
        data[cd + 8 : cd + 10] = struct.pack("<H", flag_bits)
    if method is not None:
        data[cd + 10 : cd + 12] = struct.pack("<H", method)
    if offset is not None:
        data[cd + 42 : cd + 46] = struct.pack("<I", offset)
    return bytes(data)


@pytest.mark.parametrize(
    "data",
    [_zip_bytes(flag_bits=1), _zip_bytes(method=99), _zip_bytes(offset=7)],
    ids=["encrypted", "unknown compression", "bad offset"],
)
def test_a_broken_kmz_is_exit_2_not_a_bug(tmp_path, data):
    (tmp_path / "site.kmz").write_bytes(data)
    code, _, err = run_cli("plan", str(tmp_path / "site.kmz"), "--out", str(tmp_path / "p"), "-q")
    assert code == 2 and "site.kmz" in err and "Traceback" not in err, err


def test_a_path_gdal_would_read_as_another_file_is_refused(tmp_path):
    """pyogrio reads ``x!y.gpkg`` as ``y.gpkg`` in the working folder (and ``a.zip!b`` as a
    zip's member): the file checked would not be the file read."""
    import pyogrio.raw

    folder = tmp_path / "xy"
    folder.mkdir()
    geom = np.array([shapely.to_wkb(box(X0, Y0, X0 + 20, Y0 + 15))], dtype=object)
    pyogrio.raw.write(
        folder / "site.gpkg", geom, [np.array([9.0])], fields=["height"],
        geometry_type="Polygon", crs="EPSG:25832", driver="GPKG", layer="buildings",
    )  # fmt: skip
    assert [b.id for b in planner.read_site(folder / "site.gpkg").buildings] == ["0"]
    folder.rename(tmp_path / "x!y")
    with pytest.raises(InputError, match="GDAL would read the path"):
        planner.read_site(tmp_path / "x!y" / "site.gpkg")


def test_proj_fetches_no_grid_even_when_the_environment_asks(monkeypatch):
    import pyproj

    from planner import crs

    monkeypatch.setenv("PROJ_NETWORK", "ON")
    pyproj.network.set_network_enabled(active=True)
    crs._crs.cache_clear()
    crs.name_of("EPSG:25832")
    assert not pyproj.network.is_network_enabled()


# -- 2. nothing dropped silently -------------------------------------------------------------
def _shapefile(tmp_path: Path, n: int = 2) -> Path:
    import pyogrio.raw

    path = tmp_path / "site.shp"
    geoms = np.array(
        [shapely.to_wkb(box(X0 + 40 * k, Y0, X0 + 40 * k + 20, Y0 + 15)) for k in range(n)],
        dtype=object,
    )
    pyogrio.raw.write(
        path, geoms, [np.array([9.0] * n), np.array([f"b{k}" for k in range(n)], dtype=object)],
        fields=["height", "id"], geometry_type="Polygon", crs="EPSG:25832",
        driver="ESRI Shapefile",
    )  # fmt: skip
    return path


def test_a_shapefile_whose_dbf_lost_a_record_is_refused(tmp_path):
    path = _shapefile(tmp_path)
    assert [b.id for b in planner.read_site(path).buildings] == ["b0", "b1"]  # intact: both
    dbf = path.with_suffix(".dbf")
    data = bytearray(dbf.read_bytes())
    header, record = struct.unpack("<HH", data[8:12])
    data[4:8] = struct.pack("<I", 1)  # one record, as the hostile file had
    dbf.write_bytes(bytes(data[: header + record]) + b"\x1a")
    with pytest.raises(InputError, match=r"indexes 2 shape\(s\) but its \.dbf holds 1 record"):
        planner.read_site(path)


@settings(
    max_examples=12, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
@given(shapes=st.integers(1, 4), records=st.integers(0, 5))
def test_a_shapefile_is_read_whole_or_refused(tmp_path_factory, shapes, records):
    """However many records the .dbf claims, the shapes are all read (the counts agree) or
    the file is refused: never a building dropped without a word."""
    path = _shapefile(tmp_path_factory.mktemp("shp"), shapes)
    dbf = path.with_suffix(".dbf")
    data = bytearray(dbf.read_bytes())
    header, record = struct.unpack("<HH", data[8:12])
    body = bytes(data[header : header + record * shapes])
    data[4:8] = struct.pack("<I", records)
    rows = (body * 2)[: record * records]  # as many records as it claims
    dbf.write_bytes(bytes(data[:header]) + rows + b"\x1a")
    if records == shapes:
        assert len(planner.read_site(path).buildings) == shapes
    else:
        with pytest.raises(InputError, match=f"indexes {shapes} shape"):
            planner.read_site(path)


def test_every_kml_of_a_kmz_is_pinned(tmp_path, sentinel):
    """GDAL's LIBKML reads every KML of a KMZ (its own KMZ: doc.kml linking layers/*.kml),
    so each one must be KML: a virtual dataset as the second is refused."""
    path = tmp_path / "site.kmz"
    kml = '<kml xmlns="http://www.opengis.net/kml/2.2"><Document/></kml>'
    with zipfile.ZipFile(path, "w") as zf:
        zf.writestr("doc.kml", kml)
        zf.writestr("layers/b.kml", _vrt(f"/vsicurl/{sentinel.url}/x.geojson"))
    with pytest.raises(InputError, match=r"site.kmz:layers/b.kml is not a KML file"):
        planner.read_site(path)


# -- 3. bad numbers are exit 2, never 3 ------------------------------------------------------
SCANNER = (
    'name = "x"\nrange_rms_mm = 1\nrange_ppm = 10\nangle_rms_arcsec = 5\n'
    "step_mm_at_10m = 3\nmax_range_m = 100\n"
)


@pytest.mark.parametrize(
    ("args", "files", "message"),
    [
        (
            ["--scanner", "{tmp}/deep.toml"],
            {"deep.toml": 'name="d"\nx = ' + "[" * 50000 + "]" * 50000},
            "nests its arrays or tables too deeply",
        ),
        (
            ["--scanner", "{tmp}/tiny.toml"],
            {"tiny.toml": SCANNER.replace("range_rms_mm = 1", "range_rms_mm = 1e-300")},
            "range_rms_mm must be >= 0.01",
        ),
        (
            ["--scanner", "{tmp}/slow.toml"],
            {"slow.toml": SCANNER + "measurement_rate_hz = 1e-300\n"},
            "measurement_rate_hz must be >= 100",
        ),
        (["--scan-rate-hz", "1e-300"], {}, "scan_rate_hz must be >= 100"),
        (["--max-xy-mm", "1e308"], {}, "max_xy_mm must be >= 0.01 and <= 1000 [mm]"),
        (["--zone", "building=main,max_xy_mm=1e308"], {}, "zone 'zone1': max_xy_mm must be"),
        (
            ["--zones", "{tmp}/z.csv"],
            {"z.csv": "id,building_id,max_z_mm\nz1,main,1e308\n"},
            "max_z_mm must be",
        ),
        (["--time-limit-s", "1e308"], {}, "time_limit_s must be > 0 and <= 604800"),
        (["--block-m", "0"], {}, "argument --block-m: must be >= 20"),
        (["--block-m", "nan"], {}, "argument --block-m: must be >= 20"),
        (["--workers", "0"], {}, "argument --workers: must be a whole number >= 1"),
        (["--height", "1e308"], {}, "argument --height: must be > 0 and <= 1000 [m]"),
        (["--mesh-offset", "1e308,0,0"], {}, "argument --mesh-offset"),
        (["--mesh-offset", "1,2,3"], {}, "--mesh-offset moves the mesh of --mesh"),
        (["--worker-memory", "lots"], {}, "worker memory 'lots' is not a size"),
        (
            ["--inventory", "{tmp}/inv.txt"],
            {"inv.txt": "big, sphere, 1e308\n"},
            "size_mm must be >= 1 and <= 2000 [mm]",
        ),
        (
            ["--control", "{tmp}/c.csv"],
            {"c.csv": "id,x,y,z,rms_mm\nA,691005,5334990,1,1e-300\n"},
            "rms_mm must be >= 0.01",
        ),
    ],
)
def test_a_number_out_of_its_range_is_exit_2_naming_it(tmp_path, args, files, message):
    for name, text in files.items():
        (tmp_path / name).write_text(text)
    argv = [a.replace("{tmp}", str(tmp_path)) for a in args]
    code, _, err = run_cli("plan", *argv, "--out", str(tmp_path / "p"), "-q")
    assert code == 2 and message in err, err
    assert "Traceback" not in err and not (tmp_path / "p").exists()


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["serve", "--port", "1" + "0" * 400], "argument --port: must be a whole number >= 1"),
        (["serve", "--port", "70000"], "argument --port: must be a whole number >= 1 and <= 65535"),
        (["serve", "--kernel-idle-s", "nan"], "argument --kernel-idle-s: must be >= 1"),
        (["accuracy", "--distances", "1e308"], "argument --distances: must be > 0 and <= 10000"),
    ],
)
def test_other_commands_check_their_numbers(args, message):
    code, _, err = run_cli(*args)
    assert code == 2 and message in err, err


def _outside(rng: Range):
    """Values a quantity cannot take: NaN, ±inf, below its range, above it."""
    outs = [st.sampled_from([float("nan"), float("inf"), float("-inf")])]
    if rng.lo is not None:
        hi = rng.lo if rng.open_lo else np.nextafter(rng.lo, -np.inf)
        outs.append(st.floats(max_value=hi, allow_nan=False, allow_infinity=False))
    if rng.hi is not None:
        outs.append(
            st.floats(min_value=rng.hi, exclude_min=True, allow_nan=False, allow_infinity=False)
        )
    return st.one_of(outs)


_SPECS = [(cls, name) for cls in (Requirements, PlanSettings) for name in field_specs(cls)]


@PROPERTY
@given(data=st.data(), which=st.sampled_from(_SPECS))
def test_every_requirement_and_setting_refuses_what_it_cannot_be(data, which):
    cls, name = which
    spec = field_specs(cls)[name]
    value = data.draw(_outside(spec.range))
    with pytest.raises(InputError, match=name):
        cls(**{name: value})


@PROPERTY
@given(data=st.data(), name=st.sampled_from(sorted(RANGES)))
def test_every_ranged_number_is_refused_outside_and_kept_inside(data, name):
    rng = RANGES[name]
    with pytest.raises(InputError, match=r"must be"):
        check_number(data.draw(_outside(rng)), name, rng)
    lo = rng.lo if rng.lo is not None else -1e6
    hi = rng.hi if rng.hi is not None else 1e6
    inside = data.draw(st.floats(lo, hi, exclude_min=rng.open_lo))
    if rng.integer:
        inside = int(np.clip(round(inside), np.ceil(lo), hi))
    assert check_number(inside, name, rng) == inside


@PROPERTY
@given(
    value=st.sampled_from(["1e-300", "1e308", "-1e308", "nan", "inf", "-0", "1e-9"]),
    flag=st.sampled_from(
        [s.flag for cls in (Requirements, PlanSettings) for s in field_specs(cls).values()]
    ),
)
def test_the_command_line_never_ends_in_a_bug_on_extreme_numbers(tmp_path, value, flag):
    """Any extreme number for any requirement or setting: refused (2) or, where it is in
    range, planned — never 3. Only the refusals are run (a plan in range takes seconds)."""
    name = flag[2:].replace("-", "_")
    spec = next(
        s for cls in (Requirements, PlanSettings) for n, s in field_specs(cls).items() if n == name
    )
    try:
        check_number(float(value), name, spec.range)
        return  # in range: not a hostile number
    except InputError:
        pass
    code, _, err = run_cli("plan", flag, value, "--out", str(tmp_path / "p"), "-q")
    assert code == 2 and "Traceback" not in err, err
    assert not (tmp_path / "p").exists()


# -- 4. --scheduler fails fast and clearly ---------------------------------------------------
@pytest.mark.parametrize(
    ("address", "message"),
    [
        ("inproc://x", "uses 'inproc://'"),
        ("ucx://127.0.0.1:1", "uses 'ucx://'"),
        ("file:///etc/passwd", "uses 'file://'"),
        ("127.0.0.1:8786", "is SCHEME://HOST:PORT"),
        ("tcp://", "needs a host"),
        ("tcp://10.0.0.5", "needs a host"),
        ("tcp://" + "a" * 5000 + ":1", "at most 253 characters"),
        ("tcp://10.0.0.5:99999", "malformed"),
        ("tcp://10.0.0.5:8786/path?q=1", "more than SCHEME://HOST:PORT"),
    ],
)
def test_a_malformed_scheduler_address_is_exit_2_before_any_work(tmp_path, address, message):
    code, _, err = run_cli("plan", "--scheduler", address, "--out", str(tmp_path / "p"))
    assert code == 2 and message in err, err


@pytest.fixture()
def quick_connect(monkeypatch):
    """The scheduler's connection deadline at 3 s (1 s for Dask, three times over)."""
    from planner.pipeline.district import schedule

    monkeypatch.setattr(schedule, "SCHEDULER_TIMEOUT_S", 1.0)


def _peer(kind: str) -> tuple[socket.socket, int]:
    """A loopback peer that accepts and never answers (``silent``) or answers HTTP."""
    sock = socket.socket()
    sock.bind(("127.0.0.1", 0))
    sock.listen(8)
    held = []

    def serve() -> None:
        while True:
            try:
                conn, _ = sock.accept()
            except OSError:
                return
            held.append(conn)
            if kind == "http":
                conn.sendall(b"HTTP/1.1 200 OK\r\nContent-Length: 2\r\n\r\nhi")

    threading.Thread(target=serve, daemon=True).start()
    return sock, sock.getsockname()[1]


@pytest.mark.parametrize(
    ("kind", "message"),
    [("silent", "nothing answered as a Dask scheduler"), ("http", "as a Dask scheduler (")],
)
def test_a_peer_that_is_no_scheduler_is_exit_2_within_the_deadline(
    tmp_path, quick_connect, kind, message
):
    sock, port = _peer(kind)
    try:
        t = time.monotonic()
        code, _, err = run_cli(
            "plan", "--scheduler", f"tcp://127.0.0.1:{port}", "--out", str(tmp_path / "p"), "-q"
        )
        took = time.monotonic() - t
    finally:
        sock.close()
    assert code == 2 and message in err, err
    assert took < 15.0  # s: 3 s of deadline here, plus the command's start (promised: 45 s)


_ADDRESSES = st.builds(
    lambda scheme, user, host, port, tail: f"{scheme}://{user}{host}{port}{tail}",
    st.sampled_from(["tcp", "TCP", "tls", "ws", "wss", "inproc", "ucx", "file", "", "tcp:"]),
    st.sampled_from(["", "u:pw@", ":pw@", "@"]),
    st.one_of(st.text(max_size=30), st.sampled_from(["10.0.0.5", "[::1]", "host", "a" * 300])),
    st.one_of(
        st.just(""), st.builds(lambda p: f":{p}", st.integers(-5, 70000)), st.text(max_size=6)
    ),
    st.sampled_from(["", "/", "/x", "?q=1", "#f"]),
)


@PROPERTY
@given(text=st.one_of(_ADDRESSES, st.text(max_size=300)))
def test_any_scheduler_text_is_an_address_or_input_error(text):
    """A text is accepted only as SCHEME://HOST:PORT of Dask's network schemes, nothing
    more; anything else is an InputError (never another exception)."""
    from urllib.parse import urlsplit

    from planner.pipeline.district.schedule import SCHEDULER_SCHEMES, scheduler_address

    try:
        assert scheduler_address(text) == text
    except InputError:
        return
    parts = urlsplit(text)
    assert text.split("://")[0] in SCHEDULER_SCHEMES and parts.hostname and 1 <= parts.port <= 65535
    assert "@" not in parts.netloc and not parts.path.strip("/") and not parts.query


# -- 5. units ------------------------------------------------------------------------------
@pytest.mark.parametrize("crs", ["EPSG:2263", "EPSG:6539", "EPSG:2227"])
def test_a_crs_in_feet_is_refused_naming_the_unit_and_a_crs_in_metres(tmp_path, crs):
    from planner import crs as crs_

    x, y = crs_.wgs84_to(crs)(
        np.array([-74.0 if crs != "EPSG:2227" else -122.3]),
        np.array([40.7 if crs != "EPSG:2227" else 37.8]),
    )
    doc = json.loads(_site(crs=crs))
    ring = [
        [float(x[0]) + dx, float(y[0]) + dy]
        for dx, dy in ((0, 0), (40, 0), (40, 30), (0, 30), (0, 0))
    ]
    doc["features"][0]["geometry"] = {"type": "Polygon", "coordinates": [ring]}
    path = tmp_path / "feet.geojson"
    path.write_text(json.dumps(doc))
    with pytest.raises(
        InputError,
        match=r"measures in US survey foot .*to a CRS in metres, e\.g\. EPSG:326",
    ):
        planner.read_site(path)


def _projected_codes():
    import pyproj

    infos = pyproj.database.query_crs_info(auth_name="EPSG", pj_types=["PROJECTED_CRS"])
    return sorted(f"EPSG:{i.code}" for i in infos if not i.deprecated)


@PROPERTY
@given(code=st.sampled_from(_projected_codes()))
def test_a_projected_crs_is_taken_only_in_metres(code):
    """Any projected EPSG CRS: one whose axes are not in metres (feet, US survey feet,
    chains, links …) is refused naming its unit; one in metres is not refused for its unit."""
    import pyproj

    from planner import crs as crs_

    try:
        info = pyproj.CRS.from_user_input(code)
    except pyproj.exceptions.CRSError:
        return
    factors = [a.unit_conversion_factor for a in info.axis_info[:2]]
    metric = all(abs(f - 1.0) <= 1e-12 for f in factors)
    try:
        crs_.check_projected(code, np.empty((0, 2)))
    except InputError as exc:
        assert not metric or "measures in" not in str(exc), str(exc)
        if not metric:
            assert "measures in" in str(exc) and "the planner works in metres" in str(exc)
        return
    assert metric, code


def test_a_crs_in_metres_passes(tmp_path):
    path = tmp_path / "m.geojson"
    path.write_text(_site())
    assert planner.read_site(path).crs == "EPSG:25832"


# -- 6. user strings never become live content -----------------------------------------------
HOSTILE_ID = "A\x1b[31mRED\x0bV\x00N\u202eX\x7f"


def test_control_characters_in_ids_reach_no_file_and_no_terminal(tmp_path):
    site = tmp_path / "esc.geojson"
    site.write_text(_site(ids=[HOSTILE_ID]))
    out = tmp_path / "p"
    code, stdout, err = run_cli("plan", str(site), "--out", str(out), *FAST[:-1])
    assert code in (0, 1), err
    shown = printable(HOSTILE_ID)
    assert shown == "A\\x1b[31mRED\\x0bV\\x00N\\u202eX\\x7f"
    for text in (stdout, err, *(p.read_text() for p in out.iterdir())):
        assert not any(c in text for c in "\x1b\x0b\x00\u202e\x7f")
    ET.parse(out / "plan.kml")  # valid XML: Google Earth opens it
    assert shown in (out / "facades.csv").read_text() and shown in (out / "plan.kml").read_text()
    features = json.loads((out / "plan.geojson").read_text())["features"]
    assert any(f["properties"].get("building_id") == shown for f in features)  # one id everywhere


def test_a_zone_on_a_building_whose_id_holds_a_control_character_still_finds_it():
    from planner.site import Building, Site
    from planner.zones import Zone

    site = Site(
        [Building("B\x01", box(X0, Y0, X0 + 20, Y0 + 15), 9.0)],
        zones=[Zone(id="z", building_id="B\x01", requirement={"max_xy_mm": 3.0})],
        crs="EPSG:25832",
    )
    assert site.buildings[0].id == site.zones[0].building_id == "B\\x01"


def test_a_site_file_named_in_bytes_that_are_not_utf8_plans(tmp_path):
    import os

    name = os.fsdecode(b"site\xff.geojson")
    (tmp_path / name).write_text(_site())
    code, _, err = run_cli("plan", str(tmp_path / name), "--out", str(tmp_path / "p"), *FAST)
    assert code in (0, 1) and "Traceback" not in err, err
    assert (tmp_path / "p" / "summary.txt").exists()
    assert "\\xff" in (tmp_path / "p" / "summary.txt").read_text()  # the name, its byte shown


@given(text=st.text(alphabet=st.characters(), max_size=60))
def test_printable_leaves_no_control_character_and_keeps_safe_text(text):
    shown = printable(text)
    assert not any(
        ord(c) < 32 or 0x7F <= ord(c) <= 0x9F or 0x202A <= ord(c) <= 0x202E
        or 0x2066 <= ord(c) <= 0x2069 or 0xD800 <= ord(c) <= 0xDFFF
        for c in shown
    )  # fmt: skip
    assert printable(shown) == shown  # shown once, it is safe: nothing more to escape
    shown.encode("utf-8")  # always writable as UTF-8


# -- 7. --out never loses or leaves anything -------------------------------------------------
def test_an_input_inside_out_where_the_plan_writes_is_refused_and_kept(tmp_path):
    out = tmp_path / "p"
    out.mkdir()
    zones = out / "zones.csv"
    zones.write_text("id,building_id,max_xy_mm\nz1,main,4\n")
    code, _, err = run_cli("plan", "--zones", str(zones), "--out", str(out), "-q")
    assert code == 2 and "is where the output zones.csv is written" in err, err
    assert zones.read_text() == "id,building_id,max_xy_mm\nz1,main,4\n"
    assert sorted(p.name for p in out.iterdir()) == ["zones.csv"]
    mine = out / "my-zones.csv"  # negative control: an input of another name is carried over
    zones.rename(mine)
    code, _, err = run_cli("plan", "--zones", str(mine), "--out", str(out), *FAST)
    assert code in (0, 1), err
    assert mine.read_text() == "id,building_id,max_xy_mm\nz1,main,4\n"


def test_an_audit_or_a_profile_written_over_its_input_is_refused(tmp_path):
    from planner.synthetic3d import lod2_town, write_model

    model = write_model(lod2_town(1), tmp_path / "town.city.json")
    kept = model.read_bytes()
    code, _, err = run_cli("audit", str(model), "--plan", str(tmp_path), "--out", str(model))
    assert code == 2 and "would be lost" in err and model.read_bytes() == kept, err
    ref = tmp_path / "ref.csv"
    ref.write_text("id,x,y,z\n")
    code, _, err = run_cli("calibrate", "lab", str(ref), str(ref), "--profile-out", str(ref))
    assert code == 2 and "would be lost" in err and ref.read_text() == "id,x,y,z\n", err


@PROPERTY
@given(
    name=st.sampled_from(sorted(OWNED_FILES)),
    other=st.text(alphabet="abcdefghijklmnopqrstuvwxyz-_.", min_size=1, max_size=12),
)
def test_no_output_is_written_over_an_input(tmp_path_factory, name, other):
    """An input at the name of any file a plan writes, in the plan's folder, is refused; at
    any other name there, it is left alone (carried over as the user's own)."""
    from planner.atomic import check_inputs_kept

    out = tmp_path_factory.mktemp("out")
    outputs = [out / n for n in OWNED_FILES]
    with pytest.raises(InputError, match="would be lost"):
        check_inputs_kept(outputs, [str(out / name)])
    if other not in OWNED_FILES and other not in (".", ".."):
        check_inputs_kept(outputs, [str(out / other), str(out.parent / name)])


def test_a_dangling_link_as_out_is_refused_and_its_target_not_made(tmp_path):
    link = tmp_path / "out"
    link.symlink_to(tmp_path / "nowhere" / "deep")
    code, _, err = run_cli("plan", "--out", str(link), "-q")
    assert code == 2 and "is a symbolic link to" in err and "does not exist" in err, err
    assert not (tmp_path / "nowhere").exists()
    code, _, err = run_cli("plan", "--out", str(link / "sub"), "-q")  # a link on the way
    assert code == 2 and not (tmp_path / "nowhere").exists(), err


def test_out_that_is_a_mount_point_is_refused_before_the_plan(tmp_path, monkeypatch):
    import os

    out = tmp_path / "usb"
    out.mkdir()
    real = os.path.ismount
    monkeypatch.setattr(os.path, "ismount", lambda p: str(p) == str(out) or real(p))
    code, _, err = run_cli("plan", "--out", str(out), "-q")
    assert code == 2 and "is a mount point; a plan replaces its folder" in err, err


def test_a_mount_point_inside_out_is_refused_before_the_plan(tmp_path, monkeypatch):
    import os

    out = tmp_path / "p"
    (out / "usb").mkdir(parents=True)
    real = os.path.ismount
    monkeypatch.setattr(os.path, "ismount", lambda p: str(p).endswith("usb") or real(p))
    code, _, err = run_cli("plan", "--out", str(out), "-q")
    assert code == 2 and "is a mount point inside the output folder" in err, err
    assert sorted(p.name for p in out.iterdir()) == ["usb"]


# -- 8. budgets: what makes them hold --------------------------------------------------------
def test_a_dense_outline_is_thinned_and_noted():
    """A 100 × 60 m building drawn with 20 000 vertices (its edges 16 mm) plans as four
    facades, and the thinning is in site_repairs.csv; a negative control of 4 000 vertices
    (under the limit) keeps them."""
    from planner.pipeline.geometry.facades import build_facades
    from planner.site import Building, Site

    def dense(n: int) -> shapely.Polygon:
        corners = np.array([[0, 0], [100, 0], [100, 60], [0, 60]]) + np.array([X0, Y0])
        return shapely.Polygon(densified(corners, n // 4))

    site = Site([Building("dense", dense(20_000), 12.0)], crs="EPSG:25832")
    assert len(site.buildings[0].footprint.exterior.coords) == 5
    assert [(n.kind, n.action) for n in site.notes] == [("outline", "thinned")]
    assert len(build_facades(site, 4.0, 4.0).length_m) == 4
    kept = Site([Building("kept", dense(4_000), 12.0)], crs="EPSG:25832")
    assert len(kept.buildings[0].footprint.exterior.coords) == 4_001 and not kept.notes


def _zone_by_zone(zones, reqs, members, site_req, n):
    """The zones applied one by one, in order, as before this round (the reference)."""
    from planner.pipeline.geometry.zoning import SampleRequirements
    from planner.pipeline.inputs.requirements import CHECKS

    out = SampleRequirements.uniform(site_req, n)
    covered = np.zeros(n, dtype=bool)
    for z, zr, idx in zip(zones, reqs, members, strict=True):
        mask = np.zeros(n, dtype=bool)
        mask[idx] = True
        for c in CHECKS:
            limit = c.limit_of(zr)
            value = c.no_limit() if limit is None else float(limit)
            own = out.limits[c.key]
            own[mask & ~covered] = value
            again = mask & covered
            own[again] = (
                np.minimum(own[again], value) if c.sense == "max" else np.maximum(own[again], value)
            )
        out.stations[mask & ~covered] = zr.stations_per_sample
        out.stations[mask & covered] = np.maximum(
            out.stations[mask & covered], zr.stations_per_sample
        )
        out.zone_ids[mask] = [f"{v};{z.id}" if v else z.id for v in out.zone_ids[mask]]
        covered |= mask
    return out


@pytest.mark.parametrize("distinct", [2, 400])
def test_many_zones_are_applied_as_zone_by_zone(default_plan, distinct):
    """1 200 overlapping zones over parts of the default site's facades (along and in
    height), of 2 or 400 distinct requirements (limits, a minimum range, stations per
    sample): every sample's limits, stations and zone ids are exactly those of applying them
    one by one, as before; one Requirements per distinct requirement."""
    from dataclasses import replace

    from planner.pipeline.geometry.facades import build_facades
    from planner.pipeline.geometry.zoning import apply_zones
    from planner.zones import Zone

    rng = np.random.default_rng(7)
    fac = default_plan.facades
    zones = []
    for k in range(1200):
        f = int(rng.integers(len(fac)))
        length, height = float(fac["length_m"].iloc[f]), float(fac["height_m"].iloc[f])
        u0 = float(rng.uniform(0, length / 2))
        h0 = float(rng.uniform(0, height / 2))
        kind = k % distinct
        zones.append(
            Zone(
                id=f"z{k}",
                facade_id=str(fac["facade_id"].iloc[f]),
                along_m=(u0, min(length, u0 + length / 2)),
                height_m=(h0, min(height, h0 + height / 2)),
                requirement={
                    "max_xy_mm": 2.0 + 0.01 * kind,
                    "max_z_mm": 3.0 + (kind % 3),
                    "min_range_m": 1.0 + (kind % 4),
                    "stations_per_sample": 1 + kind % 2,
                },
            )
        )
    site = replace(default_plan.site, zones=zones)
    f = build_facades(site, 2.0, 2.0)
    site_req = Requirements()
    _, got, table = apply_zones(site, f, site_req)
    assert len({id(r) for r in table.requirements}) == distinct
    want = _zone_by_zone(table.zones, table.requirements, table.members, site_req, len(f.z))
    for key, limits in want.limits.items():
        np.testing.assert_array_equal(got.limits[key], limits, err_msg=key)
    np.testing.assert_array_equal(got.stations, want.stations)
    assert got.zone_ids.tolist() == want.zone_ids.tolist()
    # the members are the samples inside each zone's ranges (checked independently)
    u = np.hypot(*(f.xy - f.start[f.facade]).T)
    h = f.z - f.base_z[f.facade]
    for z, idx in list(zip(table.zones, table.members, strict=True))[:50]:
        fi = int(np.flatnonzero(f.facade_id == z.facade_id)[0])
        inside = (f.facade == fi) & (u >= z.along_m[0] - 1e-6) & (u <= z.along_m[1] + 1e-6)
        inside &= (h >= z.height_m[0] - 1e-6) & (h <= z.height_m[1] + 1e-6)
        assert np.flatnonzero(inside).tolist() == idx.tolist()


def test_the_summary_lists_twenty_zones_of_many(tmp_path):
    rows = ["id,building_id,max_xy_mm"] + [f"z{k},main,{4 + k % 3}" for k in range(30)]
    (tmp_path / "z.csv").write_text("\n".join(rows) + "\n")
    code, out, err = run_cli(
        "plan", "--zones", str(tmp_path / "z.csv"), "--out", str(tmp_path / "p"), *FAST[:-1]
    )
    assert code in (0, 1), err
    assert "Zones: 30," in out and "the 20 with the most unmet samples below" in out
    assert sum(line.startswith("Zone z") for line in out.splitlines()) == 20


# -- 9. planner serve ---------------------------------------------------------------------
@PROPERTY
@given(rest=st.text(max_size=40), quoted=st.booleans())
def test_a_template_path_passes_only_as_template_static_file(rest, quoted):
    """Any path under Voilà's template prefix passes to its handler only in the form the
    handler answers (``<template>/static/<file>`` without ``..``, empty segments or control
    characters, percent-encoded or not): anything else is a 404, never the handler's 500."""
    from urllib.parse import quote, unquote

    from planner.app.voila_server import TEMPLATE_PREFIX, is_template_file

    path = TEMPLATE_PREFIX + (quote(rest, safe="") if quoted else rest)
    ok = is_template_file(path)
    parts = unquote(path[len(TEMPLATE_PREFIX) :]).replace("\\", "/").split("/")
    if ok:
        assert len(parts) >= 3 and parts[1] == "static"
        assert ".." not in parts and "" not in parts
    assert is_template_file("/voila/static/x.js")  # other paths are Voilà's to answer


def test_a_far_dense_outline_that_needs_repair_is_thinned_once_repaired():
    """A far, not planned neighbour drawn as a self-crossing bow-tie of 20 000 vertices:
    repaired (make_valid, as far outlines are) and then thinned — else it stays dense and
    every sight line pays for its edges."""
    from planner.site import Building, Site

    corners = np.array([[0, 0], [100, 0], [0, 60], [100, 60]])  # its sides cross
    ring = densified(corners + np.array([X0 + 5000, Y0]), 5000)
    bowtie = shapely.Polygon(ring)
    assert not bowtie.is_valid
    site = Site(
        [
            Building("main", box(X0, Y0, X0 + 20, Y0 + 15), 9.0),
            Building("far", bowtie, 9.0, planned=False),
        ],
        crs="EPSG:25832",
        near_m=100.0,
    )
    far = next(b for b in site.buildings if b.id == "far")
    assert shapely.get_num_coordinates(far.footprint) < 20
    assert {(n.kind, n.action) for n in site.notes} == {("outline", "far"), ("outline", "thinned")}
