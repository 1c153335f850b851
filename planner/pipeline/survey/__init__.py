"""The survey itself: the plan's scans rehearsed as point clouds (E57, LAZ, a
HELIOS++ survey), and the plan made again from what was scanned.

May import every room before it.
"""
