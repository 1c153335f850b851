"""The planning engine, in rooms with one direction of knowledge.

Each room is a package; a module imports from its own room and the rooms listed before it,
never from a room after it (``tests/test_rooms.py`` holds this, and that no two modules
import each other in a circle). Below every room are the formulas and data classes of
:mod:`planner` (scanner, site, accuracy, registration error); above the last room is the
application, :mod:`planner.app`.

========== ==================================================================================
room       what it holds
========== ==================================================================================
inputs     the requirements and settings, resolved once; the column lists; the clock
geometry   facades and their samples, the 3-D scene, sight lines, candidate positions, zones
evaluation every sample's error from every candidate station
network    registration: target candidates, links, the network's layout, cloud-to-cloud,
           control and the traverse, seams between blocks
optimise   the fewest stations: the cover, its reductions and bounds
field      the crew's route, field time and set-out ties
engine     planning itself: judging a choice of stations, the plan, what-if edits, tables
district   large sites as blocks planned in parallel and stitched
documents  the plan's files: GeoJSON, DXF, KML, stake-out, the folder written at once
survey     the survey rehearsed as point clouds, and re-planned from what was scanned
========== ==================================================================================
"""

#: The rooms, lowest first: a module may import from its own room and those before it.
ROOMS = (
    "inputs",
    "geometry",
    "evaluation",
    "network",
    "optimise",
    "field",
    "engine",
    "district",
    "documents",
    "survey",
)
