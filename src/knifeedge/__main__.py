"""``python -m knifeedge``: same as the ``knifeedge`` command."""
from .cli import main

raise SystemExit(main())
