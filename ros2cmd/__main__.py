"""`python -m ros2cmd ...` is the same as `ros2 ...`."""

from ros2cmd.cli import main

raise SystemExit(main())
