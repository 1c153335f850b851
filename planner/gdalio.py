"""GDAL (through ``pyogrio``) opened so that it reads the user's file and nothing else.

GDAL picks a driver by a file's *content*, not its name: a ``.gpkg`` that is really an OGR
virtual dataset (VRT) makes GDAL fetch a URL (``/vsicurl/``), query a WFS server or read a
local system file, and GML content makes it write a ``.gfs`` file beside the input. So:

1. **Each extension is pinned to its format.** Before GDAL sees the file, its bytes must be
   that format's: a GeoPackage is an SQLite database with the GeoPackage application id
   (OGC 12-128r18, GeoPackage Encoding Standard 1.3, §1.1.1.1.1); a shapefile's ``.shp``
   starts with the file code 9994 and has its ``.shx`` and ``.dbf`` beside it, their record
   counts equal (ESRI Shapefile Technical Description, 1998); a KML file is XML whose root
   is ``kml`` (OGC 12-007r2, KML 2.3) without a document type declaration; a KMZ is a zip
   archive whose KML and other XML members are all such KML. Its path must name that file
   to GDAL too (pyogrio reads ``a.zip!b.gpkg`` as a zip's member, ``http:/…`` as a URL).
   After opening, the driver GDAL chose must be the pinned one.
2. **Nothing else is reachable.** The drivers that reach the network, run programs or open
   other datasets are not registered (``GDAL_SKIP``, set before GDAL loads), ``/vsicurl/``
   may open no file (``CPL_VSIL_CURL_ALLOWED_FILENAME``), and GDAL writes no side-car file
   (``GDAL_PAM_ENABLED=NO``; a GeoPackage is opened immutable, so SQLite writes no journal).

The configuration options are GDAL's own (https://gdal.org/en/stable/user/configoptions.html,
https://gdal.org/en/stable/user/security.html).
"""

from __future__ import annotations

import os
import struct
import sys
import zipfile
import zlib
from pathlib import Path
from typing import Any

from planner.errors import InputError

__all__ = ["PINNED_DRIVERS", "check_signature", "layers", "pyogrio", "read_layer"]

#: The GDAL driver(s) each GIS format is read by.
PINNED_DRIVERS = {
    "GeoPackage": ("GPKG",),
    "Shapefile": ("ESRI Shapefile",),
    "KML": ("LIBKML", "KML"),
    "KMZ": ("LIBKML", "KML"),
}
#: Drivers left unregistered: they fetch from the network, run other programs, or open other
#: datasets named inside a file (GDAL's security notes). Only matters if this module loads
#: GDAL first; the pin (1.) holds either way.
SKIPPED_DRIVERS = (
    "OGR_VRT", "VRT", "GDALG", "WFS", "OAPIF", "OGCAPI", "CSW", "HTTP", "NGW", "Carto",
    "AmigoCloud", "Elasticsearch", "EEDA", "PLSCENES", "GPSBabel", "ADBC", "WMS", "WCS",
    "GML", "SQLite",
)  # fmt: skip
#: Set once GDAL is loaded, for every read.
CONFIG = {
    "CPL_VSIL_CURL_ALLOWED_FILENAME": "/tls-planner/opens-no-url",
    "GDAL_HTTP_TIMEOUT": "1",
    "GDAL_HTTP_MAX_RETRY": "0",
    "GDAL_PAM_ENABLED": "NO",
    "GML_SAVE_RESOLVED_TO": "",
    "OGR_SQLITE_JOURNAL": "OFF",
    "OGR_SQLITE_ALLOW_EXTERNAL_ACCESS": "NO",  # a GeoPackage's SQL opens no other dataset
}
_SQLITE = b"SQLite format 3\x00"
_GPKG_IDS = (b"GPKG", b"GP10", b"GP11")
_SHP_CODE = 9994
_XML_HEAD = 64 * 1024


def pyogrio() -> Any:
    """The ``pyogrio`` module, GDAL configured as this module says (imported on first use:
    GDAL is heavy)."""
    if "pyogrio" not in sys.modules:
        skip = [s for s in os.environ.get("GDAL_SKIP", "").split(",") if s]
        os.environ["GDAL_SKIP"] = ",".join(dict.fromkeys([*skip, *SKIPPED_DRIVERS]))
    import pyogrio as module

    module.set_gdal_config_options(CONFIG)
    return module


def check_signature(p: Path, kind: str) -> None:
    """Refuse ``p`` unless its bytes are ``kind``'s format (see the module's text)."""
    with p.open("rb") as fh:
        head = fh.read(_XML_HEAD)
    if kind == "GeoPackage":
        if not head.startswith(_SQLITE):
            _refuse(p, kind, _looks_like(head))
        if head[68:72] not in _GPKG_IDS:
            _refuse(p, kind, "an SQLite database without the GeoPackage application id")
    elif kind == "Shapefile":
        _check_shapefile(p, head)
    elif kind == "KML":
        _check_kml(head, p.name)
    elif kind == "KMZ":
        _check_kmz(p)
    else:
        raise ValueError(f"no GDAL format {kind!r}")


def layers(p: Path, kind: str) -> list[str]:
    """The names of ``p``'s layers, opened by ``kind``'s pinned driver only."""
    og = pyogrio()
    from pyogrio.errors import DataLayerError, DataSourceError

    check_signature(p, kind)
    _check_plain_path(og, p)
    try:
        names = [str(name) for name, _ in og.list_layers(p)]
        driver = og.read_info(p, layer=names[0], **_open_options(kind))["driver"] if names else ""
    except (DataSourceError, DataLayerError) as exc:
        hint = (
            "; a shapefile is several files side by side (.shp, .shx, .dbf and .prj for its "
            "CRS): copy them all"
            if kind == "Shapefile"
            else f"; export it again as {kind}"
        )
        raise InputError(f"{p.name}: cannot open it as {kind} ({_first_line(exc)}){hint}") from None
    if names and driver not in PINNED_DRIVERS[kind]:
        _refuse(p, kind, f"a file GDAL reads as {driver}")
    return names


def read_layer(p: Path, kind: str, layer: str) -> tuple[dict, Any, Any, Any]:
    """``pyogrio.raw.read`` of one layer by ``kind``'s pinned driver: (meta, fids, wkb,
    field values)."""
    og = pyogrio()
    from pyogrio.errors import DataLayerError, DataSourceError

    try:
        return og.raw.read(p, layer=layer, **_open_options(kind))
    except (DataSourceError, DataLayerError) as exc:
        raise InputError(f"{p.name}: cannot read layer {layer!r} ({_first_line(exc)})") from None


def _check_plain_path(og: Any, p: Path) -> None:
    """Refuse a path that GDAL would read as another file: pyogrio turns ``a.zip!b.gpkg``
    into a member of a zip, ``x!y.gpkg`` into ``y.gpkg``, ``http:/…`` into a URL."""
    text = str(p)
    if og.util.vsi_path(text) != text or text.startswith("/vsi"):
        raise InputError(
            f"{p.name}: GDAL would read the path {text!r} as another file (a '!' or a "
            "'scheme:/' in it); rename the file or its folder"
        )


def _open_options(kind: str) -> dict[str, str]:
    # immutable: SQLite neither locks nor writes a -wal/-shm file beside the input
    return {"IMMUTABLE": "YES"} if kind == "GeoPackage" else {}


def _first_line(exc: BaseException) -> str:
    return (str(exc).splitlines() or [type(exc).__name__])[0][:200]


def _refuse(p: Path, kind: str, found: str) -> None:
    raise InputError(
        f"{p.name} has the extension {p.suffix} but is not a {kind} (it is {found}); "
        f"export the site again as {kind}, or give the file its own extension"
    )


def _looks_like(head: bytes) -> str:
    """What a file's first bytes say it is, in words, for a refusal."""
    text = head.lstrip(b"\xef\xbb\xbf \t\r\n")[:200].lower()
    if head.startswith(_SQLITE):
        return "an SQLite database"
    if head.startswith(b"PK\x03\x04"):
        return "a zip archive"
    if text.startswith(b"<"):
        return "an XML document"
    if text.startswith((b"{", b"[")):
        return "JSON text"
    return "text" if all(32 <= c < 127 or c in b"\t\r\n" for c in text) else "binary data"


def _check_shapefile(p: Path, head: bytes) -> None:
    if len(head) < 100 or struct.unpack(">i", head[:4])[0] != _SHP_CODE:
        _refuse(p, "Shapefile", _looks_like(head))
    sidecars = {}
    for ext in (".shx", ".dbf"):
        found = [q for q in (p.with_suffix(ext), p.with_suffix(ext.upper())) if q.is_file()]
        if not found:
            raise InputError(
                f"{p.name}: its {ext} file is missing; a shapefile is several files side by "
                "side (.shp, .shx, .dbf and .prj for its CRS): copy them all"
            )
        sidecars[ext] = found[0]
    shapes = max(0, (sidecars[".shx"].stat().st_size - 100) // 8)
    with sidecars[".dbf"].open("rb") as fh:
        dbf = fh.read(32)
    if len(dbf) < 32:
        raise InputError(f"{sidecars['.dbf'].name} is not a dBASE table (too short)")
    records = struct.unpack("<I", dbf[4:8])[0]
    if records != shapes:
        raise InputError(
            f"{p.name}: its .shx indexes {shapes} shape(s) but its .dbf holds {records} "
            "record(s), so some shapes would lose their attributes or be dropped; export the "
            "shapefile again (its .shp, .shx and .dbf together)"
        )


class _Root(Exception):
    """The first element's name, raised out of the XML parser to stop it there."""


def _check_kml(head: bytes, name: str) -> None:
    """XML whose root element is ``kml``, without a document type declaration (KML has none;
    one could declare entities): read by expat up to its first element."""
    import xml.parsers.expat as expat

    def doctype(*_args: object) -> None:
        raise InputError(f"{name}: a KML file has no document type declaration; export it again")

    def first(tag: str, _attrs: object) -> None:
        raise _Root(tag)

    parser = expat.ParserCreate()
    parser.StartDoctypeDeclHandler = doctype
    parser.EntityDeclHandler = doctype
    parser.StartElementHandler = first
    root = None
    try:
        parser.Parse(head, False)
    except _Root as found:
        root = str(found.args[0]).rsplit(":", 1)[-1]
    except (expat.ExpatError, LookupError, ValueError) as exc:  # LookupError: an encoding
        raise InputError(f"{name} is not a KML file (not well-formed XML: {exc})") from None
    if root != "kml":
        tag = "none" if root is None else repr(root)
        raise InputError(
            f"{name} is not a KML file (its root element is {tag}, not 'kml'); export the "
            "site again as KML"
        )


def _check_kmz(p: Path) -> None:
    """A zip archive of KML: every XML member of it KML (GDAL reads them all; a link in
    one may name another), no more unpacked than a site file may be."""
    from planner.reading import MAX_FILE_BYTES

    if not zipfile.is_zipfile(p):
        with p.open("rb") as fh:
            _refuse(p, "KMZ", _looks_like(fh.read(512)))
    try:
        with zipfile.ZipFile(p) as zf:
            infos = zf.infolist()
            if not any(i.filename.lower().endswith(".kml") for i in infos):
                raise InputError(f"{p.name}: a KMZ archive holds a .kml file; this one holds none")
            if sum(i.file_size for i in infos) > MAX_FILE_BYTES:
                raise InputError(
                    f"{p.name} unpacks to more than {MAX_FILE_BYTES / 1e6:.0f} MB; a site file "
                    "of that size is not a site"
                )
            for info in infos:
                with zf.open(info) as fh:
                    head = fh.read(_XML_HEAD)
                xml = head.lstrip(b"\xef\xbb\xbf \t\r\n").startswith(b"<")
                if info.filename.lower().endswith(".kml") or xml:
                    _check_kml(head, f"{p.name}:{info.filename}")
    except InputError:
        raise
    except (
        zipfile.BadZipFile,
        NotImplementedError,
        RuntimeError,
        EOFError,
        OSError,
        zlib.error,
    ) as exc:
        raise InputError(
            f"{p.name}: cannot read it as a KMZ archive ({type(exc).__name__}: {exc}); export "
            "the site again as KMZ"
        ) from None
