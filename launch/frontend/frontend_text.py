"""An attribute's text as a markup front-end wrote it, kept with its element (file:line):
its ``$(...)`` are read by launch.frontend's one scanner into substitutions, performed when
the action that holds it needs the value, within the expansion caps, and the attribute's own
check applied to the result."""

from __future__ import annotations

import shlex
from collections.abc import Callable
from typing import Any

from launch._base import Substitution
from launch.launch_context import LaunchContext
from launch_foundation.parse import Element


class FrontendText(Substitution):
    """Text with ``$(...)``: parsed once, when first performed (an element a condition turns
    off is never read), then performed in the launch's context."""

    def __init__(
        self, text: str, element: Element, check: Callable[[str, Element], str] | None = None
    ) -> None:
        super().__init__()
        self.text, self.element, self.where = text, element, element.where
        self.check = check  # the attribute's own check of its value, at its element's line
        self._parts: list[Any] | None = None

    def parts(self) -> list[Any]:
        """The substitutions of the text (ROS 2 markup)."""
        if self._parts is None:
            from launch.frontend.parse_substitution import parse_at

            self._parts = parse_at(self.text, self.where)
        return self._parts

    def perform(self, context: LaunchContext | None) -> str:
        from launch.frontend.parse_substitution import perform_capped

        if context is None:  # performed without a launch, as ros2/launch's tests do
            context = LaunchContext()

        value = perform_capped(self.parts(), context, self.where)
        return self.check(value, self.element) if self.check else value

    def describe(self) -> str:
        return repr(self.text)

    def enabled(self, context: LaunchContext) -> bool:
        """Whether the element this text is an attribute of holds (its ``if``/``unless``):
        a child of a <node> or <executable> read into the action's arguments."""
        return frontend_enabled(self.element, context)


class FrontendWords(FrontendText):
    """An attribute that is a command line (cmd, args, ros_args, launch-prefix): its words
    are split as a shell would, after its $(...) are performed."""

    def words(self, context: LaunchContext) -> list[str]:
        return shlex.split(self.perform(context))


def split_words(name: str) -> Callable[[str, Element], str]:
    """FrontendWords' check: text a shell can split (the attribute ``name``)."""

    def check(text: str, where: Element) -> str:
        try:
            shlex.split(text)
        except ValueError as error:  # No closing quotation
            raise where.error(f"{name.replace('_', '-')}={text!r}: {error}") from None
        return text

    return check


def frontend_enabled(element: Element, context: LaunchContext) -> bool:
    """An element's ``if``/``unless``, performed now: launch.conditions' reading."""
    from launch.conditions import condition_truth

    for attribute, wanted in (("if", True), ("unless", False)):
        if attribute in element.attrs:
            text = FrontendText(element.attrs[attribute], element).perform(context)
            return condition_truth(text, element.where, f"{attribute!r}") == wanted
    return True
