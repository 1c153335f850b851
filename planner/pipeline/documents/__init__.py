"""The plan's files: GeoJSON, DXF, KML, stake-out CSV, and the output folder
written at once (nothing of the user's overwritten).

May import every room before it.
"""
