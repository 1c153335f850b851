"""Planning itself: :func:`planning.plan` chooses stations, judges them with their
network (:mod:`.judge`), and returns a plain :class:`result.Plan`; what-if edits work
on the machinery kept beside it (:func:`judge.workbench_of`); the tables and the
explanation of one sample.

May import every room before it (inputs to field).
"""
