"""rqt_graph: the book's union.launch pictures, and a layout that stays readable.

The layout is checked without ROS on a generated graph of 50 nodes and 100 topics: no two
labels overlap, every label fits its shape, namespace frames are disjoint or nested and their
labels cover no shape, no edge runs through a shape. The processes check that union.launch,
with and without groups, gives exactly the book's edges.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from helpers import TIMEOUT, NodeProcess

from ros_tutorials_common.drawing import render
from ros_tutorials_common.drawing.layout import GROUP_LABEL, PAD_X, layout, monospace_measure
from ros_tutorials_common.drawing.model import GraphModel, Vertex
from ros_tutorials_common.drawing.model import example_model as generated_model

BIN = Path(sys.executable).parent


def overlaps(a, b, gap: float = 0.0) -> bool:
    return a[0] < b[2] + gap and b[0] < a[2] + gap and a[1] < b[3] + gap and b[1] < a[3] + gap


def check_readable(model: GraphModel, measure) -> None:
    lay = layout(model, measure)
    boxes = list(lay.boxes.values())
    assert len(boxes) == len(model.vertices)
    for i, a in enumerate(boxes):
        w, h = measure(a.vertex.label)
        assert w + 2 * PAD_X <= a.w and h <= a.h, f"label does not fit: {a.vertex.label}"
        assert a.x >= 0 and a.x + a.w <= lay.width and a.y >= 0 and a.y + a.h <= lay.height
        for b in boxes[i + 1 :]:
            assert not overlaps(a.rect(), b.rect(), gap=4), (a.vertex.label, b.vertex.label)
    for i, f in enumerate(lay.frames):
        frame = (f.x, f.y, f.x + f.w, f.y + f.h)
        label = (f.x, f.y, f.x + 8 + measure(f.namespace)[0], f.y + GROUP_LABEL)
        assert label[2] <= frame[2]
        for box in boxes:
            assert not overlaps(label, box.rect()), (f.namespace, box.vertex.label)
            inside = box.vertex.group == f.namespace or box.vertex.group.startswith(
                f.namespace + "/"
            )
            assert inside == overlaps(frame, box.rect()), (f.namespace, box.vertex.label)
        for g in lay.frames[i + 1 :]:
            other = (g.x, g.y, g.x + g.w, g.y + g.h)
            nested = g.namespace.startswith(f.namespace + "/")
            assert nested or not overlaps(frame, other), (f.namespace, g.namespace)
    for edge in lay.edges:
        for (x0, y0), (x1, y1) in zip(edge.points, edge.points[1:], strict=False):
            span = (min(x0, x1), min(y0, y1), max(x0, x1), max(y0, y1))
            for box in boxes:
                if not overlaps(span, box.rect()):
                    continue
                x_a, y_a, x_b, y_b = box.rect()
                for step in range(1, 50):
                    x, y = x0 + (x1 - x0) * step / 50, y0 + (y1 - y0) * step / 50
                    assert not (x_a + 1 < x < x_b - 1 and y_a + 1 < y < y_b - 1), (
                        f"an edge runs through {box.vertex.label}"
                    )
    return lay


def test_layout_of_50_nodes_and_100_topics_has_no_overlapping_labels(tmp_path):
    model = generated_model()
    assert sum(v.kind == "node" for v in model.vertices.values()) == 50
    assert sum(v.kind == "topic" for v in model.vertices.values()) == 100
    lay = check_readable(model, monospace_measure(12))
    render.write(model, tmp_path / "generated.png")  # to look at: pytest --basetemp=DIR
    assert lay.edges


def test_layout_without_groups_and_with_the_png_font_is_readable_too(tmp_path):
    model = generated_model(seed=3)
    flat = GraphModel(
        {k: Vertex(v.key, v.label, v.kind, "/") for k, v in model.vertices.items()},
        model.edges,
    )
    check_readable(flat, monospace_measure(12))
    pygame = render.load_pygame(headless=True)
    font = pygame.font.Font(None, render.PNG_FONT_SIZE + 4)
    check_readable(model, render.pygame_measure(font))


def test_svg_png_and_dot_files(tmp_path):
    model = generated_model(nodes=10, topics=12)
    for suffix in ("svg", "png", "dot"):
        render.write(model, tmp_path / f"g.{suffix}")
    svg = ET.parse(tmp_path / "g.svg").getroot()
    ns = "{http://www.w3.org/2000/svg}"
    assert len(svg.findall(f"{ns}ellipse")) == 12
    assert len(svg.findall(f"{ns}polyline")) == len(model.edges)
    assert (tmp_path / "g.png").read_bytes().startswith(b"\x89PNG")
    dot = (tmp_path / "g.dot").read_text()
    assert dot.count("->") == len(model.edges) and dot.count("shape=box") == 10


def dot_edges(dot: str) -> set[tuple[str, str]]:
    return set(re.findall(r'"([^"]+)" -> "([^"]+)";', dot))


BOOK_EDGES = {
    "union.launch": {(f"/{ns}/topic_publisher", f"/{ns}/ros_tutorial_msg") for ns in ("ns1", "ns2")}
    | {(f"/{ns}/ros_tutorial_msg", f"/{ns}/topic_subscriber") for ns in ("ns1", "ns2")},
    "union_no_groups.launch": {(f"/topic_publisher{n}", "/ros_tutorial_msg") for n in (1, 2)}
    | {("/ros_tutorial_msg", f"/topic_subscriber{n}") for n in (1, 2)},
}


@pytest.mark.parametrize("launch_file", list(BOOK_EDGES))
def test_union_launch_graph_has_exactly_the_books_edges(node_process, tmp_path, launch_file):
    launcher = node_process("-m", "launcher", launch_file)
    subscribers = {node for topic, node in BOOK_EDGES[launch_file] if "subscriber" in node}
    for subscriber in subscribers:  # each one, not six lines of any: one may start later
        launcher.wait_for_output(
            lambda lines, tag=f"[{subscriber[1:]}]": any(
                line.startswith(tag) and "recieve msg" in line for line in lines
            ),
            what=f"{subscriber} receiving",
        )
    dot = subprocess.run(
        [str(BIN / "rqt_graph")],
        capture_output=True,
        text=True,
        timeout=TIMEOUT,
        env={**os.environ, "DISPLAY": "", "WAYLAND_DISPLAY": ""},
    )
    assert dot.returncode == 0, dot.stderr
    assert dot_edges(dot.stdout) == BOOK_EDGES[launch_file]
    assert "rosout" not in dot.stdout and "_ros2cli" not in dot.stdout
    grouped = "cluster" in dot.stdout
    assert grouped == (launch_file == "union.launch")
    everything = subprocess.run(
        [str(BIN / "rqt_graph"), "--all", "-o", str(tmp_path / "g.dot")],
        capture_output=True,
        text=True,
        timeout=TIMEOUT,
    )
    assert everything.returncode == 0, everything.stderr
    assert '-> "/rosout"' in (tmp_path / "g.dot").read_text()


@pytest.mark.parametrize(
    "output,message",
    [
        ("/nonexistent_dir/g.svg", "cannot write '/nonexistent_dir/g.svg'"),
        ("graph.txt", "choose a .svg, .png or .dot file"),
    ],
)
def test_an_output_that_cannot_be_written_is_one_clear_line(ros_domain, output, message):
    proc = NodeProcess(str(BIN / "rqt_graph"), "-o", output)
    assert proc.wait() == 1
    assert proc.lines[-1].startswith("error: ") and message in proc.lines[-1], proc.output
    assert "Traceback" not in proc.output
