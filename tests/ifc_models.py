"""Small IFC models made with IfcOpenShell's authoring API, for the IFC reader's tests: a
20 × 12 m building of four 0.3 m walls 8 m high, a roof slab, a window and a door on its
south side, optionally georeferenced (IfcMapConversion to EPSG:25832, rotated 30°)."""

from __future__ import annotations

from pathlib import Path

import numpy as np

E0, N0, H0, TURN_DEG = 500000.0, 5400000.0, 100.0, 30.0


def _box(api, f, body, storey, cls: str, x, y, z, angle, length, height, thickness, **attrs):
    """An element of class ``cls``: a box ``length`` along its x axis, ``thickness``
    along y, ``height`` up, its corner at (x, y, z) turned ``angle`` degrees."""
    e = api.run("root.create_entity", f, ifc_class=cls, name=cls, **attrs)
    rep = api.run(
        "geometry.add_wall_representation",
        f,
        context=body,
        length=length,
        height=height,
        thickness=thickness,
    )
    api.run("geometry.assign_representation", f, product=e, representation=rep)
    c, s = np.cos(np.radians(angle)), np.sin(np.radians(angle))
    m = np.array([[c, -s, 0, x], [s, c, 0, y], [0, 0, 1, z], [0, 0, 0, 1.0]])
    api.run("geometry.edit_object_placement", f, product=e, matrix=m)
    api.run("spatial.assign_container", f, relating_structure=storey, products=[e])
    return e


def town_hall(path: Path, *, georeferenced: bool = True, roof: bool = True) -> Path:
    """Write the building to ``path`` and return it."""
    import ifcopenshell.api as api

    f = api.run("project.create_file", version="IFC4")
    project = api.run("root.create_entity", f, ifc_class="IfcProject", name="P")
    api.run("unit.assign_unit", f)
    model = api.run("context.add_context", f, context_type="Model")
    body = api.run(
        "context.add_context",
        f,
        context_type="Model",
        context_identifier="Body",
        target_view="MODEL_VIEW",
        parent=model,
    )
    site = api.run("root.create_entity", f, ifc_class="IfcSite", name="Site")
    building = api.run("root.create_entity", f, ifc_class="IfcBuilding", name="Town hall")
    storey = api.run("root.create_entity", f, ifc_class="IfcBuildingStorey", name="G")
    api.run("aggregate.assign_object", f, relating_object=project, products=[site])
    api.run("aggregate.assign_object", f, relating_object=site, products=[building])
    api.run("aggregate.assign_object", f, relating_object=building, products=[storey])
    for x, y, angle, length in (
        (0, 0, 0, 20),
        (20, 0, 90, 12),
        (20, 12, 180, 20),
        (0, 12, 270, 12),
    ):
        _box(api, f, body, storey, "IfcWall", x, y, 0.0, angle, length, 8.0, 0.3)
    if roof:
        _box(api, f, body, storey, "IfcSlab", 0, 0, 8.0, 0, 20, 0.3, 12, predefined_type="ROOF")
    # on the south face (y = 0), just proud of it: a window 2 × 1.5 m and a door 1 × 2.2 m
    _box(api, f, body, storey, "IfcWindow", 4, -0.05, 3.0, 0, 2.0, 1.5, 0.05)
    _box(api, f, body, storey, "IfcDoor", 12, -0.05, 0.0, 0, 1.0, 2.2, 0.05)
    if georeferenced:
        crs = f.createIfcProjectedCRS(Name="EPSG:25832")
        t = np.radians(TURN_DEG)
        f.createIfcMapConversion(
            SourceCRS=model,
            TargetCRS=crs,
            Eastings=E0,
            Northings=N0,
            OrthogonalHeight=H0,
            XAxisAbscissa=float(np.cos(t)),
            XAxisOrdinate=float(np.sin(t)),
            Scale=1.0,
        )
    f.write(str(path))
    return path
