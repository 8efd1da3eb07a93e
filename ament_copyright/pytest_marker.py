"""The `copyright` pytest marker the template's test_copyright.py uses (a pytest11 plugin)."""

from __future__ import annotations

import pytest


def pytest_configure(config: pytest.Config) -> None:
    config.addinivalue_line("markers", "copyright: marks tests checking for copyright notices")
