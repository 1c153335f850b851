"""Every sample's predicted error from every candidate station (the paper model or
the full 3-D one), with sight lines and incidence: the matrices the optimiser and the
network work on.

May import :mod:`planner.pipeline.inputs` and :mod:`planner.pipeline.geometry`.
"""
