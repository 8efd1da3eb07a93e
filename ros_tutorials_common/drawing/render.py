"""rqt_graph's picture as a file or on a surface: DOT text (graphviz's language), SVG, and
pygame's painting of a layout, which the PNG file and the window share."""

from __future__ import annotations

import html
import os
from collections import defaultdict
from pathlib import Path

from ros_tutorials_common.drawing.layout import (
    GROUP_LABEL,
    Layout,
    Measure,
    band_order,
    layout,
    monospace_measure,
)
from ros_tutorials_common.drawing.model import ROOT, GraphModel, Vertex


def to_dot(model: GraphModel) -> str:
    """The graph in graphviz's DOT language, namespaces as clusters, as rqt_graph writes it."""

    def quoted(text: str) -> str:
        return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'

    lines = ["digraph graph_view {", "  rankdir=LR;", '  node [fontname="monospace"];']
    by_group: dict[str, list[Vertex]] = defaultdict(list)
    for vertex in model.vertices.values():
        by_group[vertex.group].append(vertex)
    for n, group in enumerate(band_order(set(by_group))):
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


def load_pygame(headless: bool):
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
    pygame = load_pygame(headless=True)
    font = pygame.font.Font(None, PNG_FONT_SIZE + 4)
    lay = layout(model, pygame_measure(font))
    surface = pygame.Surface((int(lay.width) + 1, int(lay.height) + 1))
    draw(pygame, surface, lay, font)
    pygame.image.save(surface, str(path))


class CannotWrite(Exception):
    """The file cannot be written; str(error) says why, in one line."""


def write(model: GraphModel, path: Path) -> None:
    """Write DOT, SVG or PNG, chosen by the file's extension (CannotWrite if it cannot)."""
    suffix = path.suffix.lower()
    if suffix not in (".dot", ".gv", ".svg", ".png"):
        raise CannotWrite(f"cannot write '{path}': choose a .svg, .png or .dot file")
    try:
        if suffix == ".png":
            write_png(model, path)
        elif suffix == ".svg":
            path.write_text(to_svg(layout(model, monospace_measure(SVG_FONT_SIZE))))
        else:
            path.write_text(to_dot(model))
    except OSError as error:
        raise CannotWrite(f"cannot write '{path}': {error.strerror or error}") from None
    except Exception as error:  # pygame.error: e.g. a picture too large to save
        if type(error).__name__ != "error":
            raise
        raise CannotWrite(f"cannot write '{path}': {error}") from None
