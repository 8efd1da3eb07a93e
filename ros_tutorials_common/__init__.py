"""Plumbing shared by every tutorial node and tool.

- ``node_main``: how an executable starts, spins and stops (``run_node``, ``init``, ``user_args``)
- ``dds``: the one place that sets this project's DDS defaults
- ``cli``: argument types and exit codes shared by the command-line programs
- ``service_client``: how the one-shot service clients call once and report
- ``int64``: keeping the servers' results inside int64

Nothing is imported here, so a light user (the launcher needs only ``dds``) does not pay for
loading rclpy.
"""
