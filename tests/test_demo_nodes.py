"""The official tutorials' talker and listener (ros2/demos' demo_nodes_cpp), as the pages
run them: `ros2 run demo_nodes_cpp talker` / `listener`, with demo_nodes_cpp's log lines."""

from __future__ import annotations

from helpers import BIN


def test_demo_talker_and_listener_print_what_the_pages_show(own_domain, node_process):
    talker = node_process(str(BIN / "ros2"), "run", "demo_nodes_cpp", "talker")
    listener = node_process(str(BIN / "ros2"), "run", "demo_nodes_py", "listener")
    talker.wait_for_text("[talker]: Publishing: 'Hello World: 1'")
    listener.wait_for_text("[listener]: I heard: [Hello World: ")
