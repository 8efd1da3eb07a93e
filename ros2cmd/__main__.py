"""`python -m ros2cmd ...` is the same as `ros2 ...`."""

from ros2cmd.entry import main

raise SystemExit(main())
