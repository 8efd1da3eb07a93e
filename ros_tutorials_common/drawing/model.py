"""What a drawn graph holds: vertices (a node's box, a topic's or a frame's ellipse, each in a
group: its namespace) and the edges between them (and a made-up model of a robot for the
layout's tests and benchmark)."""

from __future__ import annotations

import random
from dataclasses import dataclass, field

ROOT = "/"

MAX_VERTICES = 2000  # beyond this a picture is no longer readable; say so instead


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
