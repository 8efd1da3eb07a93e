"""Headless Chromium for the tests that look at a page as a person does (Debian's chromium and
chromium-driver, driven by selenium): open the link, click, type, read what the page shows,
take a screenshot.

Where no browser is installed the test is skipped with a reason starting with NEEDS; with
CI=true, conftest.py turns such a skip into a failure (`.ci/run` installs the browser).
"""

from __future__ import annotations

import contextlib
import shutil
import time
from collections.abc import Callable, Iterator
from typing import Any, TypeVar

import pytest
from helpers import TIMEOUT

# The start of the reason of every skip for a missing browser or display (conftest.py).
NEEDS = "needs a browser or display:"
FLAGS = (
    "--headless=new",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--no-first-run",
)
T = TypeVar("T")


def browser_paths() -> tuple[str, str]:
    """Chromium and its driver, or a skip saying what to install."""
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    driver = shutil.which("chromedriver")
    if not chromium or not driver:
        pytest.skip(f"{NEEDS} Debian's chromium and chromium-driver (apt-get install)")
    return chromium, driver


def open_chromium(width: int = 1400, height: int = 1000, *flags: str) -> Any:
    """A headless Chromium window of this size (FLAGS and these ``flags``); the caller quits
    it."""
    path, driver = browser_paths()
    webdriver = pytest.importorskip("selenium.webdriver")
    from selenium.webdriver.chrome.service import Service

    options = webdriver.ChromeOptions()
    options.binary_location = path
    for flag in (*FLAGS, f"--window-size={width},{height}", *flags):
        options.add_argument(flag)
    browser = webdriver.Chrome(options=options, service=Service(driver))
    browser.set_script_timeout(TIMEOUT)
    return browser


@contextlib.contextmanager
def chromium(width: int = 1400, height: int = 1000) -> Iterator[Any]:
    """A headless Chromium window of this size, closed afterwards."""
    browser = open_chromium(width, height)
    try:
        yield browser
    finally:
        browser.quit()


def until(found: Callable[[], T], what: str, timeout: float = TIMEOUT) -> T:
    """found()'s first truthy answer, asked every 0.1 s; a failure naming ``what`` after
    ``timeout`` seconds."""
    deadline = time.monotonic() + timeout
    while True:
        answer = found()
        if answer:
            return answer
        if time.monotonic() > deadline:
            pytest.fail(f"{what}: not seen in the page within {timeout:.0f} s")
        time.sleep(0.1)


def text_of(browser: Any, css: str) -> str:
    """The visible text of the first element matching ``css`` ('' if there is none)."""
    found = browser.find_elements("css selector", css)
    return found[0].text if found else ""
