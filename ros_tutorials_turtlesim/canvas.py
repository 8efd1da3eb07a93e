"""Drawing for turtlesim: the path image, the turtles, the window and the PNG (pygame).

As ROS 2 turtlesim's frame does, the pen's trail goes into a transparent path image; a frame
is the background colour, the path image on top, then each turtle. So a new background colour
shows at once without losing the trail, and ``clear`` only empties the path image.

pygame draws, with SDL inside its wheel: one PyPI dependency gives the window and the PNG.
Headless, no SDL video is started at all: the same surfaces are drawn in memory and written
to a PNG on request. The turtle is drawn here in code (no image files): a shell, head, legs
and tail, turned to its heading, with a different shell colour per turtle.
"""

from __future__ import annotations

import contextlib
import functools
import io
import math
import os
import stat
import struct
import tempfile
import zlib
from collections.abc import Iterable, Sequence

os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")  # pygame greets on import otherwise

import pygame

from ros_tutorials_turtlesim.simulation import (
    CANVAS_PIXELS,
    METER_PIXELS,
    WORLD_SIZE,
    Stroke,
    Turtle,
)

WINDOW_TITLE = "TurtleSim"
# One shell colour per turtle, in spawn order (turtle1 gets the first); repeats after ten.
SHELL_COLORS = [
    (46, 139, 87),
    (230, 126, 34),
    (142, 68, 173),
    (192, 57, 43),
    (22, 160, 133),
    (241, 196, 15),
    (236, 112, 160),
    (93, 109, 126),
    (160, 82, 45),
    (52, 73, 94),
]
SKIN = (124, 179, 66)
SKIN_DARK = (85, 125, 45)
OUTLINE = (30, 40, 20)
# Coordinates beyond this many pixels off the canvas are cut: a turtle spawned at 1e30 m
# is drawn at the edge until its first update clamps it, instead of overflowing SDL.
_MARGIN = 1000


def display_available() -> bool:
    """Whether a window could open: an X11 or Wayland display is named."""
    return bool(os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY"))


def to_pixels(x: float, y: float) -> tuple[float, float]:
    """Metres (y up) to canvas pixels (y down), cut to a safe range."""
    px, py = x * METER_PIXELS, (WORLD_SIZE - y) * METER_PIXELS
    return (
        min(max(px, -_MARGIN), CANVAS_PIXELS + _MARGIN),
        min(max(py, -_MARGIN), CANVAS_PIXELS + _MARGIN),
    )


# What SDL says when (part of) the window becomes visible again.
EXPOSED_EVENTS = frozenset(
    {pygame.VIDEOEXPOSE, pygame.WINDOWEXPOSED, pygame.WINDOWSHOWN, pygame.WINDOWRESTORED}
)


class Canvas:
    """The path image and, when windowed, the window it is shown in."""

    def __init__(self, window: bool) -> None:
        self.path = pygame.Surface((CANVAS_PIXELS, CANVAS_PIXELS), pygame.SRCALPHA)
        # The background with the path on it, kept up to date stroke by stroke and rebuilt
        # only when the background changes or the path is cleared: a frame is then one
        # plain copy plus the turtles, not a 500 x 500 alpha blend.
        self.base = pygame.Surface((CANVAS_PIXELS, CANVAS_PIXELS))
        self._base_background: tuple[int, ...] | None = None
        self._frame: pygame.Surface | None = None  # encode()'s, made on first use
        self.clear()
        self.screen: pygame.Surface | None = None
        self.exposed = False  # the window must be repainted (see window_closed)
        if window:
            # The display that is named, and no other: SDL would otherwise fall back to an
            # invisible "offscreen" window when it cannot reach it.
            if not os.environ.get("SDL_VIDEODRIVER"):
                os.environ["SDL_VIDEODRIVER"] = "x11" if os.environ.get("DISPLAY") else "wayland"
            pygame.display.init()
            if pygame.display.get_driver() in ("offscreen", "dummy"):
                pygame.display.quit()
                raise pygame.error(
                    f"SDL video driver {os.environ['SDL_VIDEODRIVER']} has no screen"
                )
            pygame.display.set_caption(WINDOW_TITLE)
            self.screen = pygame.display.set_mode((CANVAS_PIXELS, CANVAS_PIXELS))
            self.base = self.base.convert()  # the screen's pixel format: copies are plain copies

    @property
    def windowed(self) -> bool:
        return self.screen is not None

    @staticmethod
    def video_driver() -> str:
        return pygame.display.get_driver() if pygame.display.get_init() else "none"

    def clear(self) -> None:
        self.path.fill((0, 0, 0, 0))
        self._base_background = None

    def draw_strokes(self, strokes: Iterable[Stroke]) -> None:
        for stroke in strokes:
            start, end = to_pixels(*stroke.start), to_pixels(*stroke.end)
            for surface in (self.path, self.base):
                pygame.draw.line(surface, stroke.color, start, end, stroke.width)
                if stroke.width > 2:  # round joints, so a turning trail has no notches
                    pygame.draw.circle(surface, stroke.color, end, stroke.width / 2)

    def color_under(self, x: float, y: float, background: Sequence[int]) -> tuple[int, int, int]:
        """What the turtle's colour sensor sees: the trail under it, else the background."""
        px, py = (min(max(round(c), 0), CANVAS_PIXELS - 1) for c in to_pixels(x, y))
        r, g, b, a = self.path.get_at((px, py))
        return (r, g, b) if a else (background[0], background[1], background[2])

    def compose(
        self, target: pygame.Surface, background: Sequence[int], turtles: Iterable[Turtle]
    ) -> None:
        background = tuple(background)
        if background != self._base_background:
            self.base.fill(background)
            self.base.blit(self.path, (0, 0))
            self._base_background = background
        target.blit(self.base, (0, 0))
        for turtle in turtles:
            draw_turtle(target, turtle)

    def show(self, background: Sequence[int], turtles: Iterable[Turtle]) -> None:
        """Repaint the window (nothing headless)."""
        if self.screen is not None:
            self.compose(self.screen, background, turtles)
            pygame.display.flip()

    def window_closed(self) -> bool:
        """Handle the window's events; True once the user has closed it. A window that was
        covered, hidden or minimised and is shown again sets ``exposed``: it must be
        repainted even if nothing changed (it kept the other window's pixels)."""
        if self.screen is None:
            return False
        events = pygame.event.get()
        if any(event.type in EXPOSED_EVENTS for event in events):
            self.exposed = True
        return any(event.type == pygame.QUIT for event in events)

    def snapshot(self, background: Sequence[int], turtles: Iterable[Turtle]) -> bytes:
        """The canvas as it looks now, as a PNG file marked as turtlesim's snapshot."""
        frame = pygame.Surface((CANVAS_PIXELS, CANVAS_PIXELS))
        self.compose(frame, background, turtles)
        return png_bytes(frame, SNAPSHOT_TEXT)

    def encode(self, kind: str, background: Sequence[int], turtles: Iterable[Turtle]) -> bytes:
        """The canvas as it looks now, as the bytes of a 'png' or 'jpeg' file."""
        if self._frame is None:
            self._frame = pygame.Surface((CANVAS_PIXELS, CANVAS_PIXELS))
        self.compose(self._frame, background, turtles)
        if kind == "png":
            return png_bytes(self._frame)
        encoded = io.BytesIO()
        pygame.image.save(self._frame, encoded, f"canvas.{kind}")
        return encoded.getvalue()

    def close(self) -> None:
        if self.screen is not None:
            pygame.display.quit()
            self.screen = None


PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
# A PNG text chunk in every picture written here, right after the header: what tells a
# turtlesim snapshot (which a new one may replace) from any other file (which it never does).
SNAPSHOT_TEXT = b"Software\0ros_tutorials turtlesim"


def open_canvas(logger, headless: bool, png_hint: str) -> Canvas:
    """A window if one can open and ``headless`` is false, else drawing in memory; each case
    logged as turtlesim says it (png_hint: how to get a PNG of the canvas)."""
    if headless:
        logger.info(f"Running headless (parameter headless is true); {png_hint}")
        return Canvas(window=False)
    if not display_available():
        logger.info(f"Running headless (no DISPLAY or WAYLAND_DISPLAY, so no window); {png_hint}")
        return Canvas(window=False)
    try:
        drawn = Canvas(window=True)
    except Exception as error:  # pygame.error: the display named cannot be opened
        shown = ", ".join(
            f"{name}={os.environ[name]}"
            for name in ("DISPLAY", "WAYLAND_DISPLAY")
            if os.environ.get(name)
        )
        logger.warning(f"Running headless: no window could open on {shown} ({error}); {png_hint}")
        return Canvas(window=False)
    logger.info(
        f"Drawing in a window (pygame {pygame.version.ver}, "
        f"SDL video driver {drawn.video_driver()})"
    )
    return drawn


class SnapshotRefused(Exception):
    """A snapshot that is not written, and why (the service's answer says it)."""


def is_snapshot(path: str) -> bool:
    """Whether the file at path is a PNG this turtlesim wrote (not followed if a link)."""
    try:
        descriptor = os.open(path, os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK)
    except OSError:
        return False
    try:
        if not stat.S_ISREG(os.fstat(descriptor).st_mode):
            return False
        head = os.read(descriptor, 128)
    finally:
        os.close(descriptor)
    return head.startswith(PNG_SIGNATURE) and b"tEXt" + SNAPSHOT_TEXT in head


def write_snapshot(path: str, data: bytes) -> None:
    """Write data to path, a new file or an earlier snapshot, never over any other file;
    written whole or not at all (a full disk or a quota leaves nothing behind)."""
    if os.path.lexists(path) and not is_snapshot(path):
        raise SnapshotRefused(f"{path} exists and is not a turtlesim snapshot: not overwritten")
    folder = os.path.dirname(path)
    try:
        descriptor, partial = tempfile.mkstemp(prefix=".turtlesim-", suffix=".part", dir=folder)
    except OSError as error:
        raise SnapshotRefused(f"cannot write {path}: {error.strerror}") from None
    try:
        with os.fdopen(descriptor, "wb") as file:
            file.write(data)
            file.flush()
            os.fsync(file.fileno())  # a full disk may say so only here
        os.chmod(partial, 0o644)  # mkstemp's 0600: a picture others on the machine may see
        os.replace(partial, path)  # a link at path is replaced, never followed
    except OSError as error:
        with contextlib.suppress(OSError):
            os.unlink(partial)
        raise SnapshotRefused(f"cannot write {path}: {error.strerror} (nothing written)") from None


def png_bytes(surface: pygame.Surface, text: bytes | None = None) -> bytes:
    """A PNG file of the surface, with zlib's fastest level: a third of the CPU of pygame's
    PNG (2 ms instead of 6 for the canvas), for files about twice as large (5-20 kB); with a
    tEXt chunk of ``text`` (a snapshot's mark: the canvas frames the viewer shows have none,
    so a picture saved from them is never taken for a snapshot)."""
    width, height = surface.get_size()
    pixels = memoryview(pygame.image.tobytes(surface, "RGB"))
    stride = width * 3
    # Each row starts with its filter type, 0: none (the flat background compresses anyway).
    rows = b"".join(b"\0" + pixels[y * stride : (y + 1) * stride] for y in range(height))

    def chunk(kind: bytes, data: bytes) -> bytes:
        return (
            struct.pack("!I", len(data)) + kind + data + struct.pack("!I", zlib.crc32(kind + data))
        )

    header = struct.pack("!IIBBBBB", width, height, 8, 2, 0, 0, 0)  # 8-bit RGB
    return (
        PNG_SIGNATURE
        + chunk(b"IHDR", header)
        + (chunk(b"tEXt", text) if text else b"")
        + chunk(b"IDAT", zlib.compress(rows, 1))
        + chunk(b"IEND", b"")
    )


def _ellipse(rx: float, ry: float, cx: float = 0.0, points: int = 24) -> list[tuple[float, float]]:
    return [
        (cx + rx * math.cos(2 * math.pi * i / points), ry * math.sin(2 * math.pi * i / points))
        for i in range(points)
    ]


# The figure in the turtle's own frame (pixels, x forward, y to its left), 45 px long like
# turtlesim's images: four legs, a tail, the head with two eyes, the shell with its plates.
_LEGS = [_ellipse(5, 3.5, 0) for _ in range(4)]
_LEG_PLACES = [(9, 11), (9, -11), (-9, 11), (-9, -11)]
_TAIL = [(-13, 3), (-21, 0), (-13, -3)]
_HEAD = _ellipse(6.5, 5.5, 16)
_EYES = [(19.5, 2.8), (19.5, -2.8)]
_SHELL = _ellipse(14, 11.5)
_PLATES = [(-6, 0), (-2.5, 6), (4.5, 6), (8, 0), (4.5, -6), (-2.5, -6)]


_SPRITE_SIZE = 56


@functools.lru_cache(maxsize=16)
def _sprite(index: int) -> pygame.Surface:
    """The turtle facing east, drawn once per shell colour."""
    surface = pygame.Surface((_SPRITE_SIZE, _SPRITE_SIZE), pygame.SRCALPHA)
    centre = _SPRITE_SIZE / 2

    def place(points: Iterable[tuple[float, float]], dx: float = 0.0, dy: float = 0.0) -> list:
        return [(centre + x + dx, centre - (y + dy)) for x, y in points]  # y up -> screen

    shell = SHELL_COLORS[index % len(SHELL_COLORS)]
    for leg, (dx, dy) in zip(_LEGS, _LEG_PLACES, strict=True):
        pygame.draw.polygon(surface, SKIN_DARK, place(leg, dx, dy))
    pygame.draw.polygon(surface, SKIN_DARK, place(_TAIL))
    pygame.draw.polygon(surface, SKIN, place(_HEAD))
    pygame.draw.polygon(surface, OUTLINE, place(_HEAD), 1)
    for eye in place(_EYES):
        pygame.draw.circle(surface, OUTLINE, eye, 1.4)
    pygame.draw.polygon(surface, shell, place(_SHELL))
    darker = tuple(int(c * 0.6) for c in shell)
    pygame.draw.polygon(surface, darker, place(_PLATES), 2)
    pygame.draw.polygon(surface, OUTLINE, place(_SHELL), 2)
    return surface


@functools.lru_cache(maxsize=512)
def _turned(index: int, degrees: int) -> pygame.Surface:
    """The sprite turned to a heading (whole degrees, counter-clockwise), smoothed."""
    image = pygame.transform.rotozoom(_sprite(index), degrees, 1.0)
    return image.convert_alpha() if pygame.display.get_surface() else image


def draw_turtle(surface: pygame.Surface, turtle: Turtle) -> None:
    cx, cy = to_pixels(turtle.x, turtle.y)
    image = _turned(turtle.index % len(SHELL_COLORS), round(math.degrees(turtle.theta)) % 360)
    surface.blit(image, (cx - image.get_width() / 2, cy - image.get_height() / 2))
