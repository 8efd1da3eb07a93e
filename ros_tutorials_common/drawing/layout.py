"""Where each vertex, frame and edge of rqt_graph's picture goes: no graphviz here, a layout
of this module's own.

A layered one (Sugiyama's steps: break cycles, assign layers by longest path, order each layer
by the barycentre of its neighbours, then place): left to right, publishers before their topics
before their subscribers. Each namespace gets a horizontal band of its own, so frames never
overlap, and every vertex has a slot of its own in its column, so labels never overlap; an edge
that skips columns passes through empty slots reserved for it.
"""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Callable
from dataclasses import dataclass
from itertools import pairwise

from ros_tutorials_common.drawing.model import ROOT, GraphModel, Vertex

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


def band_order(groups: set[str]) -> list[str]:
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

    bands = band_order({v.group for v in vertices.values()})
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
