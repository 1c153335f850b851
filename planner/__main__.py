"""``python -m planner`` — the same as the ``planner`` command."""

from planner.app.cli import main

raise SystemExit(main())
