"""rqt_graph's window: the picture redrawn, scaled to the window, as nodes and topics come and
go, until it is closed."""

from __future__ import annotations

import os
import time

from ros2cmd.errors import ToolError
from ros2cmd.graph import Graph
from ros2cmd.graph_view.model import current_model
from ros_tutorials_common.drawing.layout import layout
from ros_tutorials_common.drawing.render import PNG_FONT_SIZE, draw, load_pygame, pygame_measure


def window(graph: Graph, groups: bool, all_topics: bool, refresh: float = 1.0) -> None:
    """A window showing the graph, redrawn as nodes and topics come and go, until closed."""
    if not os.environ.get("DISPLAY") and not os.environ.get("WAYLAND_DISPLAY"):
        raise ToolError("no display for a window; write a file instead: rqt_graph -o g.svg")
    pygame = load_pygame(headless=False)
    try:
        pygame.display.init()
        screen = pygame.display.set_mode((900, 600), pygame.RESIZABLE)
    except pygame.error as error:
        raise ToolError(f"cannot open a window: {error}") from None
    pygame.display.set_caption("rqt_graph")
    font = pygame.font.Font(None, PNG_FONT_SIZE + 4)
    graph.settle()
    shown = None
    lay = None
    next_look = 0.0
    try:
        while True:
            for event in pygame.event.get():
                if event.type == pygame.QUIT:
                    return
                if event.type == pygame.VIDEORESIZE:
                    shown = None  # redraw at the new size
            if time.monotonic() >= next_look:
                next_look = time.monotonic() + refresh
                model = current_model(graph, groups, all_topics)
                key = (sorted(model.vertices), model.edges, screen.get_size())
                if key != shown:
                    shown = key
                    lay = layout(model, pygame_measure(font))
                    width, height = screen.get_size()
                    scale = min(1.0, width / lay.width, height / lay.height)
                    small = pygame.font.Font(None, max(8, round((PNG_FONT_SIZE + 4) * scale)))
                    draw(pygame, screen, lay, small, scale)
                    pygame.display.flip()
            graph.spin_once(0.05)
    finally:
        pygame.display.quit()
