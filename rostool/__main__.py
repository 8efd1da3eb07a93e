"""`python -m rostool ...` is the same as `rostool ...`."""

from rostool.cli import main

raise SystemExit(main())
