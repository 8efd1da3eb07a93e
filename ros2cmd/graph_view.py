"""`rqt_graph` (also `ros2 run rqt_graph rqt_graph`): the running graph as rqt_graph draws it.

Nodes are boxes, topics ellipses, an arrow from each publisher to its topic and from the
topic to each subscriber; nodes and topics of one namespace are grouped in a labelled frame.
As rqt_graph does by default, the tools' own nodes, /rosout and /parameter_events are left
out (``--all`` shows the last two). Services are not drawn (rqt_graph does not either: a call
is not a lasting connection).

    rqt_graph                      DOT on stdout (for graphviz, if you have it)
    rqt_graph -o graph.svg         an SVG picture (or .png, or .dot)
    rqt_graph --window             a window that follows nodes as they come and go
    rqt_graph                          the window where there is a display, else DOT

No graphviz here: the layout is this module's own, a layered one (Sugiyama's steps: break
cycles, assign layers by longest path, order each layer by the barycentre of its neighbours,
then place): left to right, publishers before their topics before their subscribers. Each
namespace gets a horizontal band of its own, so frames never overlap, and every vertex has a
slot of its own in its column, so labels never overlap; an edge that skips columns passes
through empty slots reserved for it.
"""

from __future__ import annotations

import argparse
import html
import os
import random
import sys
import time
from collections import defaultdict
from collections.abc import Callable
from dataclasses import dataclass, field
from itertools import pairwise
from pathlib import Path

from ros2cmd.errors import ToolError
from ros2cmd.graph import Graph, Snapshot, split_node_name, until_stopped

DEBUG_TOPICS = {"/rosout", "/parameter_events"}  # hidden unless --all, as rqt_graph does
ROOT = "/"

# Layout measures, in pixels.
PAD_X, PAD_Y = 10, 6  # around a label inside its box or ellipse
ELLIPSE_EXTRA = 16  # an ellipse needs more room than a box around the same text
COLUMN_GAP = 70  # between columns, where the edges run
ROW_GAP = 12  # between two slots of a column
DUMMY_HEIGHT = 6  # the slot an edge uses to pass through a column
GROUP_LABEL = 22  # room for a namespace frame's label
GROUP_PAD = 10  # frame around its band
BAND_GAP = 16  # between two bands
MARGIN = 20


@dataclass(frozen=True)
class Vertex:
    key: str
    label: str
    kind: str  # "node", "topic" or "dummy" (a point an edge passes through)
    group: str  # its namespace ("/" when not grouped)


@dataclass
class GraphModel:
    vertices: dict[str, Vertex] = field(default_factory=dict)
    edges: list[tuple[str, str]] = field(default_factory=list)

    def add(self, key: str, label: str, kind: str, group: str) -> None:
        self.vertices.setdefault(key, Vertex(key, label, kind, group))


def namespace_of(name: str) -> str:
    return split_node_name(name)[0]


def model_from_snapshot(snapshot: Snapshot, groups: bool = True, all_topics: bool = False):
    """Nodes and topics with their publish/subscribe edges (rqt_graph's "Nodes/Topics (all)")."""
    model = GraphModel()
    for node in snapshot.nodes:
        model.add("n:" + node, node, "node", namespace_of(node) if groups else ROOT)
    for topic, info in sorted(snapshot.topics.items()):
        if topic in DEBUG_TOPICS and not all_topics:
            continue
        if not info.publishers and not info.subscribers:
            continue
        model.add("t:" + topic, topic, "topic", namespace_of(topic) if groups else ROOT)
        for endpoint in {e.node for e in info.publishers}:
            model.add("n:" + endpoint, endpoint, "node", namespace_of(endpoint) if groups else ROOT)
            model.edges.append(("n:" + endpoint, "t:" + topic))
        for endpoint in {e.node for e in info.subscribers}:
            model.add("n:" + endpoint, endpoint, "node", namespace_of(endpoint) if groups else ROOT)
            model.edges.append(("t:" + topic, "n:" + endpoint))
    model.edges.sort()
    return model


# The layout.


@dataclass
class Box:
    vertex: Vertex
    x: float
    y: float
    w: float
    h: float

    def rect(self) -> tuple[float, float, float, float]:
        return (self.x, self.y, self.x + self.w, self.y + self.h)


@dataclass
class Frame:
    namespace: str
    x: float
    y: float
    w: float
    h: float


@dataclass
class Edge:
    points: list[tuple[float, float]]  # from the publisher's side to the subscriber's side


@dataclass
class Layout:
    width: float
    height: float
    boxes: dict[str, Box]
    frames: list[Frame]
    edges: list[Edge]


Measure = Callable[[str], tuple[float, float]]


def monospace_measure(size: float = 12.0) -> Measure:
    """Text size in a monospace font (0.6 em a character; DejaVu Sans Mono is 0.602)."""
    return lambda text: (len(text) * size * 0.62, size * 1.25)


def _break_cycles(keys: list[str], edges: list[tuple[str, str]]) -> set[tuple[str, str]]:
    """Edges that close a cycle (found by depth-first search), to be drawn reversed."""
    out: dict[str, list[str]] = defaultdict(list)
    indegree: dict[str, int] = dict.fromkeys(keys, 0)
    for a, b in edges:
        out[a].append(b)
        indegree[b] += 1
    state: dict[str, int] = {}  # 1 on the stack, 2 done
    reversed_edges = set()
    # Start from sources (publishers that subscribe to nothing) so the picture flows from them.
    for root in sorted(keys, key=lambda k: (indegree[k] > 0, k)):
        if root in state:
            continue
        stack = [(root, iter(out[root]))]
        state[root] = 1
        while stack:
            vertex, children = stack[-1]
            child = next(children, None)
            if child is None:
                state[vertex] = 2
                stack.pop()
            elif state.get(child) == 1:
                reversed_edges.add((vertex, child))
            elif child not in state:
                state[child] = 1
                stack.append((child, iter(out[child])))
    return reversed_edges


def _layers(keys: list[str], dag: list[tuple[str, str]]) -> dict[str, int]:
    """Longest path from the sources: every edge goes at least one layer to the right."""
    out: dict[str, list[str]] = defaultdict(list)
    indegree = dict.fromkeys(keys, 0)
    for a, b in dag:
        out[a].append(b)
        indegree[b] += 1
    layer = dict.fromkeys(keys, 0)
    ready = sorted(k for k in keys if indegree[k] == 0)
    while ready:
        vertex = ready.pop()
        for child in out[vertex]:
            layer[child] = max(layer[child], layer[vertex] + 1)
            indegree[child] -= 1
            if indegree[child] == 0:
                ready.append(child)
    return layer


def _band_order(groups: set[str]) -> list[str]:
    """Namespaces in an order that keeps each one's sub-namespaces right after it."""
    return sorted(groups, key=lambda g: [part for part in g.split("/") if part])


def layout(model: GraphModel, measure: Measure, sweeps: int = 8) -> Layout:
    keys = sorted(model.vertices)
    reversed_edges = _break_cycles(keys, model.edges)
    dag = [(b, a) if (a, b) in reversed_edges else (a, b) for a, b in model.edges]
    layer = _layers(keys, dag)
    vertices = dict(model.vertices)

    # Edges that skip layers pass through a dummy vertex in each layer between.
    chains: list[tuple[list[str], bool]] = []  # (keys left to right, drawn reversed)
    for (a, b), (orig_a, _orig_b) in zip(dag, model.edges, strict=True):
        chain = [a]
        for step in range(layer[a] + 1, layer[b]):
            key = f"d:{len(vertices)}"
            group = vertices[a].group if step - layer[a] <= layer[b] - step else vertices[b].group
            vertices[key] = Vertex(key, "", "dummy", group)
            layer[key] = step
            chain.append(key)
        chain.append(b)
        chains.append((chain, a != orig_a))

    bands = _band_order({v.group for v in vertices.values()})
    band_index = {g: i for i, g in enumerate(bands)}
    columns: list[list[str]] = [[] for _ in range(max(layer.values(), default=-1) + 1)]
    for key in sorted(vertices, key=lambda k: (band_index[vertices[k].group], k)):
        columns[layer[key]].append(key)

    left: dict[str, list[str]] = defaultdict(list)
    right: dict[str, list[str]] = defaultdict(list)
    for chain, _ in chains:
        for a, b in pairwise(chain):
            right[a].append(b)
            left[b].append(a)

    position = {k: i for column in columns for i, k in enumerate(column)}
    for sweep in range(sweeps):
        order = range(1, len(columns)) if sweep % 2 == 0 else range(len(columns) - 2, -1, -1)
        neighbours = left if sweep % 2 == 0 else right
        for i in order:

            def key(k: str, neighbours: dict = neighbours) -> tuple[int, float]:
                near = [position[n] for n in neighbours[k]]
                centre = sum(near) / len(near) if near else position[k]
                return (band_index[vertices[k].group], centre)

            columns[i].sort(key=key)
            for j, k in enumerate(columns[i]):
                position[k] = j

    # Sizes, then places: columns left to right, bands top to bottom.
    size: dict[str, tuple[float, float]] = {}
    for key, vertex in vertices.items():
        if vertex.kind == "dummy":
            size[key] = (0.0, DUMMY_HEIGHT)
            continue
        w, h = measure(vertex.label)
        extra = ELLIPSE_EXTRA if vertex.kind == "topic" else 0
        size[key] = (w + 2 * PAD_X + 2 * extra, h + 2 * PAD_Y + (6 if extra else 0))
    column_width = [max((size[k][0] for k in c), default=0.0) for c in columns]
    column_x = []
    x = MARGIN + GROUP_PAD * _depth(bands)
    for width in column_width:
        column_x.append(x)
        x += width + COLUMN_GAP

    band_height = dict.fromkeys(bands, 0.0)
    for column in columns:
        heights: dict[str, float] = defaultdict(float)
        for k in column:
            heights[vertices[k].group] += size[k][1] + ROW_GAP
        for group, h in heights.items():
            band_height[group] = max(band_height[group], h - ROW_GAP)

    band_top: dict[str, float] = {}
    y = MARGIN
    for group in bands:
        if group != ROOT:
            y += GROUP_LABEL + GROUP_PAD
        band_top[group] = y
        y += band_height[group] + BAND_GAP + GROUP_PAD * (_depth(bands) + 1)
    height = y - BAND_GAP + MARGIN

    boxes: dict[str, Box] = {}
    for i, column in enumerate(columns):
        by_group: dict[str, list[str]] = defaultdict(list)
        for k in column:
            by_group[vertices[k].group].append(k)
        for group, members in by_group.items():
            used = sum(size[k][1] for k in members) + ROW_GAP * (len(members) - 1)
            y = band_top[group] + (band_height[group] - used) / 2
            for k in members:
                w, h = size[k]
                boxes[k] = Box(vertices[k], column_x[i] + (column_width[i] - w) / 2, y, w, h)
                y += h + ROW_GAP

    edges = []
    for chain, drawn_reversed in chains:
        points: list[tuple[float, float]] = []
        for n, k in enumerate(chain):
            box = boxes[k]
            i = layer[k]
            middle = box.y + box.h / 2
            if n > 0:  # enter the column at its left edge, then run to the box
                points.append((column_x[i], middle))
                if box.vertex.kind != "dummy":
                    points.append((box.x, middle))
            if n < len(chain) - 1:
                if box.vertex.kind != "dummy":
                    points.append((box.x + box.w, middle))
                points.append((column_x[i] + column_width[i], middle))
        if drawn_reversed:
            points.reverse()
        edges.append(Edge(_dedupe(points)))

    real = {k: b for k, b in boxes.items() if b.vertex.kind != "dummy"}
    frames = _frames(bands, band_top, band_height, real, measure)
    width = max(
        [x - COLUMN_GAP + MARGIN + GROUP_PAD * _depth(bands)] + [f.x + f.w + MARGIN for f in frames]
    )
    return Layout(max(width, 2 * MARGIN), max(height, 2 * MARGIN), real, frames, edges)


def _depth(bands: list[str]) -> int:
    return max((len([p for p in g.split("/") if p]) for g in bands), default=0)


def _dedupe(points: list[tuple[float, float]]) -> list[tuple[float, float]]:
    kept: list[tuple[float, float]] = []
    for p in points:
        if not kept or kept[-1] != p:
            kept.append(p)
    return kept


def _frames(bands, band_top, band_height, boxes, measure) -> list[Frame]:
    """One frame per namespace around its band and its sub-namespaces' bands."""
    frames = []
    for group in bands:
        if group == ROOT:
            continue
        inside = [g for g in bands if g == group or g.startswith(group.rstrip("/") + "/")]
        members = [b for b in boxes.values() if b.vertex.group in inside]
        if not members:
            continue
        depth = len([p for p in group.split("/") if p])
        inner = _depth(bands) - depth  # sub-namespace frames sit inside this one
        x0 = min(b.x for b in members) - GROUP_PAD * (inner + 1)
        x1 = max(b.x + b.w for b in members) + GROUP_PAD * (inner + 1)
        x1 = max(x1, x0 + measure(group)[0] + 16)  # room for the label
        y0 = band_top[group] - GROUP_LABEL - GROUP_PAD
        last = inside[-1]
        y1 = band_top[last] + band_height[last] + GROUP_PAD * (inner + 1)
        frames.append(Frame(group, x0, y0, x1 - x0, y1 - y0))
    return frames


def example_model(nodes: int = 50, topics: int = 100, seed: int = 12) -> GraphModel:
    """A made-up robot-like graph, for the layout's tests and benchmark.

    Nodes in pipeline stages (drivers, perception, planning, control) and namespaces (one
    nested) and the root; each topic published by 1-2 nodes of a stage and heard by 0-3
    nodes of later stages, one in ten also by an earlier one (a cycle).
    """
    rng = random.Random(seed)
    namespaces = ["/", "/robot1", "/robot2", "/robot2/arm", "/sensors", "/a_long_namespace_name"]
    model = GraphModel()
    stages: list[list[str]] = [[] for _ in range(5)]
    for n in range(nodes):
        ns = rng.choice(namespaces)
        name = f"{ns.rstrip('/')}/node_{n}_{'x' * rng.randrange(0, 12)}"
        model.add("n:" + name, name, "node", ns)
        stages[n % 5].append("n:" + name)
    for t in range(topics):
        ns = rng.choice(namespaces)
        name = f"{ns.rstrip('/')}/topic_{t}"
        model.add("t:" + name, name, "topic", ns)
        stage = rng.randrange(4)
        for pub in rng.sample(stages[stage], rng.randint(1, 2)):
            model.edges.append((pub, "t:" + name))
        later = [key for s in stages[stage + 1 :] for key in s]
        for sub in rng.sample(later, rng.randint(0, 3)):
            model.edges.append(("t:" + name, sub))
        if rng.random() < 0.1 and stage > 0:
            model.edges.append(("t:" + name, rng.choice(stages[stage - 1])))
    return model


# Output: DOT, SVG, PNG.


def to_dot(model: GraphModel) -> str:
    """The graph in graphviz's DOT language, namespaces as clusters, as rqt_graph writes it."""

    def quoted(text: str) -> str:
        return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'

    lines = ["digraph graph_view {", "  rankdir=LR;", '  node [fontname="monospace"];']
    by_group: dict[str, list[Vertex]] = defaultdict(list)
    for vertex in model.vertices.values():
        by_group[vertex.group].append(vertex)
    for n, group in enumerate(_band_order(set(by_group))):
        indent = "  "
        if group != ROOT:
            lines.append(f"  subgraph cluster_{n} {{")
            lines.append(f"    label={quoted(group)};")
            indent = "    "
        for vertex in sorted(by_group[group], key=lambda v: v.key):
            shape = "box" if vertex.kind == "node" else "ellipse"
            lines.append(f"{indent}{quoted(vertex.label)} [shape={shape}];")
        if group != ROOT:
            lines.append("  }")
    for a, b in model.edges:
        lines.append(f"  {quoted(model.vertices[a].label)} -> {quoted(model.vertices[b].label)};")
    lines.append("}")
    return "\n".join(lines) + "\n"


NODE_FILL, TOPIC_FILL, FRAME_COLOUR, EDGE_COLOUR = "#dfeaf7", "#fdf1d6", "#7a7a7a", "#404040"
SVG_FONT_SIZE = 12.0


def to_svg(lay: Layout) -> str:
    out = [
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{lay.width:.0f}" '
        f'height="{lay.height:.0f}" viewBox="0 0 {lay.width:.0f} {lay.height:.0f}" '
        f'font-family="DejaVu Sans Mono, monospace" font-size="{SVG_FONT_SIZE:g}">',
        '<defs><marker id="arrow" viewBox="0 0 10 10" refX="10" refY="5" markerWidth="8" '
        f'markerHeight="8" orient="auto"><path d="M0,0 L10,5 L0,10 z" fill="{EDGE_COLOUR}"/>'
        "</marker></defs>",
        f'<rect width="{lay.width:.0f}" height="{lay.height:.0f}" fill="white"/>',
    ]
    for f in lay.frames:
        out.append(
            f'<rect x="{f.x:.1f}" y="{f.y:.1f}" width="{f.w:.1f}" height="{f.h:.1f}" rx="6" '
            f'fill="none" stroke="{FRAME_COLOUR}" stroke-dasharray="5,3"/>'
        )
        out.append(
            f'<text x="{f.x + 8:.1f}" y="{f.y + GROUP_LABEL - 6:.1f}" fill="{FRAME_COLOUR}">'
            f"{html.escape(f.namespace)}</text>"
        )
    for e in lay.edges:
        path = " ".join(f"{x:.1f},{y:.1f}" for x, y in e.points)
        out.append(
            f'<polyline points="{path}" fill="none" stroke="{EDGE_COLOUR}" '
            'marker-end="url(#arrow)"/>'
        )
    for b in lay.boxes.values():
        cx, cy = b.x + b.w / 2, b.y + b.h / 2
        if b.vertex.kind == "node":
            out.append(
                f'<rect x="{b.x:.1f}" y="{b.y:.1f}" width="{b.w:.1f}" height="{b.h:.1f}" '
                f'fill="{NODE_FILL}" stroke="black"/>'
            )
        else:
            out.append(
                f'<ellipse cx="{cx:.1f}" cy="{cy:.1f}" rx="{b.w / 2:.1f}" ry="{b.h / 2:.1f}" '
                f'fill="{TOPIC_FILL}" stroke="black"/>'
            )
        out.append(
            f'<text x="{cx:.1f}" y="{cy:.1f}" text-anchor="middle" dominant-baseline="central">'
            f"{html.escape(b.vertex.label)}</text>"
        )
    out.append("</svg>")
    return "\n".join(out) + "\n"


def _pygame(headless: bool):
    """pygame, imported only for PNG and the window; headless needs no display."""
    if headless:
        os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
    os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")
    import pygame

    pygame.font.init()
    return pygame


PNG_FONT_SIZE = 16


def pygame_measure(font) -> Measure:
    return lambda text: font.size(text)


def _rgb(colour: str) -> tuple[int, int, int]:
    return tuple(int(colour[i : i + 2], 16) for i in (1, 3, 5))


def draw(pygame, surface, lay: Layout, font, scale: float = 1.0) -> None:
    """Paint the layout on a pygame surface (the PNG file and the window share this)."""

    def s(v: float) -> int:
        return round(v * scale)

    surface.fill((255, 255, 255))
    for f in lay.frames:
        pygame.draw.rect(surface, _rgb(FRAME_COLOUR), (s(f.x), s(f.y), s(f.w), s(f.h)), 1, 6)
        label = font.render(f.namespace, True, _rgb(FRAME_COLOUR))
        surface.blit(label, (s(f.x + 8), s(f.y + 4)))
    for e in lay.edges:
        points = [(s(x), s(y)) for x, y in e.points]
        pygame.draw.lines(surface, _rgb(EDGE_COLOUR), False, points, 1)
        (x0, _), (x1, y1) = points[-2], points[-1]
        direction = 1 if x1 >= x0 else -1
        tip = [(x1, y1), (x1 - direction * 9, y1 - 4), (x1 - direction * 9, y1 + 4)]
        pygame.draw.polygon(surface, _rgb(EDGE_COLOUR), tip)
    for b in lay.boxes.values():
        rect = (s(b.x), s(b.y), s(b.w), s(b.h))
        if b.vertex.kind == "node":
            pygame.draw.rect(surface, _rgb(NODE_FILL), rect)
            pygame.draw.rect(surface, (0, 0, 0), rect, 1)
        else:
            pygame.draw.ellipse(surface, _rgb(TOPIC_FILL), rect)
            pygame.draw.ellipse(surface, (0, 0, 0), rect, 1)
        text = font.render(b.vertex.label, True, (0, 0, 0))
        surface.blit(text, text.get_rect(center=(s(b.x + b.w / 2), s(b.y + b.h / 2))))


def write_png(model: GraphModel, path: Path) -> None:
    pygame = _pygame(headless=True)
    font = pygame.font.Font(None, PNG_FONT_SIZE + 4)
    lay = layout(model, pygame_measure(font))
    surface = pygame.Surface((int(lay.width) + 1, int(lay.height) + 1))
    draw(pygame, surface, lay, font)
    pygame.image.save(surface, str(path))


def write(model: GraphModel, path: Path) -> None:
    """Write DOT, SVG or PNG, chosen by the file's extension."""
    suffix = path.suffix.lower()
    if suffix not in (".dot", ".gv", ".svg", ".png"):
        raise ToolError(f"cannot write '{path}': choose a .svg, .png or .dot file")
    try:
        if suffix == ".png":
            write_png(model, path)
        elif suffix == ".svg":
            path.write_text(to_svg(layout(model, monospace_measure(SVG_FONT_SIZE))))
        else:
            path.write_text(to_dot(model))
    except OSError as error:
        raise ToolError(f"cannot write '{path}': {error.strerror or error}") from None
    except Exception as error:  # pygame.error: e.g. a picture too large to save
        if type(error).__name__ != "error":
            raise
        raise ToolError(f"cannot write '{path}': {error}") from None


# The command.

MAX_VERTICES = 2000  # beyond this a picture is no longer readable; say so instead


def current_model(graph: Graph, groups: bool, all_topics: bool) -> GraphModel:
    model = model_from_snapshot(graph.snapshot(), groups, all_topics)
    if len(model.vertices) > MAX_VERTICES:
        raise ToolError(
            f"the graph has {len(model.vertices)} nodes and topics, too many to draw readably "
            f"(at most {MAX_VERTICES}); `ros2 node list` and `topic list` list them"
        )
    return model


def window(graph: Graph, groups: bool, all_topics: bool, refresh: float = 1.0) -> None:
    """A window showing the graph, redrawn as nodes and topics come and go, until closed."""
    if not os.environ.get("DISPLAY") and not os.environ.get("WAYLAND_DISPLAY"):
        raise ToolError("no display for a window; write a file instead: rqt_graph -o g.svg")
    pygame = _pygame(headless=False)
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


def run(graph: Graph, args: argparse.Namespace) -> None:
    groups, all_topics = not args.no_groups, args.all
    if args.window:
        with until_stopped():  # Ctrl-C is how a window that follows the graph ends: exit 0
            window(graph, groups, all_topics)
        return
    graph.settle()
    model = current_model(graph, groups, all_topics)
    if args.output:
        write(model, Path(args.output))
        print(f"wrote {args.output}: {_counts(model)}", file=sys.stderr)
    else:
        sys.stdout.write(to_dot(model))


def _counts(model: GraphModel) -> str:
    kinds = [v.kind for v in model.vertices.values()]
    nodes, topics = kinds.count("node"), kinds.count("topic")
    return f"{nodes} node(s), {topics} topic(s), {len(model.edges)} edge(s)"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("-o", "--output", help="write a .svg, .png or .dot file")
    parser.add_argument(
        "--window", action="store_true", help="show it in a window that follows the graph"
    )
    parser.add_argument("--no-groups", action="store_true", help="do not frame namespaces")
    parser.add_argument("--all", action="store_true", help="show /rosout and /parameter_events too")
