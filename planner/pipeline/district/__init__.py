"""Large sites: blocks planned in parallel (Dask), bounds on the fewest stations
across blocks, and the stitch that ties the blocks into one plan.

May import every room before it.
"""
