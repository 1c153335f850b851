"""The fewest stations: the set multi-cover (HiGHS, greedy, local search), its
classical reductions, and lower bounds.

Pure combinatorics on sparse matrices: may import no other room.
"""
