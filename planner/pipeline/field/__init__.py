"""The crew's day: the visiting order, walking and set-up times, the kit standing at
once, view sectors, and the tape ties that set a station out.

May import :mod:`planner.pipeline.inputs`.
"""
