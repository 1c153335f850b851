"""Where things stand: facades and their samples, the 3-D scene and its sight lines,
candidate station positions, zones of the site, and the site's audit before planning.

May import :mod:`planner.pipeline.inputs`.
"""
