"""launch.frontend.Entity: one element of a markup launch file, whatever the markup."""

from __future__ import annotations

from typing import Any


class Entity:
    """One parsed element: its tag (``type_name``), its ``children`` and its attributes read
    by ``get_attr``. Each markup front-end provides its own (launch_xml.Entity,
    launch_yaml.Entity)."""

    @property
    def type_name(self) -> str:
        raise NotImplementedError

    @property
    def parent(self) -> Entity | None:
        raise NotImplementedError

    @property
    def children(self) -> list[Entity]:
        raise NotImplementedError

    def get_attr(
        self, name: str, *, data_type: Any = str, optional: bool = False, can_be_str: bool = True
    ) -> Any:
        """The attribute ``name`` as ``data_type`` (str, int, float, bool, a list of one of
        them, ``List[Entity]`` for the children of that tag, None for its YAML value); a
        missing one is None if ``optional``, else AttributeError."""
        raise NotImplementedError

    def assert_entity_completely_parsed(self) -> None:
        """Refuse an attribute or child no parse method read (a typo in the file)."""
        raise NotImplementedError
